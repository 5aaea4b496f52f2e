#!/usr/bin/python3
"""Post-processing of the dpd/fpm validation runs (tools/validate_fpm.sh).

  fpm_analysis.py DIR [--L L] [--rho RHO] [--g G] [--omega OMEGA]

Reads DIR/fpm_viscosity.profile, DIR/fpm_diffusion.track and DIR/fpm_rotating_sphere.torque
(whichever exist) and prints a Markdown table side by side with Pan, Pivkin and Karniadakis,
EPL 84, 10012 (2008): viscosity 3.6388, D = 0.0533, R = 0.2737, torque within 1.3 % of Stokes.
"""
import argparse
import math
import os

import numpy as np

PAPER_MU, PAPER_D, PAPER_R = 3.6388, 0.0533, 0.2737
KT = 1.0
HASIMOTO = 2.837297    # finite-size correction of D in a periodic cube (Hasimoto; Yeh and Hummer)


def read_last_chunk_block(path):
    """Last block of a fix ave/chunk file: rows of (chunk, coord, count, values...)."""
    blocks, current = [], None
    with open(path) as fh:
        for line in fh:
            if line.startswith('#'):
                continue
            fields = line.split()
            if len(fields) == 3:
                current = []
                blocks.append(current)
            else:
                current.append([float(x) for x in fields])
    return np.array(blocks[-1])


def viscosity(path, rho, g):
    """Reverse Poiseuille: in each half v = +-rho g/(2 eta) z'(h - z') + v0; eta from each half."""
    data = read_last_chunk_block(path)
    z, vx = data[:, 1], data[:, 3]
    lz = z[-1] + (z[1] - z[0]) / 2
    h = lz / 2
    etas = []
    for sign, sel in ((+1, z < h), (-1, z >= h)):
        zp = z[sel] - (0 if sign > 0 else h)
        basis = np.vstack([zp * (h - zp), np.ones_like(zp)]).T
        (c, v0), *_ = np.linalg.lstsq(basis, sign * vx[sel], rcond=None)
        etas.append(rho * g / (2 * c))
    eta = float(np.mean(etas))
    return eta, abs(etas[0] - etas[1]) / 2, float(np.max(np.abs(vx)))


def diffusion(path, dt_frame, fit_from, fit_to, ngroups=5):
    """MSD of the tracked atoms with every time origin; D from the slope over [fit_from, fit_to]."""
    frames, current, reading = [], None, False
    with open(path) as fh:
        for line in fh:
            if line.startswith('ITEM: ATOMS'):
                current = []
                frames.append(current)
                reading = True
                continue
            if line.startswith('ITEM:'):
                reading = False
                continue
            if reading:
                current.append([float(x) for x in line.split()[1:4]])
    pos = np.array(frames)    # (frames, atoms, 3), unwrapped
    nframes, natoms = pos.shape[0], pos.shape[1]
    lags = np.arange(1, int(fit_to / dt_frame) + 1)
    msd = np.array([np.mean(np.sum((pos[lag:] - pos[:-lag]) ** 2, axis=2), axis=0) for lag in lags])
    t = lags * dt_frame
    fit = (t >= fit_from) & (t <= fit_to)

    def slope_d(per_atom):
        y = per_atom.mean(axis=1) if per_atom.ndim == 2 else per_atom
        return np.polyfit(t[fit], y[fit], 1)[0] / 6

    d_all = slope_d(msd)
    groups = np.array_split(np.arange(natoms), ngroups)
    d_groups = [slope_d(msd[:, gidx]) for gidx in groups]
    return d_all, float(np.std(d_groups, ddof=1) / math.sqrt(ngroups)), natoms, nframes * dt_frame


