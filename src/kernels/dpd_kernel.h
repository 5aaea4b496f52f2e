// ETD-DPD: the generalised DPD pair kernel as pure functions.
//
//   F_ij = a w_C(r) e - gamma w_D(r) (e . v_ij) e + sigma w_R(r) theta_ij e / sqrt(dt)
//   w_C = (1 - r/rc_C)^p,  w_D = (1 - r/rc_D)^s,  w_R = sqrt(w_D),  sigma^2 = 2 gamma kBT
//
// The LAMMPS pair styles only gather atoms and scatter forces; every formula lives here so the
// unit tests can check it directly.
#ifndef ETD_DPD_KERNEL_H
#define ETD_DPD_KERNEL_H

#include "host_device.h"

#include <cmath>

namespace etd {

// Exponents that occur in practice get exact, pow()-free evaluations; the kind is chosen once
// per type pair so the inner loop only switches on a predictable value.
enum class PowerKind { Zero, Quarter, Half, One, ThreeHalves, Two, General };

inline PowerKind classify_power(double exponent)
{
  if (exponent == 0.0) return PowerKind::Zero;
  if (exponent == 0.25) return PowerKind::Quarter;
  if (exponent == 0.5) return PowerKind::Half;
  if (exponent == 1.0) return PowerKind::One;
  if (exponent == 1.5) return PowerKind::ThreeHalves;
  if (exponent == 2.0) return PowerKind::Two;
  return PowerKind::General;
}

// q^exponent for 0 <= q <= 1.
ETD_HOST_DEVICE inline double power_of(double q, PowerKind kind, double exponent)
{
  switch (kind) {
    case PowerKind::Zero:
      return 1.0;
    case PowerKind::Quarter:
      return std::sqrt(std::sqrt(q));
    case PowerKind::Half:
      return std::sqrt(q);
    case PowerKind::One:
      return q;
    case PowerKind::ThreeHalves:
      return q * std::sqrt(q);
    case PowerKind::Two:
      return q * q;
    // exp(e log q) is pow to a few ulp for 0 <= q <= 1 (q = 0 gives exp(-inf) = 0) and about
    // 25 % cheaper than glibc's pow, which matters for s = 0.4244 in the pair loop
    default:
      return std::exp(exponent * std::log(q));
  }
}

// Noise amplitude from the fluctuation-dissipation theorem.
ETD_HOST_DEVICE inline double noise_amplitude(double gamma, double kT)
{
  return std::sqrt(2.0 * gamma * kT);
}

// Per type pair constants, precomputed by the pair style.
struct PairCoefficients {
  double a = 0.0;        // conservative amplitude
  double gamma = 0.0;    // friction
  double sigma = 0.0;    // noise amplitude sqrt(2 gamma kT)
  double s = 2.0;        // dissipative exponent
  double p = 1.0;        // conservative exponent
  double rc_c = 1.0;     // conservative cutoff
  double rc_d = 1.0;     // dissipative / random cutoff
  double inv_rc_c = 1.0;
  double inv_rc_d = 1.0;
  double rcsq_c = 1.0;
  double rcsq_d = 1.0;
  PowerKind conservative_kind = PowerKind::One;    // w_C = q^p
  PowerKind dissipative_kind = PowerKind::Two;     // w_D = q^s
  PowerKind random_kind = PowerKind::One;          // w_R = q^(s/2)
  PowerKind energy_kind = PowerKind::Two;          // q^(p+1)

