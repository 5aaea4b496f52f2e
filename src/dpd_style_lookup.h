// ETD-DPD: find this package's pair styles, alone or inside pair hybrid / hybrid/overlay.
#ifndef ETD_DPD_STYLE_LOOKUP_H
#define ETD_DPD_STYLE_LOOKUP_H

#include "dpd_friction_provider.h"
#include "lammps.h"

#include <vector>

namespace etd {
std::vector<DpdExtrasProvider *> find_dpd_providers(LAMMPS_NS::LAMMPS *lmp);
}

#endif
