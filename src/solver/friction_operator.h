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
  float e[3];           // unit vector from j to i
  float friction;       // gamma_ij w_D(r_ij) (special-bond factor included)
};
// Single precision halves what every solver iteration streams (24 bytes a pair), which is what
// limits large systems. Both atoms of a pair use the same rounded numbers, so G stays exactly
// symmetric and momentum-conserving; it differs from the double-precision operator by about
// 1e-7 relative, far below the solver tolerance and the statistical error of any average.
// (each pair's noise sigma_ij w_R theta_ij lives in a parallel array: the solver iterations
// stream only what G needs, 40 bytes a pair)

// out_i += (G u)_i restricted to the given pairs; out_j gets the opposite (Newton's third law).
// update_j(j) says whether j's share is kept (false for ghosts of pairs that another rank
// also holds).
// One pair's share of G u on i, gamma w_D (e . (u_i - u_j)), along e (and the opposite on j).
inline double pair_friction(const FrictionPair &p, const double *ui, const double *uj)
{
  return p.friction * (p.e[0] * (ui[0] - uj[0]) + p.e[1] * (ui[1] - uj[1]) + p.e[2] * (ui[2] - uj[2]));
}

template <typename UpdateJ>
inline void accumulate_friction(const std::vector<FrictionPair> &pairs, const double *u,
                                double *out, UpdateJ update_j, int stride = 3)
{
  for (const FrictionPair &p : pairs) {
    const double projected = pair_friction(p, u + stride * p.i, u + stride * p.j);
    double *oi = out + stride * p.i;
    oi[0] += projected * p.e[0];
    oi[1] += projected * p.e[1];
    oi[2] += projected * p.e[2];
    if (update_j(p.j)) {
      double *oj = out + stride * p.j;
      oj[0] -= projected * p.e[0];
      oj[1] -= projected * p.e[1];
      oj[2] -= projected * p.e[2];
    }
  }
}

// The pairs that share atom i come one after another (the neighbor list's order); a run is
// such a stretch, pairs [begin, end). Applying G run by run keeps u_i and the sum for atom i
// in registers instead of loading and storing them once per pair.
struct PairRun {
  int i, begin, end;
};

// runs of consecutive pairs with the same i
inline void find_runs(const std::vector<FrictionPair> &pairs, std::vector<PairRun> &runs)
{
  runs.clear();
  for (int n = 0; n < static_cast<int>(pairs.size()); n++) {
    if (runs.empty() || runs.back().i != pairs[n].i) runs.push_back({pairs[n].i, n, n});
    runs.back().end = n + 1;
  }
}

// The same sum as accumulate_friction(), run by run (Stride = 3 or 6 values per atom, the
// first 3 of which G acts on), times scale (so that a solver adds its weighted G u straight
// into M u, without a separate vector pass)
template <int Stride, typename UpdateJ>
inline void accumulate_friction_by_runs(const std::vector<FrictionPair> &pairs,
                                        const std::vector<PairRun> &runs, const double *u,
                                        double *out, UpdateJ update_j, double scale = 1.0)
{
  const FrictionPair *pair = pairs.data();
  for (const PairRun &run : runs) {
    const double *ui = u + Stride * run.i;
    const double ui0 = ui[0], ui1 = ui[1], ui2 = ui[2];
    double sum0 = 0.0, sum1 = 0.0, sum2 = 0.0;
    for (int n = run.begin; n < run.end; n++) {
      const FrictionPair &p = pair[n];
      const double *uj = u + Stride * p.j;
      const double e0 = p.e[0], e1 = p.e[1], e2 = p.e[2];
      const double projected = scale * p.friction * (e0 * (ui0 - uj[0]) + e1 * (ui1 - uj[1]) + e2 * (ui2 - uj[2]));
      const double f0 = projected * e0, f1 = projected * e1, f2 = projected * e2;
      sum0 += f0;
      sum1 += f1;
      sum2 += f2;
      if (update_j(p.j)) {
        double *oj = out + Stride * p.j;
        oj[0] -= f0;
        oj[1] -= f1;
        oj[2] -= f2;
      }
    }
    double *oi = out + Stride * run.i;
    oi[0] += sum0;
    oi[1] += sum1;
    oi[2] += sum2;
  }
}

