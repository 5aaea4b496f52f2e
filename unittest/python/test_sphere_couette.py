#!/usr/bin/python3
"""Checks python/sphere_couette.py on synthetic drag, rdf and map files with known answers."""
import os
import re
import subprocess
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
PYTHON_DIR = os.path.join(HERE, '..', '..', 'python')


def write_files(d):
    rng = np.random.default_rng(3)
    # drag: steps 100..10000; before step 2000 a transient of 1000, afterwards means 50/130/0
    with open(os.path.join(d, "drag.sphere-couette"), "w") as f:
        f.write("# Time-averaged data\n# TimeStep v_Fx c_drag[1] ... c_drag[9]\n")
        for step in range(100, 10001, 100):
            c, dd, r = (1000.0, 0.0, 0.0) if step <= 2000 else (50.0, 130.0, 0.0)
            parts = [c + rng.normal(0, 1), 1.0, 0.0, dd + rng.normal(0, 1), -1.0, 0.0,
                     r + rng.normal(0, 1), 0.0, 0.0]
            fx = parts[0] + parts[3] + parts[6]
            f.write(" ".join(str(v) for v in [step, fx] + parts) + "\n")
    # rdf blocks every 1000 steps from 3000: sphere-solvent g > 0.05 from r = 0.95, solvent from 0.30
    r = 0.025 + 0.05 * np.arange(60)
    g_cs = np.where(r > 0.95, 1.0, 0.0)
    g_ss = np.where(r > 0.30, 1.0, 0.0)
    with open(os.path.join(d, "rdf.sphere-couette"), "w") as f:
        f.write("# rdf\n# TimeStep Number-of-rows\n# Row c_rdf[1] ...\n")
        for step in range(3000, 10001, 1000):
            f.write(f"{step} 60\n")
            for i in range(60):
                f.write(f"{i + 1} {r[i]} {g_cs[i]} 0 {g_ss[i]} 0\n")
    # maps: 0.5 cells on x in (-6, 6), z in (-6, 6); u_x = 2.5, kBT = 0.25 at m = 0.01
    xs = -5.75 + 0.5 * np.arange(24)
    with open(os.path.join(d, "map.sphere-couette"), "w") as f:
        f.write("# map\n# Timestep Number-of-chunks Total-count\n# Chunk Coord1 Coord2 Ncount ...\n")
        for step in range(3000, 10001, 1000):
            f.write(f"{step} {24 * 24} 1000\n")
            k = 0
            for x in xs:
                for z in xs:
                    k += 1
                    f.write(f"{k} {x} {z} 2.0 4.0 2.5 0 0 {2.5 ** 2 + 25} 25 25\n")


def main():
    with tempfile.TemporaryDirectory() as d:
        write_files(d)
        out = subprocess.run([sys.executable, os.path.join(PYTHON_DIR, "sphere_couette.py"), d,
                              "--png", os.path.join(d, "t")], capture_output=True, text=True)
        print(out.stdout, out.stderr)
        assert out.returncode == 0
        text = out.stdout
        assert "steps > 2000" in text, "steady window should start after the equilibration"
        def value(label):
            return float(re.search(re.escape(label) + r"\s+([-\d.]+)", text).group(1))
        assert abs(value("drag F_x") - 180.0) < 1.0
        assert abs(value("conservative F_C") - 50.0) < 0.5
        assert abs(value("dissipative F_D") - 130.0) < 0.5
        assert abs(value("q-bar sphere-solvent") - 0.95) < 1e-9
        assert abs(value("a_eff solvent (q-bar/2)") - 0.15) < 1e-9
        lo, hi = map(float, re.search(r"a_eff sphere \(eq 38\)\s+([\d.]+)-([\d.]+)", text).groups())
        assert abs(lo - 0.80) < 1e-9 and abs(hi - 0.85) < 1e-9
        assert abs(value("u_x upstream x=-5.75") - 2.5) < 1e-9
        assert abs(value("kBT mid-plane (r > 1.5)") - 0.25) < 1e-9
        assert os.path.exists(os.path.join(d, "t_maps.png"))
        # the drag coefficient of a mass scan (python/sphere_couette_cd.py): this table at m = 0.01
        # and at m = 0.1 with the drag doubled: Re = 2 a U 4 m / eta, C_d = F / (0.5 pi a^2 4 m U^2)
        for mass, factor in (("0.01", 1.0), ("0.1", 2.0)):
            os.makedirs(os.path.join(d, "scan", "mass_" + mass))
            with open(os.path.join(d, "scan", "mass_" + mass, "table.txt"), "w") as f:
                f.write(text.replace(re.search(r"drag F_x\s+([-\d.]+)", text).group(1),
                                     f"{factor * value('drag F_x'):.2f}", 1))
        out = subprocess.run([sys.executable, os.path.join(PYTHON_DIR, "sphere_couette_cd.py"),
                              os.path.join(d, "scan"), "--png", os.path.join(d, "cd.png")],
                             capture_output=True, text=True)
        print(out.stdout, out.stderr)
        assert out.returncode == 0
        rows = [line.split() for line in out.stdout.splitlines()[1:]]
        assert [r[0] for r in rows] == ["0.010", "0.100"]
        a, F = 0.825, value("drag F_x")
        for r, m, factor in zip(rows, (0.01, 0.1), (1.0, 2.0)):
            assert abs(float(r[1]) - 2 * a * 3.0 * 4 * m / 3.9682) < 1e-4
            assert abs(float(r[5]) - factor * F / (0.5 * 3.141592653589793 * a * a * 4 * m * 9.0)) < 0.1
        assert os.path.exists(os.path.join(d, "cd.png"))
    print("PASS")


if __name__ == "__main__":
    main()
