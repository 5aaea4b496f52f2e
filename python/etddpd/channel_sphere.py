#!/usr/bin/python3
"""Drag on a sphere in the channel examples (examples/channel-sphere): Re, C_D and their errors.

Reads the fix ave/time files the examples write (one row per block of steps: the x, y, z force
of the fluid on the sphere, the mean fluid velocity along x relative to the sphere, the fluid
temperature and, with pair dpd/gen, the conservative, dissipative and random parts of the x
force). Drops the first --discard fraction of the rows (the flow around the sphere develops),
groups the rest into --batches batch means and takes the standard error over the batches.

  F_D  = mean x force on the sphere; by default the conservative plus dissipative part when the
         file has it (the random part has mean zero exactly and only adds noise), else the total
  U    = mean fluid velocity along x (the sphere is at rest), or --U
  Re   = rho U d / eta,    C_D = 8 F_D / (pi d^2 rho U^2)
  a_eff = F_D / (6 pi eta U): the Stokes radius (d/2 when the drag is Stokes' law; C_D = 24/Re
         then)
  a_h  = with --slit L or --tube R: the radius of the solid sphere whose Stokes drag in that
         channel equals F_D (Faxen's midway factor for walls L from the centre; Haberman and
         Sayre's for the axis of a Poiseuille flow in a tube of radius R, centre-line velocity
         2 U, or U with --centre-line): a_eff with the wall factor taken out

against Stokes (24/Re) and Brown and Lawler's correlation
C_D = 24/Re (1 + 0.150 Re^0.681) + 0.407 / (1 + 8710/Re).

  python/channel_sphere.py drag validation/channel-sphere/results/drag.U*           # table
  python/channel_sphere.py drag --series "rigid:drag.U0.5,drag.U0.9" --series "..." --png cd.png
  python/channel_sphere.py radius wall_radius.H2 ...                     # compliant walls
  python/channel_sphere.py velocity velocity_profile.H2   # centre-line velocity, hydrodynamic radius
  python/channel_sphere.py tube 4.5 4.9         # wall factor: drag in a wider tube, same U
  python/channel_sphere.py drag --slit 6.3 drag.U0.9     # a_h: the wall factor taken out
  python/channel_sphere.py shells profiles.U0.9_nx120_profiles   # slip, a_h from the flow field
  python/channel_sphere.py line line.U0.9_nx120_profiles         # density and v_x through the sphere

Defaults: rho = 4 (n = 4, m = 1), d = 3, eta = 1.083 (kinetic theory of standard DPD with
a = 18.75, gamma = 4.5, kBT = 1, n = 4, rc = 1: 0.796 kinetic + 0.287 dissipative).
"""
import argparse
import json
import math
import sys

import numpy as np

from .lammps_output import LammpsOutputError, read_ave_chunk, read_ave_time
from .statistics import batch_means, standard_error


def correlation_cd(re):
    """Brown and Lawler's drag correlation for a sphere in unbounded uniform flow."""
    re = np.asarray(re, dtype=float)
    return 24.0 / re * (1.0 + 0.150 * re**0.681) + 0.407 / (1.0 + 8710.0 / re)


def stokes_cd(re):
    return 24.0 / np.asarray(re, dtype=float)


def _tube_denominator(lam):
    return 1.0 - 2.1050 * lam + 2.0865 * lam**3 - 1.7068 * lam**5 + 0.72603 * lam**6


def tube_factor_quiescent(lam):
    """Haberman and Sayre's wall factor K for a sphere (diameter / tube diameter = lam) moving
    along the axis of a tube of fluid at rest: drag = 6 pi eta a U K."""
    lam = np.asarray(lam, dtype=float)
    return (1.0 - 0.75857 * lam**5) / _tube_denominator(lam)


def tube_factor_poiseuille(lam):
    """Haberman and Sayre's factor for a sphere held on the axis of a Poiseuille flow with
    centre-line velocity V: drag = 6 pi eta a V K'. The numerator's -2/3 lam^2 is Faxen's
    correction for the curvature of the profile; the mean velocity is V/2."""
    lam = np.asarray(lam, dtype=float)
    return (1.0 - 2.0 / 3.0 * lam**2 - 0.20217 * lam**5) / _tube_denominator(lam)


def slit_factor_midway(lam):
    """Faxen's wall factor K for a sphere of radius a moving parallel to, and midway between,
    two plane walls a distance l from its centre, fluid at rest (lam = a / l):
    drag = 6 pi eta a U K."""
    lam = np.asarray(lam, dtype=float)
    return 1.0 / (1.0 - 1.004 * lam + 0.418 * lam**3 + 0.21 * lam**4 - 0.169 * lam**5)


