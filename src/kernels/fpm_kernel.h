// ETD-DPD: the FPM-style pair kernel of pair_style dpd/fpm as pure functions (Pan, Pivkin and
// Karniadakis, "Single-particle hydrodynamics in DPD: A new formulation", EPL 84, 10012 (2008)).
//
// With e = r_ij / r, w = (1 - r/rc)^s (dissipative weight; the paper's f^2) and
// u_ij = v_ij + (r_ij/2) x (Omega_i + Omega_j), the relative velocity of the two particles'
// surfaces at the mid-point between them:
//
//   F_ij = a (1 - r/rc) e                                             conservative
//        - gamma_C w (e . v_ij) e - gamma_S w [u_ij - (e . u_ij) e]      dissipative
//        + sqrt(w) [sigma_C theta_C e + sigma_S theta_A x e] / sqrt(dt)  random
//   T_i = T_j = -(r_ij / 2) x F_ij,   sigma_X^2 = 2 kBT gamma_X
//
// e . (r_ij x Omega) = 0, so the shear term is the paper's translational shear force plus its
// rotational force -gamma_S w (r_ij/2) x (Omega_i + Omega_j). The paper's random matrix enters
// only through tr(dW)/sqrt(3) and sqrt(2) dW^A . e; these are four independent unit Gaussians
// (theta_C and the three entries of theta_A, with sqrt(2) dW^A . e = theta_A x e up to the sign
// convention of the entries), so they are drawn directly.
//
// The friction acting on (v_i, Omega_i, v_j, Omega_j) is K^T Gamma K with Gamma = w [gamma_C e e +
// gamma_S (1 - e e)] and u_ij = K q; the random force acts through the same K^T and has covariance
// 2 kBT Gamma, so fluctuation-dissipation holds for translation and rotation together.
#ifndef ETD_FPM_KERNEL_H
#define ETD_FPM_KERNEL_H

#include "dpd_kernel.h"
#include "pair_law.h"

#include <cmath>

namespace etd {

struct FpmCoefficients {
  double a = 0.0;          // conservative amplitude
  double gamma_c = 0.0;    // central friction
  double gamma_s = 0.0;    // shear friction
  double sigma_c = 0.0;    // sqrt(2 kBT gamma_C)
  double sigma_s = 0.0;    // sqrt(2 kBT gamma_S)
  double s = 2.0;          // dissipative exponent
  double rc = 1.0;
  double inv_rc = 1.0;
  double rcsq = 1.0;
  PowerKind dissipative_kind = PowerKind::Two;    // w = q^s
  PowerKind random_kind = PowerKind::One;         // sqrt(w) = q^(s/2)

