#!/usr/bin/python3
"""Post-processing of the dpd/fpm validation runs (validation/fpm/run.sh).

  fpm_analysis.py DIR [--L L] [--rho RHO] [--g G] [--omega OMEGA]
                  [--drag LABEL FILE L G NFLUID] [--couette LABEL PREFIX]
                  [--poiseuille LABEL PREFIX G H h] [--pair LABEL FILE L G NFLUID l]

Reads DIR/fpm_viscosity.profile, DIR/fpm_diffusion.track and DIR/fpm_rotating_sphere.torque
(whichever exist) and prints a Markdown table side by side with Pan, Pivkin and Karniadakis,
EPL 84, 10012 (2008): viscosity 3.6388, D = 0.0533, R = 0.2737, torque within 1.3 % of Stokes.
"""
import argparse
import math
import os

import numpy as np

from .lammps_output import read_ave_chunk, read_ave_time, read_dump
from .statistics import batch_means, standard_error

PAPER_MU, PAPER_D, PAPER_R = 3.6388, 0.0533, 0.2737
KT = 1.0
HASIMOTO = 2.837297    # finite-size correction of D in a periodic cube (Hasimoto; Yeh and Hummer)


def read_last_chunk_block(path):
    """Last block of a fix ave/chunk file: rows of (chunk, coord, count, values...)."""
    return read_ave_chunk(path).data[-1]


def read_blocks(path):
    """The rows of a fix ave/time file: step, then the values."""
    return read_ave_time(path).data


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
    pos = read_dump(path).data[:, :, 1:4]    # (frames, atoms, 3): id xu yu zu, unwrapped
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
    return d_all, float(standard_error(d_groups)), natoms, nframes * dt_frame


def torque(path, skip_blocks=0):
    tz = read_blocks(path)[skip_blocks:, 3]
    return float(tz.mean()), float(standard_error(tz)), len(tz)


def dissipative_torque(path, skip_blocks=0):
    """Mean and error of the z torque's dissipative part (column 4 of a rotating-sphere file
    written with compute dpd/split torque yes), or None for files without it."""
    d = read_blocks(path)[skip_blocks:]
    if d.shape[1] < 5:
        return None
    return float(d[:, 4].mean()), float(standard_error(d[:, 4]))


def batch_mean(x, nbatch=20):
    """Mean and standard error from nbatch consecutive batches (blocks may be correlated)."""
    x = np.asarray(x, dtype=float)
    return float(x.mean()), float(standard_error(batch_means(x, nbatch)))


def hasimoto_k(phi):
    """Drag on a simple cubic array over 6 pi mu u R (Hasimoto 1959; coefficients as in Sangani
    and Acrivos 1982): 1/K = 1 - 1.7601 phi^(1/3) + phi - 1.5593 phi^2."""
    return 1.0 / (1.0 - 1.7601 * phi ** (1 / 3) + phi - 1.5593 * phi ** 2)


def drag_radius(zeta, mu, L):
    """Radius R with 6 pi mu R K(phi(R)) = zeta (fixed point)."""
    r = zeta / (6 * math.pi * mu)
    for _ in range(100):
        r = zeta / (6 * math.pi * mu * hasimoto_k(4 * math.pi * r ** 3 / (3 * L ** 3)))
    return r


