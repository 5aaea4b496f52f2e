"""The accuracy matrix (bench/accuracy/README.md): each cell (fluid, mass, integrator, dt) against
stock velocity-Verlet at a small step, observable by observable, the largest step within
tolerance, and the speed-up at equal accuracy.

Records are the JSON lines of bench/accuracy/run.py: scan.jsonl (equilibrium observables per
window) and timing.jsonl (loop times of alternated runs); and of viscosity_shear.sh:
viscosity_shear.jsonl (the viscosity under shear per seed), which caps a largest step where the
viscosity there is outside its tolerance.
"""
import json
import re
from dataclasses import dataclass, field

import numpy as np

from .statistics import standard_error

# the tolerances: relative for kBT, P, D and eta, absolute for g(r)
TOLERANCE = {"kBT": 0.01, "kBT_friction": 0.01, "P": 0.01, "g(r)": 0.01, "D": 0.02, "eta": 0.02}

# The viscosity under shear of each fluid and mass: the set of viscosity_shear.jsonl that
# measures it (bench/accuracy/README.md, "Viscosity") and the set whose reference it is compared
# with (HS at m = 0.01 and 0.001 have none of their own)
VISCOSITY_SETS = {
    ("GW", 0.01): ("", ""), ("GW", 0.001): ("m0.001.rate5.", "m0.001.rate5."),
    ("GW", 0.1): ("m0.1.", "m0.1."), ("GW", 1.0): ("m1.rate0.5.tprod20.", "m1.rate0.5.tprod20."),
    ("P", 1.0): ("P.m1.rate0.5.tprod20.", "P.m1.rate0.5.tprod20."), ("P", 0.1): ("P.m0.1.", "P.m0.1."),
    ("P", 0.01): ("P.m0.01.", "P.m0.01."), ("P", 0.001): ("P.m0.001.rate5.", "P.m0.001.rate5."),
    ("HS", 1.0): ("HS.m1.rate0.2.", "HS.m1.rate0.2."), ("HS", 0.1): ("HS.m0.1.rate0.2.", "HS.m0.1.rate0.2."),
    ("HS", 0.01): ("HS.m0.01.rate0.2.", "HS.m0.1.rate0.2."),
    ("HS", 0.001): ("HS.m0.001.rate0.2.", "HS.m0.1.rate0.2."),
}
OBSERVABLES = ["kBT", "kBT_friction", "P", "g(r)", "D"]


def read_jsonl(path):
    with open(path) as lines:
        return [json.loads(line) for line in lines if line.strip()]


@dataclass
class Deviation:
    """One observable of one cell against the reference: value (relative, or absolute for g(r))
    and its standard error from the windows of both runs. resolved: the part of the deviation
    that the test compares with the tolerance (the value itself, except for g(r))."""
    value: float
    error: float
    resolved: float = None

    def within(self, tolerance):
        return abs(self.value if self.resolved is None else self.resolved) <= tolerance

    def beyond(self, tolerance):
        """Outside the tolerance by more than two standard errors."""
        return abs(self.value if self.resolved is None else self.resolved) - 2.0 * self.error > tolerance


@dataclass
class Cell:
    fluid: str
    mass: float
    integrator: str
    dt: float
    deviations: dict = field(default_factory=dict)
    cg_iterations: float = None
    stopped: bool = False    # the run stopped with a LAMMPS ERROR (a step too large for the skin)

    def passes(self, observables):
        return not self.stopped and all(self.deviations[name].within(TOLERANCE[name])
                                        for name in observables if name in self.deviations)

    def clearly_fails(self, observables):
        return self.stopped or any(self.deviations[name].beyond(TOLERANCE[name])
                                   for name in observables if name in self.deviations)


def mean_and_error(samples):
    """Mean of independent samples (windows, seeds) and its standard error (nan below two)."""
    samples = np.asarray(samples, dtype=float)
    return samples.mean(), standard_error(samples)


def relative_deviation(cell_samples, ref_samples):
    """The cell's mean relative to the reference's, minus one, with the error of that ratio."""
    mean, error = mean_and_error(cell_samples)
    ref, ref_error = mean_and_error(ref_samples)
    return Deviation(mean / ref - 1.0, np.hypot(error / ref, mean * ref_error / ref**2))


# g(r) is compared after a running mean over this many bins (0.1 in r for the 0.02 bins of
# in.accuracy): a step's bias in g(r) is smooth on that scale, while the counting noise of single
# bins (about 0.004 per bin and run here) would by itself make the largest difference over 50 bins
# about 0.01, the tolerance.
RDF_SMOOTHING_BINS = 5


