// ETD-DPD: fix etd/kk scheme implicit (fix_etd_implicit_kokkos.h).
#include "fix_etd_implicit_kokkos.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "neighbor.h"
#include "update.h"

#include <cmath>
#include <cstring>
#include <functional>

using namespace LAMMPS_NS;

// the scheme's own pair search (its slabs of cells) and the step's loops over the atoms run on
// the host's threads
template <class DeviceType>
FixETDImplicitKokkos<DeviceType>::FixETDImplicitKokkos(LAMMPS *lmp, int narg, char **arg) :
    FixETDImplicit(lmp, narg, arg)
{
  threads.chunks = Kokkos::DefaultHostExecutionSpace().concurrency();
  threads.runner = etd::kk::host_chunk_runner("etd:host_loops");
}

template <class DeviceType> void *FixETDImplicitKokkos<DeviceType>::extract(const char *name, int &dim)
{
  if (std::strcmp(name, "kernel_solves") == 0) {
    dim = 0;
    return &kernel_solves;
  }
  if (std::strcmp(name, "kernel_assemblies") == 0) {
    dim = 0;
    return &kernel_assemblies;
  }
  return FixETDImplicit::extract(name, dim);
}

template <class DeviceType> int FixETDImplicitKokkos<DeviceType>::setmask()
{
  return FixETDImplicit::setmask() | FixConst::PRE_EXCHANGE;
}

// where the solve stays on the host, the run says why (as fix etd/kk scheme diagonal does)
template <class DeviceType> void FixETDImplicitKokkos<DeviceType>::init()
{
  FixETDImplicit::init();
  if (dofs != 3 && comm->me == 0)
    error->warning(FLERR,
                   "Fix etd/kk scheme implicit: the friction solve runs on the host with dpd/fpm "
                   "pairs (rotation) (the CPU solver, same results)");
}

template <class DeviceType> void FixETDImplicitKokkos<DeviceType>::setup(int vflag)
{
  kernel_solves = kernel_assemblies = 0.0;
  pairs_on_device = false;
  if (assembles_in_kernels()) {
    const int ntypes1 = assembly.ntypes1();
    std::vector<const etd::PairCoefficients *> table(ntypes1 * ntypes1, nullptr);
    for (int i = 1; i < ntypes1; i++)
      for (int j = 1; j < ntypes1; j++) table[i * ntypes1 + j] = assembly.coefficients(i, j);
    pairs_kk.set_coefficients(table, ntypes1, assembly.noise());
  }
  FixETDImplicit::setup(vflag);
  sorting.run_started(update->ntimestep);
}

// LAMMPS sorts the atoms often while the kernels run (atom_sort_schedule.h)
template <class DeviceType> void FixETDImplicitKokkos<DeviceType>::pre_exchange()
{
  if (assembles_in_kernels()) sorting.before_exchange(atom, update->ntimestep);
}

template <class DeviceType> double FixETDImplicitKokkos<DeviceType>::memory_usage()
{
  const std::size_t vectors = sizeof(int) * mobile.capacity() +
      sizeof(double) * (zero_u.capacity() + unused.capacity() + image_friction.capacity());
  return FixETDImplicit::memory_usage() + static_cast<double>(pairs_kk.memory_usage()) +
      static_cast<double>(kernels.memory_usage()) + static_cast<double>(vectors);
}

// the kernels assemble dpd/gen-type pairs (translation), for the inertial step and the overdamped
template <class DeviceType> bool FixETDImplicitKokkos<DeviceType>::assembles_in_kernels() const
{
  return dofs == 3 && !assembly.has_fpm_pairs();
}

// this assembly's pairs into the solve's kernels, once: the kernels' own, else the host's
template <class DeviceType> void FixETDImplicitKokkos<DeviceType>::hand_pairs_to_kernels()
{
  if (pairs_handed) return;
  const int nlocal = atom->nlocal;
  if (pairs_on_device)
    kernels.set_pairs(pairs_kk.pair_i(), pairs_kk.pair_j(), pairs_kk.geometry(), pairs_kk.pairs(),
                      nlocal, partners.count(nlocal), &pairs_kk.rows(), &pairs_kk.row_starts(),
                      pairs_kk.listed());
  else
    kernels.set_pairs(assembly.pairs(), nlocal, partners.count(nlocal));
  pairs_handed = true;
}

template <class DeviceType>
bool FixETDImplicitKokkos<DeviceType>::assemble_pairs(
    const etd::FrictionPairAssembly::Context &context)
{
  pairs_on_device = pairs_on_host = pairs_handed = false;
  if (!assembles_in_kernels()) return FixETDImplicit::assemble_pairs(context);
  typename etd::FrictionPairsKokkos<DeviceType>::Input in;
  in.nlocal = atom->nlocal;
  in.nall = atom->nlocal + atom->nghost;
  in.inum = context.list.inum;
  in.ilist = context.list.ilist;
  in.numneigh = context.list.numneigh;
  in.firstneigh = context.list.firstneigh;
  in.neighbor_mask = NEIGHMASK;
  in.special_shift = SBBITS;
  in.special = force->special_lj;
  in.x = in.nall > 0 ? atom->x[0] : nullptr;
  in.type = atom->type;
  in.mask = atom->mask;
  in.ghost_partner = partners.ghost_partners().data();
  in.groupbit = groupbit;
  in.newton_off = context.list_newton_off;
  in.step = context.step;
  in.cutsq_max = assembly.friction_cutsq_max();
  if (domain->deform_vremap) {    // moving images (fix deform ... remap v)
    in.image = partners.image_counts().data();
    for (int k = 0; k < 6; k++) in.image_rate[k] = domain->h_rate[k];
    in.deform_groupbit = domain->deform_groupbit;
  }
  const bool fixed_partner = pairs_kk.build(in, atom->tag);
  pairs_on_device = true;
  kernel_assemblies += 1.0;
  // the virial and the force split are summed on the host from the assembly's pairs
  if (virial_this_step || split_requested) {
    std::vector<etd::FrictionPair> pairs;
    std::vector<double> noise, distance, offsets;
    pairs_kk.copy_to_host(pairs, noise, distance, &offsets);
    assembly.adopt_pairs(std::move(pairs), std::move(noise), std::move(distance), atom->nlocal,
                         std::move(offsets));
    pairs_on_host = true;
  } else {
    assembly.adopt_pairs({}, {}, {}, atom->nlocal);    // none on the host this step
  }
  return fixed_partner;
}

