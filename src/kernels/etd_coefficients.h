// ETD-DPD: coefficients of the exponential-time-differencing update (Mai-Duy et al. 2013, eqs 3-7, 28-31).
//
// For one velocity component with diagonal friction rate c = Gamma/m and z = -c dt:
//   first order:  v' = e^z v + dt phi1(z) A_n
//   second order: v' = e^z v + dt [(phi1 + phi2) A_n - phi2 A_(n-1)]
// with phi1(z) = (e^z - 1)/z and phi2(z) = (e^z - 1 - z)/z^2, both evaluated without
// cancellation near z = 0.
#ifndef ETD_COEFFICIENTS_H
#define ETD_COEFFICIENTS_H

#include "host_device.h"

#include <cmath>

namespace etd {

// phi1(z) = (e^z - 1)/z; expm1 keeps full relative accuracy for every z.
inline double phi1(double z)
{
  if (z == 0.0) return 1.0;
  return std::expm1(z) / z;
}

// phi2(z) = (e^z - 1 - z)/z^2 = sum_k z^k/(k+2)!. The series is used for |z| < 1, where the
// closed form loses digits; beyond that the cancellation costs less than one bit.
inline double phi2(double z)
{
  if (std::fabs(z) < 1.0) {
    double term = 0.5;    // z^0/2!
    double sum = 0.5;
    for (int k = 1; k < 30; ++k) {
      term *= z / (k + 2);
      sum += term;
      if (std::fabs(term) < 1e-18 * std::fabs(sum)) break;
    }
    return sum;
  }
  return (std::expm1(z) - z) / (z * z);
}

// Standard deviation factor of an Ornstein-Uhlenbeck velocity over one step relative to a
// force held constant over the step: sqrt((1 - e^(2z)) / (-2z)) = sqrt(phi1(2z)).
inline double ou_noise_factor(double z)
{
  return std::sqrt(phi1(2.0 * z));
}

// Coefficients for one component: v' = decay v + current A_n + previous A_(n-1), and the
// weights of a random force held over the step (piecewise) or integrated exactly (OU).
struct EtdCoefficients {
  double decay;              // e^z
  double current;            // weight of A_n (includes dt)
  double previous;           // weight of A_(n-1) (includes dt); zero for first order
  double noise_piecewise;    // dt phi1(z)
  double noise_exact;        // dt sqrt(phi1(2z)): same variance as the exact OU update (if asked)
};

// One expm1 per component serves every coefficient (the integrator calls this 3 times per
// atom and step): e^z = 1 + expm1(z) and expm1(2z) = expm1(z) (expm1(z) + 2), neither of which
// cancels; only far in the tail, where 1 + expm1(z) would lose relative digits, is exp called.
inline EtdCoefficients etd_coefficients(double friction_rate, double dt, int order,
                                        bool want_exact_noise = true)
{
  const double z = -friction_rate * dt;
  const double em1 = std::expm1(z);
  const double p1 = (z == 0.0) ? 1.0 : em1 / z;
  EtdCoefficients c;
  c.decay = (z > -10.0) ? 1.0 + em1 : std::exp(z);
  c.noise_piecewise = dt * p1;
  // (a square root and a division the piecewise-noise update does without)
  c.noise_exact = (z == 0.0 || !want_exact_noise) ? dt
                                                  : dt * std::sqrt(em1 * (em1 + 2.0) / (2.0 * z));
  if (order == 2) {
    const double p2 = (std::fabs(z) < 1.0) ? phi2(z) : (em1 - z) / (z * z);
    c.current = dt * (p1 + p2);
    c.previous = -dt * p2;
  } else {
    c.current = dt * p1;
    c.previous = 0.0;
  }
  return c;
}

// First order with the piecewise noise, written with the total force F = m A - Gamma v (the
// pair style's force, its diagonal friction included):
//   e^z v + dt phi1(z) (F + Gamma v)/m = v + dt phi1(z) F/m,   since dt phi1(z) Gamma/m = -(e^z - 1).
// The update is an explicit Euler step whose length dt phi1(z) <= dt shrinks where the friction
// is stiff; this returns that effective step (one expm1, no decay factor needed).
ETD_HOST_DEVICE inline double first_order_effective_step(double friction_rate, double dt)
{
  const double z = -friction_rate * dt;
  return (z == 0.0) ? dt : std::expm1(z) / (-friction_rate);
}

}    // namespace etd

#endif
