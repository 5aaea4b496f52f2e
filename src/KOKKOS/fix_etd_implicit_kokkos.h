// ETD-DPD: fix etd/kk scheme implicit. The friction step's solve, the block-Jacobi
// preconditioner, G applied atom by atom and conjugate gradients (friction_solve_kokkos.h), runs
// in Kokkos kernels in DeviceType's execution space, for translation (dpd/gen pairs, inertial).
// The rest of the step is the CPU scheme's, on the host: the pair search and assembly, the
// right-hand side and the momentum correction; so are the zero-mass limit (overdamped yes) and
// dpd/fpm's rotation, which solve on the host with the CPU solver.
#ifndef ETD_FIX_ETD_IMPLICIT_KOKKOS_H
#define ETD_FIX_ETD_IMPLICIT_KOKKOS_H

#include "fix_etd_implicit.h"
#include "friction_solve_kokkos.h"

#include "kokkos_type.h"

namespace LAMMPS_NS {

template <class DeviceType> class FixETDImplicitKokkos : public FixETDImplicit {
 public:
  FixETDImplicitKokkos(class LAMMPS *lmp, int narg, char **arg) : FixETDImplicit(lmp, narg, arg) {}
  // "kernel_solves" (dim 0, a double): how many solves of this run ran in the kernels
  void *extract(const char *name, int &dim) override;
  void init() override;
  void setup(int vflag) override;

 protected:
  etd::SolverResult solve_system(const std::vector<double> &rhs, std::vector<double> &solution,
                                 double mass_weight, double friction_weight, bool deflate,
                                 const std::vector<double> *start,
                                 const std::vector<double> *start_friction) override;

 private:
  etd::FrictionSolveKokkos<DeviceType> kernels;
  std::vector<int> mobile;    // per owned atom: in the group
  double kernel_solves = 0.0;
};

}    // namespace LAMMPS_NS

#endif
