#!/usr/bin/python3
"""bench/kokkos/results/throughput.jsonl (run.sh) as a table: atom-steps per second of each
set-up, mean +- sd over rounds, and the ratio to dpd/gen on 2 MPI ranks with the same integrator
in the same round (mean +- sd, lowest); and, for the threaded set-ups where run.sh read the
sharing probe just before the run (sharing_ms), the ratio in each of the machine's two states.

Usage: /usr/bin/python3 bench/kokkos/table.py results/throughput.jsonl > results/throughput.md
"""
import json
import statistics
import sys

# sharing_probe.cpp's "split differently, 2 threads" time that parts the two states (about
# 0.1 ms in the fast one, about 0.4 ms in the slow one on the 2-core machines measured)
SLOW_SHARING_MS = 0.25

INTEGRATORS = {"nve": "fix nve", "etd": "fix etd scheme diagonal", "implicit": "fix etd scheme implicit"}


def baseline(runs, integrator):
    """The set-up of dpd/gen on 2 MPI ranks without Kokkos with this integrator."""
    return next(r["setup"] for r in runs if r.get("integrator", "nve") == integrator
                and r["ranks"] == 2 and r["threads"] == 0 and r["pair_style"] == "dpd/gen")


def main(path):
    with open(path) as handle:
        runs = [json.loads(line) for line in handle if line.strip()]
    rounds = sorted({r["round"] for r in runs})
    loop = {(r["round"], r["setup"]): r["loop_s"] for r in runs}
    setups = list(dict.fromkeys(r["setup"] for r in runs))
    first = runs[0]
    work = first["atoms"] * first["steps"]
    print(f"{first['atoms']:,} atoms of the standard fluid, {first['steps']} steps per run, "
          f"{len(rounds)} alternated rounds (bench/kokkos/run.sh), LAMMPS {first.get('lammps', '?')} with "
          f"KOKKOS (OpenMP backend) on {first.get('cores', '?')} cores. fix nve: m = 1, dt = 0.01; "
          "fix etd scheme diagonal: m = 0.01, dt = 0.002; fix etd scheme implicit: m = 0.01, dt = 0.005. "
          "Ratio: to dpd/gen on 2 MPI ranks with the "
          "same integrator, in the same round.")
    print()
    print("| set-up | integrator | pair style run | atom-steps/s (mean +- sd) | ratio to dpd/gen on 2 ranks (lowest) |")
    print("|---|---|---|---|---|")
    for setup in setups:
        run = next(r for r in runs if r["setup"] == setup)
        integrator = run.get("integrator", "nve")
        base = baseline(runs, integrator)
        rates = [work / loop[(k, setup)] for k in rounds]
        ratios = [loop[(k, base)] / loop[(k, setup)] for k in rounds]
        sd = statistics.stdev if len(rounds) > 1 else (lambda values: 0.0)
        print(f"| {setup} | {INTEGRATORS[integrator]} | {run['pair_style']} | "
              f"{statistics.mean(rates):.3e} +- {sd(rates):.1e} | "
              f"{statistics.mean(ratios):.3f} +- {sd(ratios):.3f} ({min(ratios):.3f}) |")
    states(runs, rounds, loop)


def states(runs, rounds, loop):
    """The ratio of each threaded set-up that has probe readings, per state of the machine."""
    probed = [r for r in runs if r.get("sharing_ms") is not None]
    if not probed:
        return
    print()
    print("By the state of the machine just before the run (bench/kokkos/sharing_probe.cpp, two "
          f"passes split differently on 2 threads: fast below {SLOW_SHARING_MS} ms, slow above):")
    print()
    print("| set-up | state | rounds | probe (ms) | ratio to dpd/gen on 2 ranks (each round) |")
    print("|---|---|---|---|---|")
    for setup in dict.fromkeys(r["setup"] for r in probed):
        base = baseline(runs, next(r for r in probed if r["setup"] == setup).get("integrator", "nve"))
        for state, slow in (("fast", False), ("slow", True)):
            mine = [r for r in probed if r["setup"] == setup
                    and (r["sharing_ms"] > SLOW_SHARING_MS) == slow]
            if not mine:
                continue
            ratios = [loop[(r["round"], base)] / r["loop_s"] for r in mine]
            probes = ", ".join(f"{r['sharing_ms']:.2f}" for r in mine)
            print(f"| {setup} | {state} | {len(mine)} | {probes} | "
                  f"{', '.join(f'{x:.3f}' for x in ratios)} |")


if __name__ == "__main__":
    main(sys.argv[1])
