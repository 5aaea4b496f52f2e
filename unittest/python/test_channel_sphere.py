#!/usr/bin/python3
"""Tests of python/channel_sphere.py on synthetic files with known answers: the drag analysis
of fix ave/time files (mean drag and velocity, Re and C_D from them, the conservative +
dissipative estimator against the total, the batch error against the known noise, the discarded
start, pooling of runs, the drag correlation's values, the hydrodynamic radius with the wall
factors taken out) and the wall-radius, velocity and density profiles of fix ave/chunk files."""
import argparse
import contextlib
import io
import json
import math
import os
import re
import subprocess
import sys
import tempfile
import unittest

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
PYTHON_DIR = os.path.join(HERE, "..", "..", "python")
SCRIPT = os.path.join(PYTHON_DIR, "channel_sphere.py")
sys.path.insert(0, PYTHON_DIR)
from etddpd import channel_sphere, kinetic_theory  # noqa: E402
from etddpd.lammps_output import read_ave_chunk  # noqa: E402

# the header of in.sphere_shear's drag file, with the inside count of in.sphere_compliant
HEADER = ("# Time-averaged data for fix drag\n"
          "# TimeStep c_fsphere[1] c_fsphere[2] c_fsphere[3] c_vfluid c_tfluid "
          "c_split[1] c_split[4] c_split[7] v_inside\n")


def write_drag_transient(path, drag, u, rows, noise_random, noise_cd, seed=3, start_rows=0):
    """Rows of block means: C + D = drag + noise_cd, R = noise_random (mean zero), total = sum;
    the first start_rows rows carry a transient (drag 10x) that --discard must drop."""
    rng = np.random.default_rng(seed)
    with open(path, "w") as f:
        f.write(HEADER)
        for k in range(rows):
            scale = 10.0 if k < start_rows else 1.0
            cons = 0.3 * drag * scale + noise_cd * rng.standard_normal()
            diss = 0.7 * drag * scale
            rand = noise_random * rng.standard_normal()
            f.write(f"{100 * (k + 1)} {cons + diss + rand} 0.1 -0.1 {u} 1.0 {cons} {diss} {rand} 14\n")


def run_script(args):
    """The drag command's results (its --json) for these arguments, run as the script."""
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "r.json")
        subprocess.run([sys.executable, SCRIPT, "drag"] + args + ["--json", out], check=True,
                       stdout=subprocess.DEVNULL)
        with open(out) as f:
            return json.load(f)


HEADER_SPLIT = "# Time-averaged data for fix drag\n# TimeStep c_fsphere[1] c_fsphere[2] c_fsphere[3] c_vfluid c_tfluid c_split[1] c_split[4] c_split[7]\n"


def write_drag(path, drag, velocity, rows=200, noise=1.0, seed=1):
    """Rows of block means: C + D = drag, C, D and R each with Gaussian noise."""
    rng = np.random.default_rng(seed)
    with open(path, "w") as out:
        out.write(HEADER_SPLIT)
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


class InTempDir(unittest.TestCase):
    """A test whose files live in a fresh temporary directory: self.path(name)."""

    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.path = lambda name: os.path.join(self.dir.name, name)

    def tearDown(self):
        self.dir.cleanup()


class Drag(InTempDir):
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


class WallRadius(InTempDir):
    def test_near_window_sees_a_local_bulge(self):
        # 20 bins of width 1.26; the wall bulges to 7 in the 4 middle bins, 6.5 elsewhere
        path = self.path("wall_radius.x")
        with open(path, "w") as out:
            out.write("# Chunk-averaged data\n# Timestep Number-of-chunks Total-count\n"
                      "# Chunk Coord1 Ncount v_wall_r\n")
            for block in range(10):
                out.write(f"{1000 * (block + 1)} 21 2000\n")
                for k in range(21):
                    x = (k + 0.5) * 1.26
                    count = 100.0 if k < 20 else 0.0
                    r = 7.0 if abs(x - 12.6) < 2.0 else 6.5
                    out.write(f"  {k + 1} {x} {count} {r if count else 0.0}\n")
        line = printed(["radius", path, "--near", "2.0"])
        self.assertIn("mean wall radius 6.6000", line)      # (4 x 7 + 16 x 6.5) / 20
        self.assertIn("within 2 of x = 12.60: 7.0000", line)