def _smoothed(g):
    kernel = np.ones(RDF_SMOOTHING_BINS) / RDF_SMOOTHING_BINS
    return np.array([np.convolve(row, kernel, mode="valid") for row in np.atleast_2d(g)])


def _rdf_deviation(cell, ref):
    """Largest |g - g_ref| over r after the running mean, with the combined standard error of the
    two smoothed curves at that r. The test takes, over r, the largest |g - g_ref| less two of
    its standard errors: the largest deviation the runs resolve (with 46 smoothed points the
    largest noise excursion is itself about two standard errors)."""
    g = _smoothed(np.asarray(cell["rdf_blocks"], dtype=float))
    g_ref = _smoothed(np.asarray(ref["rdf_blocks"], dtype=float))
    diff = np.abs(g.mean(axis=0) - g_ref.mean(axis=0))
    errors = np.hypot(standard_error(g, axis=0), standard_error(g_ref, axis=0))
    worst = int(np.argmax(diff))
    resolved = float(np.max(np.maximum(diff - 2.0 * errors, 0.0)))
    return Deviation(float(diff[worst]), float(errors[worst]), resolved)


def compare(cell, ref):
    """The deviations of one scan record from the reference record of its fluid and mass.
    kBT_friction: the implicit scheme's friction-step temperature (fix output 5), else the
    end-of-step kBT (the other integrators have one temperature)."""
    out = Cell(cell["fluid"], cell["mass"], cell["integrator"], cell["dt"],
               cg_iterations=cell.get("cg_iterations"))
    out.deviations["kBT"] = relative_deviation(cell["T_blocks"], ref["T_blocks"])
    out.deviations["kBT_friction"] = relative_deviation(cell.get("T5_blocks", cell["T_blocks"]), ref["T_blocks"])
    out.deviations["P"] = relative_deviation(cell["P_blocks"], ref["P_blocks"])
    out.deviations["g(r)"] = _rdf_deviation(cell, ref)
    out.deviations["D"] = relative_deviation(cell["D_blocks"], ref["D_blocks"])
    return out


def references(records):
    """The reference record of each (fluid, mass): the last 'ref' run."""
    refs = {}
    for record in records:
        if record.get("role") == "ref" and record.get("exit") == 0 and "error" not in record:
            refs[(record["fluid"], record["mass"])] = record
    return refs


def derived_reference(records, fluid, mass, static_from, diffusion_from):
    """A reference where velocity-Verlet at a converged step is out of reach (HS at m = 0.001).
    At equilibrium the configurations are Boltzmann-distributed whatever the mass, so kBT, P and
    g(r) are those of the reference at mass `static_from` (its window blocks, copied). D is not:
    it is fitted as D(m) = D0 - c m by least squares to the references' means at the masses
    `diffusion_from` (at least two) and evaluated at `mass`; the blocks of D are those of
    `static_from` scaled to that value, so that their scatter stays a measured one. Returns the
    record (role 'ref', pair 'derived', with the fit's values), ready to append to scan.jsonl."""
    refs = references(records)
    missing = [m for m in [static_from, *diffusion_from] if (fluid, m) not in refs]
    if missing:
        raise ValueError(f"no reference of {fluid} at m = {missing}")
    if len(set(diffusion_from)) < 2:
        raise ValueError("the fit of D(m) needs references at two masses at least")
    masses = np.array(sorted(set(diffusion_from)), dtype=float)
    means = np.array([np.mean(refs[(fluid, m)]["D_blocks"]) for m in masses])
    slope, intercept = np.polyfit(masses, means, 1)
    fit = intercept + slope * masses
    d_at_mass = intercept + slope * mass
    source = refs[(fluid, static_from)]
    fit_info = {"D_masses": masses.tolist(), "D_means": means.tolist(),
                "D_fit_residuals": (means - fit).tolist(), "D_at_mass": d_at_mass}
    return _derived_record(source, mass, d_at_mass / np.mean(source["D_blocks"]), fit_info, dt=None)


def _derived_record(source, mass, d_scale, fit_info, dt):
    record = {key: source[key] for key in ("fluid", "equil", "windows", "nwin", "window_time", "stride",
                                           "msdstride", "T_blocks", "P_blocks", "rdf_r", "rdf_blocks")}
    record.update({"mass": mass, "integrator": "stock", "fix": "derived", "pair": "derived",
                   "dt": dt, "role": "ref", "seed": source["seed"], "exit": 0,
                   "derived_from": dict(fit_info, static=[source["mass"], source["dt"]]),
                   "D_blocks": (np.asarray(source["D_blocks"]) * d_scale).tolist(),
                   "Dslope_blocks": (np.asarray(source.get("Dslope_blocks", source["D_blocks"])) * d_scale).tolist()})
    return record


