// ETD-DPD: fix etd/kk (fix_etd_diagonal_kokkos.h).
#include "fix_etd_diagonal_kokkos.h"

#include "atom_kokkos.h"
#include "atom_masks.h"
#include "comm.h"
#include "dpd_pair_interface.h"
#include "error.h"
#include "etd_coefficients.h"
#include "fix_etd_implicit_kokkos.h"
#include "fix_etd_options.h"
#include "force.h"
#include "kokkos_views.h"
#include "lammpsplugin.h"
#include "pair.h"
#include "update.h"

#include <string>

using namespace LAMMPS_NS;

namespace {
constexpr unsigned int DEVICE_READ = X_MASK | V_MASK | F_MASK | MASK_MASK | RMASS_MASK | TYPE_MASK;
constexpr unsigned int DEVICE_MODIFY = X_MASK | V_MASK;
}    // namespace

template <class DeviceType>
FixETDDiagonalKokkos<DeviceType>::FixETDDiagonalKokkos(LAMMPS *lmp, int narg, char **arg) :
    FixETDDiagonal(lmp, narg, arg)
{
  kokkosable = 1;
  atomKK = (AtomKokkos *) atom;
  execution_space = ExecutionSpaceFromDevice<DeviceType>::space;
  datamask_read = DEVICE_READ;
  datamask_modify = DEVICE_MODIFY;
}

template <class DeviceType> std::string FixETDDiagonalKokkos<DeviceType>::host_reason() const
{
  if (order != 1) return "order 2";
  if (noise != Noise::Piecewise) return "noise exact";
  if (conserve_momentum) return "momentum conserve";
  if (dpd_styles.size() != 1) return "more than one DPD pair style";
  const auto *pair = dynamic_cast<const Pair *>(dpd_styles.front());
  if (!pair || !pair->kokkosable) return "a pair style without a KOKKOS variant";
  return "";
}

template <class DeviceType> void FixETDDiagonalKokkos<DeviceType>::init()
{
  atomKK->sync(Host, V_MASK | MASK_MASK);    // the CPU fix's checks read them on the host
  FixETDDiagonal::init();
  const std::string reason = host_reason();
  on_device = reason.empty();
  if (!on_device && comm->me == 0)
    error->warning(
        FLERR, "Fix etd/kk: the step runs on the host with {} (the CPU fix's step, same results)",
        reason);
  execution_space = on_device ? ExecutionSpaceFromDevice<DeviceType>::space : Host;
  datamask_read = on_device ? DEVICE_READ : ALL_MASK;
  datamask_modify = on_device ? DEVICE_MODIFY : ALL_MASK;
}

template <class DeviceType> void FixETDDiagonalKokkos<DeviceType>::initial_integrate(int vflag)
{
  if (!on_device) {
    atomKK->sync(Host, ALL_MASK);
    FixETDDiagonal::initial_integrate(vflag);
    atomKK->modified(Host, ALL_MASK);
    return;
  }
  atomKK->sync(execution_space, X_MASK | V_MASK | MASK_MASK);
  auto x = atomKK->k_x.template view<DeviceType>();
  auto v = atomKK->k_v.template view<DeviceType>();
  auto mask = atomKK->k_mask.template view<DeviceType>();
  const int bit = groupbit;
  const double step = dt;
  Kokkos::parallel_for(
      Kokkos::RangePolicy<DeviceType>(0, atom->nlocal), KOKKOS_LAMBDA(const int i) {
        if (mask(i) & bit)
          for (int k = 0; k < 3; k++) x(i, k) += step * v(i, k);
      });
  atomKK->modified(execution_space, X_MASK);
}

// The pair style's friction diagonal of the owned atoms: the CPU style's host array (its
// reverse communication summed the ghosts' parts there), read in place where DeviceType reads
// host memory, else copied.
template <class DeviceType>
Kokkos::View<double **, Kokkos::LayoutRight, DeviceType>
FixETDDiagonalKokkos<DeviceType>::friction_on_device(int nlocal)
{
  using View = Kokkos::View<double **, Kokkos::LayoutRight, DeviceType>;
  double **friction = dpd_styles.front()->diagonal_friction();
  if (nlocal == 0 || !friction) return View();
  if constexpr (Kokkos::SpaceAccessibility<typename DeviceType::memory_space,
                                           Kokkos::HostSpace>::accessible) {
    return View(&friction[0][0], nlocal, 3);
  } else {
    if (static_cast<int>(d_friction_copy.extent(0)) < nlocal)
      d_friction_copy = View("fix etd/kk: friction", nlocal, 3);
    auto target = Kokkos::subview(d_friction_copy, Kokkos::make_pair(0, nlocal), Kokkos::ALL);
    Kokkos::deep_copy(target,
                      Kokkos::View<double **, Kokkos::LayoutRight, Kokkos::HostSpace>(
                          &friction[0][0], nlocal, 3));
    return d_friction_copy;
  }
}

