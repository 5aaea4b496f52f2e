#!/usr/bin/python3
"""D from MSD and VACF (validation/diffusion/in.diffusion output) and the Schmidt number, one row per run
directory, with Mai-Duy, Phan-Thien and Tran-Cong's (2013) Table 1 side by side.
Usage: diffusion_table.py DIR:MASS:DT:INTEGRATOR[:ETA_MEASURED] ..."""
import argparse
import glob
import os
from typing import NamedTuple

import numpy as np
from scipy.integrate import trapezoid

from . import kinetic_theory
from .lammps_output import read_ave_time
from .statistics import standard_error

PAPER = {1.0: (0.10, 0.12, 6.0, 5.0), 0.1: (0.12, 0.13, 46.9, 43.3), 0.01: (0.15, 0.14, 372.3, 398.9),
         0.001: (0.15, 0.14, 3720.3, 3986.1)}    # D (MSD), D (VACF), Sc (MSD), Sc (VACF)
DENSITY = 4.0
GAMMA, EXPONENT, TEMPERATURE, CUTOFF = 4.5, 0.5, 1.0, 1.0    # the fluid of in.diffusion


class Run(NamedTuple):
    directory: str
    mass: float
    dt: float
    integrator: str
    eta_measured: float    # None when not given


def parse_run(text):
    """DIR:MASS:DT:INTEGRATOR[:ETA_MEASURED] (the integrator may hold spaces)."""
    parts = text.split(":")
    if len(parts) < 4:
        raise argparse.ArgumentTypeError(f"expected DIR:MASS:DT:INTEGRATOR[:ETA_MEASURED], got {text!r}")
    try:
        eta_measured = float(parts[4]) if len(parts) > 4 and parts[4] else None
        return Run(parts[0], float(parts[1]), float(parts[2]), parts[3], eta_measured)
    except ValueError:
        raise argparse.ArgumentTypeError(f"MASS, DT and ETA_MEASURED must be numbers: {text!r}") from None


def parse_args(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\nUsage")[0])
    parser.add_argument("runs", nargs="+", type=parse_run, metavar="DIR:MASS:DT:INTEGRATOR[:ETA_MEASURED]",
                        help="a run directory of validation/diffusion/run.sh (msd.txt, vacf.*.txt), its "
                             "mass, time step and integrator, and optionally the measured viscosity")
    return parser.parse_args(argv)


def kinetic_viscosity(mass):
    """Kinetic-theory viscosity of the fluid of in.diffusion at this mass."""
    fluid = kinetic_theory.FluidState(DENSITY, mass, TEMPERATURE, CUTOFF)
    return kinetic_theory.viscosity(fluid, GAMMA, EXPONENT)


def table(path):
    """Steps and values of a one-value fix ave/time file."""
    rows = read_ave_time(path).data
    return rows[:, 0], rows[:, 1]


def msd_diffusivity(directory, dt):
    """D from the slope of the MSD over the second half of the run."""
    steps, msd = table(os.path.join(directory, "msd.txt"))
    t = steps * dt
    half = t >= 0.5 * t[-1]
    slope = np.polyfit(t[half], msd[half], 1)[0]
    return slope / 6.0


def vacf_diffusivity(directory, dt):
    """D from the Green-Kubo integral of the VACF: mean and standard error over the origins."""
    values = []
    for path in sorted(glob.glob(os.path.join(directory, "vacf.*.txt"))):
        steps, c = table(path)
        t = (steps - steps[0]) * dt
        values.append(trapezoid(c, t) / 3.0)
    return float(np.mean(values)), float(standard_error(values))


def row(run):
    d_msd = msd_diffusivity(run.directory, run.dt)
    d_vacf, err = vacf_diffusivity(run.directory, run.dt)
    rho = DENSITY * run.mass
    eta = kinetic_viscosity(run.mass)
    sc = f"{eta / (rho * d_msd):.1f} / {eta / (rho * d_vacf):.1f}"
    eta_m = run.eta_measured
    sc_measured = f"{eta_m / (rho * d_msd):.1f} / {eta_m / (rho * d_vacf):.1f}" if eta_m else ""
    paper = PAPER.get(run.mass)
    pd = f"{paper[0]:.2f} / {paper[1]:.2f}" if paper else ""
    ps = f"{paper[2]:.1f} / {paper[3]:.1f}" if paper else ""
    return (f"| {run.mass:g} | {run.integrator} | {run.dt:g} | {d_msd:.4f} | {d_vacf:.4f} +- {err:.4f} | "
            f"{sc} | {sc_measured} | {pd} | {ps} |")


def main(argv=None):
    args = parse_args(argv)
    print("| m | integrator | dt | D (MSD) | D (VACF) | Sc = eta/(rho D), kinetic-theory eta | Sc, measured eta | paper D (MSD / VACF) | paper Sc (MSD / VACF) |")
    print("|---|---|---|---|---|---|---|---|---|")
    for run in args.runs:
        print(row(run))


if __name__ == "__main__":
    main()
