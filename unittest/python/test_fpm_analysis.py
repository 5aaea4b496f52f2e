#!/usr/bin/python3
"""Check the flow post-processing of python/fpm_analysis.py (periodic-array drag, Couette,
Poiseuille, two spheres) on synthetic files whose answers are known: each synthetic run is
built to match its theory exactly (ratio 1) or off by a known factor, with noise whose
standard error is known. Exits 1 on any mismatch."""
import math
import os
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
PYTHON_DIR = os.path.join(HERE, '..', '..', 'python')
sys.path.insert(0, PYTHON_DIR)
sys.path.insert(0, HERE)
from etddpd import fpm_analysis as fa  # noqa: E402
from scriptcheck import check, finish, write_ave_chunk  # noqa: E402

MU, R = fa.PAPER_MU, fa.PAPER_R


def write_blocks(path, columns):
    with open(path, 'w') as f:
        f.write('# Time-averaged data\n# TimeStep ...\n')
        for k, row in enumerate(zip(*columns)):
            f.write(f'{(k + 1) * 1000} ' + ' '.join(f'{v:.10g}' for v in row) + '\n')


def write_profile(path, z, cols):
    write_ave_chunk(path, ['Coord1', 'Ncount', '...'], [(zz, 30, *(c[i] for c in cols))
                                                         for i, zz in enumerate(z)],
                    step=100000, total=1000)


rng = np.random.default_rng(11)
tmp = tempfile.mkdtemp()
n = 400

# Hasimoto: the paper's volume fraction gives K = 1.0841 (leading term 2.837 R / L)
check('Hasimoto K at phi = 8.588e-5', fa.hasimoto_k(8.588e-5), 1.08409, 2e-5)
check('drag radius inverts 6 pi mu R K(phi(R))',
      fa.drag_radius(6 * math.pi * MU * R * fa.hasimoto_k(4 * math.pi * R ** 3 / 3 / 216), MU, 6.0), R, 1e-9)

# periodic drag: u chosen so that N g = 1.05 x 6 pi mu u R K, noise 0.01 per block
L, g, nf = 6.0, 0.0133, 647
K = fa.hasimoto_k(4 * math.pi * R ** 3 / (3 * L ** 3))
u = nf * g / (1.05 * 6 * math.pi * MU * R * K)
v = u * (nf + 1) / nf + 0.01 * rng.standard_normal(n)
write_blocks(os.path.join(tmp, 'd.drag'),
             [v, nf * g + rng.standard_normal(n), np.zeros(n), np.zeros(n), np.zeros(n), np.ones(n)])
r = fa.periodic_drag(os.path.join(tmp, 'd.drag'), L, g, nf)
check('periodic drag ratio', r['ratio'], 1.05, 4 * 1.05 * 0.01 / math.sqrt(n) / u)
# error of u: the larger of the batch error (noise 0.01 per block) and the momentum-relaxation
# model sqrt(kBT/M) sqrt(2 tau / t), tau = M u / F, t = 400 blocks of 10 time units
model = math.sqrt(1.0 / nf) * math.sqrt(2 * (nf * u / (nf * g)) / 4000.0) * nf / (nf + 1)
check('periodic drag error model', r['uerr_model'], model, 1e-2 * model)
expected = max(model, 0.01 * nf / (nf + 1) / math.sqrt(n))
check('periodic drag error estimate', r['ratio_err'], 1.05 * expected / u, 0.5 * 1.05 * expected / u)

# Couette: v_x = 2 z (+ small offset), torque = 0.97 x theory, free spin = 1.02 x half rate
z = np.arange(-3.875, 4.0, 0.25)
write_profile(os.path.join(tmp, 'c.profile'), z, [2.0 * z + 0.01, 3 * np.ones_like(z)])
t_the = 8 * math.pi * MU * R ** 3 * 1.0
write_blocks(os.path.join(tmp, 'c.colloid'),
             [np.zeros(n), 0.97 * t_the + 0.1 * rng.standard_normal(n), 1.02 + 0.05 * rng.standard_normal(n),
              np.ones(n), np.ones(n)])