# the largest a / l at which each series is used: beyond it the truncated series are not
# trusted (Faxen's midway series to about 0.5, Haberman and Sayre's to about 0.8)
SLIT_LAMBDA_MAX = 0.5
TUBE_LAMBDA_MAX = 0.8


def hydrodynamic_radius(a_eff, factor, length, lam_max):
    """The radius a of the solid sphere whose confined Stokes drag a * factor(a / length) equals
    a_eff * (6 pi eta U); None when no a with a / length <= lam_max gives it."""
    from scipy.optimize import brentq
    drag_radius = lambda a: a * float(factor(a / length)) - a_eff
    upper = lam_max * length
    if a_eff <= 0.0 or drag_radius(upper) < 0.0:
        return None
    return brentq(drag_radius, 0.0, upper, xtol=1e-12)


def confined_radius(result, args):
    """The hydrodynamic radius a_h of the sphere and its error: a_eff with the wall factor of
    the channel taken out (--slit: walls moving with the stream, i.e. a sphere moving between
    walls at rest; --tube: a sphere held on the axis of a no-slip Poiseuille flow whose
    centre-line velocity is twice the mean U, or the reference velocity itself with
    --centre-line)."""
    if args.slit is not None:
        factor, length, lam_max, scale = slit_factor_midway, args.slit, SLIT_LAMBDA_MAX, 1.0
    else:
        factor, length, lam_max = tube_factor_poiseuille, args.tube, TUBE_LAMBDA_MAX
        scale = 1.0 if args.centre_line else 0.5    # a_eff per unit centre-line velocity
    a_eff, err = scale * result['a_eff'], scale * result['a_eff_err']
    centre = hydrodynamic_radius(a_eff, factor, length, lam_max)
    if centre is None:
        return None, None
    low = hydrodynamic_radius(a_eff - err, factor, length, lam_max) if err < a_eff else 0.0
    high = hydrodynamic_radius(a_eff + err, factor, length, lam_max)
    if high is None:
        return centre, centre - low
    return centre, 0.5 * (high - low)


def read_drag(path):
    """A drag file of the examples (fix ave/time, scalar mode) as a Table."""
    try:
        table = read_ave_time(path)
    except LammpsOutputError as error:
        sys.exit(f'channel_sphere: {error}')
    if table.names is None:
        sys.exit(f'channel_sphere: {path} is not a fix ave/time file with data (its header does '
                 f'not name its {table.data.shape[1]} columns)')
    return table


def read_chunks(path):
    """A profile or wall-radius file of the examples (fix ave/chunk) as Blocks."""
    try:
        blocks = read_ave_chunk(path)
    except LammpsOutputError as error:
        sys.exit(f'channel_sphere: {error}')
    if blocks.names is None:
        sys.exit(f'channel_sphere: {path} is not a fix ave/chunk file with data')
    return blocks


def read_kept_chunks(path, discard, minimum):
    """A fix ave/chunk file of the examples without the first --discard fraction of its blocks;
    stops with a message where fewer than `minimum` blocks are left."""
    blocks = read_chunks(path)
    start = int(round(discard * len(blocks.steps)))
    blocks = blocks._replace(steps=blocks.steps[start:], data=blocks.data[start:])
    if len(blocks.steps) < minimum:
        left = 'no block' if minimum == 1 else f'fewer than {minimum} blocks'
        sys.exit(f'channel_sphere: {path} has {left} after --discard')
    return blocks


def batch_mean(values, batches):
    """Mean and its standard error from `batches` contiguous batch means."""
    values = np.asarray(values, dtype=float)
    means = batch_means(values, max(2, min(batches, len(values))))
    return float(means.mean()), float(standard_error(means))


