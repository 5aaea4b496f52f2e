#!/usr/bin/python3
"""Steady-shear viscosity table and plot from validation/shear/results/results.dat.

Each line of the results file is one run: integrator dt rate seed kBT eta slope
(eta = -<P_xy>/rate over the production run, kBT from compute temp/deform, slope = the fitted
velocity gradient). Runs are grouped by (integrator, dt) and rate; for every group the script
prints the mean over seeds with its standard error, and the spread (sample standard deviation
of the runs). The noise of a run's mean stress is set by the fluid, the box and the averaging
time, not by the integrator, so the spread is also pooled over all groups at a rate (more
degrees of freedom than 2-4 seeds give); the ratios to the reference integrators (default:
stock dpd/ext + fix nve) at the same rate carry errors from that pooled spread, and so do the
error bars of the plot.

  shear_viscosity.py validation/shear/results/results.dat --plot validation/shear/figures/eta_vs_rate.png \
      [--reference stock[,nve]] [--tcaf validation/shear/results/tcaf/nve-0.0005_summary.txt] [--eta0 X+-E]

--tcaf reads the Newtonian eta_0 of python/tcaf_fit.py's summary (zero-shear reference, drawn
as a horizontal band); --eta0 gives it by hand. Needs numpy and, for the plot, matplotlib
(Debian python3-numpy, python3-matplotlib).
"""
import argparse
import math
import re
import sys
from collections import defaultdict

import numpy as np


def read_results(path):
    """Rows (integrator, dt, rate, seed, kBT, eta, slope)."""
    rows = []
    with open(path) as handle:
        for line in handle:
            line = line.split("#", 1)[0].split()
            if not line:
                continue
            if len(line) != 7:
                raise ValueError(f"{path}: expected 7 columns, got {' '.join(line)!r}")
            integ, dt, rate, seed = line[0], float(line[1]), float(line[2]), line[3]
            kt, eta, slope = (float(x) for x in line[4:7])
            rows.append((integ, dt, rate, seed, kt, eta, slope))
    if not rows:
        raise ValueError(f"{path}: no results")
    return rows


def label(integ, dt):
    return f"{integ} dt={dt:g}"


def summarise(rows):
    """{(integ, dt): {rate: dict(n, eta, spread, sem, kt, slope)}}"""
    groups = defaultdict(lambda: defaultdict(list))
    for integ, dt, rate, _seed, kt, eta, slope in rows:
        groups[(integ, dt)][rate].append((eta, kt, slope))
    table = {}
    for key, by_rate in groups.items():
        table[key] = {}
        for rate, values in by_rate.items():
            v = np.array(values)
            n = len(v)
            spread = float(np.std(v[:, 0], ddof=1)) if n > 1 else float("nan")
            table[key][rate] = {
                "n": n, "eta": float(v[:, 0].mean()), "spread": spread,
                "sem": spread / math.sqrt(n) if n > 1 else float("nan"),
                "kt": float(v[:, 1].mean()), "slope": float(v[:, 2].mean()),
            }
    return table


def pooled_spread(table):
    """{rate: (pooled sample standard deviation of one run, degrees of freedom)}"""
    acc = defaultdict(lambda: [0.0, 0])
    for by_rate in table.values():
        for rate, c in by_rate.items():
            if c["n"] > 1:
                acc[rate][0] += (c["n"] - 1) * c["spread"] ** 2
                acc[rate][1] += c["n"] - 1
    return {rate: (math.sqrt(ss / dof), dof) for rate, (ss, dof) in acc.items() if dof > 0}


def order_keys(keys, reference):
    preferred = {"stock": 0, "nve": 1, "diag": 2, "implicit": 3, "overdamped": 4}
    return sorted(keys, key=lambda k: (k[0] != reference, preferred.get(k[0], 9), k[0], k[1]))


def ratio(a, b, sd):
    """a/b with the error from the pooled spread sd of one run (nan where it is missing)."""
    r = a["eta"] / b["eta"]
    err = r * sd * math.hypot(1.0 / (a["eta"] * math.sqrt(a["n"])), 1.0 / (b["eta"] * math.sqrt(b["n"])))
    return r, err


def fmt(x, digits=3):
    return "-" if x is None or not math.isfinite(x) else f"{x:.{digits}f}"


def reference_key(table, name):
    """(integrator, smallest dt) of the reference integrator, or None."""
    keys = sorted(k for k in table if k[0] == name)
    return keys[0] if keys else None


