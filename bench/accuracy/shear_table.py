#!/usr/bin/python3
"""The viscosity column's table from viscosity_shear.sh's logs: for each set of runs (the log
name's prefix: fluid, mass, rate, time) and each cell, eta = -<P_xy> / rate as the mean over
seeds with its standard error, kBT likewise, and the deviation from the set's reference (cell
"ref") with the error of the ratio (accuracy_matrix.relative_deviation, as in the matrix).

A set without a reference of its own (HS at m = 0.01 and 0.001, where velocity-Verlet is out of
reach) is compared with another set's: --ref-from SET=REFSET (repeatable).

Usage: shear_table.py [--dir DIR] [--ref-from SET=REFSET ...] [PREFIX ...]   (default DIR:
results/viscosity_shear; PREFIX e.g. "HS.m1.rate0.2." selects sets, "" is the GW m = 0.01 rate-2
set; default: every set)
"""
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from etddpd.accuracy_matrix import mean_and_error, relative_deviation  # noqa: E402

LOG = re.compile(r"^log\.(?P<prefix>(?:[A-Za-z0-9.]+\.)?)(?P<cell>(?:ref|stock|impv?|diag)[0-9.]*?)\.(?P<seed>[0-9]+)$")
RESULT = re.compile(r"^RESULT .* kT (?P<kT>[-0-9.eE+]+) eta (?P<eta>[-0-9.eE+]+)")


def read_runs(directory):
    """{prefix: {cell: [(seed, eta, kT), ...]}} from the logs that finished (a RESULT line)."""
    runs = {}
    for name in sorted(os.listdir(directory)):
        match = LOG.match(name)
        if not match:
            continue
        with open(os.path.join(directory, name)) as log:
            results = [RESULT.match(line) for line in log]
        results = [r for r in results if r]
        if not results:
            continue
        runs.setdefault(match["prefix"], {}).setdefault(match["cell"], []).append(
            (int(match["seed"]), float(results[-1]["eta"]), float(results[-1]["kT"])))
    return runs


def table(cells, reference=None):
    """Rows (cell, n, eta, eta error, kT, deviation % from ref, its error %), ref first. The
    reference is the set's cell "ref", or the runs `reference` [(seed, eta, kT), ...] given."""
    rows = []
    ref_etas = [r[1] for r in (cells.get("ref", []) if reference is None else reference)]
    for cell in sorted(cells, key=lambda c: (c != "ref", c)):
        etas = [r[1] for r in cells[cell]]
        eta, error = mean_and_error(etas)
        kT, _ = mean_and_error([r[2] for r in cells[cell]])
        deviation = deviation_error = None
        if ref_etas and cell != "ref":
            against = relative_deviation(etas, ref_etas)
            deviation, deviation_error = 100.0 * against.value, 100.0 * against.error
        rows.append((cell, len(etas), eta, error, kT, deviation, deviation_error))
    return rows


def main(argv):
    directory = os.path.join(os.path.dirname(os.path.abspath(__file__)), "results", "viscosity_shear")
    ref_from = {}
    while argv[:1] in (["--dir"], ["--ref-from"]):
        if len(argv) < 2 or (argv[0] == "--ref-from" and "=" not in argv[1]):
            sys.exit(f"shear_table.py: {argv[0]} needs {'DIR' if argv[0] == '--dir' else 'SET=REFSET'}")
        if argv[0] == "--dir":
            directory = argv[1]
        else:
            target, source = argv[1].split("=", 1)
            ref_from[target] = source
        argv = argv[2:]
    runs = read_runs(directory)
    for target, source in ref_from.items():
        if "ref" not in runs.get(source, {}):
            sys.exit(f"shear_table.py: --ref-from {target}={source}: set '{source}' has no reference runs")
    for prefix in (argv or sorted(runs)):
        source = ref_from.get(prefix)
        print(f"\n{prefix or '(GW m = 0.01, rate 2)'}" + (f" (against the reference of {source})" if source else "") + "\n")
        print("| cell | seeds | eta | kBT | against the reference |")
        print("|---|---|---|---|---|")
        reference = runs[source]["ref"] if source else None
        for cell, n, eta, error, kT, deviation, deviation_error in table(runs.get(prefix, {}), reference):
            against = "" if deviation is None else f"{deviation:+.1f} +- {deviation_error:.1f} %"
            print(f"| {cell} | {n} | {eta:.4g} +- {error:.2g} | {kT:.3f} | {against} |")


if __name__ == "__main__":
    main(sys.argv[1:])