SLABS = (3.15, 9.45, 15.75, 22.05)      # four slabs of 6.3; the sphere at x = 12.6
RINGS = (np.arange(30) + 0.5) * 0.242


def write_radial_bins(path, blocks, count_and_vx, rings=RINGS, slabs=SLABS):
    """A fix ave/chunk file of bin/cylinder chunks as in.sphere_compliant writes them (radius
    Coord1, slab Coord2, the slab varying fastest); count_and_vx(r, x) gives one chunk's values."""
    with open(path, "w") as out:
        out.write("# Chunk-averaged data\n# Timestep Number-of-chunks Total-count\n"
                  "# Chunk Coord1 Coord2 Ncount vx\n")
        for block in range(blocks):
            out.write(f"{1000 * (block + 1)} {len(rings) * len(slabs)} 10000\n")
            k = 0
            for r in rings:
                for x in slabs:
                    k += 1
                    n, u = count_and_vx(r, x)
                    out.write(f"  {k} {r} {x} {n} {u}\n")


def captured(function, *args):
    """(what function(*args) returns, what it printed)."""
    text = io.StringIO()
    with contextlib.redirect_stdout(text):
        value = function(*args)
    return value, text.getvalue()


def printed(argv):
    return captured(channel_sphere.main, argv)[1]


class VelocityProfile(InTempDir):
    def test_poiseuille_fit_recovers_centre_velocity_and_radius(self):
        # the two slabs far from the sphere carry u = 1.2 (1 - r^2/25) plus noise; the near
        # ones a flat profile that the fit must not see
        rng = np.random.default_rng(5)

        def chunk(r, x):
            u = 1.2 * (1 - r * r / 25.0) if abs(x - 12.6) > 6.3 else 0.3
            return 10 * r, u + 0.01 * rng.standard_normal()
        path = self.path("velocity_profile.x")
        write_radial_bins(path, 20, chunk)
        words = printed(["velocity", path]).split()
        v_c = float(words[words.index("velocity") + 1])
        r_h = float(words[words.index("radius") + 1])
        self.assertAlmostEqual(v_c, 1.2, delta=0.005)
        self.assertAlmostEqual(r_h, 5.0, delta=0.02)

    def test_density_per_ring(self):
        # counts proportional to each ring's volume in the far slabs: density 4 everywhere there;
        # the near slabs hold nothing and must not dilute it
        def chunk(r, x):
            volume = math.pi * ((r + 0.121) ** 2 - (r - 0.121) ** 2) * 6.3
            return (4.0 * volume if abs(x - 12.6) > 6.3 else 0.0), 0.0
        path = self.path("velocity_profile.x")
        write_radial_bins(path, 5, chunk)
        values = [float(line.split()[1]) for line in printed(["density", path]).splitlines()[1:]]
        self.assertEqual(len(values), 30)
        for v in values:
            self.assertAlmostEqual(v, 4.0, places=6)

    def test_bad_options_are_refused(self):
        path = self.path("velocity_profile.x")
        write_radial_bins(path, 5, lambda r, x: (10.0, 1.0 - r * r / 25.0))
        for argv, message in ((["--fit", "0"], "--fit must be positive"),
                              (["--fit", "0.3"], "fewer than 3 radial bins"),
                              (["--batches", "1"], "--batches must be at least 2"),
                              (["--discard", "1.0"], "--discard must be in [0, 1)")):
            with self.assertRaises(SystemExit) as caught:
                channel_sphere.main(["velocity", path] + argv)
            self.assertIn(message, str(caught.exception.code))

    def test_unusable_profile_files_are_refused(self):
        def written(name, blocks=5, **bins):
            path = self.path(name)
            write_radial_bins(path, blocks, lambda r, x: (10.0, 1.0), **bins)
            return path
        one_block = written("one_block", blocks=1)
        one_slab = written("one_slab", slabs=(12.6,))
        two_slabs = written("two_slabs", slabs=(9.45, 15.75))    # both next to the sphere
        coarse = written("coarse", rings=(np.arange(20) + 0.5) * 0.3)
        fine = written("fine")
        for argv, message in ((["velocity", one_block], "fewer than 2 blocks"),
                              (["velocity", one_slab], "at least two slabs"),
                              (["density", two_slabs], "no slab farther than a quarter box"),
                              (["density", fine, coarse], "other radial bins")):
            with self.assertRaises(SystemExit) as caught:
                channel_sphere.main(argv)
            self.assertIn(message, str(caught.exception.code))

    def test_parabola_fit_is_exact_on_a_parabola(self):
        r = np.linspace(0.1, 3.0, 12)
        v, rh = channel_sphere.parabola_fit(r, 0.8 * (1 - r**2 / 5.3**2), np.ones_like(r))
        self.assertAlmostEqual(v, 0.8, places=12)
        self.assertAlmostEqual(rh, 5.3, places=10)