def torque(path, skip_blocks=0):
    values = np.loadtxt(path, comments='#')
    tz = values[skip_blocks:, 3]
    return float(tz.mean()), float(tz.std(ddof=1) / math.sqrt(len(tz))), len(tz)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('dir')
    ap.add_argument('--rho', type=float, default=3.0)
    ap.add_argument('--g', type=float, default=0.05)
    ap.add_argument('--L', type=float, default=10.0, help='box side of the diffusion run')
    ap.add_argument('--omega', type=float, default=-2.0)
    ap.add_argument('--frame', type=float, default=0.5, help='time between track frames')
    ap.add_argument('--fit', type=float, nargs=2, default=(5.0, 25.0))
    ap.add_argument('--torque', nargs=3, action='append', default=[], metavar=('LABEL', 'FILE', 'OMEGA'),
                    help='extra torque block file (e.g. a time-step scan) to report against Stokes with the '
                         "paper's mu and R; repeatable")
    a = ap.parse_args()
    rows = []
    mu = PAPER_MU
    f = os.path.join(a.dir, 'fpm_viscosity.profile')
    if os.path.exists(f):
        mu, err, vmax = viscosity(f, a.rho, a.g)
        rows.append(('fluid viscosity mu (reverse Poiseuille)', f'{PAPER_MU}', f'{mu:.4f} +- {err:.4f}',
                     f'{100 * (mu / PAPER_MU - 1):+.1f} %'))
        print(f'# viscosity: max |v| = {vmax:.3f}, halves differ by {2 * err:.4f}')
    R = PAPER_R
    f = os.path.join(a.dir, 'fpm_diffusion.track')
    if os.path.exists(f):
        d, derr, n, span = diffusion(f, a.frame, *a.fit)
        d_inf = d + HASIMOTO * KT / (6 * math.pi * mu * a.L)
        R = KT / (6 * math.pi * mu * d_inf)
        r_box = KT / (6 * math.pi * mu * d)
        rows.append((f'colloid D in the periodic box L = {a.L:g}', '', f'{d:.4f} +- {derr:.4f}', ''))
        rows.append(('colloid D, finite-size corrected (Hasimoto)', f'{PAPER_D}', f'{d_inf:.4f} +- {derr:.4f}',
                     f'{100 * (d_inf / PAPER_D - 1):+.1f} %'))
        rows.append(('Stokes-Einstein radius R = kBT/(6 pi mu D)', f'{PAPER_R}',
                     f'{R:.4f} +- {R * derr / d_inf:.4f} (uncorrected D: {r_box:.4f})',
                     f'{100 * (R / PAPER_R - 1):+.1f} %'))
        print(f'# diffusion: {n} colloids over {span:g} time units, MSD slope fitted on {a.fit}')
    f = os.path.join(a.dir, 'fpm_rotating_sphere.torque')
    if os.path.exists(f):
        t, terr, nb = torque(f)
        stokes_paper = -8 * math.pi * PAPER_MU * a.omega * PAPER_R ** 3
        stokes_ours = -8 * math.pi * mu * a.omega * R ** 3
        rows.append((f'torque on a sphere spun at Omega = {a.omega:g}: T / (-8 pi mu Omega R^3), '
                     'paper mu and R', '1 (within 1.3 %)', f'{t / stokes_paper:.3f} +- {terr / stokes_paper:.3f}',
                     f'T = {t:.3f} +- {terr:.3f}, Stokes {stokes_paper:.3f}'))
        rows.append(('same, with the mu and R measured here', '1', f'{t / stokes_ours:.3f} +- {terr / stokes_ours:.3f}',
                     f'Stokes {stokes_ours:.3f}'))
        print(f'# torque: {nb} blocks')
    for label, path, omega in a.torque:
        t, terr, nb = torque(path)
        stokes = -8 * math.pi * PAPER_MU * float(omega) * PAPER_R ** 3
        rows.append((f'torque T / (-8 pi mu Omega R^3), {label}, Omega = {float(omega):g}, {nb} blocks',
                     '1 (within 1.3 %)', f'{t / stokes:.3f} +- {terr / abs(stokes):.3f}',
                     f'T = {t:.3f} +- {terr:.3f}, Stokes {stokes:.3f}'))
    print('| quantity | paper | this package | difference |')
    print('|---|---|---|---|')
    for r in rows:
        print('| ' + ' | '.join(r) + ' |')


if __name__ == '__main__':
    main()
