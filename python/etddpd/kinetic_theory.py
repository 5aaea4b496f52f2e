"""Kinetic-theory transport coefficients of a DPD fluid with the dissipative weight
w_D = (1 - r/rc)^s, and the inverse problem: the (s, gamma) that give a fluid a prescribed
viscosity and Schmidt number (or particle diffusion time).

The Python twin of src/kernels/kinetic_theory.h: the same functions under the same names, tied
to it by unittest/python/test_kinetic_theory.py, which checks the values that
unittest/test_kinetic_theory.cpp checks in C++.

  [w_D]     = 4 pi int_0^rc r^2 w_D dr = 8 pi rc^3 / ((s+1)(s+2)(s+3))
  [r^2 w_D] = 4 pi int_0^rc r^4 w_D dr = 96 pi rc^5 / ((s+1)(s+2)(s+3)(s+4)(s+5))
  eta       = 3 m kBT / (2 gamma [w_D])  +  gamma n^2 [r^2 w_D] / 30   (kinetic + dissipative)
  D         = 3 kBT / (gamma n [w_D]),   Sc = eta / (m n D)
  tau_P     = R^2 / D with the Stokes-Einstein radius R = kBT / (6 pi eta D)
  E         = 6 kBT m n^2 rc^2 Sc / (5 eta^2); s = (-9 + sqrt(1 + 4E)) / 2 for E > 20

For s = 1/2 the viscosity is Phan-Thien, Mai-Duy and Khoo's eq 22,
eta = 315 m kBT / (128 pi gamma rc^3) + 512 pi gamma n^2 rc^5 / 51975.
"""
import math
from typing import NamedTuple

# std::cbrt's twin (math.cbrt is Python 3.11's; the power is the fallback for older ones)
_cbrt = getattr(math, 'cbrt', lambda x: x ** (1.0 / 3.0))

# E must exceed this for a positive exponent s (E = 20 is s = 0, a flat weight).
MIN_DESIGN_PARAMETER = 20.0


class FluidState(NamedTuple):
    """The state the estimates refer to (the fields of etd::kinetic::FluidState)."""
    number_density: float    # n
    mass: float              # m
    temperature: float       # kBT (energy units)
    cutoff: float            # rc of the dissipative weight


class Design(NamedTuple):
    feasible: bool    # E > 20
    e: float          # design parameter E
    s: float          # exponent of w_D (only if feasible)
    gamma: float      # friction coefficient (only if feasible)


def dissipative_weight_integral(s, rc):
    """4 pi int_0^rc r^2 (1 - r/rc)^s dr"""
    return 8.0 * math.pi * rc * rc * rc / ((s + 1.0) * (s + 2.0) * (s + 3.0))


def dissipative_weight_second_moment(s, rc):
    """4 pi int_0^rc r^4 (1 - r/rc)^s dr"""
    return 96.0 * math.pi * rc**5 / ((s + 1.0) * (s + 2.0) * (s + 3.0) * (s + 4.0) * (s + 5.0))


def kinetic_viscosity(f, gamma, s):
    return 3.0 * f.mass * f.temperature / (2.0 * gamma * dissipative_weight_integral(s, f.cutoff))


def dissipative_viscosity(f, gamma, s):
    return (gamma * f.number_density * f.number_density
            * dissipative_weight_second_moment(s, f.cutoff) / 30.0)


def viscosity(f, gamma, s):
    return kinetic_viscosity(f, gamma, s) + dissipative_viscosity(f, gamma, s)


def diffusivity(f, gamma, s):
    return 3.0 * f.temperature / (gamma * f.number_density * dissipative_weight_integral(s, f.cutoff))


def schmidt_number(f, gamma, s):
    return viscosity(f, gamma, s) / (f.mass * f.number_density * diffusivity(f, gamma, s))


def particle_diffusion_time(temperature, eta, diffusivity):
    """Time to diffuse one Stokes-Einstein radius, R^2 / D with R = kBT / (6 pi eta D)."""
    return temperature * temperature / (36.0 * math.pi**2 * diffusivity**3 * eta * eta)


def particle_diffusion_time_from_schmidt(f, eta, sc):
    """The same time written with rho = m n and Sc = eta / (rho D)."""
    rho_sc = f.mass * f.number_density * sc
    return rho_sc**3 * f.temperature * f.temperature / (36.0 * math.pi**2 * eta**5)


def schmidt_from_particle_diffusion_time(f, eta, tau_p):
    return _cbrt(36.0 * math.pi**2 * eta**5 * tau_p / (f.temperature * f.temperature)) / (
        f.mass * f.number_density)


def correlation_length(f, gamma, s):
    """Dynamic correlation length l0 = v0 / omega0 with omega0 = n [w_D] gamma / (3 m): below rc
    is the collective regime."""
    omega0 = f.number_density * dissipative_weight_integral(s, f.cutoff) * gamma / (3.0 * f.mass)
    return math.sqrt(f.temperature / f.mass) / omega0


# ---- inverse problem -------------------------------------------------------------------

def design_parameter(f, eta, tau_p):
    """E of the quadratic s^2 + 9 s + 20 - E = 0 for a target dissipative viscosity and tau_P."""
    kt = f.temperature
    return (6.0 * kt * f.number_density * f.cutoff * f.cutoff / (5.0 * eta)
            * _cbrt(36.0 * math.pi**2 * eta * eta * tau_p / (kt * kt)))


def design_parameter_from_schmidt(f, eta, sc):
    """The same E from the Schmidt number (the cube root cancels exactly)."""
    n = f.number_density
    return 6.0 * f.temperature * f.mass * n * n * f.cutoff * f.cutoff * sc / (5.0 * eta * eta)


def exponent_from_design_parameter(e):
    """Positive root of s^2 + 9 s + 20 - E = 0 (meaningful for E > 20 only)."""
    return 0.5 * (-9.0 + math.sqrt(1.0 + 4.0 * e))


def friction_for_viscosity(f, eta, s):
    """gamma that makes the dissipative viscosity equal eta for exponent s."""
    n = f.number_density
    return (5.0 * eta * (s + 1.0) * (s + 2.0) * (s + 3.0) * (s + 4.0) * (s + 5.0)
            / (16.0 * math.pi * n * n * f.cutoff**5))


def min_particle_diffusion_time(f, eta):
    n = f.number_density
    return 31250.0 / (243.0 * math.pi**2) * eta / (f.temperature * n**3 * f.cutoff**6)


def max_viscosity_for_particle_diffusion_time(f, tau_p):
    n = f.number_density
    return 243.0 * math.pi**2 / 31250.0 * f.temperature * n**3 * f.cutoff**6 * tau_p


def min_schmidt_number(f, eta):
    n = f.number_density
    return 50.0 * eta * eta / (3.0 * f.temperature * f.mass * n * n * f.cutoff * f.cutoff)


def max_viscosity_for_schmidt(f, sc):
    n = f.number_density
    return math.sqrt(3.0 * f.temperature * f.mass * n * n * f.cutoff * f.cutoff * sc / 50.0)


def _design(f, eta, e):
    if not e > MIN_DESIGN_PARAMETER:
        return Design(False, e, 0.0, 0.0)
    s = exponent_from_design_parameter(e)
    return Design(True, e, s, friction_for_viscosity(f, eta, s))


def design_from_particle_diffusion_time(f, eta, tau_p):
    return _design(f, eta, design_parameter(f, eta, tau_p))


def design_from_schmidt(f, eta, sc):
    return _design(f, eta, design_parameter_from_schmidt(f, eta, sc))
