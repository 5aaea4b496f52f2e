#!/usr/bin/python3
"""Where LAMMPS's Shardlow splitting breaks down, and where the implicit scheme holds
(bench/shardlow/README.md): every s = 2 cell of the accuracy matrix's records (the Groot-Warren
fluid GW, its gamma = 45 variant HG and the eta = 30, Sc = 500 fluid S2) against the per-pair friction stiffness gamma dt / m (the
stiffness of a pair at r -> 0, where w_D = 1) and an atom's, Gamma dt / m (Gamma = gamma n [w_D] / 3,
its partners' friction summed), with each observable's deviation from stock
velocity-Verlet at a small step, and the viscosity from reverse-Poiseuille flow where it was run.

Usage: map.py [--results DIR] [--figure PATH]   (markdown on standard output)
"""
import argparse
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "python"))
from etddpd import accuracy_matrix as am  # noqa: E402

FLUIDS = ("GW", "HG", "S2")
INTEGRATORS = ("shardlow", "imp", "stock")


def viscosity_deviations(records):
    """{(fluid, mass, integrator, dt): (relative deviation, its error, seeds, key)} of the
    reverse-Poiseuille viscosity against the smallest-step stock runs of the same fluid, mass and
    force (each seed one sample); eta from the velocities in v ('eta') and from the
    displacements per step ('eta_disp') where the record has it."""
    usable = [r for r in records if r.get("exit") == 0 and "eta" in r]
    groups = {}
    for r in usable:
        groups.setdefault((r["fluid"], r["mass"], r["force"], r["integrator"], r["dt"]), []).append(r)
    out = {}
    for (fluid, mass, force, integrator, dt), runs in groups.items():
        stock = [k for k in groups if k[:3] == (fluid, mass, force) and k[3] == "stock"]
        if not stock:
            continue
        ref_key = min(stock, key=lambda k: k[4])
        if ref_key == (fluid, mass, force, integrator, dt):
            continue
        ref = np.array([r["eta"] for r in groups[ref_key]])
        for key in ("eta", "eta_disp"):
            values = np.array([r[key] for r in runs if key in r])
            if len(values) < 2 or len(ref) < 2:
                continue
            dev = am.relative_deviation(values, ref)
            out[(fluid, mass, integrator, dt, key)] = (dev.value, dev.error, len(values), len(ref))
    return out


def rows(cell_list, viscosity):
    out = []
    for c in cell_list:
        if c.fluid not in FLUIDS or c.integrator not in INTEGRATORS or c.stopped:
            continue
        gamma = am.FLUIDS[c.fluid]["gamma"]
        out.append({"fluid": c.fluid, "mass": c.mass, "integrator": c.integrator, "dt": c.dt,
                    "pair_stiffness": gamma * c.dt / c.mass,
                    "atom_stiffness": am.friction_coefficient(c.fluid) * c.dt / c.mass,
                    "deviations": c.deviations,
                    "eta": viscosity.get((c.fluid, c.mass, c.integrator, c.dt, "eta")),
                    "eta_disp": viscosity.get((c.fluid, c.mass, c.integrator, c.dt, "eta_disp"))})
    return sorted(out, key=lambda r: (r["fluid"], -r["mass"], INTEGRATORS.index(r["integrator"]), r["dt"]))


def table(map_rows):
    lines = ["| fluid | m | integrator | dt | gamma dt / m | Gamma dt / m | kBT % | P % | max dg(r) | D % "
             "| eta (v) % | eta (displacements) % |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|"]

    def pct(d, name):
        mark = "" if d.within(am.TOLERANCE[name]) else " **x**"
        return f"{100 * d.value:+.1f} +- {100 * d.error:.1f}{mark}"

    def eta(value):
        if value is None:
            return "-"
        mark = "" if abs(value[0]) <= 0.02 else " **x**"
        return f"{100 * value[0]:+.1f} +- {100 * value[1]:.1f} ({value[2]}){mark}"
    for r in map_rows:
        d = r["deviations"]
        g = d["g(r)"]
        gmark = "" if g.within(am.TOLERANCE["g(r)"]) else " **x**"
        lines.append(f"| {r['fluid']} | {r['mass']:g} | {am.INTEGRATOR_NAMES[r['integrator']]} | {r['dt']:g} | "
                     f"{r['pair_stiffness']:.3g} | {r['atom_stiffness']:.3g} | {pct(d['kBT'], 'kBT')} | {pct(d['P'], 'P')} | "
                     f"{g.value:.3f}{gmark} | {pct(d['D'], 'D')} | {eta(r['eta'])} | {eta(r['eta_disp'])} |")
    return "\n".join(lines)