r = fa.couette(os.path.join(tmp, 'c'), 8.0)
check('Couette shear rate', r['rate'], 2.0, 1e-9)
check('Couette torque ratio', r['T'] / r['T_the'], 0.97, 4 * 0.1 / math.sqrt(n) / t_the)
check('Couette free spin ratio', r['Omega'] / r['half'], 1.02, 4 * 0.05 / math.sqrt(n))
check('Couette without a split file: no split values', float('TD' in r), 0.0, 0.0)

# the same flow with the even colloids spun at Omega = 1.5 (not integrated: the same value in
# every block) and the split file: fixed colloids' dissipative torque 1.01 x theory, the spun
# ones' dissipative torque 1.01 T_the - 0.96 x 8 pi mu R^3 Omega: B = 0.96
unit = 8 * math.pi * MU * R ** 3
write_blocks(os.path.join(tmp, 's.colloid'),
             [np.zeros(n), 0.97 * t_the + 0.1 * rng.standard_normal(n), 1.5 * np.ones(n),
              np.ones(n), np.ones(n)])
write_profile(os.path.join(tmp, 's.profile'), z, [2.0 * z + 0.01, 3 * np.ones_like(z)])
td_fixed = 1.01 * t_the + 0.05 * rng.standard_normal(n)
td_spun = 1.01 * t_the - 0.96 * unit * 1.5 + 0.05 * rng.standard_normal(n)
write_blocks(os.path.join(tmp, 's.split'), [td_fixed, td_spun - 0.3, td_spun])
r = fa.couette(os.path.join(tmp, 's'), 8.0)
check('Couette split: fixed colloids\' dissipative torque ratio', r['TD'] / r['T_the'], 1.01,
      4 * 0.05 / math.sqrt(n) / t_the)
check('Couette split: spun colloids read as spun', float(r['spun']), 1.0, 0.0)
check('Couette split: rotational friction B', r['B'], 0.96, 4 * 0.07 / math.sqrt(n) / (unit * 1.5))
check('Couette split: spun colloids\' total torque column', r['T_even'] - r['TD_even'], -0.3, 1e-9)

# Poiseuille: far profile (rho g - F/V)/(2 mu)(16 - z^2) with mu = 3.7, drag = 1.1 x eq. 22,
# torque = 0.9 x eq. 22
g, H, h, mu_true = 0.2, 8.0, 2.0, 3.7
x = R / h
fk = (1 - x * x / 9) / (1 - 0.6526 * x + 0.3160 * x ** 3 - 0.242 * x ** 4)
tk = 8 / 3 * math.pi * MU * R ** 3 / h * (1 + 0.0758 * x + 0.049 * x * x)
# u_h depends on F through F/V and F on u_h: solve the pair by iteration
F = 20.0
for _ in range(50):
    c2 = (3 * g - F / (15 * 6 * H)) / (2 * mu_true)
    uh = c2 * (H * H / 4 - (h - H / 2) ** 2)
    F = 1.1 * 6 * math.pi * MU * R * fk * uh
write_profile(os.path.join(tmp, 'p.far'), z, [c2 * (H * H / 4 - z * z)])
write_blocks(os.path.join(tmp, 'p.colloid'),
             [F + 0.2 * rng.standard_normal(n), 0.9 * tk * uh + 0.05 * rng.standard_normal(n),
              np.zeros(n), np.ones(n), np.ones(n)])
r = fa.poiseuille(os.path.join(tmp, 'p'), g, H, h)
check('Poiseuille u_h', r['uh'], uh, 1e-9)
check('Poiseuille viscosity of the far parabola', r['mu_fit'], mu_true, 0.02)
check('Poiseuille drag ratio', r['F'] / r['F_the'], 1.1, 4 * 0.2 / math.sqrt(n) / (F / 1.1))
check('Poiseuille torque ratio', r['T'] / r['T_the'], 0.9, 4 * 0.05 / math.sqrt(n) / (tk * uh))

