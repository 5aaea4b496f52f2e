#!/usr/bin/env python3
"""Summarise a LAMMPS log: mean temperature of the last run, throughput, where outputs went."""
import argparse
import os
import sys

import numpy as np

from .lammps_output import loop_times, thermo_tables


def parse_args(argv=None):
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("log")
    parser.add_argument("--target-temperature", type=float, default=None)
    parser.add_argument("--wall", type=float, default=None, help="wall-clock seconds of the job")
    parser.add_argument("--outputs", default=None, help="folder holding the outputs")
    return parser.parse_args(argv)


def production_temperatures(text, log):
    """Temp of the last thermo table of the log, its first row (the start) left out."""
    tables = thermo_tables(text, log)
    if not tables:
        sys.exit("no thermo output in " + log)
    last = tables[-1]
    if "Temp" not in last.names:
        sys.exit(f"no Temp column in the last thermo table of {log} (columns: {' '.join(last.names)})")
    return last.column("Temp")[1:]


def temperature_line(label, temps, target):
    mean = float(np.mean(temps))
    spread = float(np.std(temps, ddof=1)) if len(temps) > 1 else 0.0
    line = f"  {label}: {mean:.4f} (sample spread {spread:.4f}, {len(temps)} samples)"
    if target:
        line += f"; target {target}, deviation {100 * (mean / target - 1):+.2f} %"
    return line


def print_summary(temps, loop, args):
    print("ETD-DPD run summary")
    print(f"  atoms {loop.atoms}, MPI ranks {loop.procs}, steps {loop.steps}, loop time {loop.seconds:.2f} s")
    print(temperature_line("temperature (kBT) over the production run", temps, args.target_temperature))
    print(f"  throughput: {loop.steps * loop.atoms / loop.seconds:.3e} atom-steps/s")
    if args.wall is not None:
        print(f"  wall-clock of the whole job: {args.wall:.1f} s")
    if args.outputs:
        print(f"  outputs in {args.outputs}:")
        for name in sorted(os.listdir(args.outputs)):
            print(f"    {name}")


def main(argv=None):
    args = parse_args(argv)
    with open(args.log) as f:
        text = f.read()
    if "ERROR" in text:
        print("\n".join(l for l in text.splitlines() if "ERROR" in l))
        sys.exit(1)
    temps = production_temperatures(text, args.log)
    print_summary(temps, loop_times(text)[-1], args)


if __name__ == "__main__":
    main()