def tuned_costs(timings):
    """Markdown: the cells timed at more than one neighbor skin in a fluid and mass's latest
    sitting (each integrator's own best tuning), fastest round per (cell, ranks, skin), and the
    implicit scheme's speed-up over fix shardlow with each at its fastest skin."""
    best = {}
    for ranks in sorted({r.get("ranks", 1) for r in timings}):
        for r in am._latest_sitting(timings, ranks, "s_per_tu", any_skin=True):
            key = (r["fluid"], r["mass"], r["integrator"], r["dt"], ranks, r.get("skin", 0.3))
            best[key] = min(best.get(key, np.inf), r["s_per_tu"])
    tuned = {k[:5] for k in best if k[5] != 0.3}
    lines = ["| fluid | m | integrator | dt | ranks | s per time unit, skin 0.3 | skin 0.7 | fastest |",
             "|---|---|---|---|---|---|---|---|"]
    fastest = {}
    for key in sorted(tuned):
        by_skin = {k[5]: v for k, v in best.items() if k[:5] == key}
        fastest[key] = min(by_skin.values())
        cols = [f"{by_skin[sk]:.2f}" if sk in by_skin else "-" for sk in (0.3, 0.7)]
        lines.append(f"| {key[0]} | {key[1]:g} | {key[2]} | {key[3]:g} | {key[4]} | {cols[0]} | {cols[1]} | "
                     f"{fastest[key]:.2f} |")
    for (fluid, mass, integrator, dt, ranks), cost in sorted(fastest.items()):
        if integrator != "imp":
            continue
        peers = [v for k, v in fastest.items() if k[:2] == (fluid, mass) and k[2] == "shardlow" and k[4] == ranks]
        if peers:
            lines.append(f"\n{fluid} m = {mass:g}, {ranks} rank(s): the implicit scheme at its fastest skin "
                         f"{min(peers) / cost:.2f} times fix shardlow at its fastest skin")
    return "\n".join(lines)


def plot(map_rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(9, 3.6))
    styles = {"shardlow": ("C3", "shardlow + nve"), "imp": ("C0", "etd implicit"), "stock": ("0.5", "stock + nve")}
    markers = {("GW", 0.01): "o", ("GW", 0.001): "s", ("HG", 0.01): "D", ("GW", 0.1): "^", ("GW", 1.0): "v",
               ("S2", 1.0): "P"}
    for ax, (name, label) in zip(axes, (("D", "self-diffusion D (%)"), ("eta", "viscosity, from v (%)"))):
        for integrator, (colour, text) in styles.items():
            for (fluid, mass), marker in markers.items():
                pts = [r for r in map_rows if (r["integrator"], r["fluid"], r["mass"]) == (integrator, fluid, mass)]
                if name == "eta":
                    pts = [r for r in pts if r["eta"] is not None]
                    y = [100 * r["eta"][0] for r in pts]
                    e = [100 * r["eta"][1] for r in pts]
                else:
                    y = [100 * r["deviations"]["D"].value for r in pts]
                    e = [100 * r["deviations"]["D"].error for r in pts]
                if pts:
                    ax.errorbar([r["atom_stiffness"] for r in pts], y, yerr=e, color=colour, marker=marker,
                                ms=4, capsize=2, ls="-", label=f"{text}, {fluid} m = {mass:g}")
        ax.axhspan(-2, 2, color="0.9", zorder=0)
        ax.set_xscale("log")
        ax.set_xlabel("friction stiffness of an atom, Gamma dt / m")
        ax.set_ylabel(label)
    axes[0].legend(fontsize=6)
    fig.suptitle("s = 2 fluids: deviation from velocity-Verlet at a small step (band: 2 %)", fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)
    return path


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--results", default=os.path.join(HERE, "..", "accuracy", "results"))
    parser.add_argument("--figure", default=None)
    args = parser.parse_args(argv)
    cell_list = am.cells(am.read_jsonl(os.path.join(args.results, "scan.jsonl")))
    vpath = os.path.join(args.results, "viscosity.jsonl")
    viscosity = viscosity_deviations(am.read_jsonl(vpath)) if os.path.exists(vpath) else {}
    map_rows = rows(cell_list, viscosity)
    print(table(map_rows))
    tpath = os.path.join(args.results, "timing.jsonl")
    if os.path.exists(tpath):
        print("\n## Each integrator at its own best neighbor skin (alternated rounds, fastest)\n")
        print(tuned_costs(am.read_jsonl(tpath)))
    if args.figure:
        plot(map_rows, args.figure)
        print(f"\n![map]({os.path.basename(args.figure)})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
