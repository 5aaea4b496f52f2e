#!/usr/bin/python3
"""python/summarise_log.py (the main job's summary) on synthetic logs: the production run's mean
temperature without its first row, and with fix etd scheme implicit's friction-step column both
temperatures, each against the target."""
import contextlib
import io
import os
import re
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

    def test_the_main_jobs_committed_log(self):
        log = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "examples",
                           "quickstart", "log.quickstart.g++.1")
        with open(log) as f:
            text = summary(f.read())
        # LAMMPS's temp of the implicit scheme at m = 0.01, dt = 0.003 within 1 % of kBT
        mean = float(re.search(r"production run: ([0-9.]+)", text).group(1))
        self.assertAlmostEqual(mean, 1.0, delta=0.01)
        self.assertIn("steps 1000", text)


if __name__ == "__main__":
    unittest.main()
