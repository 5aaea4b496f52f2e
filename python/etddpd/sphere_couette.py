#!/usr/bin/python3
"""Post-process examples/sphere-couette: drag on the sphere and its conservative, dissipative and
random parts (means over the steady window), effective radius from the sphere-solvent g(q)
(Mai-Duy, Phan-Thien and Khoo 2013, eq 38), Stokes drag 6 pi eta a U (eq 39), u_x at the
upstream/downstream planes against the Stokes solution (eq 40), mid-plane maps as PNG.

usage: python/sphere_couette.py [DIR] [--from-step N] [--png PREFIX] [--mass M] [--U U] [--eta ETA]
DIR holds drag.sphere-couette, rdf.sphere-couette, map.sphere-couette (default: .).
"""
import argparse
import math
import os
import sys

import numpy as np

from .lammps_output import read_ave_chunk, read_ave_time, read_ave_time_vector
from .statistics import batch_means, standard_error

PAPER = {"F": 178.36, "FC": 47.53, "FD": 130.73, "FR": 0.10, "qbar": 0.95, "a_lo": 0.79, "a_hi": 0.84,
         "F_stokes_lo": 177.27, "F_stokes_hi": 188.49, "ux_up": 2.8651, "ux_down": 2.8323}
# columns of drag.sphere-couette (v_Fx, then c_drag[1..9]: x, y, z of the conservative,
# dissipative and random parts)
DRAG_COLUMNS = {"F": 1, "FC": 2, "FD": 5, "FR": 8}


def first_nonzero(r, g, dq, threshold=0.05):
    """Inner edge of the first bin where g exceeds the threshold (the paper's q-bar)."""
    idx = np.nonzero(g > threshold)[0]
    return r[idx[0]] - 0.5 * dq if len(idx) else float("nan")


def block_error(x, nblocks=10):
    """Standard error of the mean from nblocks contiguous blocks (nan for fewer samples)."""
    if len(x) // nblocks < 1:
        return float("nan")
    return standard_error(batch_means(x, nblocks, keep="first"))


