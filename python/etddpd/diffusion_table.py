#!/usr/bin/python3
"""D from MSD and VACF (validation/diffusion/in.diffusion output) and the Schmidt number, one row per run
directory, with Mai-Duy, Phan-Thien and Tran-Cong's (2013) Table 1 side by side.
Usage: diffusion_table.py DIR:MASS:DT:INTEGRATOR[:ETA_MEASURED] ..."""
import glob
import os
import sys

import numpy as np

PAPER = {1.0: (0.10, 0.12, 6.0, 5.0), 0.1: (0.12, 0.13, 46.9, 43.3), 0.01: (0.15, 0.14, 372.3, 398.9),
         0.001: (0.15, 0.14, 3720.3, 3986.1)}    # D (MSD), D (VACF), Sc (MSD), Sc (VACF)
DENSITY = 4.0


def kinetic_viscosity(mass):
    # kinetic theory of this fluid (s = 1/2, gamma = 4.5, n = 4, rc = 1, kBT = 1): dissipative
    # part 2.2282, kinetic part 0.1741 m (src/kinetic_theory.h, unit test HalfExponentCheckValues)
    return 2.228219 + 0.174076 * mass


def table(path):
    rows = np.loadtxt(path, comments="#")
    return rows[:, 0], rows[:, 1]


def msd_diffusivity(directory, dt):
    steps, msd = table(os.path.join(directory, "msd.txt"))
    t = steps * dt
    half = t >= 0.5 * t[-1]
    slope = np.polyfit(t[half], msd[half], 1)[0]
    return slope / 6.0


def vacf_diffusivity(directory, dt):
    values = []
    for path in sorted(glob.glob(os.path.join(directory, "vacf.*.txt"))):
        steps, c = table(path)
        t = (steps - steps[0]) * dt
        values.append(np.trapz(c, t) / 3.0)
    return float(np.mean(values)), float(np.std(values, ddof=1) / np.sqrt(len(values)))


def main():
    print("| m | integrator | dt | D (MSD) | D (VACF) | Sc = eta/(rho D), kinetic-theory eta | Sc, measured eta | paper D (MSD / VACF) | paper Sc (MSD / VACF) |")
    print("|---|---|---|---|---|---|---|---|---|")
    for arg in sys.argv[1:]:
        parts = arg.split(":")
        directory, mass, dt, integrator = parts[0], float(parts[1]), float(parts[2]), parts[3]
        eta_measured = float(parts[4]) if len(parts) > 4 and parts[4] else None
        d_msd = msd_diffusivity(directory, dt)
        d_vacf, err = vacf_diffusivity(directory, dt)
        rho = DENSITY * mass
        eta = kinetic_viscosity(mass)
        sc = f"{eta / (rho * d_msd):.1f} / {eta / (rho * d_vacf):.1f}"
        sc_measured = (f"{eta_measured / (rho * d_msd):.1f} / {eta_measured / (rho * d_vacf):.1f}"
                       if eta_measured else "")
        paper = PAPER.get(mass)
        pd = f"{paper[0]:.2f} / {paper[1]:.2f}" if paper else ""
        ps = f"{paper[2]:.1f} / {paper[3]:.1f}" if paper else ""
        print(f"| {mass:g} | {integrator} | {dt:g} | {d_msd:.4f} | {d_vacf:.4f} +- {err:.4f} | {sc} | {sc_measured} | {pd} | {ps} |")


if __name__ == "__main__":
    main()
