// ETD-DPD: kinetic-theory transport coefficients of a DPD fluid with the generalised
// dissipative weight w_D = (1 - r/rc)^s, and the inverse problem: the (s, gamma) that give a
// fluid a prescribed viscosity and Schmidt number (or particle diffusion time).
//
// Sources (Marsh's kinetic theory as used by Mai-Duy, Phan-Thien and Tran-Cong):
//   [w_D]       = 4 pi int_0^rc r^2 w_D dr = 8 pi rc^3 / ((s+1)(s+2)(s+3))
//   [r^2 w_D]   = 4 pi int_0^rc r^4 w_D dr = 96 pi rc^5 / ((s+1)(s+2)(s+3)(s+4)(s+5))
//   eta         = 3 m kBT / (2 gamma [w_D])   +   gamma n^2 [r^2 w_D] / 30
//                 (kinetic part)                  (dissipative part)
//   D           = 3 kBT / (gamma n [w_D]),    Sc = eta / (m n D)
//   tau_P       = R^2 / D with the Stokes-Einstein radius R = kBT / (6 pi eta D)
//               = kBT^2 / (36 pi^2 D^3 eta^2) = rho^3 Sc^3 kBT^2 / (36 pi^2 eta^5)
// The inverse problem imposes the dissipative part of eta (the kinetic part is small in the
// collective regime; design_report() says how small) and D through tau_P, which leaves the
// quadratic s^2 + 9 s + 20 - E = 0 with
//   E = (6 kBT n rc^2 / (5 eta)) cbrt(36 pi^2 eta^2 tau_P / kBT^2) = 6 kBT m n^2 rc^2 Sc / (5 eta^2)
// Its positive root s = (-9 + sqrt(1 + 4E))/2 exists only for E > 20 (s > 0); E <= 20 is a
// fluid that no positive exponent can make.
#ifndef ETD_KINETIC_THEORY_H
#define ETD_KINETIC_THEORY_H

#include <cmath>

namespace etd {
namespace kinetic {

  constexpr double pi = 3.14159265358979323846;

  // E must exceed this for a positive exponent s (E = 20 is s = 0, a flat weight).
  constexpr double min_design_parameter = 20.0;

  // State of the fluid the estimates refer to.
  struct FluidState {
    double number_density;    // n
    double mass;              // m
    double temperature;       // kBT (energy units)
    double cutoff;            // rc of the dissipative weight
  };

  // 4 pi int_0^rc r^2 (1 - r/rc)^s dr
  inline double dissipative_weight_integral(double s, double rc)
  {
    return 8.0 * pi * rc * rc * rc / ((s + 1.0) * (s + 2.0) * (s + 3.0));
  }

  // 4 pi int_0^rc r^4 (1 - r/rc)^s dr
  inline double dissipative_weight_second_moment(double s, double rc)
  {
    return 96.0 * pi * std::pow(rc, 5) /
        ((s + 1.0) * (s + 2.0) * (s + 3.0) * (s + 4.0) * (s + 5.0));
  }

  inline double kinetic_viscosity(const FluidState &f, double gamma, double s)
  {
    return 3.0 * f.mass * f.temperature / (2.0 * gamma * dissipative_weight_integral(s, f.cutoff));
  }

  inline double dissipative_viscosity(const FluidState &f, double gamma, double s)
  {
    return gamma * f.number_density * f.number_density *
        dissipative_weight_second_moment(s, f.cutoff) / 30.0;
  }

  inline double viscosity(const FluidState &f, double gamma, double s)
  {
    return kinetic_viscosity(f, gamma, s) + dissipative_viscosity(f, gamma, s);
  }

  inline double diffusivity(const FluidState &f, double gamma, double s)
  {
    return 3.0 * f.temperature /
        (gamma * f.number_density * dissipative_weight_integral(s, f.cutoff));
  }

  inline double schmidt_number(const FluidState &f, double gamma, double s)
  {
    return viscosity(f, gamma, s) / (f.mass * f.number_density * diffusivity(f, gamma, s));
  }

  // Time to diffuse one Stokes-Einstein radius, R^2 / D with R = kBT / (6 pi eta D).
  inline double particle_diffusion_time(double temperature, double eta, double diffusivity)
  {
    return temperature * temperature /
        (36.0 * pi * pi * diffusivity * diffusivity * diffusivity * eta * eta);
  }

  // The same time written with rho = m n and Sc = eta / (rho D).
  inline double particle_diffusion_time_from_schmidt(const FluidState &f, double eta, double sc)
  {
    const double rho_sc = f.mass * f.number_density * sc;
    return rho_sc * rho_sc * rho_sc * f.temperature * f.temperature /
        (36.0 * pi * pi * std::pow(eta, 5));
  }