def analyse(path, args):
    table = read_drag(path)
    start = int(round(args.discard * len(table.data)))
    table = table._replace(data=table.data[start:])
    rows = len(table.data)
    if rows < 2 * args.batches:
        sys.exit(f'channel_sphere: {path}: only {rows} rows after discarding, '
                 f'need at least {2 * args.batches}')
    total = table.data[:, 1]
    conservative = table.get('c_split[1]')
    dissipative = table.get('c_split[4]')
    random_part = table.get('c_split[7]')
    velocity = table.get(args.velocity)
    if velocity is None:
        sys.exit(f'channel_sphere: {path} has no {args.velocity} column (mean fluid velocity)')
    use_split = conservative is not None and args.force != 'total'
    drag_series = conservative + dissipative if use_split else total
    drag, drag_err = batch_mean(drag_series, args.batches)
    total_mean, total_err = batch_mean(total, args.batches)
    u, u_err = batch_mean(velocity, args.batches)
    if args.U is not None:          # a set reference velocity (e.g. the wall speed), no error
        u, u_err = args.U, 0.0
    re = args.rho * u * args.d / args.eta
    re_err = re * u_err / u
    cd = 8.0 * drag / (math.pi * args.d**2 * args.rho * u * u)
    cd_err = cd * math.hypot(drag_err / drag, 2.0 * u_err / u)
    # Stokes radius: the radius of the sphere whose Stokes drag 6 pi eta a U equals F_D
    a_eff = drag / (6.0 * math.pi * args.eta * u)
    a_eff_err = a_eff * math.hypot(drag_err / drag, u_err / u)
    result = {
        'file': path, 'rows': rows, 'U': u, 'U_err': u_err, 'Re': re, 'Re_err': re_err,
        'F_D': drag, 'F_D_err': drag_err, 'F_total': total_mean, 'F_total_err': total_err,
        'estimator': 'C+D' if use_split else 'total',
        'C_D': cd, 'C_D_err': cd_err, 'a_eff': a_eff, 'a_eff_err': a_eff_err,
        'C_D_correlation': float(correlation_cd(re)), 'C_D_stokes': float(stokes_cd(re)),
    }
    if use_split:
        result['F_C'] = batch_mean(conservative, args.batches)[0]
        result['F_D_diss'] = batch_mean(dissipative, args.batches)[0]
        result['F_R'], result['F_R_err'] = batch_mean(random_part, args.batches)
    fy = table.get('c_fsphere[2]', 'c_fcolloid[2]')
    if fy is not None:
        result['F_y'], result['F_y_err'] = batch_mean(fy, args.batches)
    temperature = table.get('c_tfluid')
    if temperature is not None:
        result['kT'] = float(temperature.mean())
    return result


def pool(results):
    """One result from independent runs of the same case (each analysed on its own): every
    quantity with an error becomes the inverse-variance weighted mean of the runs, with the
    error of that mean; F_C and F_D_diss, which have none here, the plain mean."""
    pooled = dict(results[0])
    pooled['file'] = '+'.join(r['file'] for r in results)
    pooled['rows'] = sum(r['rows'] for r in results)
    for key in [k for k in results[0] if k + '_err' in results[0]]:
        values = np.array([r[key] for r in results])
        errors = np.array([r[key + '_err'] for r in results])
        if np.all(errors > 0):
            weights = 1.0 / errors**2
            pooled[key] = float(np.sum(weights * values) / np.sum(weights))
            pooled[key + '_err'] = float(1.0 / math.sqrt(np.sum(weights)))
        else:    # a set value (--U): the same in every run
            pooled[key] = float(values.mean())
            pooled[key + '_err'] = 0.0
    for key in ('F_C', 'F_D_diss', 'kT'):
        if key in results[0]:
            pooled[key] = float(np.mean([r[key] for r in results]))
    pooled['C_D_correlation'] = float(correlation_cd(pooled['Re']))
    pooled['C_D_stokes'] = float(stokes_cd(pooled['Re']))
    return pooled


def analyse_pooled(spec, args):
    """A drag file, or several joined by '+' (independent runs of one case, pooled)."""
    paths = [p for p in spec.split('+') if p]
    results = [analyse(p, args) for p in paths]
    return results[0] if len(results) == 1 else pool(results)


def drag_series(args):
    """(label, files) of the drag command after checking its options."""
    series = []
    for spec in args.series or []:
        label, _, files = spec.partition(':')
        series.append((label, [f for f in files.split(',') if f]))
    if args.files:
        series.append(('', args.files))
    if not series:
        sys.exit('channel_sphere: give drag files or --series label:file,file')
    if args.slit is not None and args.tube is not None:
        sys.exit('channel_sphere: drag takes --slit or --tube, not both')
    for name, length in (('slit', args.slit), ('tube', args.tube)):
        if length is not None and length <= 0.0:
            sys.exit(f'channel_sphere: drag --{name} must be positive, not {length}')
    if args.centre_line and args.tube is None:
        sys.exit('channel_sphere: drag --centre-line needs --tube')
    return series


def print_drag_header(args, confined):
    print(f'# rho {args.rho} d {args.d} eta {args.eta}; discard {args.discard}, '
          f'{args.batches} batches; errors are one standard error')
    if confined:
        where = (f'midway between walls {args.slit} from its centre (Faxen)' if args.slit is not None
                 else f'on the axis of a tube of radius {args.tube}, Poiseuille flow with centre-line '
                      f'velocity {"U" if args.centre_line else "2 U"} (Haberman and Sayre)')
        print(f'# a_h: radius of the solid sphere with the same Stokes drag {where}')
    print(f'{"series":>10} {"file":>28} {"U":>14} {"Re":>13} {"F_D":>14} {"F_total":>14} '
          f'{"C_D":>14} {"corr.":>6} {"C_D/corr":>8} {"24/Re":>6} {"a_eff":>12}'
          + (f' {"a_h":>12}' if confined else ''))


