// ETD-DPD: find this package's pair styles, alone or inside pair hybrid / hybrid/overlay.
#ifndef ETD_DPD_STYLE_LOOKUP_H
#define ETD_DPD_STYLE_LOOKUP_H

#include "dpd_pair_interface.h"
#include "lammps.h"

#include <vector>

namespace LAMMPS_NS {
class Fix;
}

namespace etd {
// The pair style if it implements DpdPairInterface, else those of the sub-styles of pair
// hybrid (and its variants) that do, in the order of the pair_style command; empty if none.
std::vector<DpdPairInterface *> find_dpd_pair_styles(LAMMPS_NS::LAMMPS *lmp);

// The preamble of fix etd's init(), both schemes: r-RESPA refused (the step is one piece), and
// the package's pair styles found; ERROR if there are none, naming what the scheme takes from
// them (friction: e.g. "diagonal friction").
std::vector<DpdPairInterface *> fix_etd_pair_styles(LAMMPS_NS::LAMMPS *lmp, const char *friction);

// The first fix whose style matches the pattern (utils::strmatch), or nullptr.
LAMMPS_NS::Fix *find_fix_style(LAMMPS_NS::LAMMPS *lmp, const char *pattern);
}    // namespace etd

#endif