def periodic_drag(path, L, g, nfluid, mu=PAPER_MU, R=PAPER_R, dt=0.01):
    """Fixed colloid in a periodic cube, fluid driven by g per fluid atom. Columns of the block
    file: step, fluid <v_x>, colloid f_x, f_y, f_z, torque_y, fluid kBT about its mean flow."""
    d = read_blocks(path)
    natoms = nfluid + 1
    u, uerr = batch_mean(d[:, 1] * nfluid / natoms)       # superficial velocity
    fd, fderr = batch_mean(d[:, 2])                        # measured force on the colloid
    force = nfluid * g                                     # steady-state momentum balance
    # the fluid's total momentum is the slow variable: variance kBT / M, relaxation time
    # tau = M u / F; the standard error of its mean over a run t is sqrt(kBT/M) sqrt(2 tau / t).
    # Batches shorter than a few tau underestimate it, so the larger of the two is used.
    t_run = (d[-1, 0] - d[0, 0] + (d[1, 0] - d[0, 0])) * dt
    tau = nfluid * u / force
    uerr_model = math.sqrt(KT / nfluid) * math.sqrt(2 * tau / t_run) * nfluid / natoms
    uerr = max(uerr, uerr_model)
    phi = 4 * math.pi * R ** 3 / (3 * L ** 3)
    k = hasimoto_k(phi)
    stokes = 6 * math.pi * mu * u * R
    return dict(u=u, uerr=uerr, tau=tau, uerr_model=uerr_model, F=force, Fd=fd, Fderr=fderr, phi=phi, K=k, stokes=stokes,
                ratio=force / (stokes * k), ratio_err=force / (stokes * k) * uerr / u,
                ratio_d=fd / (stokes * k), ratio_d_err=fderr / (stokes * k),
                R_drag=drag_radius(force / u, mu, L), T=float(d[:, 6].mean()), nblocks=len(d),
                Re=3.0 * u * R / mu)


def read_profile(path):
    """Single-block fix ave/chunk file: z, count, values."""
    data = read_last_chunk_block(path)
    return data[:, 1], data[:, 3:]


def couette(prefix, H, zfit=2.5, mu=PAPER_MU, R=PAPER_R):
    """Fixed (Omega = 0) and freely spinning colloids in Couette flow. Shear rate from a linear
    fit of the fluid's v_x(z) over |z| < zfit; torque against 8 pi mu R^3 (1/2)(curl v)."""
    z, vals = read_profile(prefix + '.profile')
    vx = vals[:, 0]
    sel = np.abs(z) < zfit
    rate, v0 = np.polyfit(z[sel], vx[sel], 1)
    d = read_blocks(prefix + '.colloid')
    t, terr = batch_mean(d[:, 2])
    w, werr = batch_mean(d[:, 3])
    half = rate / 2
    t_the = 8 * math.pi * mu * R ** 3 * half
    out = dict(rate=rate, v0=v0, half=half, T=t, Terr=terr, T_the=t_the, Omega=w, Omega_err=werr,
               wall_v=(np.polyval([rate, v0], -H / 2), np.polyval([rate, v0], H / 2)),
               Ty=float(d[:, 4].mean()), Trot=float(d[:, 5].mean()), nblocks=len(d),
               Re=3.0 * half * R ** 2 / mu, spun=bool(np.all(d[:, 3] == d[0, 3])))
    if os.path.exists(prefix + '.split'):
        # the torques' dissipative parts (compute dpd/split torque yes): fixed colloids, and the
        # even colloids' total and dissipative torque (spun at a fixed Omega with even_mode spun).
        # With Omega the even colloids' spin, T_fixed - T_even = B Omega: the rotational friction
        # measured in the shear flow itself, in units of 8 pi mu R^3 below.
        sp = read_blocks(prefix + '.split')
        out['TD'], out['TDerr'] = batch_mean(sp[:, 1])
        out['T_even'], out['T_even_err'] = batch_mean(sp[:, 2])
        out['TD_even'], out['TD_even_err'] = batch_mean(sp[:, 3])
        if out['spun'] and w != 0.0:
            diff, diff_err = batch_mean(sp[:, 1] - sp[:, 3])
            unit = 8 * math.pi * mu * R ** 3 * w
            out['B'], out['B_err'] = diff / unit, diff_err / unit
    return out