def derived_seed_references(confirm_records, derived, static_from):
    """The seed check's references for a mass out of reach: each seed's reference run at mass
    `static_from` (results/confirm.jsonl) as derived_reference() makes the scan's, its D scaled
    by the one factor that takes the seeds' mean to the fitted D of `derived` (that record).
    Their step is the source's (the seed check takes each fluid and mass's smallest reference
    step)."""
    fluid, mass = derived["fluid"], derived["mass"]
    usable = [r for r in confirm_records if r.get("exit") == 0 and "error" not in r and r.get("role") == "ref"
              and r["fluid"] == fluid and r["mass"] == static_from]
    if not usable:
        raise ValueError(f"no seed-check reference of {fluid} at m = {static_from}")
    smallest = min(r["dt"] for r in usable)
    sources = [r for r in usable if r["dt"] == smallest]
    d_at_mass = derived["derived_from"]["D_at_mass"]
    scale = d_at_mass / np.mean([np.mean(r["D_blocks"]) for r in sources])
    return [_derived_record(r, mass, scale, derived["derived_from"], dt=r["dt"]) for r in sources]


def cells(records):
    """Every completed scan cell compared with its reference (the last record of each
    (fluid, mass, integrator, dt) counts). An earlier reference run at a larger step than the
    one in use is a cell like the others."""
    refs = references(records)
    latest = {}
    for record in records:
        if record.get("exit") != 0 and record.get("role") == "cell":
            # a run that LAMMPS stopped fails its step (and ends the scan there)
            latest[(record["fluid"], record["mass"], record["integrator"], record["dt"])] = record
            continue
        if record.get("exit") != 0 or "error" in record:
            continue
        if record.get("role") != "cell" and (record.get("role") != "ref"
                                             or record is refs.get((record["fluid"], record["mass"]))
                                             or record.get("pair") == "derived"):    # no run of its own
            continue
        latest[(record["fluid"], record["mass"], record["integrator"], record["dt"])] = record
    out = []
    for key, record in sorted(latest.items()):
        ref = refs.get(key[:2])
        if ref is None:
            continue
        if record.get("exit") != 0:
            out.append(Cell(*key, stopped=True))
        else:
            out.append(compare(record, ref))
    return out


def viscosity_deviations(records):
    """{(fluid, mass, integrator): {dt: Deviation of eta from the set's reference}} from the
    records of viscosity_shear.jsonl (cells imp*, impv*, stock*, diag* of VISCOSITY_SETS)."""
    runs = {}
    for r in records:
        runs.setdefault(r["set"], {}).setdefault(r["cell"], []).append(r)
    out = {}
    for (fluid, mass), (name, reference) in VISCOSITY_SETS.items():
        ref = runs.get(reference, {}).get("ref")
        if not ref:
            continue
        for cell, seeds in runs.get(name, {}).items():
            kind = re.match(r"(impv|imp|stock|diag)(?![a-z])", cell)
            if not kind or seeds[0].get("dt") is None:
                continue
            out.setdefault((fluid, mass, kind.group(1)), {})[seeds[0]["dt"]] = relative_deviation(
                [r["eta"] for r in seeds], [r["eta"] for r in ref])
    return out


def _viscosity_step(dt, measured):
    """dt, or where the viscosity under shear measured at dt is outside its tolerance (or, dt
    not measured, at a smaller step), the largest measured step up to it within tolerance, by
    largest_step()'s rule (a step only just outside is taken for noise, one outside by more than
    two standard errors ends the search); None if none. With whether the viscosity moved it."""
    if dt is None or not measured:
        return dt, False
    steps = sorted(d for d in measured if d <= dt)
    tolerance = TOLERANCE["eta"]
    if all(measured[d].within(tolerance) for d in steps):
        return dt, False
    best = None
    for d in steps:
        if measured[d].within(tolerance):
            best = d
        elif measured[d].beyond(tolerance):
            break
    return best, best != dt


def largest_step(scan, observables):
    """The largest dt of a scan (cells of one fluid, mass, integrator) that keeps the observables
    within tolerance, with no smaller dt of the scan outside it by more than two standard errors
    (a smaller step only just outside is taken for noise, one clearly outside ends the scan);
    None if no step qualifies."""
    best = None
    for cell in sorted(scan, key=lambda c: c.dt):
        if cell.passes(observables):
            best = cell.dt
        elif cell.clearly_fails(observables):
            break
    return best


