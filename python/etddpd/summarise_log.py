#!/usr/bin/env python3
"""Summarise a LAMMPS log: mean temperature of the last run, throughput, where outputs went."""
import argparse
import math
import os
import re
import sys


def thermo_blocks(text):
    """Yield (columns, rows) for each thermo table in a LAMMPS log."""
    lines = text.splitlines()
    i = 0
    while i < len(lines):
        if lines[i].split()[:1] == ["Step"]:
            columns = lines[i].split()
            rows = []
            i += 1
            while i < len(lines) and not lines[i].startswith("Loop time"):
                fields = lines[i].split()
                if len(fields) == len(columns):
                    try:
                        rows.append([float(x) for x in fields])
                    except ValueError:
                        pass
                i += 1
            yield columns, rows
        i += 1


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("log")
    parser.add_argument("--target-temperature", type=float, default=None)
    parser.add_argument("--wall", type=float, default=None, help="wall-clock seconds of the job")
    parser.add_argument("--outputs", default=None, help="folder holding the outputs")
    args = parser.parse_args()
    text = open(args.log).read()
    if "ERROR" in text:
        print("\n".join(l for l in text.splitlines() if "ERROR" in l))
        sys.exit(1)
    blocks = list(thermo_blocks(text))
    if not blocks:
        sys.exit("no thermo output in " + args.log)
    columns, rows = blocks[-1]
    temps = [r[columns.index("Temp")] for r in rows[1:]]
    mean = sum(temps) / len(temps)
    spread = math.sqrt(sum((t - mean) ** 2 for t in temps) / max(len(temps) - 1, 1))
    loops = re.findall(r"Loop time of ([0-9.eE+-]+) on (\d+) procs for (\d+) steps with (\d+) atoms", text)
    seconds, procs, steps, atoms = loops[-1]
    throughput = int(steps) * int(atoms) / float(seconds)
    print("ETD-DPD run summary")
    print(f"  atoms {atoms}, MPI ranks {procs}, steps {steps}, loop time {float(seconds):.2f} s")
    line = f"  temperature (kBT) over the production run: {mean:.4f} (sample spread {spread:.4f}, {len(temps)} samples)"
    if args.target_temperature:
        line += f"; target {args.target_temperature}, deviation {100 * (mean / args.target_temperature - 1):+.2f} %"
    print(line)
    print(f"  throughput: {throughput:.3e} atom-steps/s")
    if args.wall is not None:
        print(f"  wall-clock of the whole job: {args.wall:.1f} s")
    if args.outputs:
        print(f"  outputs in {args.outputs}:")
        for name in sorted(os.listdir(args.outputs)):
            print(f"    {name}")


if __name__ == "__main__":
    main()