  inline double schmidt_from_particle_diffusion_time(const FluidState &f, double eta, double tau_p)
  {
    return std::cbrt(36.0 * pi * pi * std::pow(eta, 5) * tau_p / (f.temperature * f.temperature)) /
        (f.mass * f.number_density);
  }

  // Dynamic correlation length l0 = v0 t0: thermal speed times the collision time
  // 1/omega0, omega0 = n [w_D] gamma / (3 m). l0 < rc is the collective regime.
  inline double correlation_length(const FluidState &f, double gamma, double s)
  {
    const double omega0 =
        f.number_density * dissipative_weight_integral(s, f.cutoff) * gamma / (3.0 * f.mass);
    return std::sqrt(f.temperature / f.mass) / omega0;
  }

  // ---- inverse problem -------------------------------------------------------------------

  // E of the quadratic s^2 + 9 s + 20 - E = 0 for a target dissipative viscosity and tau_P.
  inline double design_parameter(const FluidState &f, double eta, double tau_p)
  {
    const double kt = f.temperature;
    return 6.0 * kt * f.number_density * f.cutoff * f.cutoff / (5.0 * eta) *
        std::cbrt(36.0 * pi * pi * eta * eta * tau_p / (kt * kt));
  }

  // The same E from the Schmidt number (the cube root cancels exactly).
  inline double design_parameter_from_schmidt(const FluidState &f, double eta, double sc)
  {
    const double n = f.number_density;
    return 6.0 * f.temperature * f.mass * n * n * f.cutoff * f.cutoff * sc / (5.0 * eta * eta);
  }

  // Positive root of s^2 + 9 s + 20 - E = 0 (meaningful for E > 20 only).
  inline double exponent_from_design_parameter(double e)
  {
    return 0.5 * (-9.0 + std::sqrt(1.0 + 4.0 * e));
  }

  // gamma that makes the dissipative viscosity equal eta for exponent s.
  inline double friction_for_viscosity(const FluidState &f, double eta, double s)
  {
    const double n = f.number_density;
    return 5.0 * eta * (s + 1.0) * (s + 2.0) * (s + 3.0) * (s + 4.0) * (s + 5.0) /
        (16.0 * pi * n * n * std::pow(f.cutoff, 5));
  }

  // Feasibility bounds (E > 20), each with the other targets held fixed.
  inline double min_particle_diffusion_time(const FluidState &f, double eta)
  {
    const double n = f.number_density;
    return 31250.0 / (243.0 * pi * pi) * eta / (f.temperature * n * n * n * std::pow(f.cutoff, 6));
  }

  inline double max_viscosity_for_particle_diffusion_time(const FluidState &f, double tau_p)
  {
    const double n = f.number_density;
    return 243.0 * pi * pi / 31250.0 * f.temperature * n * n * n * std::pow(f.cutoff, 6) * tau_p;
  }

  inline double min_schmidt_number(const FluidState &f, double eta)
  {
    const double n = f.number_density;
    return 50.0 * eta * eta / (3.0 * f.temperature * f.mass * n * n * f.cutoff * f.cutoff);
  }

  inline double max_viscosity_for_schmidt(const FluidState &f, double sc)
  {
    const double n = f.number_density;
    return std::sqrt(3.0 * f.temperature * f.mass * n * n * f.cutoff * f.cutoff * sc / 50.0);
  }

  struct Design {
    bool feasible;    // E > 20
    double e;         // design parameter E
    double s;         // exponent of w_D (only if feasible)
    double gamma;     // friction coefficient (only if feasible)
  };

  inline Design design_from_particle_diffusion_time(const FluidState &f, double eta, double tau_p)
  {
    Design d{false, design_parameter(f, eta, tau_p), 0.0, 0.0};
    if (!(d.e > min_design_parameter)) return d;
    d.feasible = true;
    d.s = exponent_from_design_parameter(d.e);
    d.gamma = friction_for_viscosity(f, eta, d.s);
    return d;
  }

  inline Design design_from_schmidt(const FluidState &f, double eta, double sc)
  {
    Design d{false, design_parameter_from_schmidt(f, eta, sc), 0.0, 0.0};
    if (!(d.e > min_design_parameter)) return d;
    d.feasible = true;
    d.s = exponent_from_design_parameter(d.e);
    d.gamma = friction_for_viscosity(f, eta, d.s);
    return d;
  }

}    // namespace kinetic
}    // namespace etd

#endif
