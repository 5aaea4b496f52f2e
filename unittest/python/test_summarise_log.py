#!/usr/bin/python3
"""python/summarise_log.py (the main job's summary) on synthetic logs: the production run's mean
temperature without its first row, and with fix etd scheme implicit's friction-step column both
temperatures, each against the target."""
import contextlib
import io
import os
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from etddpd import summarise_log  # noqa: E402


def log_text(columns, rows):
    lines = ["LAMMPS (29 Sep 2021 - Update 2)", "Step " + " ".join(columns)]
    lines += [" ".join(str(x) for x in row) for row in [(0, 1.0, 5.0, 2.0)] + rows]
    lines.append("Loop time of 2.5 on 1 procs for 100 steps with 4000 atoms")
    return "\n".join(lines) + "\n"


def summary(text):
    with tempfile.NamedTemporaryFile("w", suffix=".log", delete=False) as log:
        log.write(text)
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        summarise_log.main([log.name, "--target-temperature", "1.0"])
    os.unlink(log.name)
    return out.getvalue()


class SummariseLog(unittest.TestCase):
    def test_one_temperature(self):
        text = summary(log_text(["Temp", "Press", "PotEng"], [(50, 0.98, 20.0, 1.0), (100, 0.99, 20.0, 1.0)]))
        self.assertIn("temperature (kBT) over the production run: 0.9850", text)
        self.assertIn("deviation -1.50 %", text)
        self.assertNotIn("friction-step", text)
        self.assertIn("throughput: 1.600e+05 atom-steps/s", text)

    def test_friction_step_temperature_beside_the_end_of_step_one(self):
        text = summary(log_text(["Temp", "f_integrate[5]", "Press"],
                                [(50, 0.99, 1.002, 20.0), (100, 0.992, 1.000, 20.0)]))
        self.assertIn("end-of-step velocities (thermo temp): 0.9910", text)
        self.assertIn("friction-step velocities (f_integrate[5]): 1.0010", text)
        self.assertIn("deviation +0.10 %", text)

    def test_the_main_jobs_committed_log(self):
        log = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "examples",
                           "quickstart", "log.quickstart.g++.1")
        with open(log) as f:
            text = summary(f.read())
        self.assertIn("end-of-step velocities (thermo temp): 0.99", text)
        self.assertIn("friction-step velocities (f_integrate[5]): 1.00", text)
        self.assertIn("steps 1000", text)


if __name__ == "__main__":
    unittest.main()
