#!/usr/bin/python3
"""Driver of the accuracy matrix (bench/accuracy/README.md).

Sub-commands (each appends one JSON line per LAMMPS run to bench/accuracy/results/):

  equilibrate  --fluid F                  random start -> /tmp/accuracy/F.data (m = 1, dpd/gen + nve)
  scan         --fluid F --mass M --integrator I --dt DT [DT ...] [--windows W --window T] [--role ref]
               [--pair gen]  (velocity-Verlet with dpd/gen's forces in place of the stock style)
               equilibrium observables (in.accuracy): kBT, friction-step kBT, P, g(r), D
               -> results/scan.jsonl
  confirm      --fluid F --mass M (--ref-dt DT [--ref-pair gen] | --no-ref) --cell I:DT [I:DT ...] [--seeds S ...] [--windows W]
               the reference and the cells once per seed (default 11-14, 16 windows) -> results/confirm.jsonl
  time         --fluid F --mass M --cell I:DT [I:DT ...] [--repeats R --steps N]
               cost: the cells alternated, R rounds, loop time of N steps each (no observables)
               -> results/timing.jsonl
  derive-ref   --fluid F --mass M --static-from M0 --d-from M1 M2 [...] [--seeds-from M3 [--seeds-only]]
               a reference out of velocity-Verlet's reach: kBT, P and g(r) of the reference at M0
               (mass-independent at equilibrium), D from a fit D0 - c m to the references at M1 M2 ...
               -> results/scan.jsonl; with --seeds-from, the seed check's references likewise from
               the reference seeds at M3 -> results/confirm.jsonl; --seeds-only: those alone,
               where the scan has a reference of its own (HS m = 0.01, whose reference step is
               the least converged of the matrix)
  viscosity    --fluid F --mass M --integrator I --dt DT [--time T --equil T --force G]
               reverse Poiseuille flow (in.viscosity) -> results/viscosity.jsonl

Integrators (I): stock = stock pair style (dpd for GW, dpd/ext for P and HS) + fix nve;
diag = dpd/gen + fix etd; imp = dpd/gen + fix etd scheme implicit; impv = dpd/gen + fix etd
scheme implicit tol 1e-4 start velocity; shardlow = LAMMPS's fix shardlow + fix nve with pair_style
dpd/fdt (DPD-REACT; s = 2 only: GW, HG and S2).  LAMMPS runs with nice -n 5 on one rank; the plugin is
the copy /tmp/accuracy/etddpdplugin.so (copy it there first; the build folder's is rebuilt).
"""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import time as clock

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from etddpd.accuracy_matrix import FLUIDS  # noqa: E402
from etddpd.lammps_output import loop_times, read_ave_chunk, read_ave_time, read_ave_time_vector, timing_breakdowns  # noqa: E402
from etddpd.statistics import standard_error  # noqa: E402
from etddpd.viscosity_fit import fit_viscosity  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
RESULTS = os.path.join(HERE, "results")
# LMP and PLUGIN as the drivers (campaign.sh, timing.sh, viscosity.sh) set them through
# tools/lammps_env.sh; run by hand, LMP must be set (tools/bootstrap.sh prints LAMMPS_PREFIX)
LMP = os.environ.get("LMP")
PLUGIN = os.environ.get("PLUGIN", "/tmp/accuracy/etddpdplugin.so")
WORK = os.environ.get("WORK", "/tmp/accuracy/runs")

INTEGRATORS = {
    "stock": ("stock", "nve"),
    "diag": ("gen", "etd"),
    "imp": ("gen", "etd scheme implicit"),
    "impv": ("gen", "etd scheme implicit tol 1e-4 start velocity"),
    "gennve": ("gen", "nve"),
    "shardlow": ("fdt", "nve"),
}