  void set(double a_, double gamma_c_, double gamma_s_, double s_, double rc_, double kT)
  {
    a = a_;
    gamma_c = gamma_c_;
    gamma_s = gamma_s_;
    s = s_;
    rc = rc_;
    sigma_c = noise_amplitude(gamma_c, kT);
    sigma_s = noise_amplitude(gamma_s, kT);
    inv_rc = 1.0 / rc;
    rcsq = rc * rc;
    dissipative_kind = classify_power(s);
    random_kind = classify_power(0.5 * s);
  }
};

// The four unit Gaussians of one pair (theta_ij = theta_ji).
struct FpmNoise {
  double central = 0.0;                 // theta_C = tr(dW) / sqrt(3 dt)
  double shear[3] = {0.0, 0.0, 0.0};    // theta_A: sqrt(2) dW^A as an axial vector / sqrt(dt)
};

// Force on i from j (the force on j is its negative), split into parts, and the torque that
// the pair puts on each of i and j (the same vector for both).
struct FpmPairResult {
  double conservative[3] = {0.0, 0.0, 0.0};
  double dissipative[3] = {0.0, 0.0, 0.0};    // central + shear, including the rotational drag
  double random[3] = {0.0, 0.0, 0.0};
  double torque[3] = {0.0, 0.0, 0.0};
  double central_friction = 0.0;    // gamma_C w (times the special factor)
  double shear_friction = 0.0;      // gamma_S w (times the special factor)
  double force(int k) const { return conservative[k] + dissipative[k] + random[k]; }
};

inline void cross(const double a[3], const double b[3], double out[3])
{
  out[0] = a[1] * b[2] - a[2] * b[1];
  out[1] = a[2] * b[0] - a[0] * b[2];
  out[2] = a[0] * b[1] - a[1] * b[0];
}

// The frictions and the noise factor of one pair at distance r inside rc (evaluated here for
// fpm_pair and for fix etd's implicit scheme, which applies friction and noise itself):
//   central = special gamma_C w,  shear = special gamma_S w,  noise = sqrt(special) sqrt(w)
struct FpmDissipation {
  double central = 0.0;
  double shear = 0.0;
  double noise = 0.0;
};

inline FpmDissipation fpm_dissipation(const FpmCoefficients &c, double r, double special = 1.0)
{
  const double q = 1.0 - r * c.inv_rc;
  const DissipativeWeights w = dissipative_weights(q, c.dissipative_kind, c.random_kind, c.s);
  FpmDissipation out;
  out.central = special * c.gamma_c * w.dissipative;
  out.shear = special * c.gamma_s * w.dissipative;
  out.noise = special_root(special) * w.random;
  return out;
}

// The random force of one pair on i, amplitude [sigma_C theta_C e + sigma_S theta_A x e]:
// its central magnitude along e and its non-central part (the only one that makes a torque).
// amplitude: the pair's noise factor (FpmDissipation::noise), times 1/sqrt(dt) for a force.
struct FpmRandomForce {
  double central = 0.0;
  double shear[3] = {0.0, 0.0, 0.0};
};

inline FpmRandomForce fpm_random_force(const FpmCoefficients &c, const double e[3],
                                       double amplitude, const FpmNoise &noise)
{
  FpmRandomForce out;
  out.central = amplitude * c.sigma_c * noise.central;
  double shear_dir[3];
  cross(noise.shear, e, shear_dir);
  const double shear_amplitude = amplitude * c.sigma_s;
  for (int k = 0; k < 3; k++) out.shear[k] = shear_amplitude * shear_dir[k];
  return out;
}

// The central conservative force special a (1 - r/rc) along e (r inside rc): it makes no torque.
inline double fpm_conservative(const FpmCoefficients &c, double r, double special = 1.0)
{
  return special * c.a * (1.0 - r * c.inv_rc);
}

// del = r_i - r_j (r = |del| > 0, inside rc), v_ij = v_i - v_j, omega_sum = Omega_i + Omega_j.
// special: special-bond factor (conservative and dissipative scale by it, random by its root).
inline FpmPairResult fpm_pair(const FpmCoefficients &c, const double del[3], double r,
                              const double v_ij[3], const double omega_sum[3],
                              const FpmNoise &noise, double inv_sqrt_dt, double special = 1.0)
{
  FpmPairResult out;
  if (r >= c.rc) return out;
  const double rinv = 1.0 / r;
  const double e[3] = {del[0] * rinv, del[1] * rinv, del[2] * rinv};
  const FpmDissipation d = fpm_dissipation(c, r, special);
  out.central_friction = d.central;
  out.shear_friction = d.shear;

  // slip velocity at the mid-point; its rotational part is perpendicular to e
  const double half_del[3] = {0.5 * del[0], 0.5 * del[1], 0.5 * del[2]};
  double spin_slip[3];
  cross(half_del, omega_sum, spin_slip);
  const double e_dot_v = e[0] * v_ij[0] + e[1] * v_ij[1] + e[2] * v_ij[2];
  const FpmRandomForce random = fpm_random_force(c, e, d.noise * inv_sqrt_dt, noise);

  const double fc = fpm_conservative(c, r, special);
  double shear_force[3];    // the non-central part: the only one that makes a torque
  for (int k = 0; k < 3; k++) {
    const double v_perp = v_ij[k] - e_dot_v * e[k];
    const double shear_dissipative = -out.shear_friction * (v_perp + spin_slip[k]);
    out.conservative[k] = fc * e[k];
    out.dissipative[k] = -out.central_friction * e_dot_v * e[k] + shear_dissipative;
    out.random[k] = random.central * e[k] + random.shear[k];
    shear_force[k] = shear_dissipative + random.shear[k];
  }
  // T = -(r_ij/2) x F_ij; the central parts are parallel to r_ij and drop out exactly
  double t[3];
  cross(half_del, shear_force, t);
  for (int k = 0; k < 3; k++) out.torque[k] = -t[k];
  return out;
}

// The torque -(r_ij/2) x F that a part F of the pair force puts on each of i and j (for the
// dissipative and random parts of the split; their sum is FpmPairResult::torque up to rounding).
inline void fpm_pair_torque(const double del[3], const double force[3], double out[3])
{
  const double half_del[3] = {0.5 * del[0], 0.5 * del[1], 0.5 * del[2]};
  cross(half_del, force, out);
  for (int k = 0; k < 3; k++) out[k] = -out[k];
}

// Conservative energy a rc / 2 (1 - r/rc)^2, zero at rc.
inline double fpm_energy(const FpmCoefficients &c, double r, double special = 1.0)
{
  if (r >= c.rc) return 0.0;
  const double q = 1.0 - r * c.inv_rc;
  return special * 0.5 * c.a * c.rc * q * q;
}

// Diagonal of the friction that one pair puts on atom i (and on j: the same values).
// Translational: d F_i / d v_i = -w [gamma_C e e + gamma_S (1 - e e)], whose diagonal is
//   w [gamma_C e_a^2 + gamma_S (1 - e_a^2)].
// Rotational: d T_i / d Omega_i = -gamma_S w (r^2/4) (1 - e e), diagonal gamma_S w (r^2/4)(1 - e_a^2).
inline void fpm_translational_friction(double central_friction, double shear_friction,
                                       const double e[3], double out[3])
{
  for (int k = 0; k < 3; k++)
    out[k] = central_friction * e[k] * e[k] + shear_friction * (1.0 - e[k] * e[k]);
}

inline void fpm_rotational_friction(double shear_friction, double rsq, const double e[3],
                                    double out[3])
{
  for (int k = 0; k < 3; k++) out[k] = shear_friction * 0.25 * rsq * (1.0 - e[k] * e[k]);
}

// The law of pair_style dpd/fpm for the pair loop (pair_law.h): fpm_pair, or with DISSIPATIVE
// false only the central conservative force.
class FpmLaw {
 public:
  using Coefficients = FpmCoefficients;
  using Friction = FpmCoefficients;
  static constexpr bool rotation = true;
  static constexpr bool central = false;
  static const Friction &friction(const Coefficients &c) { return c; }

