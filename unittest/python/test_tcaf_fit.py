#!/usr/bin/python3
"""Tests of python/tcaf_fit.py on synthetic fix ave/correlate files with known eta and tau."""
import math
import os
import sys
import tempfile
import unittest

import numpy as np
from scipy.integrate import solve_ivp

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from etddpd import tcaf_fit  # noqa: E402

BOX, RHO, DT, NEVERY, NLAG, K = 15.0, 4.0, 0.001, 5, 513, 6


def wave(j):
    return 2.0 * math.pi * j / BOX


def write_correlate(path, curves, nblock=1, noise=0.0, seed=1, truncate_last=False):
    """A fix ave/correlate file whose values give C_j(t) = curves[j-1](t) after the average
    over axes, transverse components and Re/Im (the axes get unequal shares)."""
    rng = np.random.default_rng(seed)
    lags = np.arange(NLAG) * NEVERY
    t = lags * DT
    shares = [0.5, 1.0, 1.5]    # per axis; they average to 1
    with open(path, "w") as out:
        out.write("# Time-correlated data for fix tcaf\n# Timestep Number-of-time-windows\n")
        out.write("# Index TimeDelta Ncount " +
                  " ".join(f"c_J[{i}]*c_J[{i}]" for i in range(1, 12 * K + 1)) + "\n")
        for b in range(nblock):
            values = np.zeros((NLAG, 12 * K))
            for j in range(1, K + 1):
                c = 7.0 * j * j * curves[j - 1](t)    # arbitrary C(0)
                for axis in range(3):
                    for tr in range(2):
                        base = 4 * (K * axis + j - 1) + 2 * tr
                        part = shares[axis] * c + noise * 7.0 * j * j * rng.standard_normal(NLAG)
                        values[:, base] = 0.3 * part
                        values[:, base + 1] = 0.7 * part
            nrows = NLAG if not (truncate_last and b == nblock - 1) else NLAG // 2
            out.write(f"{(b + 1) * 5130} {NLAG}\n")
            for i in range(nrows):
                out.write(f"{i + 1} {lags[i]} {1026 - i} " +
                          " ".join(f"{v:.10g}" for v in values[i]) + "\n")


def run_tool(files, out, extra=()):
    """The extrapolations of the tool run with these files and options."""
    argv = list(files) + ["--box", str(BOX), "--rho", str(RHO), "--dt", str(DT), "--out", out,
                          "--nfit", "4"] + list(extra)
    return tcaf_fit.run(tcaf_fit.parse_args(argv))


def read_table(prefix):
    with open(prefix + ".dat") as handle:
        lines = handle.readlines()
    names = lines[2][1:].split()
    rows = np.loadtxt(lines[3:], ndmin=2)
    return {name: rows[:, i] for i, name in enumerate(names)}


class MaxwellModel(unittest.TestCase):
    def test_matches_the_memory_equation_on_both_branches(self):
        # dC/dt = -(eta k^2 / (rho tau)) int_0^t exp(-(t-s)/tau) C(s) ds, C(0) = 1, as the ODE
        # pair C' = -M, M' = (eta k^2/(rho tau)) C - M/tau
        for eta, tau, k in ((30.0, 0.05, wave(1)), (30.0, 0.05, wave(3)), (10.0, 0.3, wave(2)),
                            (30.0, 1.0 / (4 * 30.0 * wave(2) ** 2 / RHO), wave(2))):
            g = eta * k * k / (RHO * tau)
            t = np.linspace(0.0, 2.0, 400)
            sol = solve_ivp(lambda _, y: [-y[1], g * y[0] - y[1] / tau], (0, 2.0), [1.0, 0.0],
                            t_eval=t, rtol=1e-10, atol=1e-12)
            model = tcaf_fit.maxwell(t, eta, tau, k * k / RHO)
            self.assertLess(np.max(np.abs(model - sol.y[0])), 1e-6, (eta, tau, k))

    def test_limits_of_the_moduli(self):
        self.assertAlmostEqual(tcaf_fit.storage_modulus(1e9, 30.0, 0.02), 30.0 / 0.02, places=3)
        self.assertAlmostEqual(tcaf_fit.storage_modulus(1e-9, 30.0, 0.02), 0.0, places=12)
        self.assertAlmostEqual(tcaf_fit.dynamic_viscosity(1e-9, 30.0, 0.02), 30.0, places=9)
        self.assertAlmostEqual(tcaf_fit.dynamic_viscosity(1e9, 30.0, 0.02), 0.0, places=9)


