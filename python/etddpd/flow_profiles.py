#!/usr/bin/python3
"""Profiles of the wall-bounded flow examples (examples/couette, examples/poiseuille).

Reads the fix ave/chunk file the examples write (bins across z with vx vy vz, vx^2 vy^2 vz^2,
the per-atom shear stress s_xz and the number density), averages its blocks, and reports

  * the velocity profile against the analytic one: linear (Couette, walls at -U and +U) or the
    parabola u = n F (H^2/4 - z^2) / (2 eta) (Poiseuille, body force F per particle);
  * the slip length: how far beyond each wall the fitted profile reaches the wall velocity;
  * viscosities: from the shear stress over the shear rate (both flows) and, for Poiseuille,
    from the curvature of the fitted parabola, against the kinetic-theory estimate;
  * the temperature kBT = m <|v - u(z)|^2> / 3 and the density across the channel.

Writes a PNG (velocity, temperature and density against z) and prints a summary; --json also
writes the numbers.

  python/flow_profiles.py couette validation/flows/results/profile.couette --png couette.png
  python/flow_profiles.py poiseuille profile.poiseuille --mass 0.01 --force 0.1
"""
import argparse
import json
import math
import sys

import numpy as np

from . import kinetic_theory
from .lammps_output import LammpsOutputError, read_ave_chunk
from .statistics import standard_error


