// ETD-DPD: fix etd/kk scheme implicit. For translation (dpd/gen pairs, inertial, no moving
// images) the friction step runs in Kokkos kernels in DeviceType's execution space: the pairs'
// assembly with their noise (friction_pairs_kokkos.h), the right-hand side and G applied (pair by
// pair on the host's threads, atom by atom on a device; friction_operator_kokkos.h), the
// block-Jacobi preconditioner and conjugate gradients (friction_solve_kokkos.h). The scheme's
// pair search (binning, slabs of cells; the same list) and the step's loops over the atoms
// (kicks, drifts, the momentum correction) run on the host's threads (FixETDImplicit::threads),
// on the host also where the kernels run on a device; at steps that tally the virial or the
// force split the pairs are copied back to the host, where those are summed.
// Under fix deform ... remap v the pairs carry their images' velocities. The zero-mass limit
// (overdamped yes) runs in the same kernels (two assemblies and solves a step, each at its own
// positions; the solve deflated where G is singular), with its impulse and the friction of atoms
// outside the group from them; dpd/fpm's rotation solves on the host with the CPU solver.
#ifndef ETD_FIX_ETD_IMPLICIT_KOKKOS_H
#define ETD_FIX_ETD_IMPLICIT_KOKKOS_H

#include "atom_sort_schedule.h"
#include "fix_etd_implicit.h"
#include "friction_pairs_kokkos.h"
#include "friction_solve_kokkos.h"

#include "kokkos_type.h"

namespace LAMMPS_NS {

template <class DeviceType> class FixETDImplicitKokkos : public FixETDImplicit {
 public:
  FixETDImplicitKokkos(class LAMMPS *lmp, int narg, char **arg);
  // "kernel_solves", "kernel_assemblies" (dim 0, a double): how many solves, and pair
  // assemblies with their right-hand sides, of this run ran in the kernels
  void *extract(const char *name, int &dim) override;
  int setmask() override;
  void init() override;
  void setup(int vflag) override;
  void pre_exchange() override;
  // the CPU fix's arrays and the kernels' views (LAMMPS asks at a run's setup: the views then
  // hold the previous run's sizes, none before the first run, as the CPU fix's pairs do)
  double memory_usage() override;

 protected:
  bool assemble_pairs(const etd::FrictionPairAssembly::Context &context) override;
  void friction_rhs() override;
  void overdamped_impulse(std::vector<double> &impulse) override;
  const std::vector<double> &fixed_friction(const std::vector<double> &u,
                                            std::vector<double> &gu) override;
  etd::SolverResult solve_system(const std::vector<double> &rhs, std::vector<double> &solution,
                                 double mass_weight, double friction_weight, bool deflate,
                                 const std::vector<double> *start,
                                 const std::vector<double> *start_friction) override;

 private:
  etd::FrictionPairsKokkos<DeviceType> pairs_kk;
  etd::FrictionSolveKokkos<DeviceType> kernels;
  std::vector<int> mobile;    // per owned atom: in the group
  bool pairs_on_device = false;    // this step's pairs: assembled in the kernels (else the host)
  bool pairs_on_host = false;      // and copied back to the assembly
  bool pairs_handed = false;       // and handed to the solve's kernels (hand_pairs_to_kernels)
  void hand_pairs_to_kernels();
  // the kernels' pairs are this step's, their terms summed there (else the host sums them)
  bool terms_in_kernels() const { return pairs_on_device && !pairs_on_host; }
  std::vector<double> zero_u, unused, image_friction;    // fixed_friction()'s and its scratch
  double kernel_solves = 0.0, kernel_assemblies = 0.0;
  etd::kk::AtomSortSchedule sorting;    // while the kernels run (pre_exchange())
  bool assembles_in_kernels() const;
};

}    // namespace LAMMPS_NS

#endif
