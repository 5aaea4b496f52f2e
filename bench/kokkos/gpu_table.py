#!/usr/bin/python3
"""tools/kokkos/gpu.sh's results (gpu.jsonl, gpu-tests.jsonl) as the markdown table of
bench/kokkos/results/gpu.md: atom-steps per second of each case at each size, atom time units per
second (atom-steps/s x dt), and the two comparisons that matter on a GPU: dpd/gen/kk against dpd/kk at the
same dt (in atom-steps/s), and fix etd/kk scheme implicit against fix shardlow/kk each at its
largest seed-checked step (in atom time units per second). Without runs it says so.

Usage: python3 bench/kokkos/gpu_table.py gpu.jsonl [gpu-tests.jsonl] > gpu.md
"""
import json
import os
import sys

CASES = {
    "gen-nve": "dpd/gen/kk + fix nve",
    "dpd-nve": "LAMMPS's dpd/kk + fix nve",
    "gen-nve-half": "dpd/gen/kk + fix nve, neigh half newton on",
    "dpd-nve-half": "LAMMPS's dpd/kk + fix nve, neigh half newton on",
    "etd-implicit": "fix etd/kk scheme implicit (dpd/gen)",
    "shardlow": "fix shardlow/kk + fix nve (dpd/fdt/energy/kk)",
    "etd-diagonal": "fix etd/kk scheme diagonal (dpd/gen/kk)",
    "gen-nve-sort20": "dpd/gen/kk + fix nve, atom_modify sort 20",
}
COMPARISONS = (  # (case, against, measure, what); a tuple of cases: the fastest of them
    ("gen-nve", "dpd-nve", "rate", "dpd/gen/kk over dpd/kk, the device's defaults (atom-steps/s, same dt)"),
    ("gen-nve-half", "dpd-nve-half", "rate", "dpd/gen/kk over dpd/kk, both neigh half newton on"),
    (("gen-nve", "gen-nve-half"), ("dpd-nve", "dpd-nve-half"), "rate",
     "dpd/gen/kk over dpd/kk, each at its faster setting"),
    ("etd-implicit", "shardlow", "time", "implicit over shardlow/kk (atom time units/s, equal accuracy)"),
    ("gen-nve-sort20", "gen-nve", "rate",
     "dpd/gen/kk sorted every 20 steps over LAMMPS's period (the host threads' sorting, on the device)"),
)


def read(path):
    if not path or not os.path.exists(path):
        return []
    with open(path) as handle:
        return [json.loads(line) for line in handle if line.strip()]


def main(runs_path, tests_path=None):
    lines = read(runs_path)
    runs = [r for r in lines if r.get("kind") == "run" and "loop_s" in r]
    failed = [r for r in lines if r.get("kind") == "run" and "error" in r]
    tests = read(tests_path)
    if not runs and not failed:
        print("No GPU run yet: tools/kokkos/gpu.sh has not run on a machine with a GPU. Its table "
              "comes here (tools/kokkos/README.md says how to run it).")
        return
    first = runs[0] if runs else failed[0]
    print(f"tools/kokkos/gpu.sh on {first.get('device', '?')} ({first.get('backend', '?')} backend), "
          f"LAMMPS {first.get('lammps', '?')} with KOKKOS. Groot-Warren fluid (n = 3, a = 25, "
          "gamma = 4.5, s = 2, rc = 1, kBT = 1), m = 0.01; one run per case and size. Atom time "
          "units/s = atom-steps/s x dt: the rate at which the run covers simulated time. The steps "
          "of fix etd scheme implicit and fix shardlow are their largest seed-checked steps "
          "(bench/accuracy/results/matrix.md, GW m = 0.01). fix etd/kk scheme implicit runs its "
          "step and the pair loop on the host (README.md, KOKKOS section); fix shardlow/kk needs "
          "an EOS fix, and fix eos/cv has no KOKKOS variant, so it too runs on the host.")
    print()
    for t in tests:
        not_run = t.get("not_run", 0)
        stopped = f", {not_run} not run before the deadline (--until)" if not_run else ""
        print(f"Equivalence tests (ctest -L {t['label']}, {t['backend']} backend): "
              f"{t['total'] - t['failed'] - not_run} of {t['total']} passed, {t['failed']} failed"
              f"{stopped}.")
        print()
    print("| case | atoms | dt | steps | loop s | atom-steps/s | atom time units/s |")
    print("|---|---|---|---|---|---|---|")
    rate, time = {}, {}
    for r in runs:
        atom_steps = r["natoms"] * r["steps"] / r["loop_s"]
        rate[(r["case"], r["natoms"])] = atom_steps
        time[(r["case"], r["natoms"])] = atom_steps * r["dt"]
        steps = f"{r['steps']}{' (timeout)' if r.get('timed_out') else ''}"
        print(f"| {CASES.get(r['case'], r['case'])} | {r['natoms']:,} | {r['dt']} | {steps} | "
              f"{r['loop_s']:.3f} | {atom_steps:.3e} | {atom_steps * r['dt']:.3e} |")
    for r in failed:
        outcome = r["error"] if r["error"].startswith("skipped") else f"failed ({r['error']})"
        print(f"| {CASES.get(r['case'], r['case'])} | {r['natoms']:,} | | {outcome} | | | |")
    print()
    print("| comparison | " + " | ".join(f"{n:,} atoms" for n in sorted({r["natoms"] for r in runs})) + " |")
    print("|---|" + "---|" * len({r["natoms"] for r in runs}))
    for case, against, measure, what in COMPARISONS:
        values = rate if measure == "rate" else time
        cells = []
        def best(cases, n):
            found = [values[(c, n)] for c in (cases if isinstance(cases, tuple) else (cases,))
                     if (c, n) in values]
            return max(found) if found else None
        for n in sorted({r["natoms"] for r in runs}):
            ours, theirs = best(case, n), best(against, n)
            cells.append(f"{ours / theirs:.2f}" if ours and theirs else "-")
        print(f"| {what} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main(*sys.argv[1:3])
