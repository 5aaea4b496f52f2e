#!/usr/bin/python3
"""Check python/channel_sphere.py on synthetic drag files with known answers: the mean drag and
velocity, Re and C_D from them, the conservative + dissipative estimator against the total, the
batch error against the known noise, the discarded start, and the drag correlation's values."""
import json
import math
import os
import subprocess
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
PYTHON_DIR = os.path.join(HERE, '..', '..', 'python')
SCRIPT = os.path.join(PYTHON_DIR, 'channel_sphere.py')
sys.path.insert(0, PYTHON_DIR)
from etddpd import channel_sphere  # noqa: E402

HEADER = ('# Time-averaged data for fix drag\n'
          '# TimeStep c_fsphere[1] c_fsphere[2] c_fsphere[3] c_vfluid c_tfluid '
          'c_split[1] c_split[4] c_split[7] v_inside\n')


def write_drag(path, drag, u, rows, noise_random, noise_cd, seed=3, start_rows=0):
    """Rows of block means: C + D = drag + noise_cd, R = noise_random (mean zero), total = sum;
    the first start_rows rows carry a transient (drag 10x) that --discard must drop."""
    rng = np.random.default_rng(seed)
    with open(path, 'w') as f:
        f.write(HEADER)
        for k in range(rows):
            scale = 10.0 if k < start_rows else 1.0
            cons = 0.3 * drag * scale + noise_cd * rng.standard_normal()
            diss = 0.7 * drag * scale
            rand = noise_random * rng.standard_normal()
            f.write(f'{100 * (k + 1)} {cons + diss + rand} 0.1 -0.1 {u} 1.0 {cons} {diss} {rand} 14\n')


def run(args):
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, 'r.json')
        subprocess.run([sys.executable, SCRIPT, 'drag'] + args + ['--json', out], check=True,
                       stdout=subprocess.DEVNULL)
        with open(out) as f:
            return json.load(f)


def close(a, b, tol, what):
    if abs(a - b) > tol:
        sys.exit(f'FAIL {what}: {a} vs {b} (tolerance {tol})')


