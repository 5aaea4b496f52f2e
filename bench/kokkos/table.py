#!/usr/bin/python3
"""bench/kokkos/results/throughput.jsonl (run.sh) as a table: atom-steps per second of each
set-up, mean +- sd over rounds, and the ratio to the CPU styles on 2 MPI ranks with the same
integrator in the same round (mean +- sd, lowest); the large-step integrators at equal accuracy
(the implicit scheme and LAMMPS's fix shardlow, each at its largest step within tolerance), in
simulated time per second; and, for the threaded set-ups where run.sh read the sharing probe just
before the run (sharing_ms), the ratio in each of the machine's two states; and the threaded set-ups
against the CPU style on 2 ranks with a shorter atom_modify sort period, where run.sh ran it.

Usage: /usr/bin/python3 bench/kokkos/table.py results/throughput.jsonl > results/throughput.md
"""
import json
import statistics
import sys

# sharing_probe.cpp's "split differently, 2 threads" time that parts the two states (about
# 0.1 ms in the fast one, about 0.4 ms in the slow one on the 2-core machines measured)
SLOW_SHARING_MS = 0.25

INTEGRATORS = {"nve": "fix nve", "etd": "fix etd scheme diagonal",
               "implicit": "fix etd scheme implicit", "shardlow": "fix shardlow + fix nve"}
# the integrators compared at equal accuracy, and the one their ratios are taken to
LARGE_STEP = ("implicit", "shardlow")
PEER = "shardlow"
# atom_modify sort's default period, that of the baselines
LAMMPS_SORT = 1000


def binding(runs):
    """How the runs' OpenMP threads were placed (OMP_PROC_BIND, OMP_PLACES), in words"""
    kinds = {(r.get("omp_proc_bind", "false"), r.get("omp_places", "")) for r in runs}
    if len(kinds) > 1:
        return "threads placed in several ways"
    bind, places = kinds.pop()
    if bind == "false":
        return "threads unbound (OMP_PROC_BIND=false)"
    return f"threads bound (OMP_PROC_BIND={bind}, OMP_PLACES={places})"


def baseline(runs, integrator):
    """The set-up on 2 MPI ranks without Kokkos with this integrator (dpd/gen where there are
    several)."""
    cpu = [r for r in runs if r.get("integrator", "nve") == integrator
           and r["ranks"] == 2 and r["threads"] == 0 and r.get("sort", LAMMPS_SORT) == LAMMPS_SORT]
    return next((r for r in cpu if r["pair_style"] == "dpd/gen"), cpu[0])["setup"]


def main(path):
    with open(path) as handle:
        runs = [json.loads(line) for line in handle if line.strip()]
    rounds = sorted({r["round"] for r in runs})
    loop = {(r["round"], r["setup"]): r["loop_s"] for r in runs}
    setups = list(dict.fromkeys(r["setup"] for r in runs))
    first = runs[0]
    work = first["atoms"] * first["steps"]
    print(f"{first['atoms']:,} atoms of the standard fluid, {first['steps']} steps per run, "
          f"{len(rounds)} alternated rounds in {len({r.get('sitting', 1) for r in runs})} sitting(s) "
          f"(bench/kokkos/run.sh), LAMMPS {first.get('lammps', '?')} with "
          f"KOKKOS (OpenMP backend) on {first.get('cores', '?')} cores, {binding(runs)}. "
          "fix nve: m = 1, dt = 0.01; "
          "fix etd scheme diagonal: m = 0.01, dt = 0.002; fix etd scheme implicit: m = 0.01, dt = 0.005; "
          "fix shardlow (pair dpd/fdt/energy): m = 0.01, dt = 0.004. "
          "Ratio: to the CPU styles on 2 MPI ranks with the "
          "same integrator (dpd/gen where there are several), in the same round.")
    print()
    print("| set-up | integrator | pair style run | atom-steps/s (mean +- sd) | ratio to 2 ranks (lowest) |")
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
    shorter_sort(runs, rounds, loop)
    equal_accuracy(runs, rounds, loop)
    states(runs, rounds, loop)


