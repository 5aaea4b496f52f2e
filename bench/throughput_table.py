#!/usr/bin/python3
"""Table of atom-steps/s per 'BENCH label' block of LAMMPS logs, with ratios to stock dpd + nve on
the same atoms (atomic, or atom_style sphere for dpd/fpm)
and the share of the loop time in LAMMPS's timing sections (pair, neighbor, comm, modify = fixes)."""
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
from etddpd.lammps_output import loop_times  # noqa: E402

SECTIONS = ("Pair", "Neigh", "Comm", "Modify")


def parse(path):
    with open(path) as f:
        text = f.read()
    results = []
    for block in re.split(r"^BENCH ", text, flags=re.M)[1:]:
        label = block.splitlines()[0].strip()
        seconds, procs, steps, atoms = loop_times(block)[0]
        shares = {}
        for name in SECTIONS:
            # "Pair    | min | avg | max | %varavg | %total"
            row = re.search(rf"^{name}\s*\|([^\n]*)$", block, flags=re.M)
            shares[name] = float(row.group(1).split("|")[-1]) if row else float("nan")
        results.append((label, procs, steps * atoms / seconds, shares))
    return results


def main():
    print("| style | ranks | atom-steps/s | ratio to stock dpd + nve | pair % | neigh % | comm % | fix % |")
    print("|---|---|---|---|---|---|---|---|")
    for path in sys.argv[1:]:
        results = parse(path)
        def system(label):    # ratios within one system: atomic, or sphere atoms for dpd/fpm
            return "sphere" if ("sphere" in label or "fpm" in label) else "atomic"

        reference = {}
        for key in ("atomic", "sphere"):
            stock = [rate for label, _, rate, _ in results if label.startswith("stock dpd") and system(label) == key]
            reference[key] = sum(stock) / len(stock) if stock else float("nan")
        for label, procs, rate, shares in results:
            cols = " | ".join(f"{shares[name]:.1f}" for name in SECTIONS)
            print(f"| {label} | {procs} | {rate:.3e} | {rate / reference[system(label)]:.3f} | {cols} |")


if __name__ == "__main__":
    main()