def print_drag_row(label, path, r, confined):
    print(f'{label:>10} {path[-28:]:>28} {r["U"]:7.4f}+-{r["U_err"]:.4f} '
          f'{r["Re"]:6.3f}+-{r["Re_err"]:.3f} {r["F_D"]:7.3f}+-{r["F_D_err"]:5.3f} '
          f'{r["F_total"]:7.3f}+-{r["F_total_err"]:5.3f} '
          f'{r["C_D"]:7.3f}+-{r["C_D_err"]:5.3f} {r["C_D_correlation"]:6.3f} '
          f'{r["C_D"] / r["C_D_correlation"]:8.3f} {r["C_D_stokes"]:6.3f} '
          f'{r["a_eff"]:5.3f}+-{r["a_eff_err"]:.3f}', end='')
    if confined:
        print(f' {r["a_h"]:5.3f}+-{r["a_h_err"]:.3f}' if r['a_h'] is not None
              else '   beyond the wall factor\'s range', end='')
    print()


def drag_command(args):
    series = drag_series(args)
    confined = args.slit is not None or args.tube is not None
    print_drag_header(args, confined)
    results = []
    for label, files in series:
        for path in files:
            r = analyse_pooled(path, args)
            r['series'] = label
            if confined:
                r['a_h'], r['a_h_err'] = confined_radius(r, args)
            results.append(r)
            print_drag_row(label, path, r, confined)
    if args.json:
        with open(args.json, 'w') as f:
            json.dump(results, f, indent=1)
    if args.png:
        plot_drag(results, args)
    return results


def new_plot(height=3.6):
    """A figure and axes drawn without a display."""
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    return plt.subplots(figsize=(5.5, height), dpi=100)


def save_plot(fig, ax, xlabel, ylabel, png, legend_size=7, which='major'):
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.legend(fontsize=legend_size)
    ax.grid(True, which=which, alpha=0.3)
    fig.tight_layout()
    fig.savefig(png)
    print(f'wrote {png}')


def plot_drag(results, args):
    fig, ax = new_plot(4.2)
    res = [r['Re'] for r in results]
    grid = np.geomspace(min(res) / 1.5, max(res) * 1.5, 100)
    ax.plot(grid, correlation_cd(grid), 'k-', label='Brown & Lawler correlation')
    ax.plot(grid, stokes_cd(grid), 'k--', label='Stokes, 24/Re')
    markers = 'osD^v<>'
    labels = []
    for r in results:
        if r['series'] not in labels:
            labels.append(r['series'])
    for k, label in enumerate(labels):
        rs = [r for r in results if r['series'] == label]
        ax.errorbar([r['Re'] for r in rs], [r['C_D'] for r in rs],
                    xerr=[r['Re_err'] for r in rs], yerr=[r['C_D_err'] for r in rs],
                    fmt=markers[k % len(markers)], capsize=3, label=label or 'DPD')
    ax.set_xscale('log')
    ax.set_yscale('log')
    if args.title:
        ax.set_title(args.title, fontsize=10)
    save_plot(fig, ax, 'Re = rho U d / eta', 'C_D = 8 F_D / (pi d^2 rho U^2)', args.png,
              legend_size=8, which='both')


def wall_radius_bins(path, discard):
    """The blocks of a wall_radius file after --discard, over the bins that ever hold a wall
    particle (the box's last, partial bin may hold none and then has no radius): x of the bins,
    count and mean radius per block and bin, and the blocks' steps."""
    blocks = read_chunks(path)
    start = int(round(discard * len(blocks.steps)))
    count = blocks.column('Ncount')[start:]
    radius = blocks.column('v_wall_r')[start:]
    keep = count.sum(axis=0) > 0
    return blocks.column('Coord1')[start][keep], count[:, keep], radius[:, keep], blocks.steps[start:]