# two spheres: u set so that N g / 2 = 6 pi mu R f u / (1 - 2 x 2.837 R f / L); torques +-0.8 x eq. 23
L, g, nf, l = 8.0, 0.01442, 1534, 1.0
x = R / l
f = 1 - 3 * x / 4 + 9 * x ** 2 / 16 - 59 * x ** 3 / 64 + 465 * x ** 4 / 256 - 15813 * x ** 5 / 7168
corr = 1 - 2 * fa.HASIMOTO * R * f / L
u = nf * g / 2 * corr / (6 * math.pi * MU * R * f)
ueff = nf * g / 2 / (6 * math.pi * MU * R * f)
tf = 3 * x / (4 * l) - 9 * x ** 2 / (16 * l) + 27 * x ** 3 / (64 * l) - 273 * x ** 4 / (256 * l) + 1683 * x ** 5 / (1024 * l)
tthe = 8 * math.pi * MU * R ** 3 * ueff * tf
write_blocks(os.path.join(tmp, 'pair.drag'),
             [u * (nf + 2) / nf * np.ones(n), nf * g / 2 * np.ones(n), np.zeros(n), np.zeros(n), np.zeros(n),
              np.ones(n), 0.8 * tthe * np.ones(n), -0.8 * tthe * np.ones(n)])
r = fa.two_spheres(os.path.join(tmp, 'pair.drag'), L, g, nf, l)
check('two-sphere drag ratio', r['ratio'], 1.0, 1e-9)
check('two-sphere torque ratio', r['T'] / r['T_the'], 0.8, 1e-9)
check('two-sphere file without the torque split', 'TD' in r, False, 0)
# with the split columns: the dissipative torques (+-0.9 x eq. 23) are read from columns 10 and 11
write_blocks(os.path.join(tmp, 'pair_split.drag'),
             [u * (nf + 2) / nf * np.ones(n), nf * g / 2 * np.ones(n), np.zeros(n), np.zeros(n), np.zeros(n),
              np.ones(n), 0.8 * tthe * np.ones(n), -0.8 * tthe * np.ones(n), 0.9 * tthe * np.ones(n),
              -0.9 * tthe * np.ones(n)])
r = fa.two_spheres(os.path.join(tmp, 'pair_split.drag'), L, g, nf, l)
check('two-sphere dissipative torque ratio', r['TD'] / r['T_the'], 0.9, 1e-9)
check('two-sphere total torque ratio with the split columns', r['T'] / r['T_the'], 0.8, 1e-9)
# rotating sphere: the z torque (column 3) and its dissipative part (column 4) when present
write_blocks(os.path.join(tmp, 'spin.torque'), [np.zeros(n), np.zeros(n), -1.0 * np.ones(n)])
check('rotating-sphere file without the split', fa.dissipative_torque(os.path.join(tmp, 'spin.torque')) is None, True, 0)
write_blocks(os.path.join(tmp, 'spin_split.torque'),
             [np.zeros(n), np.zeros(n), -1.0 + 0.3 * rng.standard_normal(n), -1.0 + 0.1 * rng.standard_normal(n),
              0.3 * rng.standard_normal(n)])
td, tderr = fa.dissipative_torque(os.path.join(tmp, 'spin_split.torque'))
check('rotating-sphere dissipative torque', td, -1.0, 4 * 0.1 / math.sqrt(n))
check('its error', tderr, 0.1 / math.sqrt(n), 0.3 * 0.1 / math.sqrt(n))
check("eq. 23 torque at the paper's l = 1, u = 0.3349", 8 * math.pi * MU * R ** 3 * 0.3349 * tf, 0.106, 0.001)

finish()