  double force[3];
  double fpair;
  double torque[3];

  FpmLaw(const Coefficients &c, const PairGeometry &g) : c_(c), g_(g) {}

  template <bool DISSIPATIVE> ETD_HOST_INLINE void evaluate(const PairMotion &m, const PairStep &s)
  {
    dissipative_ = DISSIPATIVE;
    if constexpr (!DISSIPATIVE) {
      fpair = fpm_conservative(c_, g_.r, g_.special) / g_.r;
      for (int k = 0; k < 3; k++) force[k] = g_.del[k] * fpair;
    } else {
      double v_ij[3], omega_sum[3];
      for (int k = 0; k < 3; k++) {
        v_ij[k] = m.v_i[k] - m.v_j[k];
        omega_sum[k] = m.omega_i[k] + m.omega_j[k];
      }
      double theta[4];
      pair_gaussians4(s.noise, m.tag_i, m.tag_j, s.timestep, theta);
      FpmNoise noise;
      noise.central = theta[0];
      for (int k = 0; k < 3; k++) noise.shear[k] = theta[k + 1];
      pr_ = fpm_pair(c_, g_.del, g_.r, v_ij, omega_sum, noise, s.inv_sqrt_dt, g_.special);
      for (int k = 0; k < 3; k++) {
        force[k] = pr_.force(k);
        torque[k] = pr_.torque[k];
      }
    }
  }

  ETD_HOST_INLINE void friction_diagonal(double g[3], double g_rot[3]) const
  {
    const double e[3] = {g_.del[0] * g_.rinv, g_.del[1] * g_.rinv, g_.del[2] * g_.rinv};
    fpm_translational_friction(pr_.central_friction, pr_.shear_friction, e, g);
    fpm_rotational_friction(pr_.shear_friction, g_.rsq, e, g_rot);
  }

  // the torque's parts are the same on i and j
  ETD_HOST_INLINE void split(double parts[3][3], double torque_parts[2][3]) const
  {
    if (!dissipative_) {
      const double fc = fpm_conservative(c_, g_.r, g_.special);
      for (int k = 0; k < 3; k++) {
        parts[0][k] = fc * (g_.del[k] * g_.rinv);
        parts[1][k] = parts[2][k] = torque_parts[0][k] = torque_parts[1][k] = 0.0;
      }
      return;
    }
    for (int k = 0; k < 3; k++) {
      parts[0][k] = pr_.conservative[k];
      parts[1][k] = pr_.dissipative[k];
      parts[2][k] = pr_.random[k];
    }
    fpm_pair_torque(g_.del, pr_.dissipative, torque_parts[0]);
    fpm_pair_torque(g_.del, pr_.random, torque_parts[1]);
  }

  static double conservative(const Coefficients &c, double rsq, double r, double special)
  {
    return rsq >= c.rcsq ? 0.0 : fpm_conservative(c, r, special);
  }
  static double energy(const Coefficients &c, double rsq, double r, double special)
  {
    return rsq >= c.rcsq ? 0.0 : fpm_energy(c, r, special);
  }

 private:
  const Coefficients &c_;
  const PairGeometry &g_;
  FpmPairResult pr_;
  bool dissipative_ = false;
};

}    // namespace etd

#endif