class Fits(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.dir.cleanup()

    def path(self, name):
        return os.path.join(self.dir.name, name)

    def test_newtonian_recovers_eta_and_the_k2_law(self):
        eta_k = [30.0 - 2.0 * wave(j) ** 2 for j in range(1, K + 1)]
        curves = [lambda t, e=e, j=j: np.exp(-e * wave(j) ** 2 * t / RHO)
                  for j, e in enumerate(eta_k, start=1)]
        write_correlate(self.path("a.dat"), curves, nblock=2)
        fits = run_tool([self.path("a.dat")], self.path("fit"), ["--no-plots"])
        table = read_table(self.path("fit"))
        np.testing.assert_allclose(table["eta_newton"], eta_k, rtol=1e-6)
        np.testing.assert_allclose(table["k"], [wave(j) for j in range(1, K + 1)], rtol=1e-6)
        eta0, a = fits["newton"][:2]
        self.assertAlmostEqual(eta0, 30.0, places=4)
        self.assertAlmostEqual(a, -2.0, places=4)
        # a Maxwell fit of Newtonian data: tau -> 0, eta -> eta_k
        np.testing.assert_allclose(table["eta_maxwell"], eta_k, rtol=2e-3)
        self.assertTrue(np.all(table["tau_maxwell"] < 1e-3))

    def test_maxwell_recovers_eta_and_tau_on_both_branches(self):
        eta, tau = 30.0, 0.05
        curves = [lambda t, j=j: tcaf_fit.maxwell(t, eta, tau, wave(j) ** 2 / RHO)
                  for j in range(1, K + 1)]
        write_correlate(self.path("m.dat"), curves, nblock=1)
        fits = run_tool([self.path("m.dat")], self.path("fit"), ["--no-plots"])
        table = read_table(self.path("fit"))
        # j = 1, 2: W real (overdamped); j >= 3: W imaginary (oscillating)
        self.assertGreater(table["omega2"][0], 0.0)
        self.assertLess(table["omega2"][-1], 0.0)
        np.testing.assert_allclose(table["eta_maxwell"], eta, rtol=1e-4)
        np.testing.assert_allclose(table["tau_maxwell"], tau, rtol=1e-4)
        self.assertAlmostEqual(fits["maxwell"][0], eta, places=3)
        # the Newtonian fit of viscoelastic data is biased low (decays slower at first)
        self.assertTrue(np.all(table["eta_newton"] < eta))
        # moduli table: eta' -> eta_k at small omega, G' -> eta_k / tau_k at large omega
        moduli = np.loadtxt(self.path("fit_moduli.dat"))
        self.assertAlmostEqual(moduli[0, 2] / eta, 1.0, places=3)
        self.assertAlmostEqual(moduli[-1, 1] / (eta / tau), 1.0, places=3)

    def test_noisy_blocks_give_honest_error_bars(self):
        eta_k = [29.0 + 0.5 * wave(j) ** 2 for j in range(1, K + 1)]
        curves = [lambda t, e=e, j=j: np.exp(-e * wave(j) ** 2 * t / RHO)
                  for j, e in enumerate(eta_k, start=1)]
        write_correlate(self.path("n1.dat"), curves, nblock=6, noise=0.01, seed=5)
        write_correlate(self.path("n2.dat"), curves, nblock=6, noise=0.01, seed=6)
        fits = run_tool([self.path("n1.dat"), self.path("n2.dat")], self.path("fit"),
                        ["--natoms", "7"])
        eta0, _, err0, _ = fits["newton"]
        self.assertGreater(err0, 0.0)
        self.assertLess(err0, 1.0)
        self.assertLess(abs(eta0 - 29.0), 4.0 * err0)
        table = read_table(self.path("fit"))
        z = (table["eta_newton"] - eta_k) / table["err_newton"]
        self.assertLess(np.max(np.abs(z)), 4.0)
        # C(k,0) / N with N = 7 is the "kBT/m" of the synthetic data: 7 j^2 / 7
        np.testing.assert_allclose(table["kT_over_m"], [j * j for j in range(1, K + 1)], rtol=0.05)
        for suffix in ("_tcaf.png", "_eta.png", "_moduli.png", "_summary.txt"):
            self.assertTrue(os.path.getsize(self.path("fit" + suffix)) > 0, suffix)

    def test_incomplete_block_is_dropped_and_bad_files_are_refused(self):
        curves = [lambda t, j=j: np.exp(-wave(j) ** 2 * t) for j in range(1, K + 1)]
        write_correlate(self.path("c.dat"), curves, nblock=3, truncate_last=True)
        lags, corr = tcaf_fit.load([self.path("c.dat")])
        self.assertEqual(corr.shape, (2, K, NLAG))
        with open(self.path("bad.dat"), "w") as out:
            out.write("# x\n# y\n# z\n100 2\n1 0 10 1 2 3\n2 5 9 1 2 3\n")
        with self.assertRaises(ValueError):
            tcaf_fit.load([self.path("bad.dat")])


if __name__ == "__main__":
    unittest.main()