def limiting(scan, observables, dt):
    """The observables that fail at the first scanned step beyond dt (what limits the cell)."""
    beyond = [c for c in sorted(scan, key=lambda c: c.dt) if dt is None or c.dt > dt]
    if not beyond:
        return []
    cell = beyond[0]
    if cell.stopped:
        return ["stopped (ERROR)"]
    return [name for name in observables
            if name in cell.deviations and not cell.deviations[name].within(TOLERANCE[name])]


def _sitting(record):
    """When a timing was taken: its day and the sitting's start (run.py --sitting)."""
    return (record.get("date", "")[:10], str(record.get("sitting", "")))


def _latest_sitting(timings, ranks, wanted, any_skin=False):
    """The timings the tables use: successful rounds on that many ranks at the default settings
    (skin 0.3, or any skin with any_skin; newton on) that have the field `wanted`, from the
    latest sitting that timed each fluid and mass (cells are compared only with timings of the
    same sitting: a later sitting may be on another machine)."""
    usable = [r for r in timings
              if r.get("exit") == 0 and r.get(wanted) and r.get("ranks", 1) == ranks
              and (any_skin or r.get("skin", 0.3) == 0.3) and r.get("newton", "on") == "on"]
    latest = {}
    for record in usable:
        key = (record["fluid"], record["mass"])
        latest[key] = max(latest.get(key, _sitting(record)), _sitting(record))
    return [r for r in usable if _sitting(r) == latest[(r["fluid"], r["mass"])]]


def cost_per_time_unit(timings, ranks=1):
    """Seconds per time unit of each (fluid, mass, integrator, dt) on that many ranks: the fastest
    of the alternated rounds (other load only slows a run down), from the latest sitting of each
    fluid and mass."""
    best = {}
    for record in _latest_sitting(timings, ranks, "s_per_tu"):
        key = (record["fluid"], record["mass"], record["integrator"], record["dt"])
        best[key] = min(best.get(key, np.inf), record["s_per_tu"])
    return best


