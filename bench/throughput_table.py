#!/usr/bin/env python3
"""Table of atom-steps/s per 'BENCH label' block of LAMMPS logs, with ratios to the stock style."""
import re
import sys


def parse(path):
    text = open(path).read()
    results = []
    for block in re.split(r"^BENCH ", text, flags=re.M)[1:]:
        label = block.splitlines()[0].strip()
        m = re.search(r"Loop time of ([0-9.eE+-]+) on (\d+) procs for (\d+) steps with (\d+) atoms", block)
        seconds, procs, steps, atoms = float(m.group(1)), int(m.group(2)), int(m.group(3)), int(m.group(4))
        results.append((label, procs, steps * atoms / seconds))
    return results


def main():
    print("| style | ranks | atom-steps/s | ratio to stock dpd + nve |")
    print("|---|---|---|---|")
    for path in sys.argv[1:]:
        results = parse(path)
        stock = [rate for label, _, rate in results if label.startswith("stock dpd")]
        reference = sum(stock) / len(stock)
        for label, procs, rate in results:
            print(f"| {label} | {procs} | {rate:.3e} | {rate / reference:.3f} |")


if __name__ == "__main__":
    main()
