#!/usr/bin/python3
"""The package's headline numbers on one generated page, bench/results.md: the speed-ups at equal
accuracy and the cost of a step (from the accuracy matrix's records, bench/accuracy/results/*.jsonl,
through python/etddpd/accuracy_matrix.py), the pair styles' throughput and its scaling
(bench/results/throughput.md, scaling.md), the KOKKOS styles' threads against ranks
(bench/kokkos/results/throughput.md) and the validation ratios against published results
(from the studies' summaries under validation/). README.md and doc/*.rst link here instead of
restating these numbers; unittest/python/test_results_page.py checks that they do.

Usage: /usr/bin/python3 bench/results_page.py > bench/results.md
"""
import contextlib
import io
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
sys.path.insert(0, os.path.join(ROOT, "python"))
from etddpd import accuracy_matrix, study_records  # noqa: E402

HEADLINE_SECTIONS = ("## Largest steps re-run with independent seeds",
                     "## Largest step within tolerance on every observable",
                     "## Cost of a step against a stock step")


def read(relative):
    with open(os.path.join(ROOT, relative)) as handle:
        return handle.read()


def matrix_sections():
    """The accuracy matrix's headline sections, regenerated from its records."""
    text = io.StringIO()
    with contextlib.redirect_stdout(text):
        accuracy_matrix.main([os.path.join(ROOT, "bench", "accuracy", "results")])
    sections = re.split(r"(?m)^(?=## )", text.getvalue())
    keep = [s.rstrip() for s in sections if s.startswith(HEADLINE_SECTIONS)]
    return "\n\n".join(s.replace("## ", "### ", 1) for s in keep)


def channel_sphere_drag(*names):
    """{record name: (U, Re, C_D, C_D error, correlation)} from `channel_sphere.py drag` run on
    the study's committed records (validation/channel-sphere/results/records.json)."""
    records = study_records.read(os.path.join(ROOT, "validation", "channel-sphere", "results", "records.json"))
    with tempfile.TemporaryDirectory() as work:
        for name in names:
            with open(os.path.join(work, name), "w") as handle:
                handle.write(records[name])
        out = subprocess.run([sys.executable, os.path.join(ROOT, "python", "channel_sphere.py"), "drag", *names],
                             cwd=work, capture_output=True, text=True, check=True).stdout
    rows = {}
    for line in out.splitlines():
        row = line.split()
        if row[:1] and row[0] in names:
            cd, cd_error = (float(x) for x in row[5].split("+-"))
            rows[row[0]] = (row[1], row[2].split("+-")[0], cd, cd_error, float(row[6]))
    return rows


def channel_sphere_ratio():
    """C_D of the 56-particle sphere in the paper's box over Brown and Lawler's correlation."""
    _, re_value, cd, cd_error, corr = channel_sphere_drag("drag.U0.9_full")["drag.U0.9_full"]
    return (f"{cd / corr:.2f} +- {cd_error / corr:.2f}",
            f"C_D {cd:.3f}+-{cd_error:.3f} against {corr} at Re = {re_value}",
            "validation/channel-sphere/results/records.json (drag.U0.9_full)")


def channel_sphere_re6_ratio(paper=4.0, re_target=6.0):
    """C_D at Re = 6 over the paper's quoted "C_D about 4 at Re about 6": C_D Re interpolated
    linearly in Re between the two runs of the paper's length that bracket Re = 6 (U_wall = 0.5,
    reduced width, and U_wall = 0.9, the paper's box). The interpolated value carries the
    relative error of the less certain of the two (the interpolation's own error is not known)."""
    names = ("drag.U0.5_nx120", "drag.U0.9_full")
    rows = channel_sphere_drag(*names)
    (_, re1, cd1, e1, _), (_, re2, cd2, e2, _) = (rows[n] for n in names)
    re1, re2 = float(re1), float(re2)
    product = cd1 * re1 + (cd2 * re2 - cd1 * re1) * (re_target - re1) / (re2 - re1)
    cd = product / re_target
    cd_error = cd * max(e1 / cd1, e2 / cd2)
    return (f"{cd / paper:.2f} +- {cd_error / paper:.2f}",
            f"C_D {cd:.2f} +- {cd_error:.2f} at Re = {re_target:g}, from C_D Re at Re = {re1:.2f} and {re2:.2f}",
            "validation/channel-sphere/results/records.json (" + ", ".join(names) + ")")