class ShellProfile(InTempDir):
    def write_shells(self, path, blocks, u_inf, a, inside_u, density=4.0, noise=0.0):
        """bin/sphere chunks of 0.25 out to 5: v_x = U_inf (1 - a/r) outside 1.5, inside_u within"""
        rng = np.random.default_rng(7)
        radii = 0.125 + 0.25 * np.arange(20)
        with open(path, "w") as out:
            out.write("# Chunk-averaged data for fix shell_profile and group fluid\n"
                      "# Timestep Number-of-chunks Total-count\n"
                      "# Chunk Coord1 Ncount density/number vx\n")
            for b in range(blocks):
                out.write(f"{(b + 1) * 1000} 20 1000\n")
                for k, r in enumerate(radii):
                    volume = 4 / 3 * math.pi * ((r + 0.125) ** 3 - (r - 0.125) ** 3)
                    u = inside_u if r < 1.5 else u_inf * (1 - a / r)
                    u += noise * rng.standard_normal()
                    out.write(f"  {k + 1} {r} {density * volume} {density} {u}\n")

    def test_fit_recovers_the_radius_and_the_flow_inside(self):
        path = self.path("profiles.x")
        self.write_shells(path, 10, 0.9, 1.1, 0.3)
        text = printed(["shells", "--discard", "0", path])
        self.assertIn("U_inf = 0.9000 +- 0.0000, a_h = 1.100 +- 0.000", text)
        inside = 4.0 * 4 / 3 * math.pi * 1.5 ** 3
        self.assertIn(f"{inside:.1f} +- 0.0 particles, mean v_x 0.3000 +- 0.0000 (0.333 of U_inf)", text)
        # density per shell: the count over the shell's volume
        rows = [line.split() for line in text.splitlines()[4:]]
        self.assertTrue(all(abs(float(row[1]) - 4.0) < 1e-3 for row in rows))

    def test_noise_gives_an_error_and_the_range_is_checked(self):
        path = self.path("profiles.x")
        self.write_shells(path, 20, 0.9, 1.1, 0.3, noise=0.02)
        found = re.search(r"a_h = (\S+) \+- (\S+)", printed(["shells", "--discard", "0", path]))
        a_h, err = float(found.group(1)), float(found.group(2))
        self.assertGreater(err, 0.0)
        self.assertLess(abs(a_h - 1.1), 5 * err)
        with self.assertRaises(SystemExit):
            channel_sphere.main(["shells", "--fit-from", "4", "--fit-to", "2", path])


class LineProfile(InTempDir):
    def test_density_per_cell_and_weighted_velocity(self):
        # two blocks: cell 2 holds 0.4 then 0.2 particles at v_x 1.0 then 0.4; the count-weighted
        # v_x is (0.4 + 0.08) / 0.6 = 0.8, the density 0.3 / cell volume
        path = self.path("line.x")
        with open(path, "w") as out:
            out.write("# Chunk-averaged data for fix line_profile and group fluid\n"
                      "# Timestep Number-of-chunks Total-count\n"
                      "# Chunk Coord1 Ncount density/number vx\n")
            for step, (n2, v2) in ((1000, (0.4, 1.0)), (2000, (0.2, 0.4))):
                out.write(f"{step} 3 1\n  1 0.5 0.1 0.0 2.0\n  2 1.5 {n2} 0.0 {v2}\n  3 2.5 0.1 0.0 2.0\n")
        rows = printed(["line", "--discard", "0", "--cell-volume", "0.1", path]).splitlines()[1:]
        self.assertEqual(rows[1].split(), ["0.000", "3.000", "0.8000"])
        self.assertEqual(rows[0].split(), ["-1.000", "1.000", "2.0000"])


