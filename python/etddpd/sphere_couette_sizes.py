#!/usr/bin/python3
"""Size scan of examples/sphere-couette (validation/sphere-couette/size_scan.sh): the drag on the
sphere per box size from independent runs, and its extrapolation to the paper's box.

Each run folder holds drag.sphere-couette and a log.lammps whose last 'sphere-couette: scheme'
line gives Lx; s = Lx / 40 is the box's scale against the paper's 40 x 30 x 30. Per run the
drag is the mean over the steady window (steps > --from-step); per size the mean over the runs
with the standard error from their scatter (independent seeds, not blocks of one run). The
walls' and periodic images' share of the drag falls as 1/s to leading order, so a weighted
straight line in 1/s through the sizes gives the drag at s = 1 (the paper's box) and at
1/s = 0 (no walls or images).

usage: python/sphere_couette_sizes.py RUN_DIR... [--from-step N]
(the steady window of each run starts where python/sphere_couette.py starts it)
"""
import argparse
import collections
import math
import os
import re
import sys

import numpy as np

from .lammps_output import read_ave_time, read_ave_time_vector
from .sphere_couette import DRAG_COLUMNS, PAPER, steady_start
from .statistics import standard_error

PAPER_LX = 40.0


def box_length(log_path):
    """Lx of the run from the log's summary line."""
    with open(log_path) as log:
        found = re.findall(r"sphere-couette: scheme .* Lx (\S+) ", log.read())
    if not found:
        sys.exit(f"sphere_couette_sizes: no 'sphere-couette: scheme ... Lx' line in {log_path}")
    return float(found[-1])


def run_drag(run_dir, from_step):
    """Mean total drag and mean conservative + dissipative drag over the steady window."""
    drag = read_ave_time(os.path.join(run_dir, "drag.sphere-couette")).data
    if from_step is None:    # each run's own start-up: where its production-only rdf blocks begin
        rdf_path = os.path.join(run_dir, "rdf.sphere-couette")
        rdf_steps = read_ave_time_vector(rdf_path).steps if os.path.exists(rdf_path) else []
        from_step = steady_start(None, drag[:, 0], rdf_steps)
    window = drag[:, 0] > from_step
    if window.sum() < 2:
        sys.exit(f"sphere_couette_sizes: fewer than 2 rows after step {from_step} in {run_dir}")
    total = float(drag[window, DRAG_COLUMNS["F"]].mean())
    c_plus_d = float((drag[window, DRAG_COLUMNS["FC"]] + drag[window, DRAG_COLUMNS["FD"]]).mean())
    return total, c_plus_d


def per_size(values_by_scale):
    """{scale: [values]} -> sorted rows (scale, mean, standard error, runs); the error of a
    single run is nan."""
    rows = []
    for scale in sorted(values_by_scale):
        values = np.asarray(values_by_scale[scale], dtype=float)
        error = float(standard_error(values)) if len(values) > 1 else float("nan")
        rows.append((scale, float(values.mean()), error, len(values)))
    return rows


def extrapolate(rows):
    """Weighted least squares F = F_inf + c / s over the sizes with an error: (F at s = 1 and its
    error, F_inf and its error, c), or None with fewer than two such sizes."""
    usable = [r for r in rows if r[3] > 1 and r[2] > 0]
    if len(usable) < 2:
        return None
    x = np.array([1.0 / r[0] for r in usable])
    y = np.array([r[1] for r in usable])
    w = np.array([1.0 / r[2] ** 2 for r in usable])
    design = np.column_stack([np.ones_like(x), x])
    covariance = np.linalg.inv(design.T @ (design * w[:, None]))
    f_inf, slope = covariance @ (design.T @ (w * y))
    at_one = np.array([1.0, 1.0])
    f_one = float(at_one @ np.array([f_inf, slope]))
    f_one_err = float(math.sqrt(at_one @ covariance @ at_one))
    return f_one, f_one_err, float(f_inf), float(math.sqrt(covariance[0, 0])), float(slope)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("runs", nargs="+", help="run folders (drag.sphere-couette and log.lammps each)")
    ap.add_argument("--from-step", type=int, default=None,
                    help="last step of the start-up, excluded (default: each run's own, where its rdf "
                         "blocks begin (python/sphere_couette.py: its map blocks); without one the first 20 %%)")
    args = ap.parse_args(argv)
    totals, split = collections.defaultdict(list), collections.defaultdict(list)
    for run in args.runs:
        scale = box_length(os.path.join(run, "log.lammps")) / PAPER_LX
        total, c_plus_d = run_drag(run, args.from_step)
        totals[scale].append(total)
        split[scale].append(c_plus_d)
        print(f"{run}: s = {scale:.2f}, F = {total:.2f}, F_C + F_D = {c_plus_d:.2f}")
    for name, values in (("drag F_x (C + D + R)", totals), ("F_C + F_D", split)):
        rows = per_size(values)
        print(f"\n{name}: s, mean over runs, standard error over runs, runs")
        for scale, mean, error, count in rows:
            print(f"  {scale:.2f}  {mean:8.2f}  {error:6.2f}  {count}")
        fit = extrapolate(rows)
        if fit is None:
            print("  (fewer than two sizes with repeated runs: no extrapolation)")
        else:
            f_one, f_one_err, f_inf, f_inf_err, slope = fit
            print(f"  F = F_inf + c / s: at the paper's box (s = 1) {f_one:.2f} +- {f_one_err:.2f} "
                  f"(paper {PAPER['F']:.2f}: ratio {f_one / PAPER['F']:.3f} +- {f_one_err / PAPER['F']:.3f}); "
                  f"F_inf {f_inf:.2f} +- {f_inf_err:.2f}, c {slope:.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
