#!/usr/bin/python3
"""python/etddpd/accuracy_matrix.py on synthetic scan records with known deviations: relative and
absolute deviations and their errors, the largest step of a scan (it and every smaller step within
tolerance), what limits it, the friction-step temperature as the implicit scheme's criterion, the
speed-up from the timings, and the tables and plots written."""
import json
import os
import sys
import tempfile
import unittest

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from etddpd import accuracy_matrix as am  # noqa: E402

R = [0.1 * k for k in range(1, 11)]
G_REF = [1.0] * 10


def record(integrator, dt, T, P, D, g_shift=0.0, T5=None, role="cell"):
    # two windows each, symmetric about the mean: the standard error is |a - b| / 2
    out = {"fluid": "GW", "mass": 0.01, "integrator": integrator, "dt": dt, "role": role, "exit": 0,
           "T_blocks": [T - 0.001, T + 0.001], "P_blocks": [P - 0.01, P + 0.01],
           "D_blocks": [D - 0.002, D + 0.002], "rdf_r": R,
           "rdf_blocks": [[g + g_shift for g in G_REF], [g + g_shift for g in G_REF]]}
    if T5 is not None:
        out["T5_blocks"] = [T5, T5]
        out["cg_iterations"] = 9.5
    return out


def scan_records():
    return [
        record("stock", 0.0001, 1.0, 20.0, 1.0, role="ref"),
        record("stock", 0.0003, 1.002, 20.05, 1.005),
        record("stock", 0.0005, 1.008, 20.1, 1.01),
        record("stock", 0.0007, 1.015, 20.15, 1.012),    # kBT +1.5 %: limits stock at 0.0005
        record("imp", 0.002, 0.996, 19.9, 0.99, T5=1.0),
        record("imp", 0.003, 0.985, 19.85, 0.99, T5=1.001),    # end-of-step kBT -1.5 %
        record("imp", 0.004, 0.98, 19.81, 0.985, g_shift=0.02, T5=1.002),    # g(r) off by 0.02
    ]


