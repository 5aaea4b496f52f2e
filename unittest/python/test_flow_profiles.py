#!/usr/bin/python3
"""Check python/flow_profiles.py on synthetic fix ave/chunk files with known answers: a Couette
profile with slip, a Poiseuille parabola with slip, a given temperature and shear stress."""
import json
import os
import subprocess
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
PYTHON_DIR = os.path.join(HERE, '..', '..', 'python')
SCRIPT = os.path.join(PYTHON_DIR, 'flow_profiles.py')
MASS, KT, N, H = 0.01, 0.98, 4.0, 30.0


def write_profile(path, u_of_z, stress_of_z, blocks=4, seed=1):
    rng = np.random.default_rng(seed)
    z = -H / 2 + 0.125 + 0.25 * np.arange(120)
    with open(path, 'w') as f:
        f.write('# Chunk-averaged data for fix profile and group fluid\n')
        f.write('# Timestep Number-of-chunks Total-count\n')
        f.write('# Chunk Coord1 Ncount vx vy vz v_vx2 v_vy2 v_vz2 c_stress[5] density/number\n')
        for b in range(blocks):
            f.write(f'{2000 * (b + 1)} 120 6000\n')
            for i, zi in enumerate(z):
                u = u_of_z(zi) + 1e-3 * rng.standard_normal()
                var = KT / MASS
                f.write(f'{i + 1} {zi} 50 {u} 0 0 {u * u + var} {var} {var} '
                        f'{stress_of_z(zi) / N} {N}\n')


def run(args):
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, 'r.json')
        subprocess.run([sys.executable, SCRIPT] + args + ['--json', out, '--skip', '0'], check=True,
                       stdout=subprocess.DEVNULL)
        with open(out) as f:
            return json.load(f)


def close(name, got, want, tol):
    ok = abs(got - want) <= tol
    print(f'{"ok  " if ok else "FAIL"} {name}: {got:.6g} (expected {want:.6g} +- {tol:g})')
    return ok


def main():
    ok = True
    # kinetic theory, s = 1/2, m = 0.01: the package's check value 0.17409 m + 2.2283, and the
    # estimate the script prints is that one
    sys.path.insert(0, PYTHON_DIR)
    from etddpd import kinetic_theory
    eta_kt = kinetic_theory.viscosity(kinetic_theory.FluidState(4, 0.01, 1, 1), 4.5, 0.5)
    ok &= close('eta kinetic theory', eta_kt, 0.17409 * 0.01 + 2.2283, 1e-4)
    with tempfile.TemporaryDirectory() as tmp:
        # Couette: walls at +-7.5, slip length 0.4 on both sides, eta = 2.0
        U, slip, eta = 7.5, 0.4, 2.0
        rate = U / (H / 2 + slip)
        path = os.path.join(tmp, 'c')
        write_profile(path, lambda z: rate * z, lambda z: eta * rate)
        r = run(['couette', path, '--mass', str(MASS)])
        ok &= close('couette slip length', r['slip_length'], slip, 1e-3)
        ok &= close('couette shear rate', r['shear_rate_fit'], rate, 1e-4)
        ok &= close('couette eta from stress', r['eta_from_stress'], eta, 1e-3)
        ok &= close('couette kT', r['kT_fluid'], KT, 1e-9)
        ok &= close('couette eta kinetic theory', r['eta_kinetic_theory'], eta_kt, 1e-12)
        # Poiseuille: F = 0.1, eta = 1.95, zero of the parabola 0.3 beyond each wall
        F, eta, slip = 0.1, 1.95, 0.3
        B = N * F / (2 * eta)
        z0 = H / 2 + slip
        path = os.path.join(tmp, 'p')
        write_profile(path, lambda z: B * (z0 * z0 - z * z), lambda z: -N * F * z)
        r = run(['poiseuille', path, '--mass', str(MASS), '--force', str(F)])
        ok &= close('poiseuille eta from parabola', r['eta_from_parabola'], eta, 1e-3)
        ok &= close('poiseuille slip length', r['slip_length'], slip, 1e-2)
        ok &= close('poiseuille eta from stress', r['eta_from_stress'], eta, 1e-3)
        ok &= close('poiseuille stress slope', r['stress_slope'], -N * F, 1e-9)
    sys.exit(0 if ok else 1)


if __name__ == '__main__':
    main()
