#!/usr/bin/python3
"""Drag coefficient against the Reynolds number from a mass scan of examples/sphere-couette
(validation/sphere-couette/scan.sh mass OUTDIR), as Figure 10 of Mai-Duy, Phan-Thien and Khoo (2013):
Re = 2 a U rho / eta and C_d = F / (0.5 pi a^2 rho U^2), rho = n m the mass density, a the middle
of the eq 38 range of the effective radius, eta fixed (the paper's 3.9682); Stokes: C_d = 24/Re.

usage: python/sphere_couette_cd.py [LABEL=]OUTDIR ... [--png FILE] [--U U] [--eta ETA] [--density N]
Each OUTDIR holds mass_<m>/table.txt (the output of python/sphere_couette.py for each mass); with
several, each gets its table and its series in the plot (LABEL names it).
"""
import argparse
import glob
import math
import os
import re
import sys


def parse_table(path):
    """drag F_x (mean, error), a_eff range, mid-plane kBT from a python/sphere_couette.py table."""
    with open(path) as f:
        text = f.read()
    m = re.search(r"drag F_x\s+([-\d.]+) \+- ([\d.na]+)", text)
    a = re.search(r"a_eff sphere \(eq 38\)\s+([\d.]+)-([\d.]+)", text)
    t = re.search(r"kBT mid-plane \(r > 1.5\)\s+([\d.]+)", text)
    if not (m and a and t):
        raise ValueError(f"{path}: not a python/sphere_couette.py table")
    return float(m.group(1)), float(m.group(2)), float(a.group(1)), float(a.group(2)), float(t.group(1))


def rows(outdir, U, eta, density):
    out = []
    for path in glob.glob(os.path.join(outdir, "mass_*", "table.txt")):
        mass = float(os.path.basename(os.path.dirname(path))[len("mass_"):])
        F, dF, a_lo, a_hi, kT = parse_table(path)
        a = 0.5 * (a_lo + a_hi)
        rho = density * mass
        Re = 2.0 * a * U * rho / eta
        scale = 0.5 * math.pi * a * a * rho * U * U
        out.append({"m": mass, "Re": Re, "F": F, "dF": dF, "Cd": F / scale, "dCd": dF / scale,
                    "stokes": 24.0 / Re, "kT": kT, "a": a})
    return sorted(out, key=lambda r: r["m"])


def parse_args(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("outdirs", nargs="+")
    ap.add_argument("--png", default=None)
    ap.add_argument("--U", type=float, default=3.0)
    ap.add_argument("--eta", type=float, default=3.9682)
    ap.add_argument("--density", type=float, default=4.0)
    return ap.parse_args(argv)


def print_table(table):
    print(f"{'m':>7} {'Re':>7} {'F':>16} {'C_d':>16} {'24/Re':>8} {'C_d Re/24':>14} {'kBT':>7}")
    for r in table:
        ratio, dratio = r["Cd"] / r["stokes"], r["dCd"] / r["stokes"]
        print(f"{r['m']:7.3f} {r['Re']:7.4f} {r['F']:8.1f} +- {r['dF']:5.1f} {r['Cd']:8.1f} +- {r['dCd']:5.1f}"
              f" {r['stokes']:8.1f} {ratio:7.3f} +- {dratio:.3f} {r['kT']:7.4f}")


def plot(series, png):
    """C_d against Re of every series, log-log, with Stokes' 24/Re."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(5, 4))
    for k, (label, table) in enumerate(series):
        shift = 1.0 + 0.04 * k    # side by side where the Re are the same
        ax.errorbar([shift * r["Re"] for r in table], [r["Cd"] for r in table],
                    yerr=[r["dCd"] for r in table], fmt="os^"[k % 3], capsize=3, label=label)
    res = [r["Re"] for _, table in series for r in table]
    lo, hi = 0.8 * min(res), 1.25 * max(res)
    ax.plot([lo, hi], [24.0 / lo, 24.0 / hi], "k-", label="Stokes, 24/Re")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("Re = 2 a U rho / eta")
    ax.set_ylabel("C_d = F / (0.5 pi a^2 rho U^2)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png, dpi=120)


def main(argv=None):
    args = parse_args(argv)
    series = []
    for spec in args.outdirs:
        label, _, outdir = spec.rpartition("=")
        table = rows(outdir, args.U, args.eta, args.density)
        if not table:
            sys.exit(f"no mass_*/table.txt under {outdir}")
        series.append((label or "fix etd scheme diagonal, reduced box", table))
    for label, table in series:
        if len(series) > 1:
            print(f"# {label}")
        print_table(table)
    if args.png:
        plot(series, args.png)


if __name__ == "__main__":
    main()