// out_i += scale * sum_j noise_ij e_ij (and the opposite on j), noise_ij = sigma w_R theta: the
// random impulse, which sums to zero over all atoms.
template <typename UpdateJ>
inline void accumulate_noise(const std::vector<FrictionPair> &pairs, const std::vector<double> &noise,
                             double scale, double *out, UpdateJ update_j, int stride = 3)
{
  for (size_t n = 0; n < pairs.size(); n++) {
    const FrictionPair &p = pairs[n];
    const double amount = scale * noise[n];
    double *oi = out + stride * p.i;
    oi[0] += amount * p.e[0];
    oi[1] += amount * p.e[1];
    oi[2] += amount * p.e[2];
    if (update_j(p.j)) {
      double *oj = out + stride * p.j;
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

// Per-atom 3x3 diagonal blocks of G, sum_j gamma w_D e e^T (6 values: xx yy zz xy xz yz), for
// the block-Jacobi preconditioner.
template <typename UpdateJ>
inline void accumulate_blocks(const std::vector<FrictionPair> &pairs, double *blocks,
                              UpdateJ update_j, int stride = 6)
{
  for (const FrictionPair &p : pairs) {
    const double g = p.friction;
    const double b[6] = {g * p.e[0] * p.e[0], g * p.e[1] * p.e[1], g * p.e[2] * p.e[2],
                         g * p.e[0] * p.e[1], g * p.e[0] * p.e[2], g * p.e[1] * p.e[2]};
    for (int k = 0; k < 6; k++) blocks[stride * p.i + k] += b[k];
    if (update_j(p.j))
      for (int k = 0; k < 6; k++) blocks[stride * p.j + k] += b[k];
  }
}

/* ---- dpd/fpm pairs: translation and rotation, 6 unknowns per atom (v, Omega) ------------------
   The friction acts on the slip velocity of the two surfaces at the mid-point,
     u = v_i - v_j + (r/2) e x (Omega_i + Omega_j),   F = central (e.u) e + shear (u - (e.u) e),
   and (G q) gets +F on v_i, -F on v_j and -(r/2) e x F on both Omega_i and Omega_j (the
   transpose of u's dependence on them). The random generalised force has the same structure, so
   B B^T = 2 kBT G holds for translation and rotation together. */
struct FpmFrictionPair {
  int i, j;
  float e[3];
  float half_r;     // r/2
  float central;    // gamma_C w
  float shear;      // gamma_S w
};

// The generalised force of one pair given the pair force F on i: adds it with the given sign.
template <typename UpdateJ>
inline void scatter_fpm(const FpmFrictionPair &p, const double force[3], double *out, UpdateJ update_j)
{
  const double t[3] = {-p.half_r * (p.e[1] * force[2] - p.e[2] * force[1]),
                       -p.half_r * (p.e[2] * force[0] - p.e[0] * force[2]),
                       -p.half_r * (p.e[0] * force[1] - p.e[1] * force[0])};
  double *oi = out + 6 * p.i;
  for (int k = 0; k < 3; k++) {
    oi[k] += force[k];
    oi[3 + k] += t[k];
  }
  if (update_j(p.j)) {
    double *oj = out + 6 * p.j;
    for (int k = 0; k < 3; k++) {
      oj[k] -= force[k];
      oj[3 + k] += t[k];
    }
  }
}

// One pair's friction force on i from the generalised velocities qi, qj (v, Omega each), times
// scale: central (e.u) e + shear (u - (e.u) e) of the slip velocity u.
inline void fpm_pair_friction(const FpmFrictionPair &p, const double *qi, const double *qj,
                              double scale, double force[3])
{
  const double spin[3] = {qi[3] + qj[3], qi[4] + qj[4], qi[5] + qj[5]};
  const double u[3] = {qi[0] - qj[0] + p.half_r * (p.e[1] * spin[2] - p.e[2] * spin[1]),
                       qi[1] - qj[1] + p.half_r * (p.e[2] * spin[0] - p.e[0] * spin[2]),
                       qi[2] - qj[2] + p.half_r * (p.e[0] * spin[1] - p.e[1] * spin[0])};
  const double shear = scale * p.shear;
  const double normal = scale * (p.central - p.shear) * (p.e[0] * u[0] + p.e[1] * u[1] + p.e[2] * u[2]);
  for (int k = 0; k < 3; k++) force[k] = shear * u[k] + normal * p.e[k];
}

template <typename UpdateJ>
inline void accumulate_fpm_friction(const std::vector<FpmFrictionPair> &pairs, const double *q,
                                    double *out, UpdateJ update_j, double scale = 1.0)
{
  for (const FpmFrictionPair &p : pairs) {
    double force[3];
    fpm_pair_friction(p, q + 6 * p.i, q + 6 * p.j, scale, force);
    scatter_fpm(p, force, out, update_j);
  }
}

/* ---- periodic images that move with a deforming box --------------------------------------
   Under fix deform ... remap v the image of atom j across a periodic boundary moves with j's
   velocity plus a constant offset (the box's rate of change times the image's count of box
   vectors). The solver's unknowns are the owners' velocities, so for such a pair G u gains the
   pair's operator applied to (u_i = 0, u_j = offset): a term that does not depend on the
   unknowns and moves to the right-hand side of the step (the shear the boundary imposes). */
template <typename UpdateJ>
inline void accumulate_image_offset(const FrictionPair &p, const double offset[3], double *out,
                                    UpdateJ update_j, int stride = 3)
{
  const double at_rest[3] = {0.0, 0.0, 0.0};
  const double projected = pair_friction(p, at_rest, offset);
  for (int k = 0; k < 3; k++) out[stride * p.i + k] += projected * p.e[k];
  if (update_j(p.j))
    for (int k = 0; k < 3; k++) out[stride * p.j + k] -= projected * p.e[k];
}

template <typename UpdateJ>
inline void accumulate_fpm_image_offset(const FpmFrictionPair &p, const double offset[3], double *out,
                                        UpdateJ update_j)
{
  const double at_rest[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  const double moving[6] = {offset[0], offset[1], offset[2], 0.0, 0.0, 0.0};
  double force[3];
  fpm_pair_friction(p, at_rest, moving, 1.0, force);
  scatter_fpm(p, force, out, update_j);
}

// noise: 3 values per pair, the random force on i (without the time factor), times scale
template <typename UpdateJ>
inline void accumulate_fpm_noise(const std::vector<FpmFrictionPair> &pairs, const std::vector<double> &noise,
                                 double scale, double *out, UpdateJ update_j)
{
  for (size_t n = 0; n < pairs.size(); n++) {
    const double force[3] = {scale * noise[3 * n], scale * noise[3 * n + 1], scale * noise[3 * n + 2]};
    scatter_fpm(pairs[n], force, out, update_j);
  }
}

// The two 3x3 diagonal blocks per atom (12 values: v-v then Omega-Omega, each xx yy zz xy xz yz):
// central e e + shear (1 - e e) and (r/2)^2 shear (1 - e e). (The v-Omega coupling within one
// atom is left out of the preconditioner, which stays symmetric positive definite.)
template <typename UpdateJ>
inline void accumulate_fpm_blocks(const std::vector<FpmFrictionPair> &pairs, double *blocks, UpdateJ update_j)
{
  for (const FpmFrictionPair &p : pairs) {
    const double ee[6] = {p.e[0] * p.e[0], p.e[1] * p.e[1], p.e[2] * p.e[2],
                          p.e[0] * p.e[1], p.e[0] * p.e[2], p.e[1] * p.e[2]};
    const double rot = p.half_r * p.half_r * p.shear;
    double b[12];
    for (int k = 0; k < 6; k++) {
      const double identity = (k < 3) ? 1.0 : 0.0;
      b[k] = p.central * ee[k] + p.shear * (identity - ee[k]);
      b[6 + k] = rot * (identity - ee[k]);
    }
    for (int k = 0; k < 12; k++) blocks[12 * p.i + k] += b[k];
    if (update_j(p.j))
      for (int k = 0; k < 12; k++) blocks[12 * p.j + k] += b[k];
  }
}

// Inverse of the symmetric 3x3 block (shift I + scale B) into 9 values. A nearly singular
// block (an atom with one or two partners in the zero-mass limit: no friction across their
// directions) falls back to the inverse of its diagonal; false if even that is zero.
inline bool invert_block(const double *block, double shift, double scale, double *inverse)
{
  const double a = shift + scale * block[0], d = shift + scale * block[1], f = shift + scale * block[2];
  const double b = scale * block[3], c = scale * block[4], e = scale * block[5];
  const double c00 = d * f - e * e, c01 = c * e - b * f, c02 = b * e - c * d;
  const double det = a * c00 + b * c01 + c * c02;
  const double trace = a + d + f;
  if (!(det > 1e-6 * trace * trace * trace / 27.0)) {
    for (int k = 0; k < 9; k++) inverse[k] = 0.0;
    const double diag[3] = {a, d, f};
    bool any = false;
    for (int k = 0; k < 3; k++)
      if (diag[k] > 0.0) { inverse[4 * k] = 1.0 / diag[k]; any = true; }
    return any;
  }
  const double inv = 1.0 / det;
  inverse[0] = c00 * inv; inverse[1] = c01 * inv; inverse[2] = c02 * inv;
  inverse[3] = c01 * inv; inverse[4] = (a * f - c * c) * inv; inverse[5] = (b * c - a * e) * inv;
  inverse[6] = c02 * inv; inverse[7] = (b * c - a * e) * inv; inverse[8] = (a * d - b * b) * inv;
  return true;
}

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

// block_inverse (optional, 9 values per atom, n = 3 atoms): block-Jacobi preconditioning, which
// also couples the components of one atom; inv_diag then only marks the held unknowns.
// project (optional): removes a null space (the uniform translation of a singular G) from the
// preconditioned residual, so that every search direction stays in the space where A is
// positive definite (b and A's output must already lie in it).
template <typename Apply, typename GlobalSum, typename Project = NoProjection>
inline SolverResult conjugate_gradient(int n, Apply apply, GlobalSum global_sum,
                                       const double *inv_diag, const double *b, double *x,
                                       double tolerance, int max_iterations,
                                       const double *block_inverse = nullptr,
                                       Project project = Project(),
                                       CgWorkspace *workspace = nullptr,
                                       const double *start_product = nullptr)
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
  // z = P r, projected. (Fusing this into the iteration's update loop, atom by atom, measured
  // no faster: the update loop then no longer vectorises.)
  auto precondition = [&]() {
    if (!block_inverse) {
      for (int k = 0; k < n; k++) z[k] = inv_diag[k] * r[k];
    } else {
      for (int a = 0; a < n / 3; a++) {
        const double *m = block_inverse + 9 * a;
        const double *ra = r + 3 * a;
        for (int k = 0; k < 3; k++)
          z[3 * a + k] = (inv_diag[3 * a + k] != 0.0) ? m[3 * k] * ra[0] + m[3 * k + 1] * ra[1] + m[3 * k + 2] * ra[2] : 0.0;
      }
    }
    project(z);
  };
  // the one reduction of an iteration: rz = (r,z), wz = (w,z), rr = (r,r), and for the next
  // residual's norm rw = (r,w), rs = (r,s), ww = (w,w), ws = (w,s), ss = (s,s), with s the
  // previous A p. w = A z is first zeroed on held unknowns (so that r, updated by s, stays zero
  // there), in the same pass.
  enum { RZ, WZ, RR, RW, RS, WW, WS, SS, BB, NSUMS };
  double sums[NSUMS];
  auto apply_and_reduce = [&](bool with_b) {
    apply(z, w);
    for (double &v : sums) v = 0.0;
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
    global_sum(sums, with_b ? NSUMS : BB);
  };

  SolverResult result;
  // start_product (optional): A x of the start, where the caller has it (then x must already
  // lie in the projected space)
  if (!start_product) {
    project(x);
    apply(x, w);
  }
  const double *ax = start_product ? start_product : w;
  for (int k = 0; k < n; k++) r[k] = (inv_diag[k] != 0.0) ? b[k] - ax[k] : 0.0;
  precondition();
  apply_and_reduce(true);
  const double bb = sums[BB];
  if (bb == 0.0) {
    for (int k = 0; k < n; k++) x[k] = 0.0;
    result.converged = true;
    return result;
  }
  const double target = tolerance * tolerance * bb;
  double rr = sums[RR], rz_old = 1.0, alpha = 1.0;
  while (rr > target && result.iterations < max_iterations) {
    const double rz = sums[RZ];
    const double beta = result.iterations == 0 ? 0.0 : rz / rz_old;
    const double curvature = sums[WZ] - beta * rz / alpha;    // (p, A p) of the new direction
    if (!(curvature > 0.0) || !(rz > 0.0)) break;    // breakdown: A not positive (cannot happen for SPD A)
    alpha = rz / curvature;
    rz_old = rz;
    for (int k = 0; k < n; k++) {
      p[k] = z[k] + beta * p[k];
      s[k] = w[k] + beta * s[k];
      x[k] += alpha * p[k];
      r[k] -= alpha * s[k];
    }
    result.iterations++;
    // |r - alpha s|^2 with s = w + beta s_old, from this iteration's sums
    const double rs = sums[RW] + beta * sums[RS];
    const double ss = sums[WW] + 2.0 * beta * sums[WS] + beta * beta * sums[SS];
    const double predicted = rr - 2.0 * alpha * rs + alpha * alpha * ss;
    if (predicted <= target) {
      double actual = 0.0;
      for (int k = 0; k < n; k++) actual += r[k] * r[k];
      global_sum(&actual, 1);
      rr = actual;
      if (rr <= target || result.iterations >= max_iterations) break;
    }
    precondition();
    apply_and_reduce(false);
    rr = sums[RR];
  }
  result.relative_residual = std::sqrt(rr / bb);
  result.converged = rr <= target;
  return result;
}

}    // namespace etd

#endif
