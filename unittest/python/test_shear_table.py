#!/usr/bin/python3
"""bench/accuracy/shear_table.py on synthetic viscosity_shear.sh logs: sets split by the log
name's prefix, cells by name, the mean over seeds with its standard error, the deviation from
the set's reference with the error of the ratio; unfinished logs (no RESULT line) left out."""
import importlib.util
import math
import os
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
spec = importlib.util.spec_from_file_location(
    "shear_table", os.path.join(HERE, "..", "..", "bench", "accuracy", "shear_table.py"))
shear_table = importlib.util.module_from_spec(spec)
spec.loader.exec_module(shear_table)


def write_log(directory, name, eta, kT=1.0, eta_v=None, slope=0.5, sdisp=None):
    with open(os.path.join(directory, name), "w") as log:
        log.write("LAMMPS (29 Sep 2021)\n")
        if eta is not None:
            tail = ("" if sdisp is None else f" sdisp {sdisp}") + ("" if eta_v is None else f" eta_v {eta_v}")
            log.write(f"RESULT integ stock dt 0.001 rate 0.5 plane xy seed 1 kT {kT} eta {eta} slope {slope}{tail}\n")


class ShearTable(unittest.TestCase):
    def test_sets_cells_and_deviation(self):
        with tempfile.TemporaryDirectory() as directory:
            for seed, eta in ((1, 1.0), (2, 1.2)):
                write_log(directory, f"log.HS.m1.rate0.2.ref.{seed}", eta)
            for seed, eta in ((1, 0.9), (2, 1.0)):
                write_log(directory, f"log.HS.m1.rate0.2.imp0.04.{seed}", eta, kT=0.98, eta_v=eta + 0.2,
                          slope=0.5 + 0.01 * seed, sdisp=0.5 + 0.01 * seed - 0.001 * seed)
            write_log(directory, "log.HS.m1.rate0.2.stock.1", None)    # still running
            write_log(directory, "log.HS.m1.rate0.2.stock0.003.1", 1.05)
            write_log(directory, "log.ref.1", 0.16)                    # the GW m = 0.01 set
            runs = shear_table.read_runs(directory)
            self.assertEqual(sorted(runs), ["", "HS.m1.rate0.2."])
            self.assertEqual(sorted(runs["HS.m1.rate0.2."]), ["imp0.04", "ref", "stock0.003"])
            rows = {row[0]: row for row in shear_table.table(runs["HS.m1.rate0.2."])}
            cell, n, eta, error, kT, deviation, deviation_error, end, profile, lag = rows["imp0.04"]
            self.assertEqual(n, 2)
            self.assertAlmostEqual(eta, 0.95)
            self.assertAlmostEqual(error, 0.05)    # |a - b| / 2 for two seeds
            self.assertAlmostEqual(kT, 0.98)
            self.assertAlmostEqual(deviation, 100 * (0.95 / 1.1 - 1))
            expected = 100 * (0.95 / 1.1) * math.hypot(0.05 / 0.95, 0.1 / 1.1)
            self.assertAlmostEqual(deviation_error, expected)
            self.assertIsNone(rows["ref"][5])
            # eta_v (the implicit scheme's second reading) against the same reference
            self.assertAlmostEqual(end[0], 100 * (1.15 / 1.1 - 1))
            self.assertIsNone(rows["stock0.003"][7])    # no eta_v in its RESULT line
            # the profile's slope (0.51 and 0.52) against the RESULT line's rate 0.5
            self.assertAlmostEqual(profile[0], 100 * (0.515 / 0.5 - 1))
            self.assertAlmostEqual(profile[1], 100 * 0.005 / 0.5)
            self.assertAlmostEqual(rows["ref"][8][0], 0.0)
            # against the displacements' slope, seed by seed: (0.001, 0.002) / 0.5, both seeds
            self.assertAlmostEqual(rows["imp0.04"][9][0], 100 * 0.0015 / 0.5)
            self.assertAlmostEqual(rows["imp0.04"][9][1], 100 * 0.0005 / 0.5)
            self.assertEqual(rows["imp0.04"][9][2], 2)
            self.assertIsNone(rows["ref"][9])    # no sdisp in its RESULT line

    def test_diagonal_cells_and_a_reference_from_another_set(self):
        with tempfile.TemporaryDirectory() as directory:
            for seed, eta in ((1, 28.0), (2, 30.0)):
                write_log(directory, f"log.HS.m0.1.rate0.2.ref.{seed}", eta)
            for seed, eta in ((1, 29.5), (2, 30.5)):
                write_log(directory, f"log.HS.m0.01.rate0.2.imp.{seed}", eta)
            write_log(directory, "log.m0.1.diag0.003.1", 0.33)
            runs = shear_table.read_runs(directory)
            self.assertEqual(sorted(runs["m0.1."]), ["diag0.003"])
            own = {row[0]: row for row in shear_table.table(runs["HS.m0.01.rate0.2."])}
            self.assertIsNone(own["imp"][5])    # no reference of its own
            rows = {row[0]: row for row in shear_table.table(runs["HS.m0.01.rate0.2."],
                                                             runs["HS.m0.1.rate0.2."]["ref"])}
            self.assertAlmostEqual(rows["imp"][5], 100 * (30.0 / 29.0 - 1))

    def test_reference_from_a_set_without_references_is_an_error(self):
        with tempfile.TemporaryDirectory() as directory:
            write_log(directory, "log.HS.m0.01.rate0.2.imp.1", 29.0)
            with self.assertRaises(SystemExit) as stop:
                shear_table.main(["--summary", os.path.join(directory, "s.jsonl"), "--dir", directory,
                                  "--ref-from", "HS.m0.01.rate0.2.=HS.m0.1.rate0.2."])
            self.assertIn("has no reference runs", str(stop.exception))
            with self.assertRaises(SystemExit) as stop:
                shear_table.main(["--summary", os.path.join(directory, "s.jsonl"), "--dir", directory,
                                  "--ref-from", "HS.m0.01.rate0.2."])
            self.assertIn("SET=REFSET", str(stop.exception))

    def test_summary_merges_new_logs_and_gives_the_same_runs(self):
        with tempfile.TemporaryDirectory() as directory:
            summary = os.path.join(directory, "viscosity_shear.jsonl")
            write_log(directory, "log.P.m1.ref.1", 2.0)
            write_log(directory, "log.P.m1.imp.1", 2.2)
            shear_table.merge_summary(summary, shear_table.log_records(directory))
            os.remove(os.path.join(directory, "log.P.m1.ref.1"))    # logs are not kept
            write_log(directory, "log.P.m1.imp.1", 2.1)             # a re-run replaces its record
            write_log(directory, "log.P.m1.imp.2", 2.3)
            records = shear_table.merge_summary(summary, shear_table.log_records(directory))
            runs = shear_table.runs_from_records(shear_table.read_summary(summary))
            self.assertEqual(len(records), 3)
            self.assertEqual(runs["P.m1."]["ref"], [(1, 2.0, 1.0, None, 1.0, None)])
            self.assertEqual(runs["P.m1."]["imp"], [(1, 2.1, 1.0, None, 1.0, None), (2, 2.3, 1.0, None, 1.0, None)])
            self.assertEqual(records[0]["integ"], "stock")    # the RESULT line's fields are kept


if __name__ == "__main__":
    unittest.main()