class AccuracyMatrix(unittest.TestCase):
    def setUp(self):
        self.cells = am.cells(scan_records())

    def cell(self, integrator, dt):
        return next(c for c in self.cells if c.integrator == integrator and c.dt == dt)

    def test_deviations(self):
        c = self.cell("stock", 0.0007)
        self.assertAlmostEqual(c.deviations["kBT"].value, 0.015, places=12)
        self.assertAlmostEqual(c.deviations["P"].value, 0.0075, places=12)
        self.assertAlmostEqual(c.deviations["D"].value, 0.012, places=12)
        # errors: both runs' standard errors combined (0.001 each for T, relative)
        self.assertAlmostEqual(c.deviations["kBT"].error, np.hypot(0.001 / 1.0, 1.015 * 0.001), places=9)
        self.assertAlmostEqual(self.cell("imp", 0.004).deviations["g(r)"].value, 0.02, places=12)
        self.assertEqual(len(self.cells), 6)    # the reference is not a cell

    def test_largest_step_and_what_limits_it(self):
        rows = {r["integrator"]: r for r in am.summary_rows(self.cells, temperature="kBT")}
        self.assertEqual(rows["stock"]["dt"], 0.0005)
        self.assertEqual(rows["stock"]["limited_by"], ["kBT"])
        self.assertEqual(rows["imp"]["dt"], 0.002)
        self.assertEqual(rows["imp"]["limited_by"], ["kBT"])
        self.assertAlmostEqual(rows["imp"]["step_ratio"], 4.0)

    def test_viscosity_under_shear_caps_a_largest_step(self):
        # GW m = 0.01 (set ""): imp's largest step 0.002; under shear, against the reference's
        # eta 1.0 (two seeds 0.99, 1.01): +1.0 % at 0.001, +3.0 % at 0.002 (outside 2 %)
        def shear(cell, dt, etas):
            return [{"set": "", "cell": cell, "seed": k, "dt": dt, "eta": eta} for k, eta in enumerate(etas)]
        records = shear("ref", 0.0001, [0.99, 1.01]) + shear("imp0.001", 0.001, [1.005, 1.015]) \
            + shear("imp", 0.002, [1.025, 1.035]) + shear("stock", 0.0005, [1.0, 1.02]) \
            + shear("ref0.00005", 0.00005, [1.0, 1.0])    # (the reference's own convergence: no row)
        viscosity = am.viscosity_deviations(records)
        self.assertAlmostEqual(viscosity[("GW", 0.01, "imp")][0.002].value, 0.03, places=12)
        self.assertEqual(sorted(viscosity[("GW", 0.01, "imp")]), [0.001, 0.002])
        self.assertEqual(sorted(k[2] for k in viscosity), ["imp", "stock"])
        rows = {r["integrator"]: r for r in am.summary_rows(self.cells, viscosity=viscosity)}
        self.assertEqual(rows["imp"]["dt"], 0.001)
        self.assertEqual(rows["imp"]["limited_by"], ["eta (shear)"])
        self.assertEqual(rows["stock"]["dt"], 0.0005)    # +1 %: kept
        self.assertFalse(rows["imp"]["seed_checked"])
        # seeds run at the capped step: kept with them (an asterisk), or named where they fail
        ok = {n: am.Deviation(0.0, 0.001) for n in ["kBT", "P", "g(r)", "D"]}
        hot = dict(ok, kBT=am.Deviation(0.02, 0.001))
        for deviations, checked, limited in ((ok, True, ["eta (shear)"]),
                                             (hot, False, ["eta (shear)", "kBT fails (seeds)"])):
            seeds = [am.Cell("GW", 0.01, "imp", 0.001, deviations)]
            rows = {r["integrator"]: r for r in am.summary_rows(self.cells, checked=seeds, viscosity=viscosity)}
            self.assertEqual((rows["imp"]["dt"], rows["imp"]["seed_checked"], rows["imp"]["limited_by"]),
                             (0.001, checked, limited))
        # a step just outside below passing ones is noise; one clearly outside ends the search
        dev = am.Deviation
        self.assertEqual(am._viscosity_step(0.03, {0.01: dev(0.0, 0.01), 0.02: dev(0.021, 0.005),
                                                   0.03: dev(0.01, 0.005)}), (0.03, False))
        self.assertEqual(am._viscosity_step(0.03, {0.01: dev(0.0, 0.01), 0.02: dev(0.05, 0.005),
                                                   0.03: dev(0.01, 0.005)}), (0.01, True))
        # a step not measured keeps its largest step unless a smaller measured one fails
        self.assertEqual(am._viscosity_step(0.03, {0.01: dev(0.0, 0.01)}), (0.03, False))
        self.assertEqual(am._viscosity_step(0.03, {0.01: dev(0.0, 0.01), 0.02: dev(0.03, 0.01)}),
                         (0.01, True))
        self.assertEqual(am._viscosity_step(0.03, {0.01: dev(0.05, 0.001)}), (None, True))

    def test_friction_step_temperature_criterion(self):
        rows = {r["integrator"]: r for r in am.summary_rows(self.cells, temperature="kBT_friction")}
        self.assertEqual(rows["imp"]["dt"], 0.003)
        self.assertEqual(rows["imp"]["limited_by"], ["g(r)"])
        self.assertEqual(rows["stock"]["dt"], 0.0005)    # stock has one temperature

    def test_a_step_just_outside_between_passing_ones_is_noise(self):
        records = scan_records()[:1] + [
            record("stock", 0.001, 1.002, 20.0, 1.0),
            dict(record("stock", 0.002, 1.0108, 20.0, 1.0), T_blocks=[1.0058, 1.0158]),    # +1.08 +- 0.5 %
            record("stock", 0.003, 1.004, 20.0, 1.0),
            record("stock", 0.004, 1.03, 20.0, 1.0),    # clearly outside: ends the scan
            record("stock", 0.005, 1.0, 20.0, 1.0)]
        rows = am.summary_rows(am.cells(records))
        self.assertEqual(rows[0]["dt"], 0.003)

    def test_an_earlier_reference_at_a_larger_step_is_a_cell(self):
        records = [record("stock", 0.0001, 1.004, 20.1, 1.0, role="ref")] + scan_records()
        c = am.cells(records)
        self.assertIn(0.0001, [x.dt for x in c if x.integrator == "stock"])
        self.assertEqual(len(c), 7)

    def test_a_failing_smallest_step_gives_none(self):
        bad = scan_records()[:1] + [record("diag", 0.001, 1.05, 20.0, 1.0)]
        rows = am.summary_rows(am.cells(bad))
        self.assertIsNone(rows[0]["dt"])
        self.assertEqual(rows[0]["limited_by"], ["kBT"])

    def test_breakdown_per_step_against_stock(self):
        base = {"fluid": "GW", "mass": 0.01, "exit": 0, "ranks": 1, "steps": 400}
        timings = [
            dict(base, integrator="stock", dt=0.0005, loop=0.4,
                 breakdown={"Pair": 0.2, "Neigh": 0.16, "Comm": 0.02, "Modify": 0.01, "Other": 0.01}),
            dict(base, integrator="imp", dt=0.005, loop=1.2,
                 breakdown={"Pair": 0.1, "Neigh": 0.5, "Comm": 0.02, "Modify": 0.57, "Other": 0.01}),
            dict(base, integrator="imp", dt=0.005, loop=1.6, breakdown={"Pair": 1.0}),    # slower round
        ]
        table = am.breakdown_table(timings)
        self.assertIn("| GW | 0.01 | stock | 0.0005 | 1.000 | 0.500 | 0.400 | 0.050 | 0.025 | 0.025 | 1.00 |", table)
        self.assertIn("| GW | 0.01 | imp | 0.005 | 3.000 | 0.250 | 1.250 | 0.050 | 1.425 | 0.025 | 3.00 |", table)

    def test_speedup_from_fastest_round(self):
        timings = [
            {"fluid": "GW", "mass": 0.01, "integrator": "stock", "dt": 0.0005, "exit": 0, "s_per_tu": 10.0},
            {"fluid": "GW", "mass": 0.01, "integrator": "stock", "dt": 0.0005, "exit": 0, "s_per_tu": 12.0},
            {"fluid": "GW", "mass": 0.01, "integrator": "imp", "dt": 0.002, "exit": 0, "s_per_tu": 4.0},
        ]
        rows = {r["integrator"]: r for r in am.summary_rows(self.cells, am.cost_per_time_unit(timings))}
        self.assertAlmostEqual(rows["imp"]["speedup"], 2.5)
        self.assertIsNone(rows["imp"]["speedup_shardlow"])    # no peer timed
        self.assertIn("| 2.50 | - |", am.summary_table(list(rows.values())))

    def test_a_run_lammps_stopped_ends_the_scan(self):
        # the implicit scheme passes at 0.002 and 0.004 by its observables, but its run at 0.003
        # stopped with an ERROR (a step the skin does not cover): 0.002 is its largest step
        records = scan_records()[:5] + [dict(record("imp", 0.003, 1.0, 20.0, 1.0), exit=1),
                                        record("imp", 0.004, 1.0, 20.0, 1.0)]
        cells = am.cells(records)
        stopped = next(c for c in cells if c.integrator == "imp" and c.dt == 0.003)
        self.assertTrue(stopped.stopped)
        self.assertFalse(stopped.passes(["kBT", "P", "g(r)", "D"]))
        rows = {r["integrator"]: r for r in am.summary_rows(cells)}
        self.assertEqual(rows["imp"]["dt"], 0.002)
        self.assertEqual(rows["imp"]["limited_by"], ["stopped (ERROR)"])
        self.assertIn("stopped: LAMMPS ERROR", am.cell_table(cells))

    def test_speedup_over_shardlow_at_its_own_largest_step(self):
        records = scan_records() + [record("shardlow", 0.001, 1.002, 20.0, 1.01),
                                    record("shardlow", 0.0015, 1.004, 20.0, 1.03)]    # D +3 %
        timings = [
            {"fluid": "GW", "mass": 0.01, "integrator": "stock", "dt": 0.0005, "exit": 0, "s_per_tu": 10.0},
            {"fluid": "GW", "mass": 0.01, "integrator": "shardlow", "dt": 0.001, "exit": 0, "s_per_tu": 6.0},
            {"fluid": "GW", "mass": 0.01, "integrator": "shardlow", "dt": 0.0015, "exit": 0, "s_per_tu": 4.0},
            {"fluid": "GW", "mass": 0.01, "integrator": "imp", "dt": 0.002, "exit": 0, "s_per_tu": 4.0},
        ]
        rows = {r["integrator"]: r for r in am.summary_rows(am.cells(records), am.cost_per_time_unit(timings))}
        self.assertEqual(rows["shardlow"]["dt"], 0.001)
        self.assertEqual(rows["shardlow"]["limited_by"], ["D"])
        self.assertAlmostEqual(rows["imp"]["speedup_shardlow"], 1.5)
        self.assertAlmostEqual(rows["shardlow"]["speedup"], 10.0 / 6.0)
        self.assertIn("| shardlow + nve (dpd/fdt) | 0.001 |", am.summary_table(list(rows.values())))

    def test_only_the_latest_sitting_of_a_fluid_and_mass_counts(self):
        # a later sitting (another machine, say) re-times this fluid and mass: its stock and its
        # implicit cell are compared with each other, not with an earlier, faster stock round
        def timing(integrator, dt, s_per_tu, date, sitting):
            return {"fluid": "GW", "mass": 0.01, "integrator": integrator, "dt": dt, "exit": 0,
                    "s_per_tu": s_per_tu, "date": date, "sitting": sitting}
        timings = [timing("stock", 0.0005, 10.0, "2026-11-25 10:08", "1008"),
                   timing("imp", 0.003, 4.0, "2026-11-25 10:08", "1008"),
                   timing("stock", 0.0005, 15.0, "2026-11-26 05:00", "0500"),
                   timing("imp", 0.002, 5.0, "2026-11-26 05:00", "0500"),
                   dict(timing("stock", 0.0005, 1.0, "2026-11-26 05:00", "0500"), fluid="P")]
        costs = am.cost_per_time_unit(timings)
        self.assertEqual(costs[("GW", 0.01, "stock", 0.0005)], 15.0)
        self.assertEqual(costs[("GW", 0.01, "imp", 0.002)], 5.0)
        self.assertNotIn(("GW", 0.01, "imp", 0.003), costs)
        self.assertEqual(costs[("P", 0.01, "stock", 0.0005)], 1.0)

    def test_newton_off_and_other_skins_stay_out_of_the_tables(self):
        # the tables compare the default settings; a faster newton-off or other-skin round of
        # the same cell must not become its time
        timings = [
            {"fluid": "GW", "mass": 0.01, "integrator": "imp", "dt": 0.002, "exit": 0, "s_per_tu": 4.0},
            {"fluid": "GW", "mass": 0.01, "integrator": "imp", "dt": 0.002, "exit": 0, "s_per_tu": 3.0,
             "newton": "off"},
            {"fluid": "GW", "mass": 0.01, "integrator": "imp", "dt": 0.002, "exit": 0, "s_per_tu": 2.0,
             "skin": 0.5},
        ]
        self.assertEqual(am.cost_per_time_unit(timings), {("GW", 0.01, "imp", 0.002): 4.0})
        steps = [dict(t, ranks=1, steps=400, loop=t["s_per_tu"], breakdown={"Pair": 0.1}) for t in timings]
        self.assertIn("| GW | 0.01 | imp | 0.002 | 10.000 |", am.breakdown_table(steps))

    def test_rdf_deviation_counts_only_what_the_runs_resolve(self):
        ref = scan_records()[0]
        steady = record("diag", 0.001, 1.0, 20.0, 1.0, g_shift=0.015)
        noisy = dict(steady, rdf_blocks=[[g + 0.055 for g in G_REF], [g - 0.025 for g in G_REF]])
        self.assertFalse(am.compare(steady, ref).deviations["g(r)"].within(0.01))
        deviation = am.compare(noisy, ref).deviations["g(r)"]
        self.assertAlmostEqual(deviation.value, 0.015, places=12)
        self.assertAlmostEqual(deviation.error, 0.04, places=12)
        self.assertTrue(deviation.within(0.01))

    def test_guide_axes(self):
        # Groot-Warren: [w_D] = 8 pi / 60 for s = 2, rc = 1, so Gamma = 4.5 * 3 * (8 pi / 60) / 3
        gamma_gw = 4.5 * 3.0 * (8.0 * np.pi / 60.0) / 3.0
        self.assertAlmostEqual(am.friction_coefficient("GW"), gamma_gw, places=12)
        z, travel = am.stiffness("GW", 0.01, 0.005)
        self.assertAlmostEqual(z, gamma_gw * 0.5, places=12)
        self.assertAlmostEqual(travel, 0.05, places=12)
        # s = 1/2: [w_D] = 8 pi / (1.5 * 2.5 * 3.5)
        self.assertAlmostEqual(am.friction_coefficient("P"), 4.5 * 4.0 * 8.0 * np.pi / 13.125 / 3.0, places=12)

    def test_tables_and_plots(self):
        with tempfile.TemporaryDirectory() as folder:
            with open(os.path.join(folder, "scan.jsonl"), "w") as out:
                for r in scan_records():
                    out.write(json.dumps(r) + "\n")
            figures = os.path.join(folder, "figures")
            self.assertEqual(am.main([folder, "--figures", figures]), 0)
            self.assertTrue(os.path.getsize(os.path.join(figures, "accuracy_GW_m0.01.png")) > 1000)
            self.assertTrue(os.path.getsize(os.path.join(figures, "guide_map.png")) > 1000)
        table = am.cell_table(self.cells)
        self.assertIn("**x**", table)
        self.assertEqual(table.count("\n"), 1 + len(self.cells))

    def test_seed_check_uses_the_scatter_of_the_seeds(self):
        # three reference seeds with D means 0.99, 1.00, 1.01 and three seeds of one cell with D
        # means 0.96, 0.97, 0.98: the cell is 3 % low with an error from the seeds' scatter
        # (0.01 / sqrt(3) each), not from the windows (0.002 per seed)
        records = [record("stock", 0.0001, 1.0, 20.0, d, role="ref") for d in (0.99, 1.0, 1.01)]
        records += [record("imp", 0.007, 0.95, 19.9, d, T5=1.0) for d in (0.96, 0.97, 0.98)]
        records += [record("imp", 0.005, 0.97, 19.95, 0.99, T5=1.0)]    # one seed: no check
        records.append(dict(record("imp", 0.007, 0.95, 19.9, 0.5, T5=1.0), exit=1))    # failed run
        checked = am.seed_check(records)
        self.assertEqual(len(checked), 1)
        cell = checked[0]
        self.assertEqual((cell.integrator, cell.dt, cell.n_seeds, cell.n_ref_seeds), ("imp", 0.007, 3, 3))
        self.assertAlmostEqual(cell.deviations["D"].value, -0.03, places=12)
        self.assertAlmostEqual(cell.deviations["D"].error, np.hypot(0.01 / 3**0.5, 0.97 * 0.01 / 3**0.5), places=12)
        self.assertAlmostEqual(cell.deviations["kBT_friction"].value, 0.0, places=12)    # T5 against ref kBT
        self.assertAlmostEqual(cell.deviations["kBT"].value, -0.05, places=12)
        self.assertFalse(cell.passes(["kBT_friction", "P", "g(r)", "D"]))
        table = am.seed_check_table(checked)
        self.assertIn("| GW | 0.01 | imp | 0.007 | 3 (3) |", table)
        self.assertIn("-3.00 +- ", table)
        self.assertTrue(table.endswith("| no |"))

    def test_a_seed_run_again_counts_once(self):
        # seed 2 of the reference and seed 1 of the cell were run twice: the last record of each
        # counts, so the check is the same as with one record per seed
        def seeded(seed, *args, **kwargs):
            return dict(record(*args, **kwargs), seed=seed)
        refs = [seeded(s, "stock", 0.0001, 1.0, 20.0, d, role="ref") for s, d in ((1, 0.99), (2, 1.0), (3, 1.01))]
        cell = [seeded(s, "imp", 0.007, 0.95, 19.9, d, T5=1.0) for s, d in ((1, 0.96), (2, 0.97), (3, 0.98))]
        once = am.seed_check(refs + cell)[0]
        again = [seeded(1, "imp", 0.007, 0.95, 19.9, 0.5, T5=1.0)] + refs + cell + [dict(refs[1])]
        twice = am.seed_check(again)[0]
        self.assertEqual((twice.n_seeds, twice.n_ref_seeds), (3, 3))
        self.assertAlmostEqual(twice.deviations["D"].value, once.deviations["D"].value, places=12)
        self.assertAlmostEqual(twice.deviations["D"].error, once.deviations["D"].error, places=12)

    def test_seed_check_g_of_r_error_from_the_seeds(self):
        # every seed's two windows have the same g(r) (no window scatter), but the seeds' curves
        # differ by +-0.02 about their mean: the cell's 0.04 offset, less two of the seeds' errors,
        # is within 0.01, so g(r) passes; with the windows of all seeds pooled (six samples, a
        # smaller error) it would fail
        refs = [record("stock", 0.0001, 1.0, 20.0, 1.0, g_shift=s, role="ref") for s in (-0.02, 0.0, 0.02)]
        cells = [record("imp", 0.003, 1.0, 20.0, 1.0, g_shift=0.04 + s, T5=1.0) for s in (-0.02, 0.0, 0.02)]
        for r in refs + cells:
            r["rdf_blocks"] = [r["rdf_blocks"][0], r["rdf_blocks"][0]]
        checked = am.seed_check(refs + cells)
        g = checked[0].deviations["g(r)"]
        self.assertAlmostEqual(g.value, 0.04, places=12)
        self.assertAlmostEqual(g.error, np.hypot(0.02 / 3**0.5, 0.02 / 3**0.5), places=12)
        self.assertTrue(g.within(am.TOLERANCE["g(r)"]))
        pooled = am._rdf_deviation({"rdf_blocks": [b for r in cells for b in r["rdf_blocks"]]},
                                   {"rdf_blocks": [b for r in refs for b in r["rdf_blocks"]]})
        self.assertFalse(pooled.within(am.TOLERANCE["g(r)"]))
    def test_a_largest_step_the_seeds_reject_gives_way(self):
        # the scan's largest step by the friction-step kBT is 0.003; four seeds there put D 3 %
        # low, so the row takes 0.002 (not re-run: no asterisk) and says why
        refs = [record("stock", 0.0001, 1.0, 20.0, d, role="ref") for d in (0.99, 1.0, 1.01, 1.0)]
        seeds = [record("imp", 0.003, 0.985, 19.9, d, T5=1.0) for d in (0.96, 0.97, 0.98, 0.97)]
        seeds += [record("stock", 0.0005, 1.008, 20.1, d) for d in (1.0, 1.01, 1.0, 1.01)]
        checked = am.seed_check(refs + seeds)
        plain = {r["integrator"]: r for r in am.summary_rows(self.cells, temperature="kBT_friction")}
        self.assertEqual(plain["imp"]["dt"], 0.003)
        rows = {r["integrator"]: r for r in am.summary_rows(self.cells, temperature="kBT_friction",
                                                            checked=checked)}
        self.assertEqual(rows["imp"]["dt"], 0.002)
        self.assertFalse(rows["imp"]["seed_checked"])
        self.assertEqual(rows["imp"]["limited_by"], ["D (seeds)"])
        self.assertEqual(rows["stock"]["dt"], 0.0005)    # kept by its seeds: marked
        self.assertTrue(rows["stock"]["seed_checked"])
        self.assertIn("| 0.0005* |", am.summary_table(list(rows.values())))
        self.assertAlmostEqual(rows["imp"]["step_ratio"], 4.0)

    def test_larger_steps_the_seeds_pass_are_taken(self):
        # the scan's largest step (friction-step kBT) is 0.003; four seeds pass 0.003 and 0.004
        # and fail 0.005 (D 3 % low): the row takes 0.004, re-run (asterisk); with 0.003 failed
        # by its seeds, 0.004's pass would not count (the row stays at the scan's 0.002)
        refs = [record("stock", 0.0001, 1.0, 20.0, d, role="ref") for d in (0.99, 1.0, 1.01, 1.0)]
        passing = [record("imp", dt, 0.985, 19.9, d, T5=1.0) for dt in (0.003, 0.004) for d in (0.99, 1.0, 1.01, 1.0)]
        failing = [record("imp", 0.005, 0.985, 19.9, d, T5=1.0) for d in (0.96, 0.97, 0.98, 0.97)]
        checked = am.seed_check(refs + passing + failing)
        rows = {r["integrator"]: r for r in am.summary_rows(self.cells, temperature="kBT_friction",
                                                            checked=checked)}
        self.assertEqual(rows["imp"]["dt"], 0.004)
        self.assertTrue(rows["imp"]["seed_checked"])
        failed_at_3 = [record("imp", 0.003, 0.985, 19.9, d, T5=1.0) for d in (0.96, 0.97, 0.98, 0.97)]
        passing_at_4 = [r for r in passing if r["dt"] == 0.004]
        checked = am.seed_check(refs + failed_at_3 + passing_at_4)
        rows = {r["integrator"]: r for r in am.summary_rows(self.cells, temperature="kBT_friction",
                                                            checked=checked)}
        self.assertEqual(rows["imp"]["dt"], 0.002)
        self.assertEqual(rows["imp"]["limited_by"], ["D (seeds)"])

    def test_seed_check_takes_the_smallest_step_reference(self):
        # a reference at a smaller step joins later: the earlier one (larger step) becomes a stock
        # cell, 1 % high in P against it
        refs = [record("stock", 0.0001, 1.0, 20.0, d, role="ref") for d in (0.99, 1.0, 1.01)]
        finer = [record("stock", 0.00003, 1.0, p, 1.0, role="ref") for p in (19.79, 19.8, 19.81)]
        cells = [record("imp", 0.003, 0.985, 19.8, d, T5=1.0) for d in (0.99, 1.0, 1.01)]
        checked = {(c.integrator, c.dt): c for c in am.seed_check(refs + finer + cells)}
        self.assertEqual(set(checked), {("stock", 0.0001), ("imp", 0.003)})
        self.assertAlmostEqual(checked[("stock", 0.0001)].deviations["P"].value, 20.0 / 19.8 - 1.0, places=12)
        self.assertAlmostEqual(checked[("imp", 0.003)].deviations["P"].value, 0.0, places=12)
        self.assertEqual(checked[("imp", 0.003)].n_ref_seeds, 3)

    def test_derived_reference_for_a_mass_out_of_reach(self):
        # references at m = 1, 0.1, 0.01 with D = 0.0179 - 0.0022 m exactly; the one at 0.01
        # has its own P, kBT and g(r)
        records = []
        for mass, pressure in ((1.0, 33.0), (0.1, 33.1), (0.01, 33.2)):
            ref = record("stock", 0.0005 * mass, 1.0, pressure, 0.0179 - 0.0022 * mass, role="ref")
            ref.update(fluid="HS", mass=mass, seed=9823, equil=1.0, windows=2, nwin=100, window_time=0.25,
                       stride=10, msdstride=1)
            records.append(ref)
        derived = am.derived_reference(records, "HS", 0.001, 0.01, [1.0, 0.1, 0.01])
        self.assertEqual((derived["role"], derived["mass"], derived["pair"]), ("ref", 0.001, "derived"))
        self.assertEqual(derived["P_blocks"], records[2]["P_blocks"])
        self.assertEqual(derived["rdf_blocks"], records[2]["rdf_blocks"])
        self.assertAlmostEqual(np.mean(derived["D_blocks"]), 0.0179 - 0.0022 * 0.001, places=9)
        self.assertAlmostEqual(max(abs(r) for r in derived["derived_from"]["D_fit_residuals"]), 0.0, places=12)
        # the scatter of the blocks is the source's, scaled
        source = records[2]["D_blocks"]
        ratio = np.mean(derived["D_blocks"]) / np.mean(source)
        self.assertAlmostEqual(derived["D_blocks"][1] - derived["D_blocks"][0], ratio * (source[1] - source[0]))
        # a cell at that mass is compared with it
        cell = record("imp", 0.005, 1.0, 33.2, 0.0179, role="cell")
        cell.update(fluid="HS", mass=0.001)
        compared = am.cells(records + [derived, dict(derived), cell])    # derived twice: one is no cell
        self.assertEqual([(c.mass, c.integrator) for c in compared if c.mass == 0.001], [(0.001, "imp")])
        # the seed check's references: each seed of m = 0.1's (the smallest step only), D scaled
        # by one factor to the fitted value
        confirm = []
        for seed, d in ((11, 0.0176), (12, 0.0178)):
            for dt in (0.00005, 0.0005):
                ref = record("stock", dt, 1.0, 33.0 + seed, d, role="ref")
                ref.update(fluid="HS", mass=0.1, seed=seed, equil=0.2, windows=2, nwin=100, window_time=0.25,
                           stride=10, msdstride=1)
                confirm.append(ref)
        seeds = am.derived_seed_references(confirm, derived, 0.1)
        self.assertEqual([(r["seed"], r["dt"], r["mass"]) for r in seeds], [(11, 0.00005, 0.001), (12, 0.00005, 0.001)])
        self.assertEqual(seeds[1]["P_blocks"], confirm[2]["P_blocks"])
        self.assertAlmostEqual(np.mean([np.mean(r["D_blocks"]) for r in seeds]), 0.0179 - 0.0022 * 0.001, places=9)
        self.assertAlmostEqual(np.mean(seeds[1]["D_blocks"]) / np.mean(seeds[0]["D_blocks"]), 0.0178 / 0.0176)
        with self.assertRaisesRegex(ValueError, "no seed-check reference of HS at m = 1.0"):
            am.derived_seed_references(confirm, derived, 1.0)
        with self.assertRaisesRegex(ValueError, "no reference of HS"):
            am.derived_reference(records, "HS", 0.001, 0.05, [1.0, 0.1])
        with self.assertRaisesRegex(ValueError, "two masses"):
            am.derived_reference(records, "HS", 0.001, 0.01, [0.1])

    def test_main_reads_the_seed_check(self):
        import contextlib
        import io
        refs = [record("stock", 0.0001, 1.0, 20.0, d, role="ref") for d in (0.99, 1.0, 1.01)]
        # the seeds reject the implicit scheme's largest step by LAMMPS's temp (0.002); its
        # friction-step temperature (exact here) passes nothing: no table is judged by it
        seeds = [record("imp", 0.002, 0.996, 19.9, d, T5=1.0) for d in (0.96, 0.97, 0.98)]
        with tempfile.TemporaryDirectory() as folder:
            for name, records in (("scan.jsonl", scan_records()), ("confirm.jsonl", refs + seeds)):
                with open(os.path.join(folder, name), "w") as out:
                    for r in records:
                        out.write(json.dumps(r) + "\n")
            printed = io.StringIO()
            with contextlib.redirect_stdout(printed):
                self.assertEqual(am.main([folder]), 0)
        text = printed.getvalue()
        self.assertIn("re-run with independent seeds", text)
        self.assertIn("| GW | 0.01 | imp | 0.002 | 3 (3) |", text)
        self.assertIn("D (seeds)", text)
        self.assertNotIn("friction-step kBT as", text)
        self.assertNotIn("| GW | 0.01 | etd implicit | 0.003", text)


if __name__ == "__main__":
    unittest.main()
