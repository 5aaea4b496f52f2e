#!/usr/bin/python3
"""Checks python/pipe_profile.py on a synthetic fix ave/chunk file with a known parabola:
u = n F (R0^2 - r^2) / (4 eta) with n = 4, F = 0.1, eta = 2, R0 = 5.2 (slip length 0.2 at R = 5
to first order: exactly (R0^2 - R^2) / (2 R) = 0.204), radial kBT 1 at m = 0.01."""
import os
import re
import subprocess
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
PYTHON_DIR = os.path.join(HERE, '..', '..', 'python')


def main():
    rng = np.random.default_rng(5)
    n, F, eta, R0, R = 4.0, 0.1, 2.0, 5.2, 5.0
    r = 0.125 + 0.25 * np.arange(20)
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "profile.pipe")
        with open(path, "w") as f:
            f.write("# Chunk-averaged data\n# Timestep Number-of-chunks Total-count\n# Chunk Coord1 Coord2 Ncount vx v_vx2 v_vr2 density/number\n")
            for block in range(8):
                f.write(f"{2000 * (block + 1)} 20 1900\n")
                for i, ri in enumerate(r):
                    u = n * F * (R0 ** 2 - ri ** 2) / (4 * eta) + rng.normal(0, 1e-3)
                    f.write(f"  {i + 1} {ri} 3 90 {u} {u * u + 100} 100 4.0\n")
        out = subprocess.run([sys.executable, os.path.join(PYTHON_DIR, "pipe_profile.py"), path],
                             capture_output=True, text=True)
        print(out.stdout, out.stderr)
        assert out.returncode == 0

        def value(label):
            return float(re.search(re.escape(label) + r"\s+([-\d.]+)", out.stdout).group(1))
        assert abs(value("viscosity n F / (4 B)") - eta) < 0.01
        assert abs(value("no-slip radius sqrt(A/B)") - R0) < 0.01
        assert abs(value("slip length at r = R") - (R0 ** 2 - R ** 2) / (2 * R)) < 0.01
        assert abs(value("radial kBT, r < 2") - 1.0) < 1e-9
        assert abs(value("density (fit range)") - 4.0) < 1e-9
    print("PASS")


if __name__ == "__main__":
    main()