def shorter_sort(runs, rounds, loop):
    """The threaded set-ups against the CPU style on 2 ranks with a shorter atom_modify sort
    period (the /kk styles sort every 20 steps themselves), with the same integrator."""
    sorted_bases = [r for r in runs if r["round"] == rounds[0] and r["threads"] == 0
                    and r["ranks"] == 2 and r.get("sort", LAMMPS_SORT) != LAMMPS_SORT]
    if not sorted_bases:
        return
    sd = statistics.stdev if len(rounds) > 1 else (lambda values: 0.0)
    print()
    print("Against the CPU style on 2 MPI ranks with a shorter atom_modify sort period (the one "
          "the /kk styles keep while their kernels run), in the same round:")
    print()
    print("| set-up | against | ratio (mean +- sd, lowest) | each round |")
    print("|---|---|---|---|")
    for base in sorted_bases:
        threaded = dict.fromkeys(r["setup"] for r in runs if r["threads"] > 1
                                 and r.get("integrator", "nve") == base.get("integrator", "nve"))
        for setup in threaded:
            ratios = [loop[(k, base["setup"])] / loop[(k, setup)] for k in rounds]
            print(f"| {setup} | {base['setup']} | {statistics.mean(ratios):.3f} +- "
                  f"{sd(ratios):.3f} ({min(ratios):.3f}) | "
                  f"{', '.join(f'{x:.3f}' for x in ratios)} |")


def equal_accuracy(runs, rounds, loop):
    """The large-step integrators in simulated time (atoms x time units) per second, each at its
    own step, against the peer on 2 ranks and against the peer with the same ranks and threads."""
    first = {}    # each large-step set-up's first run, in the runs' order
    for r in runs:
        if r.get("integrator") in LARGE_STEP:
            first.setdefault(r["setup"], r)
    if not any(r["integrator"] == PEER for r in first.values()):
        return
    large = list(first)
    peer_base = baseline(runs, PEER)

    def rate(k, setup):
        run = first[setup]
        return run["atoms"] * run["steps"] * run["dt"] / loop[(k, setup)]

    def peer_alike(setup):
        """The peer's set-up with the same ranks and threads, if any."""
        return next((s for s in large if first[s]["integrator"] == PEER
                     and (first[s]["ranks"], first[s]["threads"])
                     == (first[setup]["ranks"], first[setup]["threads"])), None)

    sd = statistics.stdev if len(rounds) > 1 else (lambda values: 0.0)
    print()
    print("At equal accuracy: the implicit scheme and LAMMPS's fix shardlow, each at its largest step "
          "within tolerance on every observable for GW m = 0.01 (bench/accuracy: 0.005 and 0.004), "
          "in simulated time per second (atoms x time units / s = atom-steps/s x dt). Ratios in the "
          "same round.")
    print()
    print("| set-up | dt | atom-time/s (mean +- sd) | ratio to fix shardlow on 2 ranks (lowest) | "
          "ratio to shardlow with the same ranks and threads (lowest) |")
    print("|---|---|---|---|---|")
    for setup in large:
        rates = [rate(k, setup) for k in rounds]
        to_base = [rate(k, setup) / rate(k, peer_base) for k in rounds]
        alike = peer_alike(setup)
        to_alike = "-"
        if alike is not None and alike != setup:
            values = [rate(k, setup) / rate(k, alike) for k in rounds]
            to_alike = (f"{statistics.mean(values):.2f} +- {sd(values):.2f} ({min(values):.2f}) "
                        f"to {alike}")
        run = first[setup]
        print(f"| {setup} | {run['dt']} | "
              f"{statistics.mean(rates):.3e} +- {sd(rates):.1e} | "
              f"{statistics.mean(to_base):.2f} +- {sd(to_base):.2f} ({min(to_base):.2f}) | {to_alike} |")


def states(runs, rounds, loop):
    """The ratio of each threaded set-up that has probe readings, per state of the machine."""
    probed = [r for r in runs if r.get("sharing_ms") is not None]
    if not probed:
        return
    print()
    print("By the state of the machine just before the run (bench/kokkos/sharing_probe.cpp, two "
          f"passes split differently on 2 threads: fast below {SLOW_SHARING_MS} ms, slow above):")
    print()
    print("| set-up | state | rounds | probe (ms) | ratio to 2 ranks (each round) |")
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