def lammps(inp, variables, workdir, log="log.lammps", ranks=1):
    if not LMP:
        sys.exit("run.py: set LMP to the LAMMPS executable ($LAMMPS_PREFIX/bin/lmp from tools/bootstrap.sh), "
                 "or run it through campaign.sh, timing.sh or viscosity.sh")
    os.makedirs(workdir, exist_ok=True)
    if variables.get("data", "no") != "no":
        shutil.copy(variables["data"], os.path.join(workdir, "start.data"))
        variables = dict(variables, data="yes")
    mpi = []
    if ranks > 1:
        mpi = ["mpirun", "-np", str(ranks)] + (["--allow-run-as-root"] if os.geteuid() == 0 else [])
    cmd = ["nice", "-n", "5"] + mpi + [LMP, "-in", os.path.join(HERE, inp), "-screen", "none", "-log", log]
    for key, value in dict(variables, bench=HERE).items():
        cmd += ["-var", key, str(value)]
    start = clock.time()
    done = subprocess.run(cmd, cwd=workdir)
    wall = clock.time() - start
    text = open(os.path.join(workdir, log)).read() if os.path.exists(os.path.join(workdir, log)) else ""
    if done.returncode != 0:
        print(f"FAILED (exit {done.returncode}): {' '.join(cmd)} in {workdir}", file=sys.stderr)
        print("\n".join(text.splitlines()[-4:]), file=sys.stderr)
    return done.returncode, text, wall


def read_blocks(path):
    """fix ave/time scalar output without its TimeStep column: data[row, value]."""
    return read_ave_time(path).data[:, 1:]


def read_rdf(path):
    """compute rdf through fix ave/time mode vector (columns Row, r, g): r and g[block, bin]."""
    blocks = read_ave_time_vector(path).data
    return blocks[0, :, 1], blocks[:, :, 2]


# D is read off the MSD at one fixed time for every cell, whatever its step: the windows' lengths
# differ slightly between steps (a whole number of steps and sampling intervals), and the MSD
# over a window still holds some of the short-time (ballistic) part, so MSD(t_w) / 6 t_w would
# depend on t_w. DIFFUSION_TIME is below the shortest window of any scan (0.8 of the nominal).
DIFFUSION_TIME = 0.2


def diffusion(path, dt, at=DIFFUSION_TIME):
    """(MSD(at) / (6 at) by linear interpolation, slope of the MSD over the window's second half
    / 6) of one window."""
    data = read_ave_time(path).data
    t = (data[:, 0] - data[0, 0]) * dt
    msd = data[:, 1]
    if t[-1] < at:
        raise ValueError(f"{path}: window of {t[-1]} time units is shorter than {at}")
    half = t >= 0.5 * t[-1]
    slope = np.polyfit(t[half], msd[half], 1)[0]
    return np.interp(at, t, msd) / (6.0 * at), slope / 6.0


def steps_for(window, dt, stride, msdstride):
    """Steps per window: a multiple of both sampling intervals, at least window / dt (the
    diffusion is read at DIFFUSION_TIME inside it)."""
    lcm = int(np.lcm(stride, msdstride))
    return lcm * max(1, int(np.ceil(window / (dt * lcm) - 1e-9)))


def append(name, record):
    os.makedirs(RESULTS, exist_ok=True)
    with open(os.path.join(RESULTS, name), "a") as out:
        out.write(json.dumps(record) + "\n")


def tag_of(*parts):
    return "_".join(str(p).replace(" ", "") for p in parts)


def cmd_equilibrate(args):
    work = os.path.join(WORK, tag_of("equil", args.fluid))
    rc, text, wall = lammps("in.accuracy", {"plugin": PLUGIN, "fluid": args.fluid, "pair": "gen",
                                            "integrator": "nve", "mass": 1.0, "dt": 0.005, "nequil": round(args.time / 0.005),
                                            "windows": 1, "nwin": 100, "stride": 10, "msdstride": 10,
                                            "write": "yes"}, work)
    if rc == 0:
        shutil.copy(os.path.join(work, "final.data"), f"/tmp/accuracy/{args.fluid}.data")


def pair_for(args):
    """The pair style of a run: the integrator's, or dpd/gen in place of the stock style for
    velocity-Verlet (--pair gen: the same forces to round-off, a third of dpd/ext's cost at
    s != 2; the expensive references and stock scans of HS below m = 0.1)."""
    pair, integrator = INTEGRATORS[args.integrator]
    if getattr(args, "pair", None):
        if integrator != "nve":
            sys.exit(f"run.py: --pair applies to velocity-Verlet (stock, gennve), not '{args.integrator}'")
        pair = args.pair
    return pair, integrator