def parse_args(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("dir", nargs="?", default=".")
    ap.add_argument("--from-step", type=int, default=None,
                    help="first step of the steady window (default: the equilibration the rdf/map windows skip)")
    ap.add_argument("--png", default=None, help="write PREFIX_maps.png (temperature and u_x at y = 0)")
    ap.add_argument("--mass", type=float, default=0.01)
    ap.add_argument("--U", type=float, default=3.0)
    ap.add_argument("--eta", type=float, default=3.9682, help="solvent viscosity (kinetic theory, paper)")
    ap.add_argument("--density", type=float, default=4.0)
    return ap.parse_args(argv)


def steady_start(from_step, drag_steps, map_steps):
    """First step of the steady window. The rdf/map blocks cover the production run only, so by
    default the window starts one block before the first of them, where the equilibration ends."""
    if from_step is not None:
        return from_step
    if len(map_steps) > 1:
        return map_steps[0] - (map_steps[1] - map_steps[0])
    return int(0.2 * drag_steps[-1])


def drag_parts(drag, window):
    """Means and errors of the drag and its parts over the window, and the side forces."""
    means = {k: drag[window, c].mean() for k, c in DRAG_COLUMNS.items()}
    errors = {k: block_error(drag[window, c]) for k, c in DRAG_COLUMNS.items()}
    side = {"Fy": drag[window, 3] + drag[window, 6] + drag[window, 9],
            "Fz": drag[window, 4] + drag[window, 7] + drag[window, 10]}
    return means, errors, side


def effective_radius(rdf, args):
    """q-bar of the sphere-solvent and solvent-solvent g(q), the eq 38 range of the sphere's
    effective radius and the Stokes drag of its ends."""
    r, g_cs, g_ss = rdf[:, 1], rdf[:, 2], rdf[:, 4]
    dq = r[1] - r[0]
    qbar_c = first_nonzero(r, g_cs, dq)
    qbar_s = first_nonzero(r, g_ss, dq)
    a_s = qbar_s / 2
    a_lo, a_hi = qbar_c - a_s, qbar_c + dq - a_s
    stokes = [6 * math.pi * args.eta * a * args.U for a in (a_lo, a_hi)]
    return {"qbar_c": qbar_c, "a_s": a_s, "a_lo": a_lo, "a_hi": a_hi, "stokes": stokes}


def mid_plane(m, a_mid, args):
    """Temperature and u_x of the mid-plane map: u_x at the upstream and downstream planes
    against the Stokes solution (eq 40), the mean kBT away from the sphere."""
    x, z, count = m[:, 1], m[:, 2], m[:, 3]
    vx, vy, vz, vx2, vy2, vz2 = (m[:, k] for k in range(5, 11))
    kT = args.mass * ((vx2 - vx ** 2) + (vy2 - vy ** 2) + (vz2 - vz ** 2)) / 3
    xs, zs = np.unique(x), np.unique(z)
    centre = np.abs(z) < 0.5
    up = centre & (x == xs[0])
    down = centre & (x == xs[-1])
    L = abs(xs[0]) / a_mid
    # bins inside the walls' reach and the sphere's core are skipped for the temperature check
    fluid = (count > 0) & (np.hypot(x, z) > 1.5)
    return {"x": x, "z": z, "xs": xs, "zs": zs, "count": count, "vx": vx, "kT": kT,
            "ux_up": vx[up].mean(), "ux_down": vx[down].mean(), "L": L,
            "ux_stokes": args.U * (1 - 3 / (4 * L) + 1 / (4 * L ** 3)),
            "kT_mean": np.average(kT[fluid], weights=count[fluid])}


def print_table(from_step, nsamples, means, errors, side, radius, plane):
    print(f"steady window: steps > {from_step} ({nsamples} samples of 100 steps)")
    print(f"{'quantity':<28}{'this run':>18}{'paper':>18}")

    def row(name, ours, paper):
        print(f"{name:<28}{ours:>18}{paper:>18}")
    for k, name in (("F", "drag F_x"), ("FC", "  conservative F_C"), ("FD", "  dissipative F_D"),
                    ("FR", "  random F_R")):
        row(name, f"{means[k]:.2f} +- {errors[k]:.2f}", f"{PAPER[k]:.2f}")
    row("side forces F_y, F_z", f"{side['Fy'].mean():.2f}, {side['Fz'].mean():.2f}", "~0")
    row("q-bar sphere-solvent", f"{radius['qbar_c']:.2f}", f"{PAPER['qbar']:.2f}")
    row("a_eff solvent (q-bar/2)", f"{radius['a_s']:.3f}", "0.16")
    row("a_eff sphere (eq 38)", f"{radius['a_lo']:.2f}-{radius['a_hi']:.2f}",
        f"{PAPER['a_lo']:.2f}-{PAPER['a_hi']:.2f}")
    row("Stokes 6 pi eta a U", f"{radius['stokes'][0]:.1f}-{radius['stokes'][1]:.1f}",
        f"{PAPER['F_stokes_lo']:.1f}-{PAPER['F_stokes_hi']:.1f}")
    xs = plane["xs"]
    row(f"u_x upstream x={xs[0]:.2f}", f"{plane['ux_up']:.4f}", f"{PAPER['ux_up']:.4f}")
    row(f"u_x downstream x={xs[-1]:.2f}", f"{plane['ux_down']:.4f}", f"{PAPER['ux_down']:.4f}")
    row(f"Stokes u_x (eq 40), L={plane['L']:.2f}", f"{plane['ux_stokes']:.4f}", "2.9093")
    row("kBT mid-plane (r > 1.5)", f"{plane['kT_mean']:.4f}", "0.25")


def plot_maps(plane, a_mid, prefix):
    """kBT and u_x on the mid-plane y = 0, the sphere's effective radius drawn."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    x, z, xs, zs, count = plane["x"], plane["z"], plane["xs"], plane["zs"], plane["count"]
    shape = (len(xs), len(zs))
    order = np.lexsort((z, x))

    def grid(values):
        return values[order].reshape(shape).T
    fig, axes = plt.subplots(1, 2, figsize=(9, 3.6))
    extent = [xs[0] - 0.25, xs[-1] + 0.25, zs[0] - 0.25, zs[-1] + 0.25]
    for ax, values, title in ((axes[0], np.where(count > 0, plane["kT"], np.nan), "$k_BT$"),
                              (axes[1], np.where(count > 0, plane["vx"], np.nan), "$u_x$")):
        im = ax.imshow(grid(values), origin="lower", extent=extent, cmap="viridis", aspect="equal")
        ax.add_patch(plt.Circle((0, 0), a_mid, fill=False, color="w", lw=1))
        ax.set_title(f"{title} on y = 0")
        ax.set_xlabel("x")
        ax.set_ylabel("z")
        fig.colorbar(im, ax=ax, shrink=0.8)
    fig.tight_layout()
    fig.savefig(prefix + "_maps.png", dpi=80)
    print(f"wrote {prefix}_maps.png")


def main(argv=None):
    args = parse_args(argv)
    drag = read_ave_time(os.path.join(args.dir, "drag.sphere-couette")).data
    rdf = read_ave_time_vector(os.path.join(args.dir, "rdf.sphere-couette"))
    maps = read_ave_chunk(os.path.join(args.dir, "map.sphere-couette"))
    from_step = steady_start(args.from_step, drag[:, 0], maps.steps)
    window = drag[:, 0] > from_step
    means, errors, side = drag_parts(drag, window)
    radius = effective_radius(rdf.data[rdf.steps > from_step].mean(axis=0), args)
    a_mid = 0.5 * (radius["a_lo"] + radius["a_hi"])
    plane = mid_plane(maps.data[maps.steps > from_step].mean(axis=0), a_mid, args)
    print_table(from_step, window.sum(), means, errors, side, radius, plane)
    if args.png:
        plot_maps(plane, a_mid, args.png)
    return 0


if __name__ == "__main__":
    sys.exit(main())