def poiseuille(prefix, g, H, h, mu=PAPER_MU, R=PAPER_R, lx=15.0, ly=6.0):
    """Fixed colloid at height h above the lower wall in Poiseuille flow (Pan et al. eq. 22).
    u_h from a parabola fitted to v_x(z) away from the colloid (the .far file), inner 80 %."""
    z, vals = read_profile(prefix + '.far')
    vx = vals[:, 0]
    sel = np.abs(z) < 0.4 * H
    c = np.polyfit(z[sel], vx[sel], 2)
    zc = -H / 2 + h
    uh = float(np.polyval(c, zc))
    d = read_blocks(prefix + '.colloid')
    f, ferr = batch_mean(d[:, 1])
    # far from the colloid the driving is rho g less the mean pressure gradient that balances
    # the drag, F / (Lx Ly H): (rho g - F/V) / (2 mu) = -c2
    mu_fit = (3.0 * g - f / (lx * ly * H)) / (-2 * c[0])
    t, terr = batch_mean(d[:, 2])
    x = R / h
    f_the = 6 * math.pi * mu * uh * R * (1 - x * x / 9) / (1 - 0.6526 * x + 0.3160 * x ** 3 - 0.242 * x ** 4)
    t_the = 8 / 3 * math.pi * mu * uh * R ** 3 / h * (1 + 0.0758 * x + 0.049 * x * x)
    return dict(uh=uh, mu_fit=mu_fit, F=f, Ferr=ferr, F_the=f_the, T=t, Terr=terr, T_the=t_the,
                Ty=float(d[:, 4].mean()), nblocks=len(d), Re=3.0 * uh * R / mu,
                umax=float(np.polyval(c, -c[1] / (2 * c[0]))))


def eq23_factors(l, R=PAPER_R):
    """Pan et al.'s eq. (23) for two fixed spheres side by side a distance l apart in a uniform
    stream U (a series in R / l to fifth order): the drag factor f (F = 6 pi mu R f U) and the
    torque factor (T = 8 pi mu R^3 U times it)."""
    x = R / l
    f = 1 - 3 * x / 4 + 9 * x ** 2 / 16 - 59 * x ** 3 / 64 + 465 * x ** 4 / 256 - 15813 * x ** 5 / 7168
    torque = 3 * x / (4 * l) - 9 * x ** 2 / (16 * l) + 27 * x ** 3 / (64 * l) - 273 * x ** 4 / (256 * l) \
        + 1683 * x ** 5 / (1024 * l)
    return f, torque


def two_spheres(path, L, g, nfluid, l, mu=PAPER_MU, R=PAPER_R):
    """Two fixed colloids a distance l apart (along y) in a periodic cube, flow along x (Pan et
    al. eq. 23). Drag per colloid F = N_fluid g / 2. Periodic images to leading order: each
    colloid sees the mean flow u plus 2 x 2.837 F / (6 pi mu L) (its own lattice and the
    other's; the same constant as Hasimoto's one-sphere correction, valid for l << L), so the
    prediction is F = 6 pi mu R f(l) u / (1 - 2 x 2.837 R f(l) / L). Torque z: colloid 1 (lower
    y) and colloid 2 carry opposite torques; their half difference is compared with eq. 23 at the
    incident flow u_eff = F / (6 pi mu R f(l))."""
    d = read_blocks(path)
    natoms = nfluid + 2
    u, uerr = batch_mean(d[:, 1] * nfluid / natoms)
    force = nfluid * g / 2
    f, tfac = eq23_factors(l, R)
    corr = 1 - 2 * HASIMOTO * R * f / L
    f_pred = 6 * math.pi * mu * R * f * u / corr
    u_eff = force / (6 * math.pi * mu * R * f)
    t, terr = batch_mean((d[:, 7] - d[:, 8]) / 2)
    t_the = 8 * math.pi * mu * R ** 3 * u_eff * tfac
    fd, fderr = batch_mean(d[:, 2])
    out = dict(u=u, uerr=uerr, F=force, F_pred=f_pred, f=f, corr=corr, ratio=force / f_pred,
               ratio_err=force / f_pred * uerr / u, u_eff=u_eff, T=t, Terr=terr, T_the=t_the,
               Fd=fd, Fderr=fderr, Re=3.0 * u * R / mu, nblocks=len(d), Tk=float(d[:, 6].mean()))
    if d.shape[1] > 10:
        # the dissipative parts of the two torques (compute dpd/split torque yes): the same mean
        # as the total (the random part's mean is zero), a smaller error
        out['TD'], out['TDerr'] = batch_mean((d[:, 9] - d[:, 10]) / 2)
    return out