template <class DeviceType> void FixETDImplicitKokkos<DeviceType>::friction_rhs()
{
  if (!terms_in_kernels()) {
    FixETDImplicit::friction_rhs();
    return;
  }
  const int nlocal = atom->nlocal;
  hand_pairs_to_kernels();
  std::vector<double> &v = work.solution;    // (scratch until the solve)
  v.resize(3 * nlocal);
  for (int i = 0; i < nlocal; i++)
    for (int k = 0; k < 3; k++) v[3 * i + k] = atom->v[i][k];
  work.step_rhs.resize(3 * nlocal);
  // G u for the solve's start from the old velocities
  work.gu_rhs.resize(3 * nlocal);
  kernels.step_rhs(work.inertia.data(), v.data(), work.u.data(), pairs_kk.noise(), dt,
                   work.step_rhs.data(), options.warm_start ? work.gu_rhs.data() : nullptr,
                   pairs_kk.offsets());
}

// the overdamped step's B xi / sqrt(h), from the kernels' pairs
template <class DeviceType>
void FixETDImplicitKokkos<DeviceType>::overdamped_impulse(std::vector<double> &impulse)
{
  if (!terms_in_kernels()) {
    FixETDImplicit::overdamped_impulse(impulse);
    return;
  }
  hand_pairs_to_kernels();
  const int nlocal = atom->nlocal;
  zero_u.assign(3 * partners.count(nlocal), 0.0);
  impulse.resize(3 * nlocal);
  unused.resize(3 * nlocal);
  kernels.friction_terms(zero_u.data(), pairs_kk.noise(), 1.0 / std::sqrt(dt), unused.data(),
                         impulse.data(), nullptr);
}

// G u of the atoms outside the group (at rest in it), and the images' friction, from the
// kernels' pairs
template <class DeviceType>
const std::vector<double> &
FixETDImplicitKokkos<DeviceType>::fixed_friction(const std::vector<double> &u,
                                                 std::vector<double> &gu)
{
  if (!terms_in_kernels()) return FixETDImplicit::fixed_friction(u, gu);
  hand_pairs_to_kernels();
  const int nlocal = atom->nlocal;
  gather_operand(u.data(), false);    // u on all partners
  gu.resize(3 * nlocal);
  unused.resize(3 * nlocal);
  const etd::kk::Values<DeviceType> *offsets = pairs_kk.offsets();
  image_friction.assign(offsets ? 3 * nlocal : 0, 0.0);
  kernels.friction_terms(operand.data(), pairs_kk.noise(), 0.0, gu.data(), unused.data(),
                         offsets ? image_friction.data() : nullptr, offsets);
  return image_friction;
}

template <class DeviceType>
etd::SolverResult FixETDImplicitKokkos<DeviceType>::solve_system(
    const std::vector<double> &rhs, std::vector<double> &solution, double mass_weight,
    double friction_weight, bool deflate, const std::vector<double> *start,
    const std::vector<double> *start_friction)
{
  // the kernels solve for translation (the inertial step and the zero-mass limit); dpd/fpm's
  // rotation solves on the host
  if (dofs != 3)
    return FixETDImplicit::solve_system(rhs, solution, mass_weight, friction_weight, deflate,
                                        start, start_friction);
  const int nlocal = atom->nlocal;
  mobile.resize(nlocal);
  for (int i = 0; i < nlocal; i++) mobile[i] = (atom->mask[i] & groupbit) ? 1 : 0;
  hand_pairs_to_kernels();
  solution.resize(3 * nlocal);
  kernel_solves += 1.0;
  const std::vector<int> &sent = partners.sent();
  const typename etd::FrictionSolveKokkos<DeviceType>::Exchange exchange{
      sent.data(), static_cast<int>(sent.size()),
      [this](const double *sent_values, double *slot_values) {
        partners.swap(sent_values, slot_values, 3);
      }};
  return kernels.solve(work.inertia.data(), mobile.data(), rhs.data(), mass_weight,
                       friction_weight, options.tolerance, options.max_iterations, exchange,
                       sum_over_ranks(), solution.data(), start ? start->data() : nullptr,
                       (start && start_friction) ? start_friction->data() : nullptr, deflate);
}

namespace LAMMPS_NS {
template class FixETDImplicitKokkos<LMPDeviceType>;
#ifdef LMP_KOKKOS_GPU
template class FixETDImplicitKokkos<LMPHostType>;
#endif
}    // namespace LAMMPS_NS