def cmd_scan(args):
    pair, integrator = pair_for(args)
    for dt in args.dt:
        # the MSD about 100 times a window, g(r) about every 0.01 time units, at a multiple of
        # the MSD's interval (so that the window, a multiple of both, stays near its length)
        msdstride = max(1, round(args.window / dt / 100))
        stride = msdstride * max(1, round(0.01 / dt / msdstride))
        nwin = steps_for(args.window, dt, stride, msdstride)
        implicit = "implicit" in integrator
        work = os.path.join(WORK, tag_of("scan", args.fluid, args.mass, args.integrator, dt, args.seed, args.role, pair))
        if os.path.isdir(work):
            shutil.rmtree(work)
        variables = {"plugin": PLUGIN, "fluid": args.fluid, "pair": pair, "integrator": integrator,
                     "mass": args.mass, "dt": dt, "data": f"/tmp/accuracy/{args.fluid}.data",
                     "nequil": nwin * max(1, round(args.equil / (nwin * dt))),
                     "windows": args.windows, "nwin": nwin, "stride": stride, "msdstride": msdstride,
                     "seed": args.seed, "friction_step": "yes" if implicit else "no"}
        rc, text, wall = lammps("in.accuracy", variables, work)
        record = {"fluid": args.fluid, "mass": args.mass, "integrator": args.integrator, "fix": integrator,
                  "pair": pair, "dt": dt, "role": args.role, "seed": args.seed, "equil": args.equil,
                  "windows": args.windows, "nwin": nwin, "window_time": nwin * dt, "stride": stride,
                  "msdstride": msdstride, "exit": rc, "wall": round(wall, 2), "date": clock.strftime("%Y-%m-%d %H:%M")}
        try:
            blocks = read_blocks(os.path.join(work, "blocks.txt"))
            record["T_blocks"] = blocks[:, 0].tolist()
            record["P_blocks"] = blocks[:, 1].tolist()
            if implicit:
                record["T5_blocks"] = blocks[:, 2].tolist()
            r, g = read_rdf(os.path.join(work, "rdf.txt"))
            record["rdf_r"] = r.tolist()
            record["rdf_blocks"] = g.tolist()
            d = [diffusion(os.path.join(work, f"msd.{w}.txt"), dt) for w in range(1, len(blocks) + 1)]
            record["D_blocks"] = [x[0] for x in d]
            record["Dslope_blocks"] = [x[1] for x in d]
            iters = re.search(r"ITERATIONS=([0-9.]+)", text)
            if iters:
                record["cg_iterations"] = float(iters.group(1))
            loops = loop_times(text)
            record["loop_production"] = sum(loop.seconds for loop in loops[1:])
        except (OSError, ValueError, IndexError) as error:
            record["error"] = str(error)
        append(args.out, record)
        T = np.array(record.get("T_blocks", [np.nan]))
        P = np.array(record.get("P_blocks", [np.nan]))
        D = np.array(record.get("D_blocks", [np.nan]))
        extra = ""
        if "T5_blocks" in record:
            extra = f" T5={np.mean(record['T5_blocks']):.4f}"
        print(f"{args.fluid} m={args.mass} {args.integrator} dt={dt} [{args.role}] exit={rc} wall={wall:.0f}s "
              f"T={T.mean():.4f}+-{standard_error(T):.4f}{extra} P={P.mean():.3f}+-{standard_error(P):.3f} "
              f"D={D.mean():.4f}+-{standard_error(D):.4f} it={record.get('cg_iterations', '-')}", flush=True)


def cmd_confirm(args):
    """The matrix's largest steps again with independent seeds: the reference and each cell once
    per seed (longer runs than the scans' by default) -> results/confirm.jsonl."""
    if (args.ref_dt is None) == (not args.no_ref):
        sys.exit("run.py confirm: give --ref-dt, or --no-ref where the reference is derived (derive-ref --seeds)")
    runs = [] if args.no_ref else [("stock", args.ref_dt, "ref", args.ref_pair)]
    for spec in args.cell:
        name, dt = spec.split(":")
        if name not in INTEGRATORS:
            sys.exit(f"run.py confirm: unknown integrator '{name}' in --cell")
        runs.append((name, float(dt), "cell", None))
    for seed in args.seeds:
        for name, dt, role, pair in runs:
            cmd_scan(argparse.Namespace(fluid=args.fluid, mass=args.mass, integrator=name, dt=[dt], pair=pair,
                                        windows=args.windows, window=0.25, equil=0.2, role=role, seed=seed,
                                        out="confirm.jsonl"))


