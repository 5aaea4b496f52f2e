#!/usr/bin/python3
"""Time to solution at equal accuracy: for each integrator and mass, the largest time step (of
a list) at which the equilibrium kBT is within 1 % of its target (capped where the viscosity
limits the step: VISCOSITY_MAX_DT), and the wall-clock seconds per unit of simulated time at
that step, all in one go on the same machine.

Usage: bench/time_to_solution.py LMP PLUGIN [--time T] [--out FILE] [--ranks N] [--masses M ...]
                                  [--implicit-newton on|off]
The system is validation/temperature/in.temperature_scan (4,000 atoms, n = 4, a = 18.75, gamma = 4.5,
s = 1/2, kBT = 1). Stock = pair dpd/ext (ws = s/2) + fix nve.
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
SCAN = os.path.join(HERE, "..", "validation", "temperature", "in.temperature_scan")
sys.path.insert(0, os.path.join(HERE, "..", "python"))
from etddpd.lammps_output import loop_times  # noqa: E402

# (label, pair, integrator, mass, candidate steps from small to large). At m = 0.0001 velocities
# relax within a few steps, so a shorter run (MASS_TIME) resolves kBT well enough.
MASS_TIME = {0.0001: 0.05}
CASES = [
    ("stock dpd/ext + nve", "stock", "nve", 0.01, [0.0003, 0.0005, 0.0007, 0.0009]),
    ("dpd/gen + etd (diagonal)", "gen", "etd", 0.01, [0.0003, 0.0005, 0.0007, 0.001]),
    ("dpd/gen + etd scheme implicit", "gen", "etd scheme implicit", 0.01, [0.002, 0.003, 0.0035, 0.004, 0.005]),
    ("dpd/gen + etd scheme implicit tol 1e-4", "gen", "etd scheme implicit tol 1e-4", 0.01,
     [0.003, 0.0035, 0.004, 0.005]),
    ("dpd/gen + etd scheme implicit tol 1e-4 start velocity", "gen", "etd scheme implicit tol 1e-4 start velocity",
     0.01, [0.003, 0.0035, 0.004, 0.005]),
    ("stock dpd/ext + nve", "stock", "nve", 0.001, [0.00003, 0.00005, 0.00007, 0.0001]),
    ("dpd/gen + etd (diagonal)", "gen", "etd", 0.001, [0.00005, 0.0001, 0.0002]),
    ("dpd/gen + etd scheme implicit", "gen", "etd scheme implicit", 0.001, [0.0005, 0.0007, 0.001, 0.0012, 0.0015]),
    ("dpd/gen + etd scheme implicit tol 1e-4", "gen", "etd scheme implicit tol 1e-4", 0.001,
     [0.001, 0.0012, 0.0015]),
    ("dpd/gen + etd scheme implicit tol 1e-4 start velocity", "gen", "etd scheme implicit tol 1e-4 start velocity",
     0.001, [0.001, 0.0012, 0.0015]),
    ("stock dpd/ext + nve", "stock", "nve", 0.0001, [0.000003, 0.000005, 0.000007, 0.00001]),
    ("dpd/gen + etd scheme implicit", "gen", "etd scheme implicit", 0.0001, [0.0001, 0.0002, 0.0003, 0.0005]),
    # the zero-mass limit has no temperature to judge: its step is the one validated in
    # validation/overdamped/README.md, timed against stock at m = 0.0001
    ("dpd/gen + etd scheme implicit overdamped yes", "gen", "etd scheme implicit overdamped yes", 0.0001,
     [0.003]),
]


# Where the viscosity, not kBT, bounds the step: the largest step whose viscosity is validated
# (validation/implicit/README.md); larger steps are still run and reported, never chosen.
VISCOSITY_MAX_DT = {0.001: 0.001}


# The implicit scheme on several ranks needs a newton-off neighbor list, which the pair style then
# shares instead of building a second (bench/README.md); the others keep LAMMPS's faster default.
def newton_setting(integrator, ranks, implicit_newton):
    return implicit_newton if "implicit" in integrator and ranks > 1 else "on"


def run(lmp, plugin, pair, integrator, mass, dt, time, workdir, equil=None, ranks=1, newton="on"):
    log = os.path.join(workdir, "log.lammps")
    equil = 0.25 * time if equil is None else equil
    mpi = []
    if ranks > 1:
        mpi = ["mpirun", "-np", str(ranks)] + (["--allow-run-as-root"] if os.geteuid() == 0 else [])
    cmd = mpi + [lmp, "-in", SCAN, "-var", "plugin", plugin, "-var", "pair", pair, "-var", "integrator",
           integrator, "-var", "mass", str(mass), "-var", "dt", str(dt), "-var", "time", str(time),
           "-var", "equil", str(equil), "-var", "friction_step", "yes" if "implicit" in integrator else "no",
           "-var", "newton", newton,
           "-log", log, "-screen", "none"]
    done = subprocess.run(cmd, cwd=workdir)
    text = open(log).read() if os.path.exists(log) else ""
    m = re.search(r"RESULT .*kBT=([0-9.]+)", text)
    loops = loop_times(text)
    friction = re.search(r"FRICTION_STEP kBT=([0-9.]+)", text)
    if done.returncode != 0 or not m or len(loops) < 2:
        print(f"run failed (exit {done.returncode}): {' '.join(cmd)}", file=sys.stderr)
        print("\n".join(text.splitlines()[-5:]), file=sys.stderr)
        return None, None, None
    cost = loops[-1].seconds / (loops[-1].steps * dt)
    return float(m.group(1)), cost, float(friction.group(1)) if friction else None


def parse_args(argv=None):
    parser = argparse.ArgumentParser()
    parser.add_argument("lmp")
    parser.add_argument("plugin")
    parser.add_argument("--time", type=float, default=0.4, help="production time units")
    parser.add_argument("--out", default=None)
    parser.add_argument("--rounds", type=int, default=3, help="timing rounds (fastest kept)")
    parser.add_argument("--ranks", type=int, default=1, help="MPI ranks")
    parser.add_argument("--masses", type=float, nargs="*", default=None, help="only these masses")
    parser.add_argument("--implicit-newton", choices=["on", "off"], default="off",
                        help="newton pair setting of the implicit scheme on several ranks (default off)")
    args = parser.parse_args(argv)
    # the runs work in temporary directories: relative paths would not resolve there
    args.plugin = os.path.abspath(args.plugin)
    return args


def run_case(args, workdir, pair, integrator, mass, dt, time, equil=None):
    return run(args.lmp, args.plugin, pair, integrator, mass, dt, time, workdir, equil=equil,
               ranks=args.ranks, newton=newton_setting(integrator, args.ranks, args.implicit_newton))


def scan(args, cases, workdir, lines):
    """Every candidate step of every case: a table row each (into lines, and printed as it
    comes); returns the largest step within 1 % of kBT = 1 per (mass, label), judged by the
    end-of-step kBT ({key: (dt, cost, pair, integrator)}) and by the friction-step kBT
    ({key: (dt, cost)})."""
    best, best_friction_step = {}, {}
    for label, pair, integrator, mass, steps in cases:
        for dt in steps:
            # the overdamped step has no velocity relaxation to resolve: it keeps the full length
            length = args.time if "overdamped" in integrator else MASS_TIME.get(mass, args.time)
            kT, cost, kT_friction = run_case(args, workdir, pair, integrator, mass, dt, length)
            shown = "fails" if kT is None else ("n/a" if "overdamped" in integrator else f"{kT:.4f}")
            shown_friction = "" if kT_friction is None or "overdamped" in integrator else f"{kT_friction:.4f}"
            lines.append(f"| {mass} | {label} | {dt} | {shown} | {shown_friction} | "
                         f"{'' if cost is None else f'{cost:.1f}'} |")
            print(lines[-1], flush=True)
            within_viscosity = dt <= VISCOSITY_MAX_DT.get(mass, float("inf")) or pair == "stock"
            if kT is not None and within_viscosity and (abs(kT - 1.0) <= 0.01 or "overdamped" in integrator):
                best[(mass, label)] = (dt, cost, pair, integrator)
            if "overdamped" in integrator:
                continue
            if kT_friction is not None and abs(kT_friction - 1.0) <= 0.01:
                best_friction_step[(mass, label)] = (dt, cost)
    return best, best_friction_step


def time_best(args, best, workdir):
    """Time every chosen configuration for 400 steps, in rounds, keeping each one's fastest
    (other load on the machine only slows runs down). The timed steps start from a relaxed fluid
    (the solver iterates more right after the random start, where atoms overlap)."""
    for _ in range(args.rounds):
        for key, (dt, cost, pair, integrator) in best.items():
            _, seconds, _ = run_case(args, workdir, pair, integrator, key[0], dt, 400 * dt,
                                     equil=max(100 * dt, 0.02))
            if seconds is not None and seconds < best[key][1]:
                best[key] = (dt, seconds, pair, integrator)


def speed_up_lines(cases, best, best_friction_step):
    """The two tables of the chosen steps and their speed-up over stock."""
    lines = ["", "Largest step within 1 % of kBT = 1 (and, at m = 0.001, no larger than the step where the",
             "viscosity is validated) and time to solution against stock (seconds per time unit: fastest",
             "of the scan run and the timing rounds):", "",
             "| mass | integrator | largest dt | s per time unit | speed-up over stock |", "|---|---|---|---|---|"]
    for mass in sorted({c[3] for c in cases}, reverse=True):
        stock = best.get((mass, "stock dpd/ext + nve"))
        for label in dict.fromkeys(c[0] for c in cases if c[3] == mass):
            if (mass, label) not in best:
                lines.append(f"| {mass} | {label} | none of the list | | |")
                continue
            dt, cost = best[(mass, label)][:2]
            ratio = f"{stock[1] / cost:.2f}" if stock else "n/a"
            lines.append(f"| {mass} | {label} | {dt} | {cost:.1f} | {ratio} |")
    lines += ["", "The implicit scheme judged by the kBT of its friction-step velocities (fix output 5, free of",
              "the splitting's end-of-step deficit dt^2 <F^2>/(4 m kBT); cost per time unit from the scan run):", "",
              "| mass | integrator | largest dt | s per time unit | speed-up over stock |", "|---|---|---|---|---|"]
    for (mass, label), (dt, cost) in sorted(best_friction_step.items(), key=lambda item: -item[0][0]):
        stock = best.get((mass, "stock dpd/ext + nve"))
        ratio = f"{stock[1] / cost:.2f}" if stock else "n/a"
        lines.append(f"| {mass} | {label} | {dt} | {cost:.1f} | {ratio} |")
    return lines


def main(argv=None):
    args = parse_args(argv)
    cases = [c for c in CASES if args.masses is None or c[3] in args.masses]
    implicit_newton = newton_setting("implicit", args.ranks, args.implicit_newton)
    lines = [f"MPI ranks: {args.ranks}; newton {implicit_newton} for the implicit scheme, on for the others", "",
             "| mass | integrator | dt | kBT | kBT after the friction step | s per time unit |",
             "|---|---|---|---|---|---|"]
    with tempfile.TemporaryDirectory() as workdir:
        best, best_friction_step = scan(args, cases, workdir, lines)
        time_best(args, best, workdir)
    lines += speed_up_lines(cases, best, best_friction_step)
    text = "\n".join(lines) + "\n"
    print(text)
    if args.out:
        with open(args.out, "w") as f:
            f.write(text)


if __name__ == "__main__":
    main()
