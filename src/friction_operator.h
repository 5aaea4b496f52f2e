// ETD-DPD: the pairwise friction operator of DPD and the linear solver of the implicit scheme.
//
//   (G u)_i = sum_j gamma_ij w_D(r_ij) (e_ij . (u_i - u_j)) e_ij       symmetric, positive
//                                                                      semi-definite
// The implicit step solves (M + h/2 G) v' = (M - h/2 G) v + sqrt(h) B xi, the (1,1) Pade
// approximant of exp(-h M^-1 G), which leaves the Maxwell-Boltzmann distribution exactly
// invariant for any h; its zero-mass limit is G v = F + B xi / sqrt(h). Everything here is
// plain arithmetic on flat arrays (x, y, z per atom) so the unit tests can call it directly;
// the LAMMPS fix supplies the communication between the calls.
#ifndef ETD_FRICTION_OPERATOR_H
#define ETD_FRICTION_OPERATOR_H

#include <cmath>
#include <vector>

namespace etd {

// One interacting pair, its geometry cached once per step so that every solver iteration
// streams this compact array instead of the neighbor list.
struct FrictionPair {
  int i, j;             // atom indices (local or ghost)
  double e[3];          // unit vector from j to i
  double friction;      // gamma_ij w_D(r_ij) (special-bond factor included)
  double noise;         // sigma_ij w_R(r_ij) theta_ij (a unit-time impulse amplitude)
};

// out_i += (G u)_i restricted to the given pairs; out_j gets the opposite (Newton's third law).
// update_j(j) says whether j's share is kept (false for ghosts of pairs that another rank
// also holds).
template <typename UpdateJ>
inline void accumulate_friction(const std::vector<FrictionPair> &pairs, const double *u,
                                double *out, UpdateJ update_j)
{
  for (const FrictionPair &p : pairs) {
    const double *ui = u + 3 * p.i, *uj = u + 3 * p.j;
    const double projected = p.friction * (p.e[0] * (ui[0] - uj[0]) + p.e[1] * (ui[1] - uj[1]) +
                                           p.e[2] * (ui[2] - uj[2]));
    double *oi = out + 3 * p.i;
    oi[0] += projected * p.e[0];
    oi[1] += projected * p.e[1];
    oi[2] += projected * p.e[2];
    if (update_j(p.j)) {
      double *oj = out + 3 * p.j;
      oj[0] -= projected * p.e[0];
      oj[1] -= projected * p.e[1];
      oj[2] -= projected * p.e[2];
    }
  }
}

// out_i += scale * sum_j noise_ij e_ij (and the opposite on j): the random impulse, which sums
// to zero over all atoms.
template <typename UpdateJ>
inline void accumulate_noise(const std::vector<FrictionPair> &pairs, double scale, double *out,
                             UpdateJ update_j)
{
  for (const FrictionPair &p : pairs) {
    const double amount = scale * p.noise;
    double *oi = out + 3 * p.i;
    oi[0] += amount * p.e[0];
    oi[1] += amount * p.e[1];
    oi[2] += amount * p.e[2];
    if (update_j(p.j)) {
      double *oj = out + 3 * p.j;
      oj[0] -= amount * p.e[0];
      oj[1] -= amount * p.e[1];
      oj[2] -= amount * p.e[2];
    }
  }
}

// Diagonal of G per atom and component: sum_j gamma w_D e_alpha^2 (the Jacobi preconditioner).
template <typename UpdateJ>
inline void accumulate_diagonal(const std::vector<FrictionPair> &pairs, double *diag,
                                UpdateJ update_j)
{
  for (const FrictionPair &p : pairs)
    for (int k = 0; k < 3; k++) {
      const double g = p.friction * p.e[k] * p.e[k];
      diag[3 * p.i + k] += g;
      if (update_j(p.j)) diag[3 * p.j + k] += g;
    }
}

struct SolverResult {
  int iterations = 0;
  double relative_residual = 0.0;
  bool converged = false;
};

// Jacobi-preconditioned conjugate gradients for A x = b over n unknowns that this rank owns.
//   apply(p, Ap): Ap = A p (the caller communicates ghosts as needed)
//   global_sum(value): sum over all ranks
// x holds the starting guess on entry. Unknowns with inv_diag = 0 are held at their start
// value (frozen components, atoms without friction in the zero-mass limit).
template <typename Apply, typename GlobalSum>
inline SolverResult conjugate_gradient(int n, Apply apply, GlobalSum global_sum,
                                       const double *inv_diag, const double *b, double *x,
                                       double tolerance, int max_iterations)
{
  std::vector<double> r(n), z(n), p(n), ap(n);
  SolverResult result;
  double bb = 0.0;
  for (int k = 0; k < n; k++) bb += b[k] * b[k];
  bb = global_sum(bb);
  if (bb == 0.0) {
    for (int k = 0; k < n; k++) x[k] = 0.0;
    result.converged = true;
    return result;
  }
  apply(x, ap.data());
  double rz = 0.0, rr = 0.0;
  for (int k = 0; k < n; k++) {
    r[k] = (inv_diag[k] != 0.0) ? b[k] - ap[k] : 0.0;
    z[k] = inv_diag[k] * r[k];
    p[k] = z[k];
    rz += r[k] * z[k];
    rr += r[k] * r[k];
  }
  rz = global_sum(rz);
  rr = global_sum(rr);
  const double target = tolerance * tolerance * bb;
  while (rr > target && result.iterations < max_iterations) {
    apply(p.data(), ap.data());
    double pap = 0.0;
    for (int k = 0; k < n; k++) pap += p[k] * ap[k];
    pap = global_sum(pap);
    if (!(pap > 0.0)) break;    // breakdown: A not positive on p (cannot happen for SPD A)
    const double alpha = rz / pap;
    double rz_new = 0.0;
    rr = 0.0;
    for (int k = 0; k < n; k++) {
      x[k] += alpha * p[k];
      if (inv_diag[k] != 0.0) r[k] -= alpha * ap[k];
      z[k] = inv_diag[k] * r[k];
      rz_new += r[k] * z[k];
      rr += r[k] * r[k];
    }
    rz_new = global_sum(rz_new);
    rr = global_sum(rr);
    const double beta = rz_new / rz;
    rz = rz_new;
    for (int k = 0; k < n; k++) p[k] = z[k] + beta * p[k];
    result.iterations++;
  }
  result.relative_residual = std::sqrt(rr / bb);
  result.converged = rr <= target;
  return result;
}

}    // namespace etd

#endif