def main():
    # correlation and Stokes law at known points
    close(float(channel_sphere.correlation_cd(1.0)), 24 * 1.15 + 0.407 / 8711, 1e-12,
          'correlation at Re = 1')
    re10 = 24 / 10 * (1 + 0.150 * 10**0.681) + 0.407 / (1 + 871)
    close(float(channel_sphere.correlation_cd(10.0)), re10, 1e-12, 'correlation at Re = 10')
    close(float(channel_sphere.stokes_cd(4.0)), 6.0, 1e-12, 'Stokes at Re = 4')

    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, 'drag.test')
        drag, u = 20.0, 0.5
        write_drag(path, drag, u, rows=1000, noise_random=50.0, noise_cd=2.0, start_rows=100)
        r = run([path, '--discard', '0.1', '--batches', '20', '--eta', '1.0'])[0]
        # the transient rows are gone, the C + D estimate is near the drag within its small error
        close(r['U'], u, 1e-12, 'velocity')
        close(r['Re'], 4.0 * u * 3.0 / 1.0, 1e-12, 'Re')
        close(r['F_D'], drag, 4 * 2.0 / math.sqrt(900), 'C+D drag')
        expected_cd = 8 * r['F_D'] / (math.pi * 9 * 4 * u * u)
        close(r['C_D'], expected_cd, 1e-12, 'C_D from the drag')
        close(r['a_eff'], r['F_D'] / (6 * math.pi * 1.0 * u), 1e-12, 'Stokes radius')
        # C_D = 24/Re exactly when a_eff = d/2
        close(r['C_D'] / r['C_D_stokes'], r['a_eff'] / 1.5, 1e-12, 'C_D/(24/Re) = a_eff/(d/2)')
        # error of the mean of 900 rows with unit-variance noise 2: 2/30 (batch estimate, +-40 %)
        close(r['F_D_err'], 2.0 / 30.0, 0.4 * 2.0 / 30.0, 'C+D error')
        if r['estimator'] != 'C+D':
            sys.exit('FAIL: the split file should use the C+D estimator')
        # the total force carries the random part: same mean within its (25x larger) error
        t = run([path, '--discard', '0.1', '--batches', '20', '--force', 'total'])[0]
        close(t['F_D'], drag, 4 * math.hypot(50.0, 2.0) / 30.0, 'total drag')
        close(t['F_D_err'], math.hypot(50.0, 2.0) / 30.0, 0.4 * 50.0 / 30.0, 'total error')
        # another column as the reference velocity (here the temperature column, 1.0)
        v = run([path, '--discard', '0.1', '--batches', '20', '--velocity', 'c_tfluid'])[0]
        close(v['U'], 1.0, 1e-12, '--velocity column')
        p = subprocess.run([sys.executable, SCRIPT, 'drag', path, '--velocity', 'v_none'],
                           capture_output=True, text=True)
        if p.returncode == 0 or 'no v_none column' not in p.stderr:
            sys.exit(f'FAIL: missing velocity column accepted: {p.stderr}')
        # without --discard the transient biases the mean upwards
        b = run([path, '--discard', '0.0', '--batches', '20'])[0]
        if not b['F_D'] > drag + 10:
            sys.exit(f'FAIL: the transient should bias the undiscarded mean: {b["F_D"]}')
        # a file that is not an ave/time file is refused with a message
        bad = os.path.join(tmp, 'bad')
        with open(bad, 'w') as f:
            f.write('nothing here\n')
        p = subprocess.run([sys.executable, SCRIPT, 'drag', bad], capture_output=True, text=True)
        if p.returncode == 0 or 'not a fix ave/time file' not in p.stderr:
            sys.exit(f'FAIL: bad file accepted: {p.returncode} {p.stderr}')
        # the radius reader: two blocks of three bins; the second block only after --discard 0.5
        chunk = os.path.join(tmp, 'wall_radius.test')
        with open(chunk, 'w') as f:
            f.write('# Chunk-averaged data for fix radius and group inner_layer\n'
                    '# Timestep Number-of-chunks Total-count\n'
                    '# Chunk Coord1 Ncount v_wall_r\n')
            f.write('1000 4 30\n1 0.5 10 9.0\n2 1.5 10 9.0\n3 2.5 10 9.0\n4 3.5 0 0\n')
            f.write('2000 4 40\n1 0.5 10 6.0\n2 1.5 20 6.5\n3 2.5 10 7.0\n4 3.5 0 0\n')
        names, blocks = channel_sphere.read_ave_chunk(chunk)
        if blocks.shape != (2, 4, 4):
            sys.exit(f'FAIL radius reader: shape {blocks.shape}')
        p = subprocess.run([sys.executable, SCRIPT, 'radius', chunk, '--discard', '0.5'],
                           capture_output=True, text=True, check=True)
        # count-weighted mean of the kept block: (60 + 130 + 70) / 40 = 6.5; min 6.0, max 7.0 (the
        # empty fourth bin has no radius, not 0)
        if 'mean wall radius 6.5000' not in p.stdout or 'min over x 6.0000, max 7.0000' not in p.stdout:
            sys.exit(f'FAIL radius: {p.stdout}')
        # --each: one profile per block, labelled by its step, without the never-filled bin
        p = subprocess.run([sys.executable, SCRIPT, 'radius', chunk, '--discard', '0', '--each'],
                           capture_output=True, text=True, check=True)
        if ('block at step 1000: 9.00 9.00 9.00\n' not in p.stdout
                or 'block at step 2000: 6.00 6.50 7.00\n' not in p.stdout):
            sys.exit(f'FAIL radius --each: {p.stdout}')
    print('channel_sphere script: all checks passed')


if __name__ == '__main__':
    main()