class TubeWallFactor(unittest.TestCase):
    def test_small_sphere_limits(self):
        # an unbounded fluid as lam -> 0; first reflection 2.105 lam (Faxen's 2.104)
        for factor in (channel_sphere.tube_factor_quiescent, channel_sphere.tube_factor_poiseuille):
            self.assertAlmostEqual(float(factor(0.0)), 1.0, places=14)
            h = 1e-6
            self.assertAlmostEqual(float((factor(h) - factor(0.0)) / h), 2.1050, places=4)

    def test_poiseuille_curvature_term(self):
        # K - K' = (2/3 lam^2 + (0.20217 - 0.75857) lam^5) / denominator: Faxen's -2/3 lam^2
        lam = 0.01
        diff = float(channel_sphere.tube_factor_quiescent(lam) - channel_sphere.tube_factor_poiseuille(lam))
        self.assertAlmostEqual(diff / lam**2, 2.0 / 3.0 * (1 + 2.105 * lam), delta=1e-3)

    def test_grows_with_confinement(self):
        lam = np.linspace(0.0, 0.6, 61)
        for factor in (channel_sphere.tube_factor_quiescent, channel_sphere.tube_factor_poiseuille):
            self.assertTrue(np.all(np.diff(factor(lam)) > 0))
        # the tabulated value of the series at lam = 0.2 (Haberman and Sayre)
        self.assertAlmostEqual(float(channel_sphere.tube_factor_quiescent(0.2)), 1.680, places=3)

    def test_radius_at_or_below_the_sphere_is_refused(self):
        with self.assertRaises(SystemExit) as caught:
            channel_sphere.main(["tube", "--d", "3", "4.5", "1.5"])
        self.assertIn("must exceed the sphere radius", str(caught.exception.code))


class ConfinedRadius(InTempDir):
    """a_h: the Stokes radius with the channel's wall factor taken out."""

    def drag_of(self, path, **kw):
        confinement = {"slit": None, "tube": None, "centre_line": False, **kw}
        args = options(series=None, files=[path], json=None, png=None, **confinement)
        return captured(channel_sphere.drag_command, args)[0][0]

    def test_slit_factor_limits(self):
        # an unbounded fluid as lam -> 0, Faxen's first reflection 1.004 lam, growing with lam
        self.assertAlmostEqual(float(channel_sphere.slit_factor_midway(0.0)), 1.0, places=14)
        h = 1e-6
        slope = float((channel_sphere.slit_factor_midway(h) - 1.0) / h)
        self.assertAlmostEqual(slope, 1.004, places=4)
        lam = np.linspace(0.0, channel_sphere.SLIT_LAMBDA_MAX, 51)
        self.assertTrue(np.all(np.diff(channel_sphere.slit_factor_midway(lam)) > 0))
        # the higher reflections (+0.418 lam^3 ...) lower it slightly below the first one
        # summed geometrically, 1 / (1 - 1.004 lam), and keep it above 1 + 1.004 lam
        k = float(channel_sphere.slit_factor_midway(0.25))
        self.assertTrue(1.0 + 1.004 * 0.25 < k < 1.0 / (1.0 - 1.004 * 0.25))

    def test_recovers_the_radius_of_a_confined_solid_sphere(self):
        eta, u, a = 1.083, 0.5, 1.2
        # between walls 6.3 from the centre: F = 6 pi eta a U K(a / 6.3)
        slit_drag = 6 * math.pi * eta * a * u * float(channel_sphere.slit_factor_midway(a / 6.3))
        write_drag(self.path("slit"), slit_drag, u, noise=0.0)
        r = self.drag_of(self.path("slit"), slit=6.3)
        self.assertAlmostEqual(r["a_h"], a, places=9)
        self.assertGreater(r["a_eff"], 1.05 * a)      # the walls raise the plain Stokes radius
        # on the axis of a tube of radius 4.5 in Poiseuille flow of mean U: centre line 2 U
        tube_drag = 6 * math.pi * eta * a * 2 * u * float(channel_sphere.tube_factor_poiseuille(a / 4.5))
        write_drag(self.path("tube"), tube_drag, u, noise=0.0)
        self.assertAlmostEqual(self.drag_of(self.path("tube"), tube=4.5)["a_h"], a, places=9)
        # read with --centre-line, the same velocity column is taken as the centre line (half
        # the true one), so the same drag needs twice the a K'(a / R): a larger sphere
        larger = self.drag_of(self.path("tube"), tube=4.5, centre_line=True)["a_h"]
        kp = channel_sphere.tube_factor_poiseuille
        self.assertAlmostEqual(larger * float(kp(larger / 4.5)), 2 * a * float(kp(a / 4.5)), places=9)
        self.assertGreater(larger, 1.3 * a)

    def test_error_follows_the_drag_error(self):
        write_drag(self.path("noisy"), 20.0, 0.7, noise=3.0)
        r = self.drag_of(self.path("noisy"), slit=6.3)
        # d a_h / d a_eff = 1 / (K + lam K'(lam)) < 1: the error shrinks but stays positive
        self.assertGreater(r["a_h_err"], 0.5 * r["a_eff_err"])
        self.assertLess(r["a_h_err"], r["a_eff_err"])

    def test_beyond_the_factor_range_is_said(self):
        # a Stokes radius larger than any sphere that fits between the walls
        write_drag(self.path("big"), 6 * math.pi * 1.083 * 10.0 * 0.5, 0.5, noise=0.0)
        self.assertIsNone(self.drag_of(self.path("big"), slit=6.3)["a_h"])
        self.assertIn("beyond the wall factor's range", printed(["drag", "--slit", "6.3", self.path("big")]))

    def test_bad_options_are_refused(self):
        write_drag(self.path("a"), 20.0, 0.7)
        for argv, message in [
                (["--slit", "6.3", "--tube", "4.5"], "--slit or --tube, not both"),
                (["--slit", "0"], "--slit must be positive"),
                (["--tube", "-4.5"], "--tube must be positive"),
                (["--centre-line"], "--centre-line needs --tube"),
                (["--slit", "6.3", "--centre-line"], "--centre-line needs --tube")]:
            with self.assertRaises(SystemExit) as caught:
                channel_sphere.main(["drag", *argv, self.path("a")])
            self.assertIn(message, str(caught.exception.code))