def parse_args(argv=None):
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
    ap.add_argument('--drag', nargs=5, action='append', default=[], metavar=('LABEL', 'FILE', 'L', 'G', 'NFLUID'),
                    help='periodic-array drag block file (in.fpm_periodic_drag); repeatable')
    ap.add_argument('--couette', nargs=3, action='append', default=[], metavar=('LABEL', 'PREFIX', 'H'),
                    help='in.fpm_wall_channel couette output prefix; repeatable')
    ap.add_argument('--poiseuille', nargs=5, action='append', default=[],
                    metavar=('LABEL', 'PREFIX', 'G', 'H', 'h'),
                    help='in.fpm_wall_channel poiseuille output prefix; repeatable')
    ap.add_argument('--pair', nargs=6, action='append', default=[],
                    metavar=('LABEL', 'FILE', 'L', 'G', 'NFLUID', 'l'),
                    help='two-sphere block file (in.fpm_periodic_drag with l > 0); repeatable')
    return ap.parse_args(argv)


def viscosity_rows(a, rows):
    """The reverse-Poiseuille viscosity (the paper's where the run is missing)."""
    mu = PAPER_MU
    f = os.path.join(a.dir, 'fpm_viscosity.profile')
    if os.path.exists(f):
        mu, err, vmax = viscosity(f, a.rho, a.g)
        rows.append(('fluid viscosity mu (reverse Poiseuille)', f'{PAPER_MU}', f'{mu:.4f} +- {err:.4f}',
                     f'{100 * (mu / PAPER_MU - 1):+.1f} %'))
        print(f'# viscosity: max |v| = {vmax:.3f}, halves differ by {2 * err:.4f}')
    return mu


def diffusion_rows(a, mu, rows):
    """The colloid's D and Stokes-Einstein radius (the paper's radius where the run is missing)."""
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
    return R


def torque_rows(a, mu, R, rows):
    """The rotating sphere's torque against Stokes, and the extra torque files of --torque."""
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
        split = dissipative_torque(path)
        if split is not None:
            rows.append((f'  its dissipative part (compute dpd/split torque yes), {label}', '1',
                         f'{split[0] / stokes:.3f} +- {split[1] / abs(stokes):.3f}',
                         f'T_D = {split[0]:.3f} +- {split[1]:.3f}; random part {t - split[0]:.3f}'))


def drag_rows(a, rows):
    """--drag: the periodic array's drag against Stokes with Hasimoto's factor."""
    for label, path, L, g, nfluid in a.drag:
        r = periodic_drag(path, float(L), float(g), int(nfluid))
        rows.append((f'periodic-array drag F / (6 pi mu u R K), {label}: L = {float(L):g}, phi = {r["phi"]:.3g}, '
                     f'K = {r["K"]:.4f}, F = N g = {r["F"]:.3f}, u = {r["u"]:.4f} +- {r["uerr"]:.4f}, '
                     f'Re = rho u R / mu = {r["Re"]:.3f}, {r["nblocks"]} blocks',
                     'u within 1.2 % of F/(6 pi mu R) (L = 10, u = 0.2986)',
                     f'{r["ratio"]:.3f} +- {r["ratio_err"]:.3f} (mean force measured on the colloid {r["Fd"]:.3f} +- '
                     f'{r["Fderr"]:.3f}; momentum relaxation time {r["tau"]:.0f}, model error of u '
                     f'{r["uerr_model"]:.4f})',
                     f'drag radius {r["R_drag"]:.4f} (paper 0.2737), uncorrected F/(6 pi mu u R) = '
                     f'{r["F"] / r["stokes"]:.3f}, fluid kBT {r["T"]:.4f}'))


