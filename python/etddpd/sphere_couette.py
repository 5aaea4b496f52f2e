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

from .lammps_output import read_blocks

PAPER = {"F": 178.36, "FC": 47.53, "FD": 130.73, "FR": 0.10, "qbar": 0.95, "a_lo": 0.79, "a_hi": 0.84,
         "F_stokes_lo": 177.27, "F_stokes_hi": 188.49, "ux_up": 2.8651, "ux_down": 2.8323}


def first_nonzero(r, g, dq, threshold=0.05):
    """Inner edge of the first bin where g exceeds the threshold (the paper's q-bar)."""
    idx = np.nonzero(g > threshold)[0]
    return r[idx[0]] - 0.5 * dq if len(idx) else float("nan")


def block_error(x, nblocks=10):
    n = len(x) // nblocks
    if n < 1:
        return float("nan")
    means = x[: n * nblocks].reshape(nblocks, n).mean(axis=1)
    return means.std(ddof=1) / math.sqrt(nblocks)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("dir", nargs="?", default=".")
    ap.add_argument("--from-step", type=int, default=None,
                    help="first step of the steady window (default: the equilibration the rdf/map windows skip)")
    ap.add_argument("--png", default=None, help="write PREFIX_maps.png (temperature and u_x at y = 0)")
    ap.add_argument("--mass", type=float, default=0.01)
    ap.add_argument("--U", type=float, default=3.0)
    ap.add_argument("--eta", type=float, default=3.9682, help="solvent viscosity (kinetic theory, paper)")
    ap.add_argument("--density", type=float, default=4.0)
    args = ap.parse_args()
    d = args.dir

    drag = np.loadtxt(os.path.join(d, "drag.sphere-couette"))
    steps = drag[:, 0]
    rdf_blocks = read_blocks(os.path.join(d, "rdf.sphere-couette"))
    map_blocks = read_blocks(os.path.join(d, "map.sphere-couette"))
    # the rdf/map blocks cover the production run only: the first block ends one block after
    # the equilibration, which the drag means skip too
    if args.from_step is None:
        if len(map_blocks) > 1:
            args.from_step = map_blocks[0][0] - (map_blocks[1][0] - map_blocks[0][0])
        else:
            args.from_step = int(0.2 * steps[-1])
    window = steps > args.from_step
    cols = {"F": 1, "FC": 2, "FD": 5, "FR": 8}
    means = {k: drag[window, c].mean() for k, c in cols.items()}
    errors = {k: block_error(drag[window, c]) for k, c in cols.items()}
    side = {"Fy": drag[window, 3] + drag[window, 6] + drag[window, 9],
            "Fz": drag[window, 4] + drag[window, 7] + drag[window, 10]}

    rdf = np.mean([b for st, b in rdf_blocks if st > args.from_step], axis=0)
    r, g_cs, g_ss = rdf[:, 1], rdf[:, 2], rdf[:, 4]
    dq = r[1] - r[0]
    qbar_c = first_nonzero(r, g_cs, dq)
    qbar_s = first_nonzero(r, g_ss, dq)
    a_s = qbar_s / 2
    a_lo, a_hi = qbar_c - a_s, qbar_c + dq - a_s
    stokes = [6 * math.pi * args.eta * a * args.U for a in (a_lo, a_hi)]

    m = np.mean([b for st, b in map_blocks if st > args.from_step], axis=0)
    x, z, count, dens = m[:, 1], m[:, 2], m[:, 3], m[:, 4]
    vx, vy, vz, vx2, vy2, vz2 = (m[:, k] for k in range(5, 11))
    kT = args.mass * ((vx2 - vx ** 2) + (vy2 - vy ** 2) + (vz2 - vz ** 2)) / 3
    xs, zs = np.unique(x), np.unique(z)
    centre = np.abs(z) < 0.5
    up = centre & (x == xs[0])
    down = centre & (x == xs[-1])
    ux_up, ux_down = vx[up].mean(), vx[down].mean()
    a_mid = 0.5 * (a_lo + a_hi)
    L = abs(xs[0]) / a_mid
    ux_stokes = args.U * (1 - 3 / (4 * L) + 1 / (4 * L ** 3))
    # bins inside the walls' reach and the sphere's core are skipped for the temperature check
    fluid = (count > 0) & (np.hypot(x, z) > 1.5)
    kT_mean = np.average(kT[fluid], weights=count[fluid])

    print(f"steady window: steps > {args.from_step} ({window.sum()} samples of 100 steps)")
    print(f"{'quantity':<28}{'this run':>18}{'paper':>18}")
    def row(name, ours, paper):
        print(f"{name:<28}{ours:>18}{paper:>18}")
    for k, name in (("F", "drag F_x"), ("FC", "  conservative F_C"), ("FD", "  dissipative F_D"),
                    ("FR", "  random F_R")):
        row(name, f"{means[k]:.2f} +- {errors[k]:.2f}", f"{PAPER[k]:.2f}")
    row("side forces F_y, F_z", f"{side['Fy'].mean():.2f}, {side['Fz'].mean():.2f}", "~0")
    row("q-bar sphere-solvent", f"{qbar_c:.2f}", f"{PAPER['qbar']:.2f}")
    row("a_eff solvent (q-bar/2)", f"{a_s:.3f}", "0.16")
    row("a_eff sphere (eq 38)", f"{a_lo:.2f}-{a_hi:.2f}", f"{PAPER['a_lo']:.2f}-{PAPER['a_hi']:.2f}")
    row("Stokes 6 pi eta a U", f"{stokes[0]:.1f}-{stokes[1]:.1f}",
        f"{PAPER['F_stokes_lo']:.1f}-{PAPER['F_stokes_hi']:.1f}")
    row(f"u_x upstream x={xs[0]:.2f}", f"{ux_up:.4f}", f"{PAPER['ux_up']:.4f}")
    row(f"u_x downstream x={xs[-1]:.2f}", f"{ux_down:.4f}", f"{PAPER['ux_down']:.4f}")
    row(f"Stokes u_x (eq 40), L={L:.2f}", f"{ux_stokes:.4f}", "2.9093")
    row("kBT mid-plane (r > 1.5)", f"{kT_mean:.4f}", "0.25")

    if args.png:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        shape = (len(xs), len(zs))
        order = np.lexsort((z, x))
        def grid(values):
            return values[order].reshape(shape).T
        fig, axes = plt.subplots(1, 2, figsize=(9, 3.6))
        extent = [xs[0] - 0.25, xs[-1] + 0.25, zs[0] - 0.25, zs[-1] + 0.25]
        for ax, values, title in ((axes[0], np.where(count > 0, kT, np.nan), "$k_BT$"),
                                  (axes[1], np.where(count > 0, vx, np.nan), "$u_x$")):
            im = ax.imshow(grid(values), origin="lower", extent=extent, cmap="viridis", aspect="equal")
            ax.add_patch(plt.Circle((0, 0), a_mid, fill=False, color="w", lw=1))
            ax.set_title(f"{title} on y = 0")
            ax.set_xlabel("x")
            ax.set_ylabel("z")
            fig.colorbar(im, ax=ax, shrink=0.8)
        fig.tight_layout()
        fig.savefig(args.png + "_maps.png", dpi=80)
        print(f"wrote {args.png}_maps.png")
    return 0


if __name__ == "__main__":
    sys.exit(main())