class Correlation(unittest.TestCase):
    def test_correlation_and_stokes_at_known_points(self):
        self.assertAlmostEqual(float(channel_sphere.correlation_cd(1.0)), 24 * 1.15 + 0.407 / 8711, delta=1e-12)
        re10 = 24 / 10 * (1 + 0.150 * 10**0.681) + 0.407 / (1 + 871)
        self.assertAlmostEqual(float(channel_sphere.correlation_cd(10.0)), re10, delta=1e-12)
        self.assertAlmostEqual(float(channel_sphere.stokes_cd(4.0)), 6.0, delta=1e-12)

    def test_default_viscosity_is_the_kinetic_theory_of_standard_dpd(self):
        # --eta 1.083: s = 2, gamma = 4.5, kBT = 1, n = 4, m = 1, rc = 1
        eta = kinetic_theory.viscosity(kinetic_theory.FluidState(4.0, 1.0, 1.0, 1.0), 4.5, 2.0)
        self.assertAlmostEqual(eta, 1.083, delta=5e-4)


class DragScript(InTempDir):
    """The drag command run as a script on a file with a start-up transient and known noise."""

    def setUp(self):
        super().setUp()
        self.drag, self.u = 20.0, 0.5
        self.file = self.path("drag.test")
        write_drag_transient(self.file, self.drag, self.u, rows=1000, noise_random=50.0, noise_cd=2.0,
                             start_rows=100)

    def test_split_estimator(self):
        drag, u = self.drag, self.u
        r = run_script([self.file, "--discard", "0.1", "--batches", "20", "--eta", "1.0"])[0]
        # the transient rows are gone, the C + D estimate is near the drag within its small error
        self.assertAlmostEqual(r["U"], u, delta=1e-12)
        self.assertAlmostEqual(r["Re"], 4.0 * u * 3.0 / 1.0, delta=1e-12)
        self.assertAlmostEqual(r["F_D"], drag, delta=4 * 2.0 / math.sqrt(900))
        expected_cd = 8 * r["F_D"] / (math.pi * 9 * 4 * u * u)
        self.assertAlmostEqual(r["C_D"], expected_cd, delta=1e-12)
        self.assertAlmostEqual(r["a_eff"], r["F_D"] / (6 * math.pi * 1.0 * u), delta=1e-12)
        # C_D = 24/Re exactly when a_eff = d/2
        self.assertAlmostEqual(r["C_D"] / r["C_D_stokes"], r["a_eff"] / 1.5, delta=1e-12)
        # error of the mean of 900 rows with unit-variance noise 2: 2/30 (batch estimate, +-40 %)
        self.assertAlmostEqual(r["F_D_err"], 2.0 / 30.0, delta=0.4 * 2.0 / 30.0)
        self.assertEqual(r["estimator"], "C+D", "the split file should use the C+D estimator")

    def test_total_force_and_other_velocity_column(self):
        drag = self.drag
        # the total force carries the random part: same mean within its (25x larger) error
        t = run_script([self.file, "--discard", "0.1", "--batches", "20", "--force", "total"])[0]
        self.assertAlmostEqual(t["F_D"], drag, delta=4 * math.hypot(50.0, 2.0) / 30.0)
        self.assertAlmostEqual(t["F_D_err"], math.hypot(50.0, 2.0) / 30.0, delta=0.4 * 50.0 / 30.0)
        # another column as the reference velocity (here the temperature column, 1.0)
        v = run_script([self.file, "--discard", "0.1", "--batches", "20", "--velocity", "c_tfluid"])[0]
        self.assertAlmostEqual(v["U"], 1.0, delta=1e-12)
        p = subprocess.run([sys.executable, SCRIPT, "drag", self.file, "--velocity", "v_none"],
                           capture_output=True, text=True)
        self.assertTrue(p.returncode != 0 and "no v_none column" in p.stderr,
                        f"missing velocity column accepted: {p.stderr}")

    def test_discard_and_bad_files(self):
        # without --discard the transient biases the mean upwards
        b = run_script([self.file, "--discard", "0.0", "--batches", "20"])[0]
        self.assertGreater(b["F_D"], self.drag + 10, "the transient should bias the undiscarded mean")
        # a file that is not an ave/time file is refused with a message
        bad = self.path("bad")
        with open(bad, "w") as f:
            f.write("nothing here\n")
        p = subprocess.run([sys.executable, SCRIPT, "drag", bad], capture_output=True, text=True)
        self.assertTrue(p.returncode != 0 and "not a fix ave/time file" in p.stderr,
                        f"bad file accepted: {p.returncode} {p.stderr}")