  void set(double a_, double gamma_, double s_, double p_, double rc_c_, double rc_d_, double kT)
  {
    a = a_;
    gamma = gamma_;
    s = s_;
    p = p_;
    rc_c = rc_c_;
    rc_d = rc_d_;
    sigma = noise_amplitude(gamma, kT);
    inv_rc_c = 1.0 / rc_c;
    inv_rc_d = 1.0 / rc_d;
    rcsq_c = rc_c * rc_c;
    rcsq_d = rc_d * rc_d;
    conservative_kind = classify_power(p);
    dissipative_kind = classify_power(s);
    random_kind = classify_power(0.5 * s);
    energy_kind = classify_power(p + 1.0);
  }
};

// sqrt(special) for the random force's special-bond factor; exact 1 for the common unbonded pair
// without a square root (std::sqrt(1.0) is 1.0, so the result is the same either way).
ETD_HOST_DEVICE inline double special_root(double special)
{
  return special == 1.0 ? 1.0 : std::sqrt(special);
}

// w_R = q^(s/2) and w_D = w_R^2 at q = 1 - r/rc_D (0 <= q <= 1), with the kinds of
// PairCoefficients or FpmCoefficients. For s = 2, w_R = q and w_D = q q (the same value).
struct DissipativeWeights {
  double random = 0.0;         // w_R
  double dissipative = 0.0;    // w_D
};

ETD_HOST_DEVICE inline DissipativeWeights dissipative_weights(double q, PowerKind dissipative_kind,
                                                              PowerKind random_kind, double s)
{
  DissipativeWeights w;
  w.random = power_of(q, random_kind, 0.5 * s);
  w.dissipative = (dissipative_kind == PowerKind::Two) ? q * q : w.random * w.random;
  return w;
}

// The friction and the noise amplitude of one pair at distance r inside rc_D (the one place
// these are evaluated: pair_force and fix etd's implicit scheme, which applies them itself):
//   friction = special gamma w_D(r)             (the pair's friction coefficient along e)
//   noise = sqrt(special) sigma w_R(r)          (the random force is noise theta / sqrt(dt))
struct PairDissipation {
  double friction = 0.0;
  double noise = 0.0;
};

ETD_HOST_DEVICE inline PairDissipation pair_dissipation(const PairCoefficients &c, double r,
                                                        double special = 1.0)
{
  const double q = 1.0 - r * c.inv_rc_d;
  const DissipativeWeights w = dissipative_weights(q, c.dissipative_kind, c.random_kind, c.s);
  PairDissipation out;
  out.friction = special * c.gamma * w.dissipative;
  out.noise = special_root(special) * c.sigma * w.random;
  return out;
}

// Scalar pair force magnitudes along e (positive = repulsive), split into their parts.
struct PairForce {
  double conservative = 0.0;
  double dissipative = 0.0;
  double random = 0.0;
  double friction = 0.0;    // gamma w_D: the pair's contribution to the friction operator
  ETD_HOST_DEVICE double total() const { return conservative + dissipative + random; }
};

// special a (1 - r/rc_C)^p inside rc_C, zero outside: the conservative force along e.
ETD_HOST_DEVICE inline double dpd_conservative(const PairCoefficients &c, double rsq, double r,
                                               double special = 1.0)
{
  if (rsq >= c.rcsq_c) return 0.0;
  const double q = 1.0 - r * c.inv_rc_c;
  return special * c.a * power_of(q, c.conservative_kind, c.p);
}

// r: distance, e_dot_v: (e . v_ij), theta: unit Gaussian, inv_sqrt_dt: 1/sqrt(dt),
// special: special-bond factor (dissipative scales by it, random by its root), conservative:
// the conservative force along e (a law other than dpd_conservative may supply its own).
ETD_HOST_DEVICE inline PairForce pair_force(const PairCoefficients &c, double rsq, double r,
                                            double e_dot_v, double theta, double inv_sqrt_dt,
                                            double special, double conservative)
{
  PairForce out;
  out.conservative = conservative;
  if (rsq < c.rcsq_d) {
    const PairDissipation d = pair_dissipation(c, r, special);
    out.friction = d.friction;
    out.dissipative = -out.friction * e_dot_v;
    out.random = d.noise * theta * inv_sqrt_dt;
  }
  return out;
}

ETD_HOST_DEVICE inline PairForce pair_force(const PairCoefficients &c, double rsq, double r,
                                            double e_dot_v, double theta, double inv_sqrt_dt,
                                            double special = 1.0)
{
  return pair_force(c, rsq, r, e_dot_v, theta, inv_sqrt_dt, special,
                    dpd_conservative(c, rsq, r, special));
}

ETD_HOST_DEVICE inline double pair_energy(const PairCoefficients &c, double rsq, double r,
                                          double special = 1.0)
{
  if (rsq >= c.rcsq_c) return 0.0;
  const double q = 1.0 - r * c.inv_rc_c;
  return special * c.a * c.rc_c / (c.p + 1.0) * power_of(q, c.energy_kind, c.p + 1.0);
}

}    // namespace etd

#endif
