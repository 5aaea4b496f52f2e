// ETD-DPD: plugin entry point; registers every style of the package with LAMMPS.
#include "compute_dpd_split.h"
#include "compute_dpd_tcurrent.h"
#include "dpd_design.h"
#include "error.h"
#include "fix_etd_diagonal.h"
#include "fix_etd_implicit.h"
#include "fix_etd_options.h"
#include "fix_wall_cylinder_bounce.h"
#include "fix_wall_thermal_layer.h"
#include "lammpsplugin.h"
#include "pair_dpd_fpm.h"
#include "pair_dpd_gen.h"
#include "version.h"
#ifdef ETD_DPD_KOKKOS
#include "KOKKOS/fix_etd_diagonal_kokkos.h"
#include "KOKKOS/pair_dpd_law_kokkos.h"
#endif

#include <string>

using namespace LAMMPS_NS;

namespace {
Compute *create_compute_dpd_split(LAMMPS *lmp, int narg, char **arg)
{
  return new ComputeDPDSplit(lmp, narg, arg);
}
// fix etd has two schemes with different state and steps; 'scheme' picks the class
Fix *create_fix_etd(LAMMPS *lmp, int narg, char **arg)
{
  if (etd::fix_etd_scheme_is_implicit(lmp, narg, arg)) return new FixETDImplicit(lmp, narg, arg);
  return new FixETDDiagonal(lmp, narg, arg);
}
Compute *create_compute_dpd_tcurrent(LAMMPS *lmp, int narg, char **arg)
{
  return new ComputeDPDTCurrent(lmp, narg, arg);
}
Command *create_dpd_design(LAMMPS *lmp)
{
  return new DPDDesign(lmp);
}
Fix *create_fix_wall_thermal_layer(LAMMPS *lmp, int narg, char **arg)
{
  return new FixWallThermalLayer(lmp, narg, arg);
}
Fix *create_fix_wall_cylinder_bounce(LAMMPS *lmp, int narg, char **arg)
{
  return new FixWallCylinderBounce(lmp, narg, arg);
}
}    // namespace

extern "C" void lammpsplugin_init(void *lmp, void *handle, void *regfunc)
{
  auto register_plugin = (lammpsplugin_regfunc) regfunc;
  lammpsplugin_t plugin;
  plugin.version = LAMMPS_VERSION;
  plugin.author = "ETD-DPD developers";
  plugin.handle = handle;

  register_pair_style<PairDPDGenStyle>(plugin, register_plugin, lmp);
  register_pair_style<PairDPDFPMStyle>(plugin, register_plugin, lmp);
#ifdef ETD_DPD_KOKKOS
  register_pair_style_kokkos<PairDPDGenStyle>(plugin, register_plugin, lmp);
  register_fix_etd_kokkos(plugin, register_plugin, lmp);
#endif

  plugin.style = "compute";
  plugin.name = "dpd/split";
  plugin.info = "ETD-DPD conservative/dissipative/random parts of the DPD pair force";
  plugin.creator.v2 = (lammpsplugin_factory2 *) &create_compute_dpd_split;
  (*register_plugin)(&plugin, lmp);

  plugin.style = "compute";
  plugin.name = "dpd/tcurrent";
  plugin.info = "ETD-DPD transverse current J_perp(k, t) for the TCAF viscosity";
  plugin.creator.v2 = (lammpsplugin_factory2 *) &create_compute_dpd_tcurrent;
  (*register_plugin)(&plugin, lmp);

  plugin.style = "fix";
  plugin.name = "etd";
  plugin.info = "ETD-DPD exponential time differencing integrator for low-mass DPD";
  plugin.creator.v2 = (lammpsplugin_factory2 *) &create_fix_etd;
  (*register_plugin)(&plugin, lmp);

  plugin.style = "command";
  plugin.name = "dpd/design";
  plugin.info = "ETD-DPD DPD parameters s, gamma from a target viscosity and Schmidt number";
  plugin.creator.v1 = (lammpsplugin_factory1 *) &create_dpd_design;
  (*register_plugin)(&plugin, lmp);

  plugin.style = "fix";
  plugin.name = "wall/thermal/layer";
  plugin.info = "ETD-DPD near-wall layer with velocities redrawn from the wall's Maxwellian";
  plugin.creator.v2 = (lammpsplugin_factory2 *) &create_fix_wall_thermal_layer;
  (*register_plugin)(&plugin, lmp);

  plugin.style = "fix";
  plugin.name = "wall/cylinder/bounce";
  plugin.info = "ETD-DPD bounce-back reflection on a cylinder surface";
  plugin.creator.v2 = (lammpsplugin_factory2 *) &create_fix_wall_cylinder_bounce;
  (*register_plugin)(&plugin, lmp);
}