def radius_error(per_block, batches):
    """Batch error of a per-block mean radius, only with enough blocks (4) to batch."""
    if len(per_block) < 4:
        return float('nan')
    return batch_mean(per_block, min(batches, len(per_block) // 2))[1]


def near_sphere_text(path, x, count, radius, args):
    """'; within NEAR of x = X: R +- E', the mean radius of the bins near the sphere."""
    centre = 0.5 * (x.min() + x.max()) if args.sphere_x is None else args.sphere_x
    close = np.abs(x - centre) < args.near
    if not close.any():
        sys.exit(f'channel_sphere: no bin of {path} lies within {args.near} of x = {centre}')
    near_block = (radius[:, close] * count[:, close]).sum(axis=1) / count[:, close].sum(axis=1)
    text = f'; within {args.near:g} of x = {centre:.2f}: {near_block.mean():.4f}'
    if len(near_block) >= 4:
        text += f' +- {radius_error(near_block, args.batches):.4f}'
    return text


def radius_command(args):
    """Mean radial distance of the wall particles from the channel axis along x (compliant
    channel): averages the blocks after --discard, per bin and overall."""
    out = []
    for path in args.files:
        x, count, radius, steps = wall_radius_bins(path, args.discard)
        mean_r = (radius * count).sum(axis=0) / count.sum(axis=0)
        per_block = (radius * count).sum(axis=1) / count.sum(axis=1)
        overall = float(per_block.mean())
        overall_err = radius_error(per_block, args.batches)
        err_text = f'{overall_err:.4f}' if len(steps) >= 4 else 'n/a (fewer than 4 blocks)'
        if args.each:               # one profile per kept block: a wall that is still moving
            for k, step in enumerate(steps):
                prof = np.where(count[k] > 0, radius[k], np.nan)
                print(f'  block at step {int(step)}: ' + ' '.join(f'{v:.2f}' for v in prof))
                out.append((f'{path.split("/")[-1]} step {int(step)}', x, prof))
        else:
            out.append((path, x, mean_r))
        near_text = '' if args.near is None else near_sphere_text(path, x, count, radius, args)
        print(f'{path}: mean wall radius {overall:.4f} +- {err_text}; '
              f'min over x {mean_r.min():.4f}, max {mean_r.max():.4f}{near_text}')
    if args.png:
        fig, ax = new_plot()
        for path, x, mean_r in out:
            label = path.split('/')[-1].replace('wall_radius.', '')
            ax.plot(x, mean_r, '-', label=label)
        save_plot(fig, ax, 'x (channel axis)', 'mean radial distance of wall particles', args.png,
                  legend_size=8)


def parabola_fit(r, u, weight):
    """Weighted least squares u = V (1 - r^2 / R_h^2): (V, R_h). R_h is where the fitted
    Poiseuille profile reaches zero, the channel's hydrodynamic radius."""
    design = np.column_stack([np.ones_like(r), r * r])
    w = np.sqrt(weight)
    (a, b), *_ = np.linalg.lstsq(design * w[:, None], u * w, rcond=None)
    if a <= 0.0 or b >= 0.0:
        return float(a), float('nan')
    return float(a), float(math.sqrt(-a / b))


def read_radial_bins(path, discard, sphere_x=None):
    """A velocity_profile / wall_profile file of in.sphere_compliant (chunks of bin/cylinder:
    radial bin centre Coord1, slab centre Coord2) after dropping the first --discard fraction
    of its blocks: (the blocks, radius per chunk, the distinct radii, mask of the chunks in
    the slabs more than a quarter box from the sphere, total length of those slabs)."""
    blocks = read_kept_chunks(path, discard, 2)
    radius = blocks.column('Coord1')[0]
    axial = blocks.column('Coord2')[0]
    slabs = np.unique(axial)
    if len(slabs) < 2:
        sys.exit(f'channel_sphere: {path} needs at least two slabs along the axis')
    centre = 0.5 * (slabs.min() + slabs.max()) if sphere_x is None else sphere_x
    far = np.abs(axial - centre) > 0.25 * (slabs[1] - slabs[0]) * len(slabs)
    if not far.any():
        sys.exit(f'channel_sphere: {path} has no slab farther than a quarter box from the sphere')
    far_length = (slabs[1] - slabs[0]) * len(np.unique(axial[far]))
    return blocks, radius, np.unique(radius), far, far_length


def ring_profile(count, vx, radius, far, rings, rows):
    """Count-weighted velocity per ring over the far slabs and the given blocks, and the count."""
    c = count[rows][:, far]
    m = vx[rows][:, far] * c
    u = np.array([m[:, radius[far] == ring].sum() for ring in rings])
    n = np.array([c[:, radius[far] == ring].sum() for ring in rings])
    return np.where(n > 0, u / np.maximum(n, 1e-300), 0.0), n


def velocity_fit(path, args):
    """The far-slab profile of one file and its Poiseuille fit over r < --fit, with the errors
    of the fit over --batches batches of blocks: (rings, u, n, v_c, r_h, errors)."""
    blocks, radius, rings, far, _ = read_radial_bins(path, args.discard, args.sphere_x)
    count, vx = blocks.column('Ncount'), blocks.column('vx')
    u, n = ring_profile(count, vx, radius, far, rings, slice(None))
    inside = (rings < args.fit) & (n > 0)
    if inside.sum() < 3:
        sys.exit(f'channel_sphere: fewer than 3 radial bins of {path} hold fluid inside --fit {args.fit}')
    v_c, r_h = parabola_fit(rings[inside], u[inside], n[inside])
    fits = []
    for rows in np.array_split(np.arange(len(blocks.steps)), min(args.batches, len(blocks.steps))):
        ub, nb = ring_profile(count, vx, radius, far, rings, rows)
        ok = (rings < args.fit) & (nb > 0)
        fits.append(parabola_fit(rings[ok], ub[ok], nb[ok]))
    return rings, u, n, v_c, r_h, standard_error(fits)


def velocity_command(args):
    """Radial profile of the fluid's x velocity (in.sphere_compliant's velocity_profile files) in
    the slabs away from the sphere, and its Poiseuille fit over r < --fit: centre-line velocity
    and hydrodynamic radius, each with a batch-mean error."""
    if args.fit <= 0.0:
        sys.exit('channel_sphere: velocity --fit must be positive')
    if args.batches < 2:
        sys.exit('channel_sphere: velocity --batches must be at least 2')
    out = []
    for path in args.files:
        rings, u, n, v_c, r_h, err = velocity_fit(path, args)
        print(f'{path}: centre-line velocity {v_c:.4f} +- {err[0]:.4f}, hydrodynamic radius '
              f'{r_h:.3f} +- {err[1]:.3f} (Poiseuille fit over r < {args.fit:g}, slabs away from the sphere)')
        out.append((path, rings, u, n, v_c, r_h))
    if args.png:
        fig, ax = new_plot()
        for path, rings, u, n, v_c, r_h in out:
            label = path.split('/')[-1].replace('velocity_profile.', '')
            line, = ax.plot(rings[n > 0], u[n > 0], 'o', ms=3, label=f'{label}: R_h = {r_h:.2f}')
            rr = np.linspace(0.0, r_h, 50)
            ax.plot(rr, v_c * (1 - rr**2 / r_h**2), '-', color=line.get_color(), lw=0.8)
        save_plot(fig, ax, 'distance from the axis r', 'mean fluid velocity along x', args.png)


def density_command(args):
    """Number density per ring of the radial bins (velocity_profile / wall_profile files of
    in.sphere_compliant), over the slabs away from the sphere, one column per file."""
    table, rings, labels = [], None, []
    for spec in args.files:             # LABEL=FILE names a curve of the plot
        label, _, path = spec.rpartition('=')
        labels.append(label or path.split('/')[-1])
        blocks, radius, these, far, length = read_radial_bins(path, args.discard)
        count = blocks.column('Ncount').mean(axis=0)
        if rings is not None and (len(these) != len(rings) or np.abs(these - rings).max() > 1e-6):
            sys.exit(f'channel_sphere: {path} has other radial bins than the first file')
        rings = these
        width = rings[1] - rings[0]
        volume = math.pi * ((rings + 0.5 * width)**2 - (rings - 0.5 * width)**2) * length
        table.append(np.array([count[far & (radius == q)].sum() for q in rings]) / volume)
    keep = (rings >= args.rmin) & (rings <= args.rmax)
    print('r       ' + ' '.join(f'{label[-28:]:>28s}' for label in labels))
    for k in np.nonzero(keep)[0]:
        print(f'{rings[k]:6.3f}  ' + ' '.join(f'{col[k]:28.3f}' for col in table))
    if args.png:
        fig, ax = new_plot()
        for label, col in zip(labels, table):
            ax.plot(rings[keep], col[keep], '.-', label=label)
        save_plot(fig, ax, 'distance from the axis r', 'number density (slabs away from the sphere)',
                  args.png)


def tube_command(args):
    """Haberman and Sayre's wall factors for the sphere in tubes of the given radii, and the drag
    at a fixed mean velocity relative to the first radius (Poiseuille factor)."""
    if args.d <= 0.0:
        sys.exit('channel_sphere: tube --d must be positive')
    for r in args.radii:
        if r <= 0.5 * args.d:
            sys.exit(f'channel_sphere: tube radius {r} must exceed the sphere radius {0.5 * args.d}')
    first = None
    print('radius     d/D     K (fluid at rest)   K\' (Poiseuille)   drag / first radius')
    for r in args.radii:
        lam = args.d / (2.0 * r)
        k_rest, k_flow = float(tube_factor_quiescent(lam)), float(tube_factor_poiseuille(lam))
        first = k_flow if first is None else first
        print(f'{r:8.4f}  {lam:6.4f}  {k_rest:12.4f}  {k_flow:16.4f}  {k_flow / first:16.4f}')


def shell_fit(r, u, weight):
    """Weighted least squares u = U_inf (1 - a_h / r), linear in (U_inf, U_inf a_h): the shell
    mean of v_x about a no-slip sphere of radius a_h at rest in unbounded Stokes flow (the
    angular mean of Stokes' solution; the a^3 term averages out). Returns (U_inf, a_h)."""
    design = np.column_stack([np.ones_like(r), -1.0 / r])
    w = np.sqrt(weight)
    (u_inf, u_inf_a), *_ = np.linalg.lstsq(design * w[:, None], u * w, rcond=None)
    return float(u_inf), float(u_inf_a / u_inf)


def shell_profile(count, vx, rows):
    """Count-weighted v_x and the mean count per chunk (shell, cell) over the given blocks."""
    c = count[rows]
    n = c.sum(axis=0)
    return np.where(n > 0, (vx[rows] * c).sum(axis=0) / np.maximum(n, 1e-300), 0.0), n / len(c)


def shells_command(args):
    """Shell means about the sphere (in.sphere_shear's profiles files, bin/sphere chunks):
    density and v_x per shell, the fluid inside the sphere and its mean v_x, and the fit of
    v_x = U_inf (1 - a_h / r) over --fit-from <= r <= --fit-to (a_h: the hydrodynamic radius
    of the sphere in Stokes flow; U_inf the velocity far from it), each with a batch error."""
    if not 0.0 < args.fit_from < args.fit_to:
        sys.exit('channel_sphere: shells needs 0 < --fit-from < --fit-to')
    for path in args.files:
        blocks = read_kept_chunks(path, args.discard, 2)
        count, vx = blocks.column('Ncount'), blocks.column('vx')
        radius = blocks.column('Coord1')[0]
        width = radius[1] - radius[0]
        volume = 4.0 / 3.0 * math.pi * ((radius + width / 2) ** 3 - (radius - width / 2) ** 3)
        batches = np.array_split(np.arange(len(count)), min(args.batches, len(count)))
        u, n = shell_profile(count, vx, slice(None))
        fit = (radius >= args.fit_from) & (radius <= args.fit_to) & (n > 0)
        if fit.sum() < 3:
            sys.exit(f'channel_sphere: fewer than 3 shells of {path} in the fit range')
        u_inf, a_h = shell_fit(radius[fit], u[fit], n[fit])
        inside = radius + width / 2 <= args.radius + 1e-9
        per_batch = []
        for rows in batches:
            ub, nb = shell_profile(count, vx, rows)
            ok = fit & (nb > 0)
            fb = shell_fit(radius[ok], ub[ok], nb[ok])
            inside_n = nb[inside].sum()
            per_batch.append((*fb, inside_n, (ub[inside] * nb[inside]).sum() / max(inside_n, 1e-300),
                              *ub))
        per_batch = np.array(per_batch)
        err = standard_error(per_batch)
        inside_n = n[inside].sum()
        inside_u = (u[inside] * n[inside]).sum() / max(inside_n, 1e-300)
        print(f'{path}: {len(count)} blocks, {len(batches)} batches')
        print(f'  fit v_x = U_inf (1 - a_h / r) over {args.fit_from:g} <= r <= {args.fit_to:g}: '
              f'U_inf = {u_inf:.4f} +- {err[0]:.4f}, a_h = {a_h:.3f} +- {err[1]:.3f}')
        print(f'  fluid inside r < {args.radius:g}: {inside_n:.1f} +- {err[2]:.1f} particles, '
              f'mean v_x {inside_u:.4f} +- {err[3]:.4f} ({inside_u / u_inf:.3f} of U_inf)')
        print('  r      density   v_x       +-       v_x / U_inf   Stokes (1 - a_h/r)')
        for k, r in enumerate(radius):
            if n[k] <= 0:
                continue
            stokes = 1.0 - a_h / r if r > a_h else float('nan')
            print(f'  {r:5.3f}  {n[k] / volume[k]:7.3f}  {u[k]:8.4f}  {err[4 + k]:7.4f}  '
                  f'{u[k] / u_inf:8.3f}      {stokes:8.3f}')


def line_command(args):
    """A line profile through the sphere (in.sphere_shear's line files: bin/1d chunks in a thin
    column): per cell the number density (mean count over the cell's volume --cell-volume, since
    LAMMPS divides by the whole slab's) and the count-weighted v_x, over the blocks kept."""
    for path in args.files:
        blocks = read_kept_chunks(path, args.discard, 1)
        coord = blocks.column('Coord1')[0]
        centre = 0.5 * (coord[0] + coord[-1]) if args.centre is None else args.centre
        velocity, mean_count = shell_profile(blocks.column('Ncount'), blocks.column('vx'), slice(None))
        print(f'{path}: {len(blocks.steps)} blocks; distance from the centre, density, v_x')
        for k in range(len(coord)):
            print(f'  {coord[k] - centre:7.3f}  {mean_count[k] / args.cell_volume:6.3f}  '
                  f'{velocity[k]:7.4f}')


def add_drag_parser(sub, start_up):
    drag = sub.add_parser('drag', parents=[start_up], help='Re and C_D from drag files')
    drag.add_argument('files', nargs='*',
                      help='drag files; FILE1+FILE2 pools independent runs of one case')
    drag.add_argument('--series', action='append', help='label:file1,file2,... (file1a+file1b pools runs)')
    drag.add_argument('--rho', type=float, default=4.0, help='mass density of the fluid')
    drag.add_argument('--d', type=float, default=3.0, help='sphere diameter')
    drag.add_argument('--eta', type=float, default=1.083, help='dynamic viscosity')
    drag.add_argument('--U', type=float,
                      help='reference velocity instead of the mean fluid velocity (e.g. the '
                           'wall speed of in.sphere_shear)')
    drag.add_argument('--velocity', default='c_vfluid',
                      help='column of the reference velocity (v_vcore: the core fluid of '
                           'in.sphere_compliant)')
    drag.add_argument('--force', choices=['split', 'total'], default='split',
                      help='drag estimator: conservative + dissipative part (default, when the '
                           'file has the split) or the total force')
    drag.add_argument('--batches', type=int, default=10)
    drag.add_argument('--slit', type=float,
                      help='also a_h, the Stokes radius with the wall factor of two plane walls '
                           'this far from the sphere\'s centre taken out (in.sphere_shear)')
    drag.add_argument('--tube', type=float,
                      help='also a_h for a sphere on the axis of a tube of this radius in '
                           'Poiseuille flow (in.sphere_cylinder)')
    drag.add_argument('--centre-line', action='store_true',
                      help='with --tube: the reference velocity is the centre-line velocity, '
                           'not the mean')
    drag.add_argument('--png')
    drag.add_argument('--title')
    drag.add_argument('--json')


def add_profile_parsers(sub, start_up):
    radius = sub.add_parser('radius', parents=[start_up], help='mean wall radius along the axis')
    radius.add_argument('files', nargs='+')
    radius.add_argument('--batches', type=int, default=10)
    radius.add_argument('--png')
    radius.add_argument('--near', type=float,
                        help='also the mean radius of the bins within this distance of the sphere')
    radius.add_argument('--sphere-x', type=float,
                        help='the sphere\'s x (default: the middle of the bins)')
    radius.add_argument('--each', action='store_true',
                        help='print and plot the profile of every kept block, not their mean')
    velocity = sub.add_parser('velocity', parents=[start_up],
                              help='radial velocity profile away from the sphere')
    velocity.add_argument('files', nargs='+')
    velocity.add_argument('--fit', type=float, default=3.0,
                          help='fit the Poiseuille profile over r < this (default 3)')
    velocity.add_argument('--batches', type=int, default=5)
    velocity.add_argument('--sphere-x', type=float,
                          help='the sphere\'s x (default: the middle of the slabs)')
    velocity.add_argument('--png')
    density = sub.add_parser('density', parents=[start_up],
                             help='number density per ring away from the sphere')
    density.add_argument('files', nargs='+')
    density.add_argument('--rmin', type=float, default=0.0)
    density.add_argument('--rmax', type=float, default=1e30)
    density.add_argument('--png')
    shells = sub.add_parser('shells', parents=[start_up],
                            help='density and v_x in shells about the sphere, hydrodynamic radius')
    shells.add_argument('files', nargs='+')
    shells.add_argument('--fit-from', type=float, default=2.0)
    shells.add_argument('--fit-to', type=float, default=4.5)
    shells.add_argument('--radius', type=float, default=1.5,
                        help='the sphere\'s nominal radius (the fluid inside it is counted)')
    shells.add_argument('--batches', type=int, default=5)
    line = sub.add_parser('line', parents=[start_up],
                          help='density and v_x along a line of cells through the sphere')
    line.add_argument('files', nargs='+')
    line.add_argument('--cell-volume', type=float, default=0.4 * 0.4 * (20 * 4 ** (-1 / 3)) / 29,
                      help="volume of one cell (default: in.sphere_shear's 0.4 x H/29 x 0.4)")
    line.add_argument('--centre', type=float,
                      help='the sphere centre along the line (default: the middle of the cells)')


def parse_args(argv=None):
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest='command', required=True)
    start_up = argparse.ArgumentParser(add_help=False)     # every subcommand but tube
    start_up.add_argument('--discard', type=float, default=0.2,
                          help='fraction of the rows (blocks) dropped at the start')
    add_drag_parser(sub, start_up)
    add_profile_parsers(sub, start_up)
    tube = sub.add_parser('tube', help='wall factor of a sphere on the axis of a tube')
    tube.add_argument('radii', nargs='+', type=float, help='tube radii (the first is the reference)')
    tube.add_argument('--d', type=float, default=3.0, help='sphere diameter')
    args = parser.parse_args(argv)
    if not 0.0 <= getattr(args, 'discard', 0.0) < 1.0:     # every subcommand but tube has one
        sys.exit('channel_sphere: --discard must be in [0, 1)')
    return args


COMMANDS = {'drag': drag_command, 'radius': radius_command, 'velocity': velocity_command,
            'density': density_command, 'tube': tube_command, 'shells': shells_command,
            'line': line_command}


def main(argv=None):
    args = parse_args(argv)
    COMMANDS[args.command](args)


if __name__ == '__main__':
    main()