def markdown(table, references):
    keys = order_keys(table.keys(), references[0])
    pooled = pooled_spread(table)
    refs = [(name, reference_key(table, name)) for name in references]
    refs = [(name, key) for name, key in refs if key is not None]
    head = "| integrator | dt | rate | runs | kBT | slope/rate | eta +- s.e. | spread (sd) |"
    for _name, key in refs:
        head += f" ratio to {label(*key)} |"
    lines = [head, "|" + "---|" * (8 + len(refs))]
    for key in keys:
        for rate in sorted(table[key]):
            c = table[key][rate]
            sd = pooled.get(rate, (float("nan"), 0))[0]
            row = (f"| {key[0]} | {key[1]:g} | {rate:g} | {c['n']} | {c['kt']:.4f} | "
                   f"{c['slope'] / rate:.3f} | {c['eta']:.3f} +- {fmt(c['sem'])} | "
                   f"{fmt(c['spread'])} |")
            for _name, ref in refs:
                if key == ref:
                    row += " 1 |"
                elif rate in table[ref]:
                    r, err = ratio(c, table[ref][rate], sd)
                    row += f" {r:.3f} +- {fmt(err)} |"
                else:
                    row += " - |"
            lines.append(row)
    lines.append("")
    lines.append("pooled spread of one run (all groups at a rate): " + ", ".join(
        f"rate {rate:g}: {sd:.3f} ({dof} dof)" for rate, (sd, dof) in sorted(pooled.items())))
    return "\n".join(lines)


def read_tcaf(path):
    """(eta_0, error) of the Newtonian extrapolation in tcaf_fit.py's summary."""
    with open(path) as handle:
        for line in handle:
            m = re.search(r"Newtonian\s*:\s*eta_0\s*=\s*([-\d.eE+]+)\s*\+-\s*([-\d.eE+naN]+)", line)
            if m:
                return float(m.group(1)), float(m.group(2))
    raise ValueError(f"{path}: no 'Newtonian: eta_0 = X +- E' line")


def parse_eta0(text):
    value, _, err = text.partition("+-")
    return float(value), float(err) if err else float("nan")


def plot(table, reference, path, eta0=None, eta0_label="zero-shear eta_0 (TCAF)"):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    keys = order_keys(table.keys(), reference)
    pooled = pooled_spread(table)
    fig, ax = plt.subplots(figsize=(6, 4.2))
    rates_all = sorted({r for k in keys for r in table[k]})
    # small horizontal offsets so that the error bars do not overlap
    span = math.log(max(rates_all) / min(rates_all)) if len(rates_all) > 1 else 1.0
    markers = "osD^vP*X"
    for i, key in enumerate(keys):
        rates = np.array(sorted(table[key]))
        eta = np.array([table[key][r]["eta"] for r in rates])
        err = np.array([pooled.get(r, (float("nan"), 0))[0] / math.sqrt(table[key][r]["n"])
                        for r in rates])
        shift = np.exp((i - (len(keys) - 1) / 2) * 0.025 * span)
        ax.errorbar(rates * shift, eta, yerr=np.nan_to_num(err), fmt=markers[i % len(markers)] + "-",
                    ms=5, capsize=3, lw=1, mfc="none", label=label(*key))
    if eta0 is not None:
        value, err = eta0
        ax.axhline(value, color="k", ls=":", lw=1,
                   label=f"{eta0_label}: {value:.3f}" + (f" +- {err:.3f}" if math.isfinite(err) else ""))
        if math.isfinite(err):
            ax.axhspan(value - err, value + err, color="grey", alpha=0.15, lw=0)
    ax.set_xscale("log")
    ax.set_xticks(rates_all)
    ax.set_xticklabels([f"{r:g}" for r in rates_all])
    ax.minorticks_off()
    ax.set_xlabel("shear rate")
    ax.set_ylabel(r"$\eta = -\langle P_{xy}\rangle / \dot\gamma$")
    ax.set_title("steady shear, 4,000 atoms, m = 0.01, s = 1/2\n(mean over seeds +- standard error from the pooled spread)", fontsize=9)
    lo, hi = ax.get_ylim()
    ax.set_ylim(lo - 0.45 * (hi - lo), hi)    # room for the legend below the data
    ax.legend(fontsize=7, ncol=2, loc="lower center")
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def parse_args(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("results", help="results file of validation/shear/run.sh")
    parser.add_argument("--reference", default="stock",
                        help="integrator(s) the ratios refer to, comma-separated "
                             "(default stock; each at its smallest dt)")
    parser.add_argument("--plot", help="write eta against rate to this PNG")
    parser.add_argument("--tcaf", help="tcaf_fit.py summary with the zero-shear eta_0")
    parser.add_argument("--eta0", type=parse_eta0, help="zero-shear eta_0 as VALUE[+-ERR]")
    return parser.parse_args(argv)


def zero_shear(args):
    """(eta_0, error) from --tcaf, else --eta0, else None."""
    return read_tcaf(args.tcaf) if args.tcaf else args.eta0


def main(argv=None):
    args = parse_args(argv)
    table = summarise(read_results(args.results))
    references = [r for r in args.reference.split(",") if r]
    print(markdown(table, references))
    print("eta: mean over seeds +- its standard error; spread: sample standard deviation of the "
          "runs; ratio errors from the pooled spread.")
    eta0 = zero_shear(args)
    if eta0 is not None:
        print(f"zero-shear eta_0 = {eta0[0]:.3f} +- {fmt(eta0[1])}")
    if args.plot:
        plot(table, references[0], args.plot, eta0)
        print(f"plot: {args.plot}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
