#!/usr/bin/python3
"""alternate.sh's runs (ETD_DPD_BENCH_OUT, one line per round and variant) as a table: per
variant, the median and range of the loop times on 2 threads (fix etd/kk or dpd/gen/kk, 1 rank)
and on 2 MPI ranks (the CPU styles), and the ratio 2 ranks / 2 threads in each round.

Usage: /usr/bin/python3 bench/kokkos/alternate_table.py FILE.jsonl > FILE.md
"""
import json
import statistics
import sys

SCHEMES = {"implicit": "fix etd scheme implicit (m = 0.01, dt = 0.005)",
           "diagonal": "fix etd scheme diagonal (m = 0.01, dt = 0.002)",
           "nve": "fix nve (m = 1, dt = 0.01)"}


def spread(values, digits):
    return (f"{statistics.median(values):.{digits}f} "
            f"({min(values):.{digits}f}-{max(values):.{digits}f})")


def main(path):
    with open(path) as handle:
        runs = [json.loads(line) for line in handle if line.strip()]
    if not runs:
        sys.exit(f"{path}: no runs")
    first = runs[0]
    rounds = sorted({r["round"] for r in runs})
    print(f"Builds side by side (bench/kokkos/alternate.sh): {SCHEMES[first['scheme']]}, "
          f"24,000 atoms, {first['steps']} steps per run, {len(rounds)} alternated rounds, "
          f"LAMMPS {first['lammps']} on {first['cores']} cores, OMP_PROC_BIND={first['omp_proc_bind']}. "
          "Times in seconds, median (range); ratio: 2 ranks / 2 threads in the same round.")
    print()
    print("| variant | atom_modify sort | 2 threads (s) | 2 ranks (s) | ratio, median (range) | ratio per round |")
    print("|---|---|---|---|---|---|")
    for variant in dict.fromkeys(r["variant"] for r in runs):
        mine = sorted((r for r in runs if r["variant"] == variant), key=lambda r: r["round"])
        ratios = [r["ranks_s"] / r["threads_s"] for r in mine]
        print(f"| {variant} | {mine[0]['sort']} | {spread([r['threads_s'] for r in mine], 2)} | "
              f"{spread([r['ranks_s'] for r in mine], 2)} | {spread(ratios, 3)} | "
              f"{', '.join(f'{x:.3f}' for x in ratios)} |")


if __name__ == "__main__":
    main(sys.argv[1])
