// ETD-DPD: the implicit scheme's linear solve (mass_weight M + friction_weight G) x = b as one
// function over flat arrays: the block-Jacobi preconditioner, the translation null space of a
// singular G, the start vector, then conjugate gradients. The caller supplies G, which atoms
// move, and the sums over ranks as callbacks, so this runs (and is tested) without LAMMPS.
#ifndef ETD_FRICTION_SOLVE_H
#define ETD_FRICTION_SOLVE_H

#include "conjugate_gradient.h"
#include "host_device.h"

#include <vector>

namespace etd {

// Inverse of the symmetric 3x3 block (shift I + scale B) into 9 values. A nearly singular
// block (an atom with one or two partners in the zero-mass limit: no friction across their
// directions) falls back to the inverse of its diagonal; false if even that is zero.
ETD_HOST_DEVICE inline bool invert_block(const double *block, double shift, double scale, double *inverse)
{
  const double a = shift + scale * block[0], d = shift + scale * block[1],
               f = shift + scale * block[2];
  const double b = scale * block[3], c = scale * block[4], e = scale * block[5];
  const double c00 = d * f - e * e, c01 = c * e - b * f, c02 = b * e - c * d;
  const double det = a * c00 + b * c01 + c * c02;
  const double trace = a + d + f;
  if (!(det > 1e-6 * trace * trace * trace / 27.0)) {
    for (int k = 0; k < 9; k++) inverse[k] = 0.0;
    const double diag[3] = {a, d, f};
    bool any = false;
    for (int k = 0; k < 3; k++)
      if (diag[k] > 0.0) {
        inverse[4 * k] = 1.0 / diag[k];
        any = true;
      }
    return any;
  }
  const double inv = 1.0 / det;
  inverse[0] = c00 * inv;
  inverse[1] = c01 * inv;
  inverse[2] = c02 * inv;
  inverse[3] = c01 * inv;
  inverse[4] = (a * f - c * c) * inv;
  inverse[5] = (b * c - a * e) * inv;
  inverse[6] = c02 * inv;
  inverse[7] = (b * c - a * e) * inv;
  inverse[8] = (a * d - b * b) * inv;
  return true;
}

// The system over n unknowns, three per block: an atom's velocity, or with rotation its
// velocity and its angular velocity (two blocks per atom).
struct FrictionSystem {
  int n = 0;
  const double *inertia = nullptr;    // per unknown: mass or moment of inertia
  const double *blocks = nullptr;     // per block, G's diagonal 3x3 block: xx yy zz xy xz yz
  double mass_weight = 1.0, friction_weight = 0.0;
  // remove the uniform translation (the null space of G when no atom is held and M = 0) from
  // the right-hand side, every product and the solution
  bool deflate = false;
};

// vectors kept by the caller between solves (per-step allocation costs page faults at scale)
struct FrictionSolveWorkspace {
  std::vector<double> rhs, inv_diag, block_inverse, start_product;
  CgWorkspace cg;
};

// Solves sys for x = solution (n values). Blocks where mobile(block) is false, or where the
// block has neither mass nor friction, are held at zero.
//   apply_friction(u, out, weight): out += weight G u (the caller communicates ghosts)
//   global_sum(values, count): sums count values (at most 9) over all ranks, in place
// start (optional): the start vector (else the block-Jacobi solution); with it, start_friction
// (optional) is G start, which saves one application of G.
template <typename Mobile, typename ApplyFriction, typename GlobalSum>
inline SolverResult
solve_friction_system(const FrictionSystem &sys, Mobile mobile, ApplyFriction apply_friction,
                      GlobalSum global_sum, const double *rhs_in, std::vector<double> &solution,
                      double tolerance, int max_iterations, FrictionSolveWorkspace &work,
                      const double *start = nullptr, const double *start_friction = nullptr)
{
  const int n = sys.n;
  const int nblocks = n / 3;
  const double *inertia = sys.inertia;
  std::vector<double> &rhs = work.rhs, &inv_diag = work.inv_diag,
                      &block_inverse = work.block_inverse;
  rhs.assign(rhs_in, rhs_in + n);

  // block-Jacobi preconditioner: each block of mass_weight M + friction_weight G, inverted
  inv_diag.assign(n, 0.0);
  block_inverse.assign(9 * nblocks, 0.0);
  for (int b = 0; b < nblocks; b++) {
    if (!mobile(b)) continue;
    if (!invert_block(sys.blocks + 6 * b, sys.mass_weight * inertia[3 * b], sys.friction_weight,
                      &block_inverse[9 * b]))
      continue;
    for (int k = 0; k < 3; k++) inv_diag[3 * b + k] = block_inverse[9 * b + 4 * k];
  }

  // per-component mean over the solved unknowns (not those held at zero), removed where the
  // translation is singular; held unknowns must stay untouched for CG to stay consistent
  double active_count[3] = {0.0, 0.0, 0.0};
  if (sys.deflate) {    // (a reduction only where it is needed)
    for (int k = 0; k < n; k++)
      if (inv_diag[k] != 0.0) active_count[k % 3] += 1.0;
    global_sum(active_count, 3);
  }
  const double group_count = active_count[0] + active_count[1] + active_count[2];
  auto remove_mean = [&](double *vec) {
    double sum[3] = {0.0, 0.0, 0.0};
    for (int k = 0; k < n; k++)
      if (inv_diag[k] != 0.0) sum[k % 3] += vec[k];
    global_sum(sum, 3);
    for (int k = 0; k < n; k++)
      if (inv_diag[k] != 0.0 && active_count[k % 3] > 0.0)
        vec[k] -= sum[k % 3] / active_count[k % 3];
  };
  if (sys.deflate && group_count > 0.0) remove_mean(rhs.data());

  // A u = mass_weight M u + friction_weight G u (held rows are zeroed by the solver)
  auto apply = [&](const double *u, double *au) {
    for (int k = 0; k < n; k++) au[k] = sys.mass_weight * inertia[k] * u[k];
    apply_friction(u, au, sys.friction_weight);
    if (sys.deflate) remove_mean(au);
  };

  solution.assign(n, 0.0);
  const double *start_product = nullptr;
  if (start && start_friction) {
    work.start_product.resize(n);
    for (int k = 0; k < n; k++)
      work.start_product[k] = mobile(k / 3)
          ? sys.mass_weight * inertia[k] * start[k] + sys.friction_weight * start_friction[k]
          : 0.0;
    start_product = work.start_product.data();
  }
  if (start) {
    // from the given start (the old velocities): the collective motion that the block-Jacobi
    // start damps is kept, and the error left is in local relative motion, which the
    // preconditioner removes fastest (doc/fix_etd.rst: accurate at loose tolerances)
    for (int k = 0; k < n; k++)
      if (inv_diag[k] != 0.0) solution[k] = start[k];
  } else {
    for (int b = 0; b < nblocks; b++)
      for (int k = 0; k < 3; k++) {
        const double *m = &block_inverse[9 * b + 3 * k];
        solution[3 * b + k] = m[0] * rhs[3 * b] + m[1] * rhs[3 * b + 1] + m[2] * rhs[3 * b + 2];
      }
  }
  const SolverResult result = conjugate_gradient(
      n, apply, global_sum, inv_diag.data(), rhs.data(), solution.data(), tolerance, max_iterations,
      block_inverse.data(),
      [&](double *vec) {
        if (sys.deflate) remove_mean(vec);
      },
      &work.cg, start_product);
  if (sys.deflate) remove_mean(solution.data());
  return result;
}

}    // namespace etd

#endif
