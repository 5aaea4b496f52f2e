// ETD-DPD: what a pair law hands the package's one pair loop (PairDPDBase::eval), and the law of
// central DPD (dpd/gen, or any conservative weight with DPD friction and noise).
//
// A law is a class, constructed per pair from its coefficients and geometry, with
//   using Coefficients;                       per type pair constants, built by the style
//   using Friction;                           PairCoefficients or FpmCoefficients: the friction
//   static const Friction &friction(const Coefficients &);   that fix etd's implicit scheme applies
//   static constexpr bool rotation;           acts on angular velocities, puts torques
//   static constexpr bool central;            its full force lies along e (virial from fpair)
//   template <bool DISSIPATIVE> void evaluate(const PairMotion &, const PairStep &);
//       fills force (on i; -force on j), fpair (|F|/r where the force is central: always for
//       central laws, and for every law with DISSIPATIVE false, when only the conservative
//       force is computed) and torque (on each of i and j; with rotation and DISSIPATIVE)
//   void friction_diagonal(double g[3], double g_rot[3]) const;  after evaluate<true>
//   void split(double parts[3][3], double torque_parts[2][3]) const;  C, D, R of the force on
//       i (and of the torque, D and R, with rotation), after evaluate
//   static double conservative(const Coefficients &, double rsq, double r, double special);
//   static double energy(const Coefficients &, double rsq, double r, double special);
//       the conservative force along e and its energy (zero beyond the conservative cutoff),
//       for the energy tally and Pair::single.
// evaluate, friction_diagonal and split are declared ETD_PAIR_INLINE, or ETD_HOST_INLINE for a
// law that no device kernel runs (dpd/fpm's).
#ifndef ETD_PAIR_LAW_H
#define ETD_PAIR_LAW_H

#include "dpd_kernel.h"
#include "dpd_random.h"

#include <cstdint>

// A law's per-pair functions are inlined into the pair loop: out of line, the law's state goes
// through memory (GCC's own choice for dpd/fpm's evaluate made its loop 1.7 times as slow).
#if defined(__CUDACC__) || defined(__HIPCC__)
#define ETD_PAIR_INLINE __host__ __device__ __forceinline__
#define ETD_PAIR_NOINLINE __host__ __device__ __noinline__
#elif defined(__GNUC__)
#define ETD_PAIR_INLINE inline __attribute__((always_inline))
#define ETD_PAIR_NOINLINE __attribute__((noinline))
#else
#define ETD_PAIR_INLINE inline
#define ETD_PAIR_NOINLINE
#endif
// The same inlining for the host's pair loop alone (a law that no device kernel runs, the CPU
// loop's helpers): never compiled for a device, so that a CUDA build does not take host-only
// code for device code
#if defined(__GNUC__)
#define ETD_HOST_INLINE inline __attribute__((always_inline))
#else
#define ETD_HOST_INLINE inline
#endif