def couette_rows(a, rows):
    """--couette: torque on fixed colloids and spin of free ones in Couette flow."""
    for label, prefix, H in a.couette:
        r = couette(prefix, float(H))
        if abs(r['rate']) < 0.05 and 'B' in r:
            # walls at rest: only the spun colloids' rotational friction means anything
            rows.append((f'{label}: no shear (fitted rate {r["rate"]:.4f}); rotational friction '
                         f'(T_fixed - T_spun) / 8 pi mu R^3 Omega at Omega = {r["Omega"]:.3f} '
                         f'(dissipative parts)', '1', f'{r["B"]:.4f} +- {r["B_err"]:.4f}',
                         f'fluid kBT (v_y) {r["Ty"]:.4f}'))
            continue
        rows.append((f'Couette, {label}: shear rate {r["rate"]:.4f} ((1/2) curl v = {r["half"]:.4f}), '
                     f'Re = rho |(1/2) curl v| R^2 / mu = {r["Re"]:.3f}, {r["nblocks"]} blocks; '
                     f'torque on the fixed (Omega = 0) colloids / 8 pi mu R^3 (1/2) curl v',
                     'Table 1: 0.980 and 1.005 at (1/2) curl v = 0.2, 0.4',
                     f'{r["T"] / r["T_the"]:.3f} +- {r["Terr"] / r["T_the"]:.3f} (T = {r["T"]:.4f} +- {r["Terr"]:.4f}, '
                     f'theory {r["T_the"]:.4f})',
                     f'fit v(+-H/2) = {r["wall_v"][0]:.3f}, {r["wall_v"][1]:.3f}; fluid kBT (v_y) {r["Ty"]:.4f}, '
                     f'rotational {r["Trot"]:.4f}'))
        if 'TD' in r:
            rows.append((f'Couette, {label}: dissipative part of the fixed colloids\' torque / '
                         f'8 pi mu R^3 (1/2) curl v', '1',
                         f'{r["TD"] / r["T_the"]:.3f} +- {r["TDerr"] / r["T_the"]:.3f}', ''))
        if not r['spun']:
            rows.append((f'Couette, {label}: spin of the free colloids / (1/2) curl v', '',
                         f'{r["Omega"] / r["half"]:.3f} +- {r["Omega_err"] / r["half"]:.3f} '
                         f'(Omega = {r["Omega"]:.4f} +- {r["Omega_err"]:.4f})', ''))
        elif 'TD' in r:
            rows.append((f'Couette, {label}: colloids spun at Omega = {r["Omega"]:.4f} '
                         f'(= {r["Omega"] / r["half"]:.3f} (1/2) curl v): torque / 8 pi mu R^3 (1/2) curl v, '
                         f'total and dissipative part', '0 at Omega = (1/2) curl v',
                         f'{r["T_even"] / r["T_the"]:+.3f} +- {r["T_even_err"] / r["T_the"]:.3f}, '
                         f'{r["TD_even"] / r["T_the"]:+.3f} +- {r["TD_even_err"] / r["T_the"]:.3f}', ''))
            if 'B' in r:
                rows.append((f'Couette, {label}: rotational friction in the shear flow, '
                             f'(T_fixed - T_spun) / 8 pi mu R^3 Omega (dissipative parts)', '1',
                             f'{r["B"]:.4f} +- {r["B_err"]:.4f}', ''))


