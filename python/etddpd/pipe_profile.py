#!/usr/bin/python3
"""Post-process examples/pipe: fit the Hagen-Poiseuille parabola u_x = A - B r^2 to the axial
velocity over annuli r < R - skip, per block, and report the viscosity eta = n F / (4 B), the
radius where the fitted profile vanishes, R0 = sqrt(A / B), the slip length at the wall,
b = u(R) / |du/dr|(R) = (A - B R^2) / (2 B R) (R0 = R + b to first order), the density and the
radial temperature m <v_r^2>. Errors are standard errors over the blocks.

usage: python/pipe_profile.py profile.pipe [--R 5] [--force 0.1] [--mass 0.01] [--skip 1.0] [--png FILE]
"""
import argparse
import math
import sys

import numpy as np

from .lammps_output import read_ave_chunk
from .statistics import standard_error

# the annuli's columns in examples/pipe's fix ave/chunk file
RADIUS, VELOCITY, RADIAL_V2, DENSITY = 'Coord1', 'vx', 'v_vr2', 'density/number'


def fit(block, R, force, skip, columns):
    """Parabola u = A - B r^2 over the annuli r < R - skip of one block: eta, R0, slip, u0 and
    the density there."""
    r, u, n = (block[:, columns.index(name)] for name in (RADIUS, VELOCITY, DENSITY))
    core = r < R - skip
    B, A = np.polyfit(r[core] ** 2, u[core], 1)
    B = -B
    density = np.average(n[core], weights=r[core])
    return {"eta": density * force / (4.0 * B), "R0": math.sqrt(A / B) if A > 0 and B > 0 else float("nan"),
            "slip": (A - B * R * R) / (2.0 * B * R), "u0": A, "density": density}


def parse_args(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("profile")
    ap.add_argument("--R", type=float, default=5.0)
    ap.add_argument("--force", type=float, default=0.1)
    ap.add_argument("--mass", type=float, default=0.01)
    ap.add_argument("--skip", type=float, default=1.0, help="leave out annuli within this of the wall")
    ap.add_argument("--png", default=None)
    return ap.parse_args(argv)


def print_fits(fits, args):
    """Mean and standard error over the blocks of each fitted number."""
    print(f"{len(fits)} blocks, fit over r < {args.R - args.skip:g} (R = {args.R:g})")
    for key, label in (("u0", "centre velocity A"), ("eta", "viscosity n F / (4 B)"),
                       ("R0", "no-slip radius sqrt(A/B)"), ("slip", "slip length at r = R"),
                       ("density", "density (fit range)")):
        vals = np.array([f[key] for f in fits])
        print(f"{label:28s} {vals.mean():9.4f} +- {standard_error(vals):.4f}")


def print_profile(r, u, kT, n):
    """The radial temperature and the density of the block-averaged profile."""
    print(f"{'radial kBT, r < 2':28s} {np.average(kT[r < 2], weights=r[r < 2]):9.4f}")
    print(f"{'radial kBT, outer annulus':28s} {kT[-1]:9.4f}  (r = {r[-1]:.3f})")
    print(f"{'density, outer annulus':28s} {n[-1]:9.4f}")


def plot(fits, r, u, kT, n, args):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    eta = np.mean([f["eta"] for f in fits])
    A = np.mean([f["u0"] for f in fits])
    B = A / np.mean([f["R0"] for f in fits]) ** 2
    fig, ax = plt.subplots(1, 2, figsize=(9, 3.5))
    ax[0].plot(r, u, "o", ms=3, label="measured")
    rr = np.linspace(0, args.R, 100)
    ax[0].plot(rr, A - B * rr * rr, "-", label=f"parabola, eta = {eta:.3f}")
    ax[0].axvline(args.R, color="k", lw=0.8)
    ax[0].set_xlabel("r")
    ax[0].set_ylabel("u_x")
    ax[0].legend()
    ax[1].plot(r, n, "o-", ms=3, color="C0")
    ax[1].set_ylabel("number density", color="C0")
    ax[1].set_xlabel("r")
    twin = ax[1].twinx()
    twin.plot(r, kT, "s-", ms=3, color="C1")
    twin.set_ylabel("radial kBT = m <v_r^2>", color="C1")
    fig.tight_layout()
    fig.savefig(args.png, dpi=120)


def main(argv=None):
    args = parse_args(argv)
    profile = read_ave_chunk(args.profile)
    if len(profile.steps) < 2:
        sys.exit(f"{args.profile}: need at least 2 blocks, found {len(profile.steps)}")
    fits = [fit(block, args.R, args.force, args.skip, profile.names) for block in profile.data]
    print_fits(fits, args)
    mean = profile.data.mean(axis=0)
    r, u, v_r2, n = (mean[:, profile.names.index(name)] for name in (RADIUS, VELOCITY, RADIAL_V2, DENSITY))
    kT = args.mass * v_r2
    print_profile(r, u, kT, n)
    if args.png:
        plot(fits, r, u, kT, n, args)


if __name__ == "__main__":
    main()
