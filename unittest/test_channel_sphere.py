#!/usr/bin/python3
"""Tests of tools/channel_sphere.py's drag analysis on synthetic fix ave/time files."""
import argparse
import math
import os
import sys
import tempfile
import unittest

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tools"))
import channel_sphere  # noqa: E402

HEADER = "# Time-averaged data for fix drag\n# TimeStep c_fsphere[1] c_fsphere[2] c_fsphere[3] c_vfluid c_tfluid c_split[1] c_split[4] c_split[7]\n"


def write_drag(path, drag, velocity, rows=200, noise=1.0, seed=1):
    rng = np.random.default_rng(seed)
    with open(path, "w") as out:
        out.write(HEADER)
        for k in range(rows):
            conservative = 0.3 * drag + noise * rng.standard_normal()
            dissipative = 0.7 * drag + noise * rng.standard_normal()
            random_part = noise * rng.standard_normal()
            total = conservative + dissipative + random_part
            out.write(f"{100 * (k + 1)} {total} 0 0 {velocity} 1.0 {conservative} {dissipative} {random_part}\n")


def options(**kw):
    args = argparse.Namespace(
        rho=4.0, d=3.0, eta=1.083, U=None, velocity="c_vfluid", force="split", discard=0.2, batches=10)
    for key, value in kw.items():
        setattr(args, key, value)
    return args


class Drag(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.path = lambda name: os.path.join(self.dir.name, name)

    def tearDown(self):
        self.dir.cleanup()

    def test_stokes_drag_gives_24_over_re(self):
        # F = 3 pi eta d U exactly: C_D = 24/Re and a_eff = d/2
        u = 0.5
        write_drag(self.path("a"), 3 * math.pi * 1.083 * 3.0 * u, u, noise=0.0)
        r = channel_sphere.analyse(self.path("a"), options())
        self.assertAlmostEqual(r["C_D"], 24.0 / r["Re"], places=10)
        self.assertAlmostEqual(r["a_eff"], 1.5, places=10)

    def test_pooling_two_runs(self):
        write_drag(self.path("a"), 28.0, 0.53, noise=2.0, seed=1)
        write_drag(self.path("b"), 28.0, 0.53, noise=2.0, seed=2)
        write_drag(self.path("c"), 28.0, 0.53, noise=4.0, seed=3)
        a = channel_sphere.analyse(self.path("a"), options())
        b = channel_sphere.analyse(self.path("b"), options())
        both = channel_sphere.analyse_pooled(self.path("a") + "+" + self.path("b"), options())
        # the inverse-variance weighted mean lies between the runs, with a smaller error
        low, high = sorted([a["F_D"], b["F_D"]])
        self.assertTrue(low <= both["F_D"] <= high)
        self.assertLess(both["F_D_err"], min(a["F_D_err"], b["F_D_err"]))
        expected = 1.0 / math.sqrt(a["F_D_err"] ** -2 + b["F_D_err"] ** -2)
        self.assertAlmostEqual(both["F_D_err"], expected, places=12)
        # a noisier run counts less
        c = channel_sphere.analyse(self.path("c"), options())
        with_c = channel_sphere.analyse_pooled(self.path("a") + "+" + self.path("c"), options())
        self.assertLess(abs(with_c["F_D"] - a["F_D"]), abs(with_c["F_D"] - c["F_D"]))
        # one file is not pooled
        self.assertEqual(channel_sphere.analyse_pooled(self.path("a"), options())["F_D"], a["F_D"])
        # the correlation is re-evaluated at the pooled Re
        self.assertAlmostEqual(both["C_D_correlation"], channel_sphere.correlation_cd(both["Re"]), places=12)


if __name__ == "__main__":
    unittest.main()
