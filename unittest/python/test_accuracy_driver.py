#!/usr/bin/python3
"""bench/accuracy's drivers refuse bad arguments before running anything: run.py's --pair only
for velocity-Verlet (and it replaces the stock style by dpd/gen there), run.py confirm's unknown
integrator, confirm.sh's unknown fluid or mass, viscosity_shear.sh's fluid and mass without a
cell (exit 2 and a message; no LAMMPS needed)."""
import argparse
import importlib.util
import os
import subprocess
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
BENCH = os.path.join(HERE, "..", "..", "bench", "accuracy")
spec = importlib.util.spec_from_file_location("accuracy_run", os.path.join(BENCH, "run.py"))
run = importlib.util.module_from_spec(spec)
spec.loader.exec_module(run)


class PairChoice(unittest.TestCase):
    def test_integrators_pair_by_default(self):
        self.assertEqual(run.pair_for(argparse.Namespace(integrator="stock", pair=None)), ("stock", "nve"))
        self.assertEqual(run.pair_for(argparse.Namespace(integrator="imp")), ("gen", "etd scheme implicit"))

    def test_gen_replaces_the_stock_style_for_velocity_verlet(self):
        self.assertEqual(run.pair_for(argparse.Namespace(integrator="stock", pair="gen")), ("gen", "nve"))

    def test_pair_refused_for_etd(self):
        with self.assertRaises(SystemExit) as caught:
            run.pair_for(argparse.Namespace(integrator="imp", pair="stock"))
        self.assertIn("--pair applies to velocity-Verlet", str(caught.exception.code))

    def test_parser_takes_pair_and_ref_pair(self):
        args = run.parse_args(["scan", "--fluid", "HS", "--mass", "0.01", "--integrator", "stock", "--dt",
                               "0.00003", "--pair", "gen"])
        self.assertEqual(args.pair, "gen")
        args = run.parse_args(["confirm", "--fluid", "HS", "--mass", "0.1", "--ref-dt", "0.00005",
                               "--ref-pair", "gen", "--cell", "imp:0.02"])
        self.assertEqual(args.ref_pair, "gen")


class BadArguments(unittest.TestCase):
    def test_confirm_unknown_integrator(self):
        with self.assertRaises(SystemExit) as caught:
            run.main(["confirm", "--fluid", "GW", "--mass", "0.01", "--ref-dt", "0.0001", "--cell", "euler:0.001"])
        self.assertIn("unknown integrator 'euler'", str(caught.exception.code))

    def test_confirm_needs_one_reference_source(self):
        for extra in ([], ["--ref-dt", "0.0001", "--no-ref"]):
            with self.assertRaises(SystemExit) as caught:
                run.main(["confirm", "--fluid", "HS", "--mass", "0.001", "--cell", "imp:0.002", *extra])
            self.assertIn("give --ref-dt, or --no-ref", str(caught.exception.code))

    def test_derive_ref_seeds_only_needs_seeds_from(self):
        with self.assertRaises(SystemExit) as caught:
            run.main(["derive-ref", "--fluid", "HS", "--mass", "0.01", "--static-from", "0.1",
                      "--d-from", "1", "0.1", "0.01", "--seeds-only"])
        self.assertIn("--seeds-only needs --seeds-from", str(caught.exception.code))

    def bench_script(self, script, *args):
        env = dict(os.environ, LMP="/nonexistent/lmp")
        return subprocess.run(["bash", os.path.join(BENCH, script), *args], capture_output=True,
                              text=True, env=env, timeout=60)

    def test_viscosity_shear_sh_unknown_cell(self):
        for args, said in ((["0.5"], "got GW 0.5"), (["0.003", "P"], "got P 0.003"), (["0.5", "HS"], "got HS 0.5"),
                           (["1", "XX"], "got XX 1")):
            done = self.bench_script("viscosity_shear.sh", *args)
            self.assertEqual(done.returncode, 2, args)
            self.assertIn(said, done.stderr)

    def test_confirm_sh_unknown_fluid(self):
        done = self.bench_script("confirm.sh", "XX")
        self.assertEqual(done.returncode, 2)
        self.assertIn("fluid must be GW, P or HS, got 'XX'", done.stderr)

    def test_confirm_sh_unknown_mass(self):
        done = self.bench_script("confirm.sh", "HS", "11", "0.003")
        self.assertEqual(done.returncode, 2)
        self.assertIn("no seed check for HS at m = '0.003'", done.stderr)


if __name__ == "__main__":
    unittest.main()