def breakdown_table(timings, ranks=1):
    """Per-step cost of each timed cell against a stock step of the same fluid and mass (the
    fastest round of each), split as LAMMPS's timing breakdown: milliseconds per step in pair
    forces, neighbor lists, communication, fixes (the integrator; for the implicit scheme its
    whole friction step) and the rest; the latest sitting of each fluid and mass."""
    fastest = {}
    for r in _latest_sitting(timings, ranks, "steps"):
        if "breakdown" not in r:
            continue
        key = (r["fluid"], r["mass"], r["integrator"], r["dt"])
        if key not in fastest or r["loop"] < fastest[key]["loop"]:
            fastest[key] = r
    lines = ["| fluid | m | integrator | dt | ms per step | pair | neigh | comm | modify (integrator) | other | step / stock step |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    stock_step = {}
    for (fluid, mass, name, dt), r in fastest.items():
        if name == "stock":
            per_step = r["loop"] / r["steps"]
            stock_step[(fluid, mass)] = min(stock_step.get((fluid, mass), np.inf), per_step)
    order = list(INTEGRATOR_NAMES)
    for (fluid, mass, name, dt), r in sorted(fastest.items(), key=lambda kv: (kv[0][0], -kv[0][1], order.index(kv[0][2]), kv[0][3])):
        b = r["breakdown"]
        ms = {k: 1000.0 * b.get(k, 0.0) / r["steps"] for k in ("Pair", "Neigh", "Comm", "Modify", "Other")}
        total = 1000.0 * r["loop"] / r["steps"]
        ref = stock_step.get((fluid, mass))
        ratio = "-" if ref is None else f"{total / (1000.0 * ref):.2f}"
        lines.append(f"| {fluid} | {mass:g} | {name} | {dt:g} | {total:.3f} | {ms['Pair']:.3f} | {ms['Neigh']:.3f} | "
                     f"{ms['Comm']:.3f} | {ms['Modify']:.3f} | {ms['Other']:.3f} | {ratio} |")
    return "\n".join(lines)


def group(cell_list):
    """{(fluid, mass): {integrator: [cells]}}"""
    out = {}
    for cell in cell_list:
        out.setdefault((cell.fluid, cell.mass), {}).setdefault(cell.integrator, []).append(cell)
    return out


# The matrix's fluids (bench/accuracy/in.accuracy): number density, gamma, s, cutoff; HS is what
# dpd/design gives for eta 30, Sc 500, n 4, rc 1.5 at m = 1, kBT = 1.
FLUIDS = {
    "GW": {"n": 3.0, "gamma": 4.5, "s": 2.0, "rc": 1.0},
    "HG": {"n": 3.0, "gamma": 45.0, "s": 2.0, "rc": 1.0},
    "S2": {"n": 5.292, "gamma": 35.368, "s": 2.0, "rc": 1.5},
    "P": {"n": 4.0, "gamma": 4.5, "s": 0.5, "rc": 1.0},
    "HS": {"n": 4.0, "gamma": 6.97099466424446, "s": 0.424428900898052, "rc": 1.5},
}


def friction_coefficient(fluid):
    """An atom's mean friction coefficient per direction, Gamma = gamma n [w_D] / 3 (the pair
    friction gamma w_D(r) e e summed over its partners; e_x^2 averages to 1/3)."""
    from .kinetic_theory import dissipative_weight_integral
    p = FLUIDS[fluid]
    return p["gamma"] * p["n"] * dissipative_weight_integral(p["s"], p["rc"]) / 3.0


def stiffness(fluid, mass, dt):
    """The guide's two axes: the friction stiffness Gamma dt / m, and the travel per step
    sqrt(kBT/m) dt / rc (thermal speed per component, kBT = 1, in cutoffs)."""
    return friction_coefficient(fluid) * dt / mass, np.sqrt(1.0 / mass) * dt / FLUIDS[fluid]["rc"]


INTEGRATOR_NAMES = {
    "stock": "stock + nve",
    "diag": "etd (diagonal)",
    "imp": "etd implicit",
    "impv": "etd implicit tol 1e-4 start velocity",
    "shardlow": "shardlow + nve (dpd/fdt)",
}
FLUID_NAMES = {"GW": "Groot-Warren, s = 2", "HG": "Groot-Warren with gamma = 45",
               "S2": "eta = 30, Sc = 500 with s = 2", "P": "papers', s = 1/2", "HS": "high Sc (dpd/design)"}


def _format_dt(dt):
    return "-" if dt is None else f"{dt:g}"


def _checked_step(scan, observables, dt, checked):
    """dt, or where the seed check (seed_check's cells of this fluid, mass and integrator) finds
    the mean over seeds outside tolerance there, the next smaller scanned step that passed its
    scan and is not failed by a seed check; then the largest of the larger steps that the seeds
    pass in a row; with whether the step taken was seed-checked."""
    verdict = {c.dt: c.passes(observables) for c in checked}
    step = dt
    if dt is not None and not verdict.get(dt, True):
        step = next((cell.dt for cell in sorted(scan, key=lambda c: -c.dt)
                     if cell.dt < dt and cell.passes(observables) and verdict.get(cell.dt, True)), None)
    # larger steps that the seeds pass, every seed-checked step up to them passing too: the scan
    # rejected them within its own noise (its windows' errors; HS's g(r))
    for larger in sorted(d for d in verdict if d > (step or 0.0)):
        if not verdict[larger]:
            break
        step = larger
    return step, step in verdict


def summary_rows(cell_list, costs=None, temperature="kBT", checked=None, viscosity=None):
    """One row per (fluid, mass, integrator): the largest step within tolerance on every
    observable, the temperature taken as `temperature` ('kBT' end of step, or 'kBT_friction'),
    what limits it, its cost per time unit where timed, and the speed-up over stock + nve.
    checked: seed_check's cells; a largest step that they find outside tolerance gives way to
    the next smaller one, and larger steps they pass are taken (row['seed_checked'] says whether
    the step taken was re-run). viscosity: viscosity_deviations(); a step whose viscosity under
    shear is outside tolerance gives way to the largest smaller step measured within it
    (limited by "eta (shear)")."""
    observables = [temperature, "P", "g(r)", "D"]
    rows = []
    for (fluid, mass), scans in sorted(group(cell_list).items()):
        best = {name: largest_step(scan, observables) for name, scan in scans.items()}
        seed_checked, seed_limited = {}, {}
        if checked is not None:
            for name, scan in scans.items():
                mine = [c for c in checked if (c.fluid, c.mass, c.integrator) == (fluid, mass, name)]
                dt, seed_checked[name] = _checked_step(scan, observables, best[name], mine)
                if best[name] is not None and (dt is None or dt < best[name]):
                    # the seeds moved it down: what fails at the step they rejected
                    rejected = next(c for c in mine if c.dt == best[name])
                    seed_limited[name] = [n + " (seeds)" for n in observables
                                          if not rejected.deviations[n].within(TOLERANCE[n])]
                best[name] = dt
        if viscosity is not None:
            for name in scans:
                dt, capped = _viscosity_step(best[name], viscosity.get((fluid, mass, name)))
                if capped:
                    best[name] = dt
                    seed_limited[name] = ["eta (shear)"]
                    # the seeds at the capped step, where they were run: a step they reject
                    # says so in "limited by"
                    seeds = next((c for c in checked or [] if (c.fluid, c.mass, c.integrator, c.dt)
                                  == (fluid, mass, name, dt)), None)
                    seed_checked[name] = seeds is not None and seeds.passes(observables)
                    if seeds is not None and not seeds.passes(observables):
                        seed_limited[name] += [n + " fails (seeds)" for n in observables
                                               if not seeds.deviations[n].within(TOLERANCE[n])]
        cost = {}
        for name, dt in best.items():
            if costs is not None and dt is not None:
                cost[name] = costs.get((fluid, mass, name, dt))
        for name in INTEGRATOR_NAMES:
            if name not in scans:
                continue
            dt = best[name]
            speedup = speedup_shardlow = None
            if cost.get(name) and cost.get("stock"):
                speedup = cost["stock"] / cost[name]
            if cost.get(name) and cost.get("shardlow"):
                speedup_shardlow = cost["shardlow"] / cost[name]
            rows.append({"fluid": fluid, "mass": mass, "integrator": name, "dt": dt,
                         "stock_dt": best.get("stock"),
                         "step_ratio": (dt / best["stock"]) if dt and best.get("stock") else None,
                         "limited_by": seed_limited.get(name) or limiting(scans[name], observables, dt),
                         "s_per_tu": cost.get(name), "speedup": speedup,
                         "speedup_shardlow": speedup_shardlow,
                         "seed_checked": seed_checked.get(name, False)})
    return rows


def summary_table(rows):
    lines = ["| fluid | m | integrator | largest dt | dt / stock's | limited by (next dt) | s per time unit "
             "| speed-up over stock | over shardlow |",
             "|---|---|---|---|---|---|---|---|---|"]
    # a step the seed check re-ran and kept is marked with an asterisk
    for r in rows:
        ratio = "-" if r["step_ratio"] is None else f"{r['step_ratio']:.1f}"
        cost = "-" if r["s_per_tu"] is None else f"{r['s_per_tu']:.2f}"
        speed = "-" if r["speedup"] is None else f"{r['speedup']:.2f}"
        peer = "-" if r.get("speedup_shardlow") is None else f"{r['speedup_shardlow']:.2f}"
        limited = ", ".join(r["limited_by"]) or "(none scanned beyond)"
        lines.append(f"| {r['fluid']} | {r['mass']:g} | {INTEGRATOR_NAMES[r['integrator']]} | "
                     f"{_format_dt(r['dt'])}{'*' if r.get('seed_checked') else ''} | {ratio} | {limited} | {cost} | {speed} | {peer} |")
    return "\n".join(lines)


def cell_table(cell_list):
    """Every cell's deviations: relative for kBT, P, D (in %), absolute for g(r)."""
    lines = ["| fluid | m | integrator | dt | kBT % | kBT friction step % | P % | max dg(r) | D % | CG it. |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for c in sorted(cell_list, key=lambda c: (c.fluid, -c.mass, list(INTEGRATOR_NAMES).index(c.integrator), c.dt)):
        if c.stopped:
            lines.append(f"| {c.fluid} | {c.mass:g} | {c.integrator} | {c.dt:g} | stopped: LAMMPS ERROR (the step "
                         "outruns the skin) | | | | | |")
            continue
        d = c.deviations

        def pct(name):
            mark = "" if d[name].within(TOLERANCE[name]) else " **x**"
            return f"{100 * d[name].value:+.2f} +- {100 * d[name].error:.2f}{mark}"
        g = d["g(r)"]
        gmark = "" if g.within(TOLERANCE["g(r)"]) else " **x**"
        friction = pct("kBT_friction") if c.integrator in ("imp", "impv") else "(same)"
        it = "-" if c.cg_iterations is None else f"{c.cg_iterations:.1f}"
        lines.append(f"| {c.fluid} | {c.mass:g} | {c.integrator} | {c.dt:g} | {pct('kBT')} | {friction} | "
                     f"{pct('P')} | {g.value:.4f} +- {g.error:.4f}{gmark} | {pct('D')} | {it} |")
    return "\n".join(lines)


def plot(cell_list, directory):
    """One figure per (fluid, mass): each observable's deviation against dt, per integrator, with
    the tolerance band. Returns the files written."""
    import os
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    written = []
    for (fluid, mass), scans in sorted(group(cell_list).items()):
        fig, axes = plt.subplots(1, len(OBSERVABLES), figsize=(4 * len(OBSERVABLES), 3.4))
        for ax, name in zip(axes, OBSERVABLES):
            scale = 1.0 if name == "g(r)" else 100.0
            for integrator, scan in sorted(scans.items()):
                if name == "kBT_friction" and integrator not in ("imp", "impv"):
                    continue
                scan = sorted((c for c in scan if not c.stopped), key=lambda c: c.dt)
                ax.errorbar([c.dt for c in scan], [scale * c.deviations[name].value for c in scan],
                            yerr=[scale * c.deviations[name].error for c in scan], marker="o", ms=3,
                            capsize=2, label=INTEGRATOR_NAMES[integrator])
            tol = scale * TOLERANCE[name]
            ax.axhspan(-tol if name != "g(r)" else 0, tol, color="0.9", zorder=0)
            ax.set_xscale("log")
            ax.set_xlabel("dt")
            ax.set_title({"kBT": "kBT, LAMMPS's temp (%)", "kBT_friction": "kBT friction step (%)",
                          "P": "pressure (%)", "g(r)": "max |g - g_ref|", "D": "D (%)"}[name])
        axes[0].legend(fontsize=7)
        fig.suptitle(f"{FLUID_NAMES.get(fluid, fluid)}, m = {mass:g}: deviation from stock velocity-Verlet at a small step")
        fig.tight_layout()
        path = os.path.join(directory, f"accuracy_{fluid}_m{mass:g}.png")
        fig.savefig(path, dpi=90)
        plt.close(fig)
        written.append(path)
    return written


def plot_map(cell_list, path, temperature="kBT"):
    """The guide: every cell on the plane (friction stiffness, travel per step), filled where
    every observable is within tolerance, open where not, one panel per integrator."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    observables = [temperature, "P", "g(r)", "D"]
    names = [n for n in INTEGRATOR_NAMES if any(c.integrator == n for c in cell_list)]
    fig, axes = plt.subplots(1, len(names), figsize=(4.2 * len(names), 3.8), sharex=True, sharey=True)
    markers = {"GW": "o", "HG": "D", "S2": "v", "P": "s", "HS": "^"}
    colours = {1.0: "C0", 0.1: "C1", 0.01: "C2", 0.001: "C3"}
    for ax, name in zip(np.atleast_1d(axes), names):
        for c in cell_list:
            if c.integrator != name:
                continue
            z, travel = stiffness(c.fluid, c.mass, c.dt)
            ok = c.passes(observables)
            ax.plot(z, travel, markers.get(c.fluid, "o"), color=colours.get(c.mass, "k"),
                    mfc=colours.get(c.mass, "k") if ok else "none", ms=6)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_title(INTEGRATOR_NAMES[name], fontsize=9)
        ax.set_xlabel("friction stiffness Gamma dt / m")
    np.atleast_1d(axes)[0].set_ylabel("travel per step sqrt(kBT/m) dt / rc")
    handles = [plt.Line2D([], [], marker=m, ls="", color="k", label=f) for f, m in markers.items()]
    handles += [plt.Line2D([], [], marker="o", ls="", color=c, label=f"m = {m:g}") for m, c in colours.items()]
    np.atleast_1d(axes)[0].legend(handles=handles, fontsize=7, loc="upper left")
    fig.suptitle("filled: every observable within tolerance (kBT: LAMMPS's temp); open: not")
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)
    return path


def _seed_means(records, key):
    return np.array([np.mean(r.get(key, r["T_blocks"])) for r in records])


def seed_check(records):
    """The largest steps of the matrix re-run with several seeds (results/confirm.jsonl): for
    each (fluid, mass, integrator, dt), the deviation of the mean over seeds from the mean of the
    reference's seeds, with the standard error from both scatters; g(r) too, from each seed's mean
    curve. Returns Cells with n_seeds set. A seed run again (confirm.sh re-run, or derive-ref's
    seed references written again) counts once, by its last record, as in cells()."""
    usable = [r for r in records if r.get("exit") == 0 and "error" not in r]
    latest = {}
    for index, record in enumerate(usable):
        seed = record.get("seed")
        key = (index,) if seed is None else (record["fluid"], record["mass"], record.get("role"),
                                             record["integrator"], record["dt"], seed)
        latest.pop(key, None)    # (re-inserted: the order of the records is kept)
        latest[key] = record
    usable = list(latest.values())
    # the reference of a fluid and mass is its smallest-step stock run; reference runs at a
    # larger step (an earlier, less accurate reference) are stock cells against it
    ref_dt = {}
    for record in usable:
        if record.get("role") == "ref":
            key = (record["fluid"], record["mass"])
            ref_dt[key] = min(ref_dt.get(key, np.inf), record["dt"])
    refs, groups = {}, {}
    for record in usable:
        if record.get("role") == "ref" and record["dt"] == ref_dt[(record["fluid"], record["mass"])]:
            refs.setdefault((record["fluid"], record["mass"]), []).append(record)
        else:
            groups.setdefault((record["fluid"], record["mass"], record["integrator"], record["dt"]), []).append(record)
    out = []
    for (fluid, mass, integrator, dt), group_records in sorted(groups.items()):
        ref_records = refs.get((fluid, mass))
        if not ref_records or len(ref_records) < 2 or len(group_records) < 2:
            continue
        cell = Cell(fluid, mass, integrator, dt)
        cell.n_seeds = len(group_records)
        cell.n_ref_seeds = len(ref_records)
        for name, key in (("kBT", "T_blocks"), ("kBT_friction", "T5_blocks"), ("P", "P_blocks"),
                          ("D", "D_blocks")):
            # each seed's mean is one sample: the windows of one run are not independent enough
            cell.deviations[name] = relative_deviation(_seed_means(group_records, key),
                                              _seed_means(ref_records, "T_blocks" if key == "T5_blocks" else key))
        # g(r) likewise: each seed's mean curve is one sample (the windows' scatter underestimates
        # the error where a bin holds few pairs: HS below r = 0.15)
        per_seed = {"rdf_blocks": [np.mean(r["rdf_blocks"], axis=0) for r in group_records]}
        per_seed_ref = {"rdf_blocks": [np.mean(r["rdf_blocks"], axis=0) for r in ref_records]}
        cell.deviations["g(r)"] = _rdf_deviation(per_seed, per_seed_ref)
        out.append(cell)
    return out


def seed_check_table(cell_list, temperature="kBT"):
    """Markdown: one row per re-run cell, each observable's deviation +- error, and whether
    every observable (kBT read as `temperature`) is within tolerance by the mean."""
    names = [temperature, "P", "g(r)", "D"]
    lines = ["| fluid | m | integrator | dt | seeds (ref) | " + " | ".join(names) + " | within |",
             "|---|---|---|---|---|" + "---|" * len(names) + "---|"]
    for cell in cell_list:
        parts = []
        for name in names:
            d = cell.deviations[name]
            if name == "g(r)":
                parts.append(f"{d.value:.4f} +- {d.error:.4f}")
            else:
                parts.append(f"{100 * d.value:+.2f} +- {100 * d.error:.2f} %")
        within = "yes" if cell.passes(names) else "no"
        lines.append(f"| {cell.fluid} | {cell.mass:g} | {cell.integrator} | {_format_dt(cell.dt)} | "
                     f"{cell.n_seeds} ({cell.n_ref_seeds}) | " + " | ".join(parts) + f" | {within} |")
    return "\n".join(lines)


def main(argv=None):
    import argparse
    import os
    parser = argparse.ArgumentParser(description="Tables and plots of the accuracy matrix (bench/accuracy).")
    parser.add_argument("results", help="folder with scan.jsonl (and timing.jsonl)")
    parser.add_argument("--figures", help="folder for the error-against-dt plots")
    args = parser.parse_args(argv)
    cell_list = cells(read_jsonl(os.path.join(args.results, "scan.jsonl")))
    timing = os.path.join(args.results, "timing.jsonl")
    timings = read_jsonl(timing) if os.path.exists(timing) else []
    confirm = os.path.join(args.results, "confirm.jsonl")
    checked = seed_check(read_jsonl(confirm)) if os.path.exists(confirm) else None
    shear = os.path.join(args.results, "viscosity_shear.jsonl")
    viscosity = viscosity_deviations(read_jsonl(shear)) if os.path.exists(shear) else None
    if checked:
        print("## Largest steps re-run with independent seeds (results/confirm.jsonl)\n")
        print(seed_check_table(checked))
        print("\nIn the tables below a largest step that these re-runs find outside tolerance gives way to the")
        print("next smaller step of the scan; an asterisk marks a step the re-runs kept.\n")
    for ranks in sorted({r.get("ranks", 1) for r in timings} or {1}):
        costs = cost_per_time_unit(timings, ranks)
        print(f"## Largest step within tolerance on every observable (LAMMPS's temp), {ranks} rank(s)\n")
        print(summary_table(summary_rows(cell_list, costs, "kBT", checked, viscosity)))
        print(f"\n## Cost of a step against a stock step, {ranks} rank(s)\n")
        print(breakdown_table(timings, ranks))
        print()
    print("\n## Every cell\n")
    print(cell_table(cell_list))
    if args.figures:
        os.makedirs(args.figures, exist_ok=True)
        for path in plot(cell_list, args.figures) + [plot_map(cell_list, os.path.join(args.figures, "guide_map.png"))]:
            print(f"\nwrote {path}")
    return 0
