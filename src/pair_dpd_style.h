// ETD-DPD: a pair style of the package from its description, Style:
//   struct Style {
//     static constexpr const char *name, *info;    // pair_style name, plugin info line
//     using Law = ...;                             // the pair law (pair_law.h)
//     static constexpr etd::CoeffParam params[];   // its coefficients (pair_coeff_description.h)
//     static Law::Coefficients coefficients(const double *values, double kT);  // from params
//   };
// and its registration with LAMMPS, one line in the plugin's init.
#ifndef ETD_PAIR_DPD_STYLE_H
#define ETD_PAIR_DPD_STYLE_H

#include "pair_dpd_base.h"

#include "lammpsplugin.h"

#include <iterator>
#include <type_traits>
#include <vector>

namespace LAMMPS_NS {

template <class Style> class PairDPDStyle : public PairDPDBase {
 public:
  using Law = typename Style::Law;
  using Coefficients = typename Law::Coefficients;
  static constexpr int COEFFS = static_cast<int>(std::size(Style::params));

  explicit PairDPDStyle(class LAMMPS *lmp) :
      PairDPDBase(lmp, {Style::name, Style::params, COEFFS}, Law::rotation)
  {
  }

  void compute(int eflag, int vflag) override
  {
    compute_pairs<Law>(table.data(), stride, eflag, vflag);
  }

  double init_one(int i, int j) override
  {
    const double range = init_type_pair(i, j);
    double values[COEFFS];
    type_pair_values(i, j, values);
    const Coefficients c = Style::coefficients(values, force->boltz * temperature);
    table[i * stride + j] = c;
    table[j * stride + i] = c;
    return range;
  }

  // the conservative part only, as stock pair dpd: the others depend on velocities and noise
  double single(int, int, int itype, int jtype, double rsq, double, double factor_lj,
                double &fforce) override
  {
    fforce = 0.0;
    const Coefficients &c = table[itype * stride + jtype];
    const double r = std::sqrt(rsq);
    if (r < MIN_DISTANCE) return 0.0;
    fforce = Law::conservative(c, rsq, r, factor_lj) / r;
    return Law::energy(c, rsq, r, factor_lj);
  }

  // the law's friction, for fix etd's implicit scheme
  const etd::PairCoefficients *dpd_coefficients(int i, int j) override
  {
    if constexpr (std::is_same_v<typename Law::Friction, etd::PairCoefficients>)
      return type_pair_set(i, j) ? &Law::friction(table[i * stride + j]) : nullptr;
    return nullptr;
  }
  const etd::FpmCoefficients *fpm_coefficients(int i, int j) override
  {
    if constexpr (std::is_same_v<typename Law::Friction, etd::FpmCoefficients>)
      return type_pair_set(i, j) ? &Law::friction(table[i * stride + j]) : nullptr;
    return nullptr;
  }

 protected:
  std::vector<Coefficients> table;    // (ntypes+1)^2, filled by init_one
  int stride = 0;

  void allocate() override
  {
    allocate_base();
    stride = atom->ntypes + 1;
    table.assign(static_cast<size_t>(stride) * stride, Coefficients());
  }
};

template <class Style> Pair *create_pair_style(LAMMPS *lmp)
{
  return new PairDPDStyle<Style>(lmp);
}

// plugin: version, author and handle as the caller's
template <class Style>
void register_pair_style(lammpsplugin_t plugin, lammpsplugin_regfunc register_plugin, void *lmp)
{
  plugin.style = "pair";
  plugin.name = Style::name;
  plugin.info = Style::info;
  plugin.creator.v1 = (lammpsplugin_factory1 *) &create_pair_style<Style>;
  (*register_plugin)(&plugin, lmp);
}

}    // namespace LAMMPS_NS

#endif
