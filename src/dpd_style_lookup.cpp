#include "dpd_style_lookup.h"

#include "error.h"
#include "fix.h"
#include "lammps_compat.h"
#include "force.h"
#include "modify.h"
#include "pair.h"
#include "pair_hybrid.h"
#include "update.h"
#include "utils.h"

namespace {

// PairHybrid keeps its sub-styles protected (29Sep2021 and 4Jul2026 alike; LAMMPS's own users
// of them are friends). A derived class may form a pointer to such a member, and the pointer
// may be applied to any PairHybrid ([class.protected]): this reads the list through the
// class's own declarations, without a copy of its layout. Never instantiated.
class HybridSubStyles : public LAMMPS_NS::PairHybrid {
 public:
  static std::vector<LAMMPS_NS::Pair *> of(LAMMPS_NS::PairHybrid *hybrid)
  {
    const int n = hybrid->*(&HybridSubStyles::nstyles);
    LAMMPS_NS::Pair **styles = hybrid->*(&HybridSubStyles::styles);
    return std::vector<LAMMPS_NS::Pair *>(styles, styles + n);
  }
};

}    // namespace

std::vector<etd::DpdPairInterface *> etd::find_dpd_pair_styles(LAMMPS_NS::LAMMPS *lmp)
{
  std::vector<DpdPairInterface *> found;
  LAMMPS_NS::Pair *pair = lmp->force->pair;
  if (!pair) return found;
  if (auto *style = dynamic_cast<DpdPairInterface *>(pair)) {
    found.push_back(style);
  } else if (auto *hybrid = dynamic_cast<LAMMPS_NS::PairHybrid *>(pair)) {
    for (LAMMPS_NS::Pair *sub : HybridSubStyles::of(hybrid))
      if (auto *style = dynamic_cast<DpdPairInterface *>(sub)) found.push_back(style);
  }
  return found;
}

std::vector<etd::DpdPairInterface *> etd::fix_etd_pair_styles(LAMMPS_NS::LAMMPS *lmp,
                                                              const char *friction)
{
  if (LAMMPS_NS::utils::strmatch(lmp->update->integrate_style, "^respa"))
    lmp->error->all(FLERR, "Fix etd does not support run_style respa");
  std::vector<DpdPairInterface *> styles = find_dpd_pair_styles(lmp);
  if (styles.empty())
    lmp->error->all(FLERR,
                    "Fix etd requires pair style dpd/gen or dpd/fpm (alone or in pair "
                    "hybrid/overlay) to supply the {}",
                    friction);
  // there fix wall/reflect/stochastic crashes at its first step (with any integrator; measured
  // with fix nve); the package's examples use it for thermal walls
  if (lmp->num_ver >= etd::compat::first_version_with_crashing_wall_reflect_stochastic)
    if (LAMMPS_NS::Fix *walls = find_fix_style(lmp, "^wall/reflect/stochastic"))
      lmp->error->all(FLERR,
                      "Fix wall/reflect/stochastic ({}) crashes at its first step in this "
                      "LAMMPS version ({}): use fix wall/reflect with fix wall/thermal/layer "
                      "for a wall's velocity and temperature (the examples' -var wallbc layer)",
                      walls->id, lmp->num_ver);
  return styles;
}

LAMMPS_NS::Fix *etd::find_fix_style(LAMMPS_NS::LAMMPS *lmp, const char *pattern)
{
  for (int f = 0; f < lmp->modify->nfix; f++)
    if (LAMMPS_NS::utils::strmatch(lmp->modify->fix[f]->style, pattern)) return lmp->modify->fix[f];
  return nullptr;
}
