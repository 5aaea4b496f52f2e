// pair_style dpd/probe/kk: LAMMPS's PairDPDKokkos compiled into this plugin under the class
// name PairDPDProbeKokkos, so that its Kokkos kernels (parallel_for / parallel_reduce over the
// neighbor list, the Kokkos random pool) are instantiated here, in the plugin, and run on the
// Kokkos runtime that liblammps initialised (-k on). Registered as dpd/probe/kk (device type)
// and dpd/probe/kk/host; `-sf kk` maps `pair_style dpd/probe` onto dpd/probe/kk.
#define PairDPDKokkos PairDPDProbeKokkos
#include "pair_dpd_kokkos.cpp"
#undef PairDPDKokkos

#include "lammpsplugin.h"
#include "version.h"

using namespace LAMMPS_NS;

static Pair *probe_device(LAMMPS *lmp) { return new PairDPDProbeKokkos<LMPDeviceType>(lmp); }
static Pair *probe_host(LAMMPS *lmp) { return new PairDPDProbeKokkos<LMPHostType>(lmp); }

extern "C" void lammpsplugin_init(void *lmp, void *handle, void *regfunc)
{
  lammpsplugin_t plugin;
  auto register_plugin = (lammpsplugin_regfunc) regfunc;
  plugin.version = LAMMPS_VERSION;
  plugin.style = "pair";
  plugin.info = "dpd/probe/kk: dpd/kk kernels compiled in a plugin";
  plugin.author = "ETD-DPD";
  plugin.handle = handle;
  plugin.name = "dpd/probe/kk";
  plugin.creator.v1 = (lammpsplugin_factory1 *) &probe_device;
  (*register_plugin)(&plugin, lmp);
  plugin.name = "dpd/probe/kk/host";
  plugin.info = "dpd/probe/kk/host: dpd/kk kernels compiled in a plugin, host execution space";
  plugin.creator.v1 = (lammpsplugin_factory1 *) &probe_host;
  (*register_plugin)(&plugin, lmp);
}