namespace etd {

// One pair as the loop sees it: del = r_i - r_j, r = |del| > 0, rinv = 1 / r.
struct PairGeometry {
  double del[3];
  double rsq, r, rinv;
  double special;    // special-bond factor
};

// The pair's velocities (angular ones with rotation only) and the atom IDs that key its noise.
struct PairMotion {
  const double *v_i, *v_j;
  const double *omega_i, *omega_j;
  std::int64_t tag_i, tag_j;
};

// A pair's noise as one call: inlined into the loop, GCC leaves the ziggurat's draw out of line
// instead, a call per draw with the generator's state in memory.
ETD_PAIR_NOINLINE inline double pair_gaussian(const PairNoise &noise, std::int64_t tag_i,
                                              std::int64_t tag_j, std::int64_t timestep)
{
  return noise.gaussian(tag_i, tag_j, timestep);
}
ETD_PAIR_NOINLINE inline void pair_gaussians4(const PairNoise &noise, std::int64_t tag_i,
                                              std::int64_t tag_j, std::int64_t timestep,
                                              double out[4])
{
  noise.gaussians4(tag_i, tag_j, timestep, 0, out);
}

// What is the same for every pair of one force evaluation.
struct PairStep {
  const PairNoise &noise;
  std::int64_t timestep;
  double inv_sqrt_dt;
};

// DPD's conservative force a (1 - r/rc_C)^p with energy a rc_C/(p+1) (1 - r/rc_C)^(p+1).
struct PowerConservative {
  ETD_HOST_DEVICE static double force(const PairCoefficients &c, double rsq, double r,
                                      double special)
  {
    return dpd_conservative(c, rsq, r, special);
  }
  ETD_HOST_DEVICE static double energy(const PairCoefficients &c, double rsq, double r,
                                       double special)
  {
    return pair_energy(c, rsq, r, special);
  }
};

// A central pair force: Conservative's force along e (see PowerConservative) with DPD's
// friction and noise, gamma w_D(r) and sigma w_R(r), of PairCoefficients.
template <class Conservative> class CentralDpdLaw {
 public:
  using Coefficients = PairCoefficients;
  using Friction = PairCoefficients;
  static constexpr bool rotation = false;
  static constexpr bool central = true;
  ETD_HOST_DEVICE static const Friction &friction(const Coefficients &c) { return c; }

  double force[3];
  double fpair;

  ETD_HOST_DEVICE CentralDpdLaw(const Coefficients &c, const PairGeometry &g) : c_(c), g_(g) {}

  template <bool DISSIPATIVE> ETD_PAIR_INLINE void evaluate(const PairMotion &m, const PairStep &s)
  {
    const double *d = g_.del;
    const double e_dot_v = (d[0] * (m.v_i[0] - m.v_j[0]) + d[1] * (m.v_i[1] - m.v_j[1]) +
                            d[2] * (m.v_i[2] - m.v_j[2])) *
        g_.rinv;
    const double theta = (DISSIPATIVE && g_.rsq < c_.rcsq_d)
        ? pair_gaussian(s.noise, m.tag_i, m.tag_j, s.timestep)
        : 0.0;
    pf_ = pair_force(c_, g_.rsq, g_.r, e_dot_v, theta, s.inv_sqrt_dt, g_.special,
                     Conservative::force(c_, g_.rsq, g_.r, g_.special));
    if (!DISSIPATIVE) pf_.dissipative = pf_.random = pf_.friction = 0.0;
    fpair = pf_.total() * g_.rinv;
    for (int k = 0; k < 3; k++) force[k] = d[k] * fpair;
  }

  // gamma w_D e_a^2 on each of i and j (no rotation: g_rot unused)
  ETD_PAIR_INLINE void friction_diagonal(double g[3], double /*g_rot*/[3]) const
  {
    const double friction_per_rsq = pf_.friction * g_.rinv * g_.rinv;
    for (int k = 0; k < 3; k++) g[k] = friction_per_rsq * g_.del[k] * g_.del[k];
  }

  ETD_PAIR_INLINE void split(double parts[3][3], double /*torque_parts*/[2][3]) const
  {
    const double e[3] = {g_.del[0] * g_.rinv, g_.del[1] * g_.rinv, g_.del[2] * g_.rinv};
    const double magnitude[3] = {pf_.conservative, pf_.dissipative, pf_.random};
    for (int p = 0; p < 3; p++)
      for (int k = 0; k < 3; k++) parts[p][k] = magnitude[p] * e[k];
  }

  ETD_HOST_DEVICE static double conservative(const Coefficients &c, double rsq, double r,
                                             double special)
  {
    return Conservative::force(c, rsq, r, special);
  }
  ETD_HOST_DEVICE static double energy(const Coefficients &c, double rsq, double r, double special)
  {
    return Conservative::energy(c, rsq, r, special);
  }

 private:
  const Coefficients &c_;
  const PairGeometry &g_;
  PairForce pf_;
};

using DpdGenLaw = CentralDpdLaw<PowerConservative>;

}    // namespace etd

#endif