def cmd_time(args):
    cells = []
    for spec in args.cell:
        name, dt = spec.split(":")
        cells.append((name, float(dt)))
    for round_ in range(args.repeats):
        for name, dt in cells:
            pair, integrator = INTEGRATORS[name]
            work = os.path.join(WORK, tag_of("time", args.fluid, args.mass, name, dt))
            variables = {"plugin": PLUGIN, "fluid": args.fluid, "pair": pair, "integrator": integrator,
                         "mass": args.mass, "dt": dt, "data": f"/tmp/accuracy/{args.fluid}.data",
                         "nequil": args.equil_steps, "windows": 1, "nwin": args.steps, "stride": 1,
                         "msdstride": 1, "timing": "yes", "skin": args.skin, "newton": args.newton}
            rc, text, wall = lammps("in.accuracy", variables, work, ranks=args.ranks)
            loops = loop_times(text)
            loop, nsteps = (loops[-1].seconds, loops[-1].steps) if loops else (float("nan"), 0)
            load = os.getloadavg()[0]
            record = {"fluid": args.fluid, "mass": args.mass, "integrator": name, "fix": integrator, "dt": dt,
                      "ranks": args.ranks, "skin": args.skin, "newton": args.newton, "round": round_, "sitting": args.sitting, "steps": nsteps, "loop": loop,
                      "s_per_tu": loop / (nsteps * dt) if nsteps else None, "load1": load, "exit": rc,
                      "date": clock.strftime("%Y-%m-%d %H:%M")}
            breakdowns = timing_breakdowns(text)
            if breakdowns:
                record["breakdown"] = breakdowns[-1]
            append("timing.jsonl", record)
            print(f"time {args.fluid} m={args.mass} {name} dt={dt} round {round_}: loop {loop:.2f} s / {nsteps} "
                  f"steps = {record['s_per_tu']:.2f} s per time unit (load {load:.2f})", flush=True)


VISCOSITY_FORCE = {"GW": 0.02, "HG": 0.3, "S2": 3.0, "P": 0.3, "HS": 3.0}


def cmd_time_matrix(args):
    """Times every integrator of each (fluid, mass) of the scans at its largest step (the seed
    check's, capped by the viscosity under shear), alternated in rounds."""
    from etddpd import accuracy_matrix as am
    cell_list = am.cells(am.read_jsonl(os.path.join(RESULTS, "scan.jsonl")))
    confirm = os.path.join(RESULTS, "confirm.jsonl")
    checked = am.seed_check(am.read_jsonl(confirm)) if os.path.exists(confirm) else None
    shear = os.path.join(RESULTS, "viscosity_shear.jsonl")
    viscosity = am.viscosity_deviations(am.read_jsonl(shear)) if os.path.exists(shear) else None
    steps = {}
    for row in am.summary_rows(cell_list, checked=checked, viscosity=viscosity):
        if row["dt"] is not None and (not args.fluid or row["fluid"] in args.fluid) \
                and (not args.mass or row["mass"] in args.mass):
            steps.setdefault((row["fluid"], row["mass"]), set()).add((row["integrator"], row["dt"]))
    for (fluid, mass), cells in sorted(steps.items()):
        spec = [f"{name}:{dt}" for name, dt in sorted(cells)]
        print(f"time {fluid} m={mass}: {' '.join(spec)}", flush=True)
        cmd_time(argparse.Namespace(fluid=fluid, mass=mass, cell=spec, repeats=args.repeats,
                                    steps=args.steps, equil_steps=args.equil_steps, sitting=args.sitting,
                                    ranks=args.ranks, skin=0.3, newton="on"))