def parse_args(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    p.add_argument('case', choices=['couette', 'poiseuille'])
    p.add_argument('profile', help='fix ave/chunk output of the example')
    p.add_argument('--mass', type=float, default=0.01)
    p.add_argument('--kT', type=float, default=1.0)
    p.add_argument('--gamma', type=float, default=4.5, help='friction, sigma^2 / (2 kT)')
    p.add_argument('--s', type=float, default=0.5, help='dissipative weight exponent')
    p.add_argument('--n', type=float, default=4.0, help='number density of the fluid')
    p.add_argument('--rc', type=float, default=1.0)
    p.add_argument('--H', type=float, default=30.0, help='distance between the wall planes')
    p.add_argument('--U', type=float, default=7.5, help='Couette: wall speed (+U top, -U bottom)')
    p.add_argument('--force', type=float, default=0.1, help='Poiseuille: body force per particle')
    p.add_argument('--skip', type=int, default=1, help='blocks to discard at the start')
    p.add_argument('--margin', type=float, default=1.0,
                   help='bins closer than this to a wall are left out of the fits')
    p.add_argument('--png', help='write the profile plot here')
    p.add_argument('--title', default=None)
    p.add_argument('--json', help='write the numbers here')
    return p.parse_args(argv)


def read_profile(path, skip):
    """The blocks of the example's fix ave/chunk file after the first `skip`."""
    try:
        blocks = read_ave_chunk(path)
    except LammpsOutputError:
        sys.exit(f'flow_profiles: {path} is not a fix ave/chunk file with data')
    if blocks.names is None:
        sys.exit(f'flow_profiles: {path} is not a fix ave/chunk file with data')
    if skip >= len(blocks.steps):
        sys.exit(f'flow_profiles: {len(blocks.steps)} blocks, cannot skip {skip}')
    return blocks._replace(steps=blocks.steps[skip:], data=blocks.data[skip:])


def column(blocks, name):
    """One column of the blocks, array[block, bin]."""
    if name not in blocks.names:
        sys.exit(f'flow_profiles: column {name} missing (columns: {" ".join(blocks.names)})')
    return blocks.column(name)


def mean_and_error(per_block):
    """Mean over blocks and its standard error from the block-to-block scatter."""
    return per_block.mean(axis=0), standard_error(per_block)


def fit_couette(z, inner, u, shear_stress, half, U, eta_kt):
    """Linear fit of one velocity profile between walls at -U and +U: shear rate, slip
    lengths, the viscosity from the shear stress; and the fit's coefficients (c0, c1, c2)."""
    slope, offset = np.polyfit(z[inner], u[inner], 1)
    slip_top = (U - (offset + slope * half)) / slope
    slip_bottom = ((offset - slope * half) + U) / slope
    eta_stress = float(np.mean(shear_stress[inner]) / slope)
    return {
        'shear_rate_fit': slope, 'u_centre_fit': offset,
        'slip_length_top': slip_top, 'slip_length_bottom': slip_bottom,
        'slip_length': 0.5 * (slip_top + slip_bottom),
        'shear_stress_inner': float(np.mean(shear_stress[inner])),
        'eta_from_stress': eta_stress,
        'eta_stress_vs_kinetic_theory': eta_stress / eta_kt - 1.0,
    }, (offset, slope, 0.0)


def fit_poiseuille(z, inner, u, shear_stress, n_inner, half, n, force, eta_kt):
    """Parabola u = top + tilt z + curvature z^2 fitted to one velocity profile: the viscosity
    from its curvature and from the slope of the shear stress, the slip length; and the fit's
    coefficients (c0, c1, c2)."""
    curvature, tilt, top = np.polyfit(z[inner], u[inner], 2)
    B = -curvature
    body = n_inner * force                                        # force per volume
    eta_fit = body / (2.0 * B)
    eta_fit_nominal = n * force / (2.0 * B)
    zero = math.sqrt(top / B) if top > 0 and B > 0 else float('nan')
    # momentum balance: d sigma_xz / dz = -n F; with du/dz = -2 B z, eta = slope / (-2 B)
    stress_slope, _ = np.polyfit(z[inner], shear_stress[inner], 1)
    eta_stress = stress_slope / (-2.0 * B)
    return {
        'u_max_fit': top, 'curvature_B': B, 'tilt': tilt,
        'eta_from_parabola': eta_fit, 'eta_from_parabola_n_nominal': eta_fit_nominal,
        'eta_parabola_vs_kinetic_theory': eta_fit / eta_kt - 1.0,
        'eta_parabola_nominal_vs_kinetic_theory': eta_fit_nominal / eta_kt - 1.0,
        'slip_length': zero - half,
        'stress_slope': stress_slope, 'stress_slope_expected': -body,
        'eta_from_stress': eta_stress,
        'eta_stress_vs_kinetic_theory': eta_stress / eta_kt - 1.0,
    }, (top, tilt, curvature)


def analyse(a, blocks):
    """The summary of the profiles (a dict, in print order) and what the plot needs."""
    z = column(blocks, 'Coord1')[0]
    count = column(blocks, 'Ncount')
    vel = [column(blocks, c) for c in ('vx', 'vy', 'vz')]
    sq = [column(blocks, c) for c in ('v_vx2', 'v_vy2', 'v_vz2')]
    density = column(blocks, 'density/number')
    stress = density * column(blocks, 'c_stress[5]')              # sigma_xz(z), per block
    steps = blocks.steps

    # kBT from the peculiar velocity, per block: m (<v^2> - <v>^2) / 3
    temperature = a.mass * sum(s - v * v for s, v in zip(sq, vel)) / 3.0
    u, u_err = mean_and_error(vel[0])
    kT_z, kT_err = mean_and_error(temperature)
    n_z, n_err = mean_and_error(density)
    shear_stress, _ = mean_and_error(stress)
    weights = count.mean(axis=0)
    fluid_kT = float(np.sum(weights * kT_z) / np.sum(weights))

    half = a.H / 2.0
    inner = np.abs(z) <= half - a.margin
    eta_kt = kinetic_theory.viscosity(kinetic_theory.FluidState(a.n, a.mass, a.kT, a.rc), a.gamma, a.s)
    n_inner = float(n_z[inner].mean())
    result = {
        'case': a.case, 'profile': a.profile, 'blocks_used': int(len(steps)),
        'steps': [int(steps[0]), int(steps[-1])], 'mass': a.mass,
        'eta_kinetic_theory': eta_kt, 'kT_fluid': fluid_kT,
        'kT_inner': float(np.mean(kT_z[inner])),
        'kT_min': float(kT_z.min()), 'kT_max': float(kT_z.max()),
        'n_inner': n_inner, 'n_min': float(n_z.min()), 'n_max': float(n_z.max()),
    }

    def fit(u, shear_stress, n_inner):
        if a.case == 'couette':
            return fit_couette(z, inner, u, shear_stress, half, a.U, eta_kt)
        return fit_poiseuille(z, inner, u, shear_stress, n_inner, half, a.n, a.force, eta_kt)

    if a.case == 'couette':
        result.update({'wall_speed': a.U, 'shear_rate_nominal': 2.0 * a.U / a.H})
    else:
        result.update({'force': a.force,
                       'u_max_kinetic_theory': a.n * a.force * half**2 / (2 * eta_kt)})
    fitted_mean, coefficients = fit(u, shear_stress, n_inner)
    # standard errors of the fitted numbers from the scatter of the same fit over the blocks
    per_block = [fit(vel[0][b], stress[b], float(density[b][inner].mean()))[0]
                 for b in range(len(steps))]
    for k, v in fitted_mean.items():
        result[k] = v
        if len(per_block) > 1:
            result[k + '_err'] = float(standard_error([pb[k] for pb in per_block]))
    profiles = {'z': z, 'u': u, 'u_err': u_err, 'kT': kT_z, 'kT_err': kT_err, 'n': n_z,
                'n_err': n_err, 'eta_kt': eta_kt, 'coefficients': coefficients, 'steps': steps}
    return result, profiles


def print_summary(result):
    width = max(len(k) for k in result)
    for k, v in result.items():
        print(f'{k:<{width}}  {v:.6g}' if isinstance(v, float) else f'{k:<{width}}  {v}')


def plot(a, result, p):
    """Velocity against the analytic and fitted profiles, temperature and density across z."""
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    half = a.H / 2.0
    zz = np.linspace(-half, half, 201)
    c0, c1, c2 = p['coefficients']
    fitted = c0 + c1 * zz + c2 * zz**2
    if a.case == 'couette':
        analytic = a.U * zz / half
        fit_label = f'linear fit, slip length {result["slip_length"]:.2f}'
    else:
        analytic = a.n * a.force * (half**2 - zz**2) / (2.0 * p['eta_kt'])
        fit_label = f'parabola fit, eta = {result["eta_from_parabola"]:.3f}'
    z = p['z']
    fig, ax = plt.subplots(1, 3, figsize=(11, 3.4))
    ax[0].errorbar(z, p['u'], yerr=p['u_err'], fmt='.', ms=3, color='k', label='ETD-DPD')
    ax[0].plot(zz, analytic, 'r-', lw=1.2,
               label='analytic, no slip' + ('' if a.case == 'couette' else ', kinetic-theory eta'))
    ax[0].plot(zz, fitted, 'b--', lw=1.0, label=fit_label)
    ax[0].set_ylabel('u_x')
    ax[0].legend(fontsize=7, loc='best')
    ax[1].errorbar(z, p['kT'], yerr=p['kT_err'], fmt='.', ms=3, color='k')
    ax[1].axhline(a.kT, color='r', lw=1.0)
    ax[1].set_ylabel('kBT = m <|v - u|^2> / 3')
    ax[2].errorbar(z, p['n'], yerr=p['n_err'], fmt='.', ms=3, color='k')
    ax[2].axhline(a.n, color='r', lw=1.0)
    ax[2].set_ylabel('number density')
    for axis in ax:
        axis.set_xlabel('z')
        axis.axvline(-half + a.margin, color='0.7', lw=0.6, ls=':')
        axis.axvline(half - a.margin, color='0.7', lw=0.6, ls=':')
    steps = p['steps']
    title = a.title or f'{a.case}, m = {a.mass:g}, steps {steps[0]}-{steps[-1]}'
    fig.suptitle(title, fontsize=9)
    fig.tight_layout()
    fig.savefig(a.png, dpi=90)
    print(f'wrote {a.png}')


def main(argv=None):
    a = parse_args(argv)
    result, profiles = analyse(a, read_profile(a.profile, a.skip))
    print_summary(result)
    if a.json:
        with open(a.json, 'w') as f:
            json.dump(result, f, indent=1)
    if a.png:
        plot(a, result, profiles)


if __name__ == '__main__':
    main()