def fpm_two_sphere_ratios(papers=((1.0, 1.066), (1.5, 0.974), (2.0, 0.969))):
    """The two dpd/fpm spheres' torque / eq. (23), weighted over the independent runs in the cube of
    side 8 (validation/fpm/torque_field.sh), over the paper's Table 3 value at each separation."""
    source = "validation/fpm/results/torque_field/summary.txt"
    rows = []
    for l, paper in papers:
        value = search(source, rf"^l = {l:.1f}: dissipative torque / eq\. \(23\) per run (.*); "
                               r"weighted ([0-9.]+) \+- ([0-9.]+)", 0)
        runs = len(re.search(r"per run (.*);", value).group(1).split(","))
        mean, error = (float(x) for x in re.search(r"weighted ([0-9.]+) \+- ([0-9.]+)", value).groups())
        rows.append((l, paper, f"{mean / paper:.2f} +- {error / paper:.2f}",
                     f"l = {l:g}: {mean:.3f} +- {error:.3f} ({runs} runs) against {paper}", source))
    return rows


def search(relative, pattern, group=1):
    match = re.search(pattern, read(relative), re.M)
    if not match:
        sys.exit(f"results_page.py: {relative} no longer states {pattern!r}")
    return match.group(group)


def validation_rows():
    """(published result, paper, ratio, what, summary file) for each validation ratio."""
    rows = []
    ratio, what, source = channel_sphere_ratio()
    rows.append(("56-particle sphere, free flow, paper's box: C_D / Brown and Lawler's correlation "
                 "(Reddy and Abraham 2009, Fig. 7)", "within 3 %", ratio, what, source))
    ratio, what, source = channel_sphere_re6_ratio()
    rows.append(("the same sphere, C_D at Re about 6 / the paper's quoted \"about 4\" (Reddy and Abraham 2009)",
                 "about 4", ratio, what, source))
    for l, paper, ratio, what, source in fpm_two_sphere_ratios():
        rows.append((f"dpd/fpm two spheres at l = {l:g}, torque / eq. (23) over the paper's "
                     "(Pan, Pivkin and Karniadakis 2008, Table 3)", f"{paper}", ratio, what, source))
    source = "validation/sphere-couette/results/size_scan/summary.txt"
    ratio = search(source, r"ratio ([0-9.]+ \+- [0-9.]+)")
    at = search(source, r"at the paper's box \(s = 1\) ([0-9.]+ \+- [0-9.]+)")
    rows.append(("one-particle colloid in Couette flow, drag / the paper's 178.36 (Mai-Duy et al. 2013)",
                 "178.36", ratio, f"{at} extrapolated to the paper's box", source))
    source = "validation/fpm/results/rotating_sphere/results.md"
    ratio = search(source, r"^\| torque T / \(-8 pi mu Omega R\^3\), L = 8, Omega = -6, 200 blocks \| [^|]* \| ([0-9.]+ \+- [0-9.]+)")
    rows.append(("dpd/fpm spun sphere at rest, torque / Stokes (Pan, Pivkin and Karniadakis 2008)",
                 "within 1.3 %", ratio, "cube of side 8, Omega = -6", source))
    return rows


def main():
    print("# Results: the package's headline numbers")
    print()
    print("Generated by `/usr/bin/python3 bench/results_page.py > bench/results.md` from the studies'")
    print("summaries; do not edit by hand. README.md and the doc pages link here rather than restating")
    print("these numbers (unittest/python/test_results_page.py fails where they do with other values).")
    print("How each study measures and what limits it: bench/accuracy/README.md, bench/README.md and")
    print("the READMEs under validation/.")
    print()
    print("## Validation ratios against published results")
    print()
    print("| published result | paper | ratio | measured | summary |")
    print("|---|---|---|---|---|")
    for quantity, paper, ratio, what, source in validation_rows():
        print(f"| {quantity} | {paper} | {ratio} | {what} | `{source}` |")
    print()
    print("## Speed-up at equal accuracy and the cost of a step (bench/accuracy)")
    print()
    print("From `bench/accuracy/results/{scan,confirm,timing}.jsonl`; every cell and the plots:")
    print("`bench/accuracy/results/matrix.md`, `bench/accuracy/figures/`. Speed-ups are the cost per")
    print("time unit of the baseline at its own largest step over the integrator's at its own.")
    print()
    print(matrix_sections())
    print()
    print("## Pair-style throughput (bench/run_bench.sh)")
    print()
    print(read("bench/results/throughput.md").rstrip())
    print()
    print("## Cost per atom-step against system size (bench/run_scaling.sh)")
    print()
    print(read("bench/results/scaling.md").rstrip())
    print()
    print("## Threads against ranks: the KOKKOS styles (bench/kokkos/run.sh)")
    print()
    print(read("bench/kokkos/results/throughput.md").rstrip())


if __name__ == "__main__":
    main()