def cmd_derive_ref(args):
    from etddpd import accuracy_matrix as am
    if args.seeds_only and args.seeds_from is None:
        sys.exit("run.py derive-ref: --seeds-only needs --seeds-from")
    try:
        record = am.derived_reference(am.read_jsonl(os.path.join(RESULTS, "scan.jsonl")), args.fluid,
                                      args.mass, args.static_from, args.d_from)
    except ValueError as error:
        sys.exit(f"run.py derive-ref: {error}")
    record["date"] = clock.strftime("%Y-%m-%d %H:%M")
    fit = record["derived_from"]
    print(f"derived reference {args.fluid} m={args.mass}: static from m={args.static_from}; D fit over "
          f"m={fit['D_masses']}: means {fit['D_means']}, residuals {fit['D_fit_residuals']}, "
          f"D({args.mass}) = {fit['D_at_mass']:.6f}")
    if not args.seeds_only:
        append("scan.jsonl", record)
    if args.seeds_from is not None:
        try:
            seeds = am.derived_seed_references(am.read_jsonl(os.path.join(RESULTS, "confirm.jsonl")), record,
                                               args.seeds_from)
        except ValueError as error:
            sys.exit(f"run.py derive-ref: {error}")
        for seed_record in seeds:
            seed_record["date"] = record["date"]
            append("confirm.jsonl", seed_record)
        print(f"derived seed-check references from m={args.seeds_from}: seeds {[r['seed'] for r in seeds]}")


def cmd_viscosity(args):
    pair, integrator = INTEGRATORS[args.integrator]
    if args.force is None:
        args.force = VISCOSITY_FORCE[args.fluid]
    work = os.path.join(WORK, tag_of("visc", args.fluid, args.mass, args.integrator, args.dt, args.seed))
    if os.path.isdir(work):
        shutil.rmtree(work)
    variables = {"plugin": PLUGIN, "fluid": args.fluid, "pair": pair, "integrator": integrator, "mass": args.mass,
                 "dt": args.dt, "data": f"/tmp/accuracy/{args.fluid}.data", "equil": args.equil,
                 "time": args.time, "g": args.force, "seed": args.seed, "blocks": args.blocks}
    rc, text, wall = lammps("in.viscosity", variables, work)
    record = {"fluid": args.fluid, "mass": args.mass, "integrator": args.integrator, "fix": integrator,
              "dt": args.dt, "time": args.time, "equil": args.equil, "force": args.force, "seed": args.seed,
              "exit": rc, "wall": round(wall, 2), "date": clock.strftime("%Y-%m-%d %H:%M")}
    try:
        density = FLUIDS[args.fluid]["n"]
        profiles = read_ave_chunk(os.path.join(work, "profile.txt")).data
        mean_profile = np.mean(profiles, axis=0)
        # columns: chunk, z, count, vx (the velocities in v), displacement per step / dt
        for column, key in ((3, "eta"), (4, "eta_disp")):
            etas = [fit_viscosity(block[:, 1], block[:, column], args.force, 10.0, density)[0]
                    for block in profiles]
            eta, fit_error = fit_viscosity(mean_profile[:, 1], mean_profile[:, column], args.force, 10.0, density)
            record.update({key: eta, key + "_fit_error": fit_error, key + "_blocks": etas})
        m = re.search(r"RESULT .*kBT=([0-9.]+)", text)
        record["kBT"] = float(m.group(1)) if m else None
    except (OSError, ValueError, IndexError) as error:
        record["error"] = str(error)
    append("viscosity.jsonl", record)
    if "eta" in record:
        e = np.array(record["eta_blocks"])
        print(f"visc {args.fluid} m={args.mass} {args.integrator} dt={args.dt}: eta={record['eta']:.4f} "
              f"(fit +-{record['eta_fit_error']:.4f}, blocks {e.mean():.4f}+-{standard_error(e):.4f}) "
              f"from displacements {record['eta_disp']:.4f} "
              f"kBT={record['kBT']} wall={wall:.0f}s", flush=True)


