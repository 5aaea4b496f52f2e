#!/usr/bin/env python3
"""Spread of the throughput ratios over several runs of bench/run_bench.sh.

Usage: throughput_spread.py RUN.md ... > bench/results/throughput_spread.md
Each RUN.md is a throughput table as bench/throughput_table.py writes it (one run of the
command); the ratios to stock dpd + nve are collected per style and rank count and printed as
mean +- standard deviation (lowest in brackets), with the per-run values under the table.
"""
import statistics
import sys


def ratios(path):
    rows = {}
    for line in open(path):
        cells = [c.strip() for c in line.split("|")[1:-1]]
        if len(cells) > 4 and cells[1] in ("1", "2"):
            rows[(cells[0], cells[1])] = float(cells[3])
    return rows


def main(paths):
    runs = [ratios(p) for p in paths]
    styles = [k[0] for k in runs[0] if k[1] == "1" and not k[0].startswith("stock")]
    print(f"Ratios to stock dpd + nve over {len(runs)} runs of `bash bench/run_bench.sh` "
          "(mean +- standard deviation, lowest in brackets):\n")
    print("| style | 1 rank | 2 ranks |")
    print("|---|---|---|")
    for style in styles:
        cells = []
        for ranks in ("1", "2"):
            x = [r[(style, ranks)] for r in runs if (style, ranks) in r]
            cells.append(f"{statistics.mean(x):.3f} +- {statistics.stdev(x):.3f} ({min(x):.3f})")
        print(f"| {style} | {cells[0]} | {cells[1]} |")
    print("\nPer run (1 rank, then 2 ranks):\n")
    for style in styles:
        values = " ".join(f"{r[(style, '1')]:.3f}" for r in runs)
        values2 = " ".join(f"{r[(style, '2')]:.3f}" for r in runs)
        print(f"- {style}: {values} / {values2}")


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit("usage: throughput_spread.py RUN.md RUN.md ...")
    main(sys.argv[1:])
