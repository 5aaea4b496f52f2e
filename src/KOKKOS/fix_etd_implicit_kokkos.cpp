// ETD-DPD: fix etd/kk scheme implicit (fix_etd_implicit_kokkos.h).
#include "fix_etd_implicit_kokkos.h"

#include "atom.h"
#include "comm.h"
#include "error.h"

#include <cstring>

using namespace LAMMPS_NS;

template <class DeviceType> void *FixETDImplicitKokkos<DeviceType>::extract(const char *name, int &dim)
{
  if (std::strcmp(name, "kernel_solves") == 0) {
    dim = 0;
    return &kernel_solves;
  }
  return FixETDImplicit::extract(name, dim);
}

// where the solve stays on the host, the run says why (as fix etd/kk scheme diagonal does)
template <class DeviceType> void FixETDImplicitKokkos<DeviceType>::init()
{
  FixETDImplicit::init();
  const char *reason = options.overdamped ? "overdamped yes"
      : dofs != 3                         ? "dpd/fpm pairs (rotation)"
                                          : nullptr;
  if (reason && comm->me == 0)
    error->warning(FLERR,
                   "Fix etd/kk scheme implicit: the friction solve runs on the host with {} (the "
                   "CPU solver, same results)",
                   reason);
}

template <class DeviceType> void FixETDImplicitKokkos<DeviceType>::setup(int vflag)
{
  kernel_solves = 0.0;
  FixETDImplicit::setup(vflag);
}

template <class DeviceType>
etd::SolverResult FixETDImplicitKokkos<DeviceType>::solve_system(
    const std::vector<double> &rhs, std::vector<double> &solution, double mass_weight,
    double friction_weight, bool deflate, const std::vector<double> *start,
    const std::vector<double> *start_friction)
{
  // the kernels solve the inertial translation system; the rest solves on the host
  if (mass_weight == 0.0 || deflate || dofs != 3)
    return FixETDImplicit::solve_system(rhs, solution, mass_weight, friction_weight, deflate,
                                        start, start_friction);
  const int nlocal = atom->nlocal;
  const int npartners = partners.count(nlocal);
  mobile.resize(nlocal);
  for (int i = 0; i < nlocal; i++) mobile[i] = (atom->mask[i] & groupbit) ? 1 : 0;
  kernels.set_pairs(assembly.pairs(), nlocal, npartners);
  solution.resize(3 * nlocal);
  kernel_solves += 1.0;
  const typename etd::FrictionSolveKokkos<DeviceType>::Exchange exchange =
      [this, nlocal](double *values) { partners.exchange(values, nlocal, 3); };
  return kernels.solve(work.inertia.data(), mobile.data(), rhs.data(), mass_weight,
                       friction_weight, options.tolerance, options.max_iterations, exchange,
                       sum_over_ranks(), solution.data(), start ? start->data() : nullptr,
                       (start && start_friction) ? start_friction->data() : nullptr);
}

namespace LAMMPS_NS {
template class FixETDImplicitKokkos<LMPDeviceType>;
#ifdef LMP_KOKKOS_GPU
template class FixETDImplicitKokkos<LMPHostType>;
#endif
}    // namespace LAMMPS_NS