def parse_args(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="command", required=True)
    p = sub.add_parser("equilibrate")
    p.add_argument("--fluid", required=True, choices=["GW", "HG", "S2", "P", "HS"])
    p.add_argument("--time", type=float, default=5.0)
    p = sub.add_parser("scan")
    p.add_argument("--fluid", required=True, choices=["GW", "HG", "S2", "P", "HS"])
    p.add_argument("--mass", type=float, required=True)
    p.add_argument("--integrator", required=True, choices=sorted(INTEGRATORS))
    p.add_argument("--dt", type=float, nargs="+", required=True)
    p.add_argument("--windows", type=int, default=8)
    p.add_argument("--window", type=float, default=0.25, help="time units per window (block)")
    p.add_argument("--equil", type=float, default=0.2, help="time units of equilibration")
    p.add_argument("--role", default="cell", choices=["cell", "ref"])
    p.add_argument("--seed", type=int, default=9823)
    p.add_argument("--out", default="scan.jsonl", help="file under results/ the records are appended to")
    p.add_argument("--pair", choices=["gen", "stock"], default=None,
                   help="velocity-Verlet only: gen runs dpd/gen in place of the stock pair style")
    p = sub.add_parser("confirm")
    p.add_argument("--fluid", required=True, choices=["GW", "HG", "S2", "P", "HS"])
    p.add_argument("--mass", type=float, required=True)
    p.add_argument("--ref-dt", type=float, default=None, help="the reference's step (stock)")
    p.add_argument("--no-ref", action="store_true",
                   help="run the cells only: the reference is derived from another mass's (derive-ref --seeds)")
    p.add_argument("--ref-pair", choices=["gen", "stock"], default=None,
                   help="gen: the reference with dpd/gen (same forces, cheaper) in place of the stock style")
    p.add_argument("--cell", nargs="+", required=True, help="INTEGRATOR:DT")
    p.add_argument("--seeds", type=int, nargs="+", default=[11, 12, 13, 14])
    p.add_argument("--windows", type=int, default=16)
    p = sub.add_parser("time")
    p.add_argument("--fluid", required=True, choices=["GW", "HG", "S2", "P", "HS"])
    p.add_argument("--mass", type=float, required=True)
    p.add_argument("--cell", nargs="+", required=True, help="INTEGRATOR:DT")
    p.add_argument("--repeats", type=int, default=3)
    p.add_argument("--steps", type=int, default=400)
    p.add_argument("--equil-steps", type=int, default=50)
    p.add_argument("--ranks", type=int, default=1)
    p.add_argument("--skin", type=float, default=0.3)
    p.add_argument("--newton", default="on", choices=["on", "off"],
                   help="off: one newton-off neighbor list for pair style and fix (tables use on)")
    p.add_argument("--sitting", default=clock.strftime("%H%M"))
    p = sub.add_parser("time-matrix")
    p.add_argument("--fluid", nargs="*", choices=["GW", "HG", "S2", "P", "HS"])
    p.add_argument("--mass", type=float, nargs="*")
    p.add_argument("--repeats", type=int, default=3)
    p.add_argument("--steps", type=int, default=400)
    p.add_argument("--equil-steps", type=int, default=50)
    p.add_argument("--ranks", type=int, default=1)
    p.add_argument("--sitting", default=clock.strftime("%H%M"))
    p = sub.add_parser("derive-ref")
    p.add_argument("--fluid", required=True, choices=["GW", "HG", "S2", "P", "HS"])
    p.add_argument("--mass", type=float, required=True)
    p.add_argument("--static-from", type=float, required=True,
                   help="the mass whose reference gives kBT, P and g(r)")
    p.add_argument("--d-from", type=float, nargs="+", required=True,
                   help="the masses whose references' D are fitted by D0 - c m")
    p.add_argument("--seeds-from", type=float, default=None,
                   help="also the seed check's references (confirm.jsonl), from that mass's seeds")
    p.add_argument("--seeds-only", action="store_true",
                   help="write the seed check's references only, not the scan's")
    p = sub.add_parser("viscosity")
    p.add_argument("--fluid", required=True, choices=["GW", "HG", "S2", "P", "HS"])
    p.add_argument("--mass", type=float, required=True)
    p.add_argument("--integrator", required=True, choices=sorted(INTEGRATORS))
    p.add_argument("--dt", type=float, required=True)
    p.add_argument("--time", type=float, default=20.0)
    p.add_argument("--equil", type=float, default=1.0)
    p.add_argument("--force", type=float, default=None,
                   help="body force per atom (default: about 1.2-2 peak flow speed: GW 0.02, P 0.3, HS 3)")
    p.add_argument("--blocks", type=int, default=5)
    p.add_argument("--seed", type=int, default=0)
    return parser.parse_args(argv)


def main(argv=None):
    args = parse_args(argv)
    {"equilibrate": cmd_equilibrate, "scan": cmd_scan, "confirm": cmd_confirm, "time": cmd_time,
     "time-matrix": cmd_time_matrix, "derive-ref": cmd_derive_ref,
     "viscosity": cmd_viscosity}[args.command](args)


if __name__ == "__main__":
    main()