// the CPU fix's arrays and, in a device's memory, the friction diagonal's copy
template <class DeviceType> double FixETDDiagonalKokkos<DeviceType>::memory_usage()
{
  return FixETDDiagonal::memory_usage() + etd::kk::bytes_of(d_friction_copy);
}

// v += dt phi1(z) F/m per component, z = -Gamma dt / m (etd_coefficients.h)
template <class DeviceType> void FixETDDiagonalKokkos<DeviceType>::final_integrate()
{
  if (!on_device) {
    atomKK->sync(Host, ALL_MASK);
    FixETDDiagonal::final_integrate();
    atomKK->modified(Host, ALL_MASK);
    return;
  }
  atomKK->sync(execution_space, V_MASK | F_MASK | MASK_MASK | RMASS_MASK | TYPE_MASK);
  auto v = atomKK->k_v.template view<DeviceType>();
  auto f = atomKK->k_f.template view<DeviceType>();
  auto mask = atomKK->k_mask.template view<DeviceType>();
  auto type = atomKK->k_type.template view<DeviceType>();
  auto rmass = atomKK->k_rmass.template view<DeviceType>();
  atomKK->k_mass.template sync<DeviceType>();
  auto mass = atomKK->k_mass.template view<DeviceType>();
  const bool per_atom_mass = atom->rmass_flag && atom->rmass;
  const int nlocal = atom->nlocal;
  const auto friction = friction_on_device(nlocal);
  const int bit = groupbit;
  const double step = dt;
  Kokkos::parallel_for(
      Kokkos::RangePolicy<DeviceType>(0, nlocal), KOKKOS_LAMBDA(const int i) {
        if (!(mask(i) & bit)) return;
        const double inv_m = 1.0 / (per_atom_mass ? rmass(i) : mass(type(i)));
        for (int k = 0; k < 3; k++)
          v(i, k) +=
              etd::first_order_effective_step(friction(i, k) * inv_m, step) * f(i, k) * inv_m;
      });
  atomKK->modified(execution_space, V_MASK);
}

namespace LAMMPS_NS {
template class FixETDDiagonalKokkos<LMPDeviceType>;
#ifdef LMP_KOKKOS_GPU
template class FixETDDiagonalKokkos<LMPHostType>;
#endif
}    // namespace LAMMPS_NS

namespace {
// scheme implicit: the CPU scheme with its solve in kernels (fix_etd_implicit_kokkos.h)
template <class DeviceType> Fix *create_fix_etd_kokkos(LAMMPS *lmp, int narg, char **arg)
{
  if (etd::fix_etd_scheme_is_implicit(lmp, narg, arg))
    return new FixETDImplicitKokkos<DeviceType>(lmp, narg, arg);
  return new FixETDDiagonalKokkos<DeviceType>(lmp, narg, arg);
}
}    // namespace

void LAMMPS_NS::register_fix_etd_kokkos(lammpsplugin_t plugin, lammpsplugin_regfunc register_plugin,
                                        void *lmp)
{
  plugin.style = "fix";
  plugin.info = "ETD-DPD exponential time differencing integrator (KOKKOS)";
  plugin.creator.v2 = (lammpsplugin_factory2 *) &create_fix_etd_kokkos<LMPDeviceType>;
  plugin.name = "etd/kk";
  (*register_plugin)(&plugin, lmp);
  plugin.name = "etd/kk/device";
  (*register_plugin)(&plugin, lmp);
  plugin.creator.v2 = (lammpsplugin_factory2 *) &create_fix_etd_kokkos<LMPHostType>;
  plugin.name = "etd/kk/host";
  (*register_plugin)(&plugin, lmp);
}
