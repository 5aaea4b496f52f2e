// ETD-DPD: plugin entry point; registers every style of the package with LAMMPS.
#include "compute_dpd_split.h"
#include "fix_etd.h"
#include "lammpsplugin.h"
#include "pair_dpd_fpm.h"
#include "pair_dpd_gen.h"
#include "version.h"

using namespace LAMMPS_NS;

namespace {
Pair *create_pair_dpd_gen(LAMMPS *lmp) { return new PairDPDGen(lmp); }
Pair *create_pair_dpd_fpm(LAMMPS *lmp) { return new PairDPDFPM(lmp); }
Compute *create_compute_dpd_split(LAMMPS *lmp, int narg, char **arg)
{
  return new ComputeDPDSplit(lmp, narg, arg);
}
Fix *create_fix_etd(LAMMPS *lmp, int narg, char **arg) { return new FixETD(lmp, narg, arg); }
}    // namespace

extern "C" void lammpsplugin_init(void *lmp, void *handle, void *regfunc)
{
  auto register_plugin = (lammpsplugin_regfunc) regfunc;
  lammpsplugin_t plugin;
  plugin.version = LAMMPS_VERSION;
  plugin.author = "ETD-DPD developers";
  plugin.handle = handle;

  plugin.style = "pair";
  plugin.name = "dpd/gen";
  plugin.info = "ETD-DPD generalised DPD: exponent s, separate conservative/dissipative cutoffs";
  plugin.creator.v1 = (lammpsplugin_factory1 *) &create_pair_dpd_gen;
  (*register_plugin)(&plugin, lmp);

  plugin.name = "dpd/fpm";
  plugin.info = "ETD-DPD FPM-style DPD: central and shear drag, angular velocities and torques";
  plugin.creator.v1 = (lammpsplugin_factory1 *) &create_pair_dpd_fpm;
  (*register_plugin)(&plugin, lmp);

  plugin.style = "compute";
  plugin.name = "dpd/split";
  plugin.info = "ETD-DPD conservative/dissipative/random parts of the DPD pair force";
  plugin.creator.v2 = (lammpsplugin_factory2 *) &create_compute_dpd_split;
  (*register_plugin)(&plugin, lmp);

  plugin.style = "fix";
  plugin.name = "etd";
  plugin.info = "ETD-DPD exponential time differencing integrator for low-mass DPD";
  plugin.creator.v2 = (lammpsplugin_factory2 *) &create_fix_etd;
  (*register_plugin)(&plugin, lmp);
}