def poiseuille_rows(a, rows):
    """--poiseuille: drag and torque on a fixed colloid near a wall in Poiseuille flow."""
    for label, prefix, g, H, h in a.poiseuille:
        r = poiseuille(prefix, float(g), float(H), float(h))
        rows.append((f'Poiseuille, {label}: g = {float(g):g}, u_h = {r["uh"]:.4f} (far-field parabola, '
                     f'u_max {r["umax"]:.4f}, its mu {r["mu_fit"]:.3f}), Re = rho u_h R / mu = {r["Re"]:.3f}, '
                     f'{r["nblocks"]} blocks; drag F / F_eq22',
                     'Table 2: 0.954, 0.947, 0.923', f'{r["F"] / r["F_the"]:.3f} +- {r["Ferr"] / r["F_the"]:.3f} '
                     f'(F = {r["F"]:.3f} +- {r["Ferr"]:.3f}, eq. 22 {r["F_the"]:.3f})',
                     f'fluid kBT (v_y) {r["Ty"]:.4f}'))
        rows.append((f'Poiseuille, {label}: torque T / T_eq22', 'Table 2: 1.066, 1.038, 0.994',
                     f'{r["T"] / r["T_the"]:.3f} +- {r["Terr"] / abs(r["T_the"]):.3f} '
                     f'(T = {r["T"]:.4f} +- {r["Terr"]:.4f}, eq. 22 {r["T_the"]:.4f})', ''))


def pair_rows(a, rows):
    """--pair: drag and torque on two fixed colloids in a periodic cube."""
    for label, path, L, g, nfluid, l in a.pair:
        r = two_spheres(path, float(L), float(g), int(nfluid), float(l))
        rows.append((f'two spheres, {label}: l = {float(l):g}, L = {float(L):g}, drag per sphere F = N g / 2 = '
                     f'{r["F"]:.3f}, u = {r["u"]:.4f} +- {r["uerr"]:.4f}, Re = rho u R / mu = {r["Re"]:.3f}, '
                     f'{r["nblocks"]} blocks; F / eq. 23 with the periodic correction',
                     'Table 3: 0.953, 0.954, 0.938 at l = 2, 1.5, 1',
                     f'{r["ratio"]:.3f} +- {r["ratio_err"]:.3f} (eq. 23 factor {r["f"]:.4f}, periodic factor '
                     f'1/{r["corr"]:.4f})',
                     f'mean force measured on the colloids {r["Fd"]:.3f} +- {r["Fderr"]:.3f}; fluid kBT {r["Tk"]:.4f}'))
        rows.append((f'two spheres, {label}: torque (half difference of the two) / eq. 23 at u_eff = {r["u_eff"]:.4f}',
                     'Table 3: 0.969, 0.974, 1.066', f'{r["T"] / r["T_the"]:.3f} +- {r["Terr"] / abs(r["T_the"]):.3f} '
                     f'(T = {r["T"]:.4f} +- {r["Terr"]:.4f}, eq. 23 {r["T_the"]:.4f})', ''))
        if 'TD' in r:
            rows.append((f'two spheres, {label}: dissipative part of the torque / eq. 23',
                         'Table 3: 0.969, 0.974, 1.066',
                         f'{r["TD"] / r["T_the"]:.3f} +- {r["TDerr"] / abs(r["T_the"]):.3f} '
                         f'(T_D = {r["TD"]:.4f} +- {r["TDerr"]:.4f})',
                         f'random part {r["T"] - r["TD"]:.4f} (mean zero expected)'))


def main(argv=None):
    a = parse_args(argv)
    rows = []
    mu = viscosity_rows(a, rows)
    R = diffusion_rows(a, mu, rows)
    torque_rows(a, mu, R, rows)
    drag_rows(a, rows)
    couette_rows(a, rows)
    poiseuille_rows(a, rows)
    pair_rows(a, rows)
    print('| quantity | paper | this package | difference |')
    print('|---|---|---|---|')
    for r in rows:
        print('| ' + ' | '.join(r) + ' |')


if __name__ == '__main__':
    main()
