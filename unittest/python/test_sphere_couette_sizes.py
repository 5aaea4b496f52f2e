#!/usr/bin/python3
"""Checks python/sphere_couette_sizes.py: per-size means and errors over independent runs, the
extrapolation in 1/s, and the reading of run folders, on synthetic data with known answers."""
import math
import os
import subprocess
import sys
import tempfile
import unittest

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
PYTHON_DIR = os.path.join(HERE, "..", "..", "python")
sys.path.insert(0, PYTHON_DIR)
from etddpd import sphere_couette_sizes as sizes  # noqa: E402


def write_run(folder, lx, drag_c, drag_d, drag_r, rows=150, equil_rows=30):
    os.makedirs(folder)
    with open(os.path.join(folder, "drag.sphere-couette"), "w") as out:
        out.write("# Time-averaged data for fix drag_out\n"
                  "# TimeStep v_Fx c_drag[1] c_drag[2] c_drag[3] c_drag[4] c_drag[5] c_drag[6] "
                  "c_drag[7] c_drag[8] c_drag[9]\n")
        for k in range(rows):
            scale = 0.0 if k < equil_rows else 1.0    # start-up rows: zero drag, must be skipped
            c, d, r = scale * drag_c, scale * drag_d, scale * drag_r
            out.write(f"{(k + 1) * 100} {c + d + r} {c} 0 0 {d} 0 0 {r} 0 0\n")
    with open(os.path.join(folder, "log.lammps"), "w") as out:
        out.write(f"sphere-couette: scheme diagonal wallbc diffusive mass 0.01 dt 0.001 Lx {lx} Ly 12 "
                  f"H 12 U 3.0 sigma_CS 3.2 a_CS 1750 atoms 1 fluid 1\n")


class Extrapolation(unittest.TestCase):
    def test_exact_line_in_inverse_scale(self):
        # F = 150 + 12 / s at s = 0.4, 0.5, 0.6, each as runs scattered by +-1 about it
        rows = [(s, 150 + 12 / s, 1.0, 3) for s in (0.4, 0.5, 0.6)]
        f_one, f_one_err, f_inf, f_inf_err, slope = sizes.extrapolate(rows)
        self.assertAlmostEqual(f_one, 162.0, places=9)
        self.assertAlmostEqual(f_inf, 150.0, places=9)
        self.assertAlmostEqual(slope, 12.0, places=9)
        # extrapolating from s = 0.4-0.6 to 1 and to 0 costs precision: errors above one size's
        self.assertGreater(f_one_err, 0.0)
        self.assertGreater(f_inf_err, f_one_err)

    def test_single_runs_give_no_error_and_no_fit(self):
        rows = sizes.per_size({0.4: [170.0], 0.5: [160.0, 164.0]})
        self.assertTrue(math.isnan(rows[0][2]))
        self.assertAlmostEqual(rows[1][1], 162.0)
        self.assertAlmostEqual(rows[1][2], 2.0)    # standard error of (160, 164)
        self.assertIsNone(sizes.extrapolate(rows))


class Folders(unittest.TestCase):
    def test_runs_are_grouped_by_box_and_the_start_is_skipped(self):
        with tempfile.TemporaryDirectory() as tmp:
            runs = []
            for lx, drags in ((16, (170.0, 174.0)), (24, (160.0, 162.0))):
                for k, total in enumerate(drags):
                    folder = os.path.join(tmp, f"L{lx}_{k}")
                    write_run(folder, lx, 40.0, total - 45.0, 5.0)
                    runs.append(folder)
            out = subprocess.run([sys.executable, os.path.join(PYTHON_DIR, "sphere_couette_sizes.py"), *runs],
                                 capture_output=True, text=True, check=True).stdout
            self.assertIn("s = 0.40, F = 170.00, F_C + F_D = 165.00", out)
            self.assertIn("  0.40    172.00    2.00  2", out)
            self.assertIn("  0.60    161.00    1.00  2", out)
            # through (2.5, 172) and (1.667, 161): slope 13.2 per unit of 1/s, F(s = 1) = 152.2
            self.assertIn("at the paper's box (s = 1) 152.20", out)

    def test_missing_summary_line_is_said(self):
        with tempfile.TemporaryDirectory() as tmp:
            folder = os.path.join(tmp, "run")
            write_run(folder, 16, 40.0, 130.0, 5.0)
            with open(os.path.join(folder, "log.lammps"), "w") as out:
                out.write("no summary\n")
            p = subprocess.run([sys.executable, os.path.join(PYTHON_DIR, "sphere_couette_sizes.py"), folder],
                               capture_output=True, text=True)
            self.assertNotEqual(p.returncode, 0)
            self.assertIn("no 'sphere-couette: scheme ... Lx' line", p.stderr)


if __name__ == "__main__":
    unittest.main()
