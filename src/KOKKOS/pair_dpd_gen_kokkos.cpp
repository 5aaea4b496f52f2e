// ETD-DPD: pair_style dpd/gen/kk (with /kk/device and /kk/host), the KOKKOS variant of dpd/gen.
#include "pair_dpd_gen.h"
#include "pair_dpd_law_kokkos_impl.h"

namespace LAMMPS_NS {
template void register_pair_style_kokkos<PairDPDGenStyle>(lammpsplugin_t, lammpsplugin_regfunc,
                                                          void *);
}
