// ETD-DPD: preconditioned conjugate gradients over flat arrays, with the operator, the
// preconditioner's null-space projection and the sums over ranks supplied by the caller.
#ifndef ETD_CONJUGATE_GRADIENT_H
#define ETD_CONJUGATE_GRADIENT_H

#include <cmath>
#include <vector>

namespace etd {

// Preconditioned conjugate gradients for A x = b over n unknowns that this rank owns, in the
// single-reduction form of Chronopoulos and Gear (J. Comput. Appl. Math. 25, 1989): each
// iteration applies A once and sums all its dot products over the ranks in ONE reduction
// (the textbook form needs two), since on several ranks every reduction is a point where all
// ranks wait for the slowest. The norm of the next residual is predicted from that same
// reduction, so convergence is seen before the next application of A, not after it; a
// predicted convergence is confirmed with the true norm of the recursively updated residual.
//   apply(p, Ap): Ap = A p (the caller communicates ghosts as needed)
//   global_sum(values, count): sums the count values (at most 9) over all ranks, in place
// x holds the starting guess on entry. Unknowns with inv_diag = 0 are held at their start
// value (frozen components, atoms without friction in the zero-mass limit).
struct NoProjection {
  void operator()(double *) const {}
};

// The solver's vectors, kept by the caller between solves: allocating them afresh every step
// costs page faults that grow with the system.
struct CgWorkspace {
  std::vector<double> r, z, p, w, s;
};

struct SolverResult {
  int iterations = 0;
  double relative_residual = 0.0;
  bool converged = false;
};

namespace cg_detail {
// z = P r, projected (a separate pass: fused into the update loop, that loop no longer vectorises)
template <typename Project>
inline void precondition(int n, const double *inv_diag, const double *block_inverse,
                         const double *r, double *z, Project &project)
{
  if (!block_inverse) {
    for (int k = 0; k < n; k++) z[k] = inv_diag[k] * r[k];
  } else {
    for (int a = 0; a < n / 3; a++) {
      const double *m = block_inverse + 9 * a;
      const double *ra = r + 3 * a;
      for (int k = 0; k < 3; k++)
        z[3 * a + k] = (inv_diag[3 * a + k] != 0.0)
            ? m[3 * k] * ra[0] + m[3 * k + 1] * ra[1] + m[3 * k + 2] * ra[2]
            : 0.0;
    }
  }
  project(z);
}

// The one reduction of an iteration (this rank's share): rz = (r,z), wz = (w,z), rr = (r,r),
// and for the next residual's norm rw = (r,w), rs = (r,s), ww = (w,w), ws = (w,s), ss = (s,s),
// with s the previous A p; bb = (b,b) with_b. w = A z is first zeroed on held unknowns (so
// that r, updated by s, stays zero there), in the same pass.
enum { RZ, WZ, RR, RW, RS, WW, WS, SS, BB, NSUMS };
inline void local_sums(int n, const double *inv_diag, const double *b, const double *r,
                       const double *z, double *w, const double *s, bool with_b,
                       double sums[NSUMS])
{
  for (int k = 0; k < NSUMS; k++) sums[k] = 0.0;
  for (int k = 0; k < n; k++) {
    if (inv_diag[k] == 0.0) w[k] = 0.0;
    sums[RZ] += r[k] * z[k];
    sums[WZ] += w[k] * z[k];
    sums[RR] += r[k] * r[k];
    sums[RW] += r[k] * w[k];
    sums[RS] += r[k] * s[k];
    sums[WW] += w[k] * w[k];
    sums[WS] += w[k] * s[k];
    sums[SS] += s[k] * s[k];
  }
  if (with_b)
    for (int k = 0; k < n; k++) sums[BB] += b[k] * b[k];
}

// The iterations, whatever holds the vectors (this file's arrays, or Kokkos views:
// friction_solve_kokkos.h). sums holds the first iteration's sums, BB among them (bb > 0);
// ops supplies the vector work:
//   ops.update(alpha, beta): p = z + beta p, s = w + beta s, x += alpha p, r -= alpha s
//   ops.residual_norm2(): (r, r) on this rank
//   ops.next_sums(sums): z = P r, w = A z and the iteration's sums over all ranks (without BB)
template <typename Ops, typename GlobalSum>
inline SolverResult iterate(Ops &ops, GlobalSum &global_sum, double sums[NSUMS], double tolerance,
                            int max_iterations)
{
  SolverResult result;
  const double bb = sums[BB];
  const double target = tolerance * tolerance * bb;
  double rr = sums[RR], rz_old = 1.0, alpha = 1.0;
  while (rr > target && result.iterations < max_iterations) {
    const double rz = sums[RZ];
    const double beta = result.iterations == 0 ? 0.0 : rz / rz_old;
    const double curvature = sums[WZ] - beta * rz / alpha;    // (p, A p) of the new direction
    if (!(curvature > 0.0) || !(rz > 0.0))
      break;    // breakdown: A not positive (cannot happen for SPD A)
    alpha = rz / curvature;
    rz_old = rz;
    ops.update(alpha, beta);
    result.iterations++;
    // |r - alpha s|^2 with s = w + beta s_old, from this iteration's sums
    const double rs = sums[RW] + beta * sums[RS];
    const double ss = sums[WW] + 2.0 * beta * sums[WS] + beta * beta * sums[SS];
    const double predicted = rr - 2.0 * alpha * rs + alpha * alpha * ss;
    if (predicted <= target) {
      double actual = ops.residual_norm2();
      global_sum(&actual, 1);
      rr = actual;
      if (rr <= target || result.iterations >= max_iterations) break;
    }
    ops.next_sums(sums);
    rr = sums[RR];
  }
  result.relative_residual = std::sqrt(rr / bb);
  result.converged = rr <= target;
  return result;
}
}    // namespace cg_detail

// block_inverse (optional, 9 values per atom, n = 3 atoms): block-Jacobi preconditioning, which
// also couples the components of one atom; inv_diag then only marks the held unknowns.
// project (optional): removes a null space (the uniform translation of a singular G) from the
// preconditioned residual, so that every search direction stays in the space where A is
// positive definite (b and A's output must already lie in it).
template <typename Apply, typename GlobalSum, typename Project = NoProjection>
inline SolverResult
conjugate_gradient(int n, Apply apply, GlobalSum global_sum, const double *inv_diag,
                   const double *b, double *x, double tolerance, int max_iterations,
                   const double *block_inverse = nullptr, Project project = Project(),
                   CgWorkspace *workspace = nullptr, const double *start_product = nullptr)
{
  CgWorkspace local;
  CgWorkspace &work = workspace ? *workspace : local;
  work.r.resize(n);
  work.z.resize(n);
  work.p.assign(n, 0.0);
  work.w.resize(n);
  work.s.assign(n, 0.0);
  // r: residual, z: preconditioned residual, w = A z, p: search direction, s = A p
  double *r = work.r.data(), *z = work.z.data(), *p = work.p.data(), *w = work.w.data(),
         *s = work.s.data();
  auto precondition = [&]() {
    cg_detail::precondition(n, inv_diag, block_inverse, r, z, project);
  };
  using namespace cg_detail;
  double sums[NSUMS];
  auto apply_and_reduce = [&](bool with_b, double *out) {
    apply(z, w);
    local_sums(n, inv_diag, b, r, z, w, s, with_b, out);
    global_sum(out, with_b ? NSUMS : BB);
  };

  // start_product (optional): A x of the start, where the caller has it (then x must already
  // lie in the projected space)
  if (!start_product) {
    project(x);
    apply(x, w);
  }
  const double *ax = start_product ? start_product : w;
  for (int k = 0; k < n; k++) r[k] = (inv_diag[k] != 0.0) ? b[k] - ax[k] : 0.0;
  precondition();
  apply_and_reduce(true, sums);
  if (sums[BB] == 0.0) {
    for (int k = 0; k < n; k++) x[k] = 0.0;
    SolverResult result;
    result.converged = true;
    return result;
  }
  struct Ops {
    int n;
    double *x, *r, *z, *p, *w, *s;
    decltype(precondition) &precondition_r;
    decltype(apply_and_reduce) &apply_z;
    void update(double alpha, double beta)
    {
      for (int k = 0; k < n; k++) {
        p[k] = z[k] + beta * p[k];
        s[k] = w[k] + beta * s[k];
        x[k] += alpha * p[k];
        r[k] -= alpha * s[k];
      }
    }
    double residual_norm2() const
    {
      double sum = 0.0;
      for (int k = 0; k < n; k++) sum += r[k] * r[k];
      return sum;
    }
    void next_sums(double *out)
    {
      precondition_r();
      apply_z(false, out);
    }
  } ops{n, x, r, z, p, w, s, precondition, apply_and_reduce};
  return iterate(ops, global_sum, sums, tolerance, max_iterations);
}

}    // namespace etd

#endif
