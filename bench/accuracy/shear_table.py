#!/usr/bin/python3
"""The viscosity column's table from viscosity_shear.sh's logs: for each set of runs (the log
name's prefix: fluid, mass, rate, time) and each cell, eta = -<P_xy> / rate as the mean over
seeds with its standard error, kBT likewise, and the deviation from the set's reference (cell
"ref") with the error of the ratio (accuracy_matrix.relative_deviation, as in the matrix). The
last two columns are the mean flow profile: the slope of v_x on y (least squares over all atoms,
every step) against the imposed rate, and against the same slope of the atoms' displacements per
step over the seeds whose RESULT line has it (sdisp). The second is what a bias of the
velocities in v would move; the first also holds the flow's own deviation from the rate.

A set without a reference of its own (HS at m = 0.01 and 0.001, where velocity-Verlet is out of
reach) is compared with another set's: --ref-from SET=REFSET (repeatable).

The tables are made from the summary results/viscosity_shear.jsonl, one record per finished run
(set, cell, seed and its RESULT line's numbers). The logs are not kept in the repository:
viscosity_shear.sh ends with `shear_table.py --dir results/viscosity_shear`, which reads the
logs there and merges their records into the summary (a record replaces the one of the same set,
cell and seed), then prints the tables.

Usage: shear_table.py [--summary FILE] [--dir DIR] [--ref-from SET=REFSET ...] [PREFIX ...]
(default FILE: results/viscosity_shear.jsonl; --dir: merge DIR's logs into FILE first; PREFIX
e.g. "HS.m1.rate0.2." selects sets, "" is the GW m = 0.01 rate-2 set; default: every set)
"""
import json
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from etddpd.accuracy_matrix import mean_and_error, relative_deviation  # noqa: E402

LOG = re.compile(r"^log\.(?P<prefix>(?:[A-Za-z0-9.]+\.)?)(?P<cell>(?:ref|stock|impv?|diag)[0-9.]*?)\.(?P<seed>[0-9]+)$")
RESULT = re.compile(r"^RESULT .* kT (?P<kT>[-0-9.eE+]+) eta (?P<eta>[-0-9.eE+]+)")
RESULT_FIELDS = re.compile(r"^RESULT integ (?P<integ>\S+) dt (?P<dt>\S+) rate (?P<rate>\S+) .*"
                           r"kT (?P<kT>\S+) eta (?P<eta>\S+) slope (?P<slope>\S+)(?: sdisp (?P<sdisp>\S+))?"
                           r"(?: eta_v (?P<eta_v>\S+))?")


def log_records(directory):
    """One record per finished log of `directory`: set, cell, seed, kT, eta and, where the RESULT
    line has them, integ, dt, rate and slope."""
    records = []
    for name in sorted(os.listdir(directory)):
        match = LOG.match(name)
        if not match:
            continue
        with open(os.path.join(directory, name)) as log:
            lines = [line for line in log if RESULT.match(line)]
        if not lines:
            continue
        record = {"set": match["prefix"], "cell": match["cell"], "seed": int(match["seed"])}
        fields = RESULT_FIELDS.match(lines[-1])
        if fields:
            record.update(integ=fields["integ"], dt=float(fields["dt"]), rate=float(fields["rate"]),
                          slope=float(fields["slope"]))
            if fields["eta_v"]:
                record["eta_v"] = float(fields["eta_v"])
            if fields["sdisp"]:
                record["sdisp"] = float(fields["sdisp"])
        last = RESULT.match(lines[-1])
        record.update(kT=float(last["kT"]), eta=float(last["eta"]))
        records.append(record)
    return records


def read_summary(path):
    """The records of a summary file (JSON lines); none if it does not exist."""
    if not os.path.exists(path):
        return []
    with open(path) as summary:
        return [json.loads(line) for line in summary if line.strip()]


def merge_summary(path, records):
    """Write `records` into the summary at `path`, replacing those of the same set, cell and seed;
    sorted by set, cell and seed. Returns the merged records."""
    key = lambda r: (r["set"], r["cell"], r["seed"])    # noqa: E731
    merged = {key(r): r for r in read_summary(path)}
    merged.update({key(r): r for r in records})
    ordered = [merged[k] for k in sorted(merged)]
    with open(path, "w") as summary:
        for record in ordered:
            summary.write(json.dumps(record) + "\n")
    return ordered


def runs_from_records(records):
    """{prefix: {cell: [(seed, eta, kT, eta_v or None, slope / rate or None,
    (slope - sdisp) / rate or None), ...]}} from summary records."""
    runs = {}
    for r in sorted(records, key=lambda r: (r["set"], r["cell"], r["seed"])):
        slope = r["slope"] / r["rate"] if r.get("slope") is not None and r.get("rate") else None
        lag = (r["slope"] - r["sdisp"]) / r["rate"] if slope is not None and r.get("sdisp") is not None else None
        runs.setdefault(r["set"], {}).setdefault(r["cell"], []).append(
            (r["seed"], r["eta"], r["kT"], r.get("eta_v"), slope, lag))
    return runs