class WallRadiusScript(InTempDir):
    def test_radius_reader_discard_and_each(self):
        # two blocks of three bins; the second block only after --discard 0.5
        chunk = self.path("wall_radius.test")
        with open(chunk, "w") as f:
            f.write("# Chunk-averaged data for fix radius and group inner_layer\n"
                    "# Timestep Number-of-chunks Total-count\n"
                    "# Chunk Coord1 Ncount v_wall_r\n")
            f.write("1000 4 30\n1 0.5 10 9.0\n2 1.5 10 9.0\n3 2.5 10 9.0\n4 3.5 0 0\n")
            f.write("2000 4 40\n1 0.5 10 6.0\n2 1.5 20 6.5\n3 2.5 10 7.0\n4 3.5 0 0\n")
        self.assertEqual(read_ave_chunk(chunk).data.shape, (2, 4, 4))
        p = subprocess.run([sys.executable, SCRIPT, "radius", chunk, "--discard", "0.5"],
                           capture_output=True, text=True, check=True)
        # count-weighted mean of the kept block: (60 + 130 + 70) / 40 = 6.5; min 6.0, max 7.0 (the
        # empty fourth bin has no radius, not 0)
        self.assertIn("mean wall radius 6.5000", p.stdout)
        self.assertIn("min over x 6.0000, max 7.0000", p.stdout)
        # --each: one profile per block, labelled by its step, without the never-filled bin
        p = subprocess.run([sys.executable, SCRIPT, "radius", chunk, "--discard", "0", "--each"],
                           capture_output=True, text=True, check=True)
        self.assertIn("block at step 1000: 9.00 9.00 9.00\n", p.stdout)
        self.assertIn("block at step 2000: 6.00 6.50 7.00\n", p.stdout)


if __name__ == "__main__":
    unittest.main()
