// ETD-DPD: the pairwise friction operator of DPD, the product the implicit scheme's solver
// applies (the solve itself: friction_solve.h, conjugate_gradient.h).
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

#include "host_device.h"

#include <cmath>
#include <vector>

namespace etd {

// The velocity a periodic image has on top of its owner's under fix deform ... remap v, as
// LAMMPS's own ghost communication adds it (AtomVec::pack_comm_vel): counts, how many of each
// box vector (x, y, z, yz, xz, xy) the image lies from its owner; rate, LAMMPS's h_rate. One
// formula for the host assembly and the kernels', so both give the same offsets to the bit.
ETD_HOST_DEVICE inline void image_velocity_offset(const double *counts, const double *rate,
                                                  double offset[3])
{
  offset[0] = counts[0] * rate[0] + counts[5] * rate[5] + counts[4] * rate[4];
  offset[1] = counts[1] * rate[1] + counts[3] * rate[3];
  offset[2] = counts[2] * rate[2];
}

// One interacting pair, its geometry cached once per step so that every solver iteration
// streams this compact array instead of the neighbor list.
struct FrictionPair {
  int i, j;          // atom indices (local or ghost)
  float e[3];        // unit vector from j to i
  float friction;    // gamma_ij w_D(r_ij) (special-bond factor included)
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
  return p.friction *
      (p.e[0] * (ui[0] - uj[0]) + p.e[1] * (ui[1] - uj[1]) + p.e[2] * (ui[2] - uj[2]));
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
      const double projected =
          scale * p.friction * (e0 * (ui0 - uj[0]) + e1 * (ui1 - uj[1]) + e2 * (ui2 - uj[2]));
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
inline void accumulate_noise(const std::vector<FrictionPair> &pairs,
                             const std::vector<double> &noise, double scale, double *out,
                             UpdateJ update_j, int stride = 3)
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
inline void scatter_fpm(const FpmFrictionPair &p, const double force[3], double *out,
                        UpdateJ update_j)
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
  const double normal =
      scale * (p.central - p.shear) * (p.e[0] * u[0] + p.e[1] * u[1] + p.e[2] * u[2]);
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
inline void accumulate_fpm_image_offset(const FpmFrictionPair &p, const double offset[3],
                                        double *out, UpdateJ update_j)
{
  const double at_rest[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  const double moving[6] = {offset[0], offset[1], offset[2], 0.0, 0.0, 0.0};
  double force[3];
  fpm_pair_friction(p, at_rest, moving, 1.0, force);
  scatter_fpm(p, force, out, update_j);
}

// noise: 3 values per pair, the random force on i (without the time factor), times scale
template <typename UpdateJ>
inline void accumulate_fpm_noise(const std::vector<FpmFrictionPair> &pairs,
                                 const std::vector<double> &noise, double scale, double *out,
                                 UpdateJ update_j)
{
  for (size_t n = 0; n < pairs.size(); n++) {
    const double force[3] = {scale * noise[3 * n], scale * noise[3 * n + 1],
                             scale * noise[3 * n + 2]};
    scatter_fpm(pairs[n], force, out, update_j);
  }
}

// The two 3x3 diagonal blocks per atom (12 values: v-v then Omega-Omega, each xx yy zz xy xz yz):
// central e e + shear (1 - e e) and (r/2)^2 shear (1 - e e). (The v-Omega coupling within one
// atom is left out of the preconditioner, which stays symmetric positive definite.)
template <typename UpdateJ>
inline void accumulate_fpm_blocks(const std::vector<FpmFrictionPair> &pairs, double *blocks,
                                  UpdateJ update_j)
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

}    // namespace etd

#endif