def read_runs(directory):
    """{prefix: {cell: [(seed, eta, kT, eta_v, slope / rate, (slope - sdisp) / rate), ...]}} from
    the logs that finished (a RESULT line)."""
    return runs_from_records(log_records(directory))


def table(cells, reference=None):
    """Rows (cell, n, eta, eta error, kT, deviation % from ref, its error %, the same deviation
    of eta_v where every seed of the cell has one, (deviation %, error %) of the profile's slope
    from the rate where every seed has one, and (deviation %, error %, seeds) of that slope from
    the displacements' over the seeds that have both), ref first. The reference is the set's
    cell "ref", or the runs `reference` [(seed, eta, kT, eta_v, slope / rate, lag), ...] given."""
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
        end = None
        ends = [r[3] for r in cells[cell]]
        if ref_etas and cell != "ref" and all(e is not None for e in ends):
            against = relative_deviation(ends, ref_etas)
            end = (100.0 * against.value, 100.0 * against.error)
        slopes = [r[4] for r in cells[cell]]
        profile = None
        if all(s is not None for s in slopes):
            slope, slope_error = mean_and_error(slopes)
            profile = (100.0 * (slope - 1.0), 100.0 * slope_error)
        lags = [r[5] for r in cells[cell] if r[5] is not None]
        lag = None
        if lags:
            lag_mean, lag_error = mean_and_error(lags)
            lag = (100.0 * lag_mean, 100.0 * lag_error, len(lags))
        rows.append((cell, len(etas), eta, error, kT, deviation, deviation_error, end, profile, lag))
    return rows


def main(argv):
    summary = os.path.join(os.path.dirname(os.path.abspath(__file__)), "results", "viscosity_shear.jsonl")
    directory = None
    ref_from = {}
    needs = {"--dir": "DIR", "--summary": "FILE", "--ref-from": "SET=REFSET"}
    while argv[:1] and argv[0] in needs:
        if len(argv) < 2 or (argv[0] == "--ref-from" and "=" not in argv[1]):
            sys.exit(f"shear_table.py: {argv[0]} needs {needs[argv[0]]}")
        if argv[0] == "--dir":
            directory = argv[1]
        elif argv[0] == "--summary":
            summary = argv[1]
        else:
            target, source = argv[1].split("=", 1)
            ref_from[target] = source
        argv = argv[2:]
    records = merge_summary(summary, log_records(directory)) if directory else read_summary(summary)
    runs = runs_from_records(records)
    for target, source in ref_from.items():
        if "ref" not in runs.get(source, {}):
            sys.exit(f"shear_table.py: --ref-from {target}={source}: set '{source}' has no reference runs")
    steps = {(r["set"], r["cell"]): (r.get("integ", ""), r.get("dt", "")) for r in records}
    print("# Viscosity under homogeneous shear, eta = -<P_xy> / rate (bench/accuracy/shear_table.py, "
          "from results/viscosity_shear.jsonl)")
    for prefix in (argv or sorted(runs)):
        source = ref_from.get(prefix)
        print(f"\n## {prefix or '(GW m = 0.01, rate 2)'}" + (f" (against the reference of {source})" if source else "") + "\n")
        print("| cell | integrator | dt | seeds | eta | kBT | against the reference | eta from m v v of v, against it "
              "| profile slope of v, against the rate | against the displacements' (seeds) |")
        print("|---|---|---|---|---|---|---|---|---|---|")
        reference = runs[source]["ref"] if source else None
        for cell, n, eta, error, kT, deviation, deviation_error, end, profile, lag in table(runs.get(prefix, {}), reference):
            against = "" if deviation is None else f"{deviation:+.1f} +- {deviation_error:.1f} %"
            against += " | " + ("" if end is None else f"{end[0]:+.1f} +- {end[1]:.1f} %")
            against += " | " + ("" if profile is None else f"{profile[0]:+.1f} +- {profile[1]:.1f} %")
            against += " | " + ("" if lag is None else f"{lag[0]:+.2f} +- {lag[1]:.2f} % ({lag[2]})")
            integ, dt = steps.get((prefix, cell), ("", ""))
            print(f"| {cell} | {integ} | {dt:g} | {n} | {eta:.4g} +- {error:.2g} | {kT:.3f} | {against} |"
                  if dt != "" else f"| {cell} | {integ} | | {n} | {eta:.4g} +- {error:.2g} | {kT:.3f} | {against} |")


if __name__ == "__main__":
    main(sys.argv[1:])
