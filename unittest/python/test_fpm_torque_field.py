#!/usr/bin/python3
"""Check python/etddpd/fpm_torque_field.py: the pair law's torque against hand-worked cases,
the Stokes disturbance against its defining properties (no slip on the sphere, spin = half the
curl, no divergence), the linear-flow and any-direction disturbances (no slip), the method of
reflections against eq. (23)'s series, the sum over a synthetic field file against the sum over its atoms, and
the sampling ratio's limits (1 far from the neighbour, 0 torque for a lone colloid). Exits 1 on
any mismatch."""
import os
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, '..', '..', 'python'))
sys.path.insert(0, HERE)
from etddpd import fpm_torque_field as ft  # noqa: E402
from scriptcheck import check, finish, write_ave_chunk  # noqa: E402


gamma, d, U, W = ft.GAMMA_S, 0.6, 0.7, 1.3
w = (1 - d) ** ft.EXPONENT
# fluid above the colloid streaming along +x drags its top forward: torque -z, d gamma w U / 2
t = ft.shear_torque([[0, d, 0]], [[U, 0, 0]], [[0, 0, 0]])[0]
check('streaming atom above: torque z', t[2], -d * gamma * w * U / 2, 1e-12)
check('streaming atom above: torque x', t[0], 0.0, 1e-12)
# an atom co-rotating at W about z (velocity W z x x, spin W): gamma w W d^2 / 4 along +z
t = ft.shear_torque([[d, 0, 0]], [[0, W * d, 0]], [[0, 0, W]])[0]
check('co-rotating atom: torque z', t[2], gamma * w * W * d * d / 4, 1e-12)
# central motion makes no torque; nothing beyond the cutoff
t = ft.shear_torque([[0, d, 0]], [[0, U, 0]], [[0, 0, 0]])[0]
check('atom moving along the line of centres: no torque', float(np.abs(t).max()), 0.0, 1e-12)
t = ft.shear_torque([[0, 1.01, 0]], [[U, 0, 0]], [[0, 0, 0]])[0]
check('atom beyond the cutoff: no torque', float(np.abs(t).max()), 0.0, 0.0)

# Stokes flow past a sphere at rest: u + U = 0 on its surface, spin = curl / 2, div u = 0
R = ft.PAPER_R
rng = np.random.default_rng(5)
n = rng.normal(size=(20, 3))
n /= np.linalg.norm(n, axis=1)[:, None]
u, _ = ft.stokes_disturbance(R * n, U, R)
check('Stokes: no slip on the sphere', float(np.abs(u + [U, 0, 0]).max()), 0.0, 1e-12)
x = rng.uniform(-1.5, 1.5, size=(20, 3))
x = x[np.linalg.norm(x, axis=1) > 2 * R]
h = 1e-5
grad = np.empty((len(x), 3, 3))    # grad[:, i, k] = d u_k / d x_i
for i in range(3):
    step = np.zeros(3)
    step[i] = h
    grad[:, i, :] = (ft.stokes_disturbance(x + step, U, R)[0]
                     - ft.stokes_disturbance(x - step, U, R)[0]) / (2 * h)
curl = np.stack([grad[:, 1, 2] - grad[:, 2, 1], grad[:, 2, 0] - grad[:, 0, 2],
                 grad[:, 0, 1] - grad[:, 1, 0]], axis=1)
_, spin = ft.stokes_disturbance(x, U, R)
check('Stokes: spin is half the curl', float(np.abs(spin - curl / 2).max()), 0.0, 1e-6)
check('Stokes: no divergence', float(np.abs(np.trace(grad, axis1=1, axis2=2)).max()), 0.0, 1e-6)

# a synthetic field file: the bins' sum equals the sum over atoms placed at the bins' centres
with tempfile.TemporaryDirectory() as tmp:
    path = os.path.join(tmp, 'f.field')
    spacing, centre = 0.1, np.array([4.0, 3.5, 4.0])
    g = np.arange(-1 + spacing / 2, 1, spacing)
    xyz = np.stack(np.meshgrid(g, g, g, indexing='ij'), axis=-1).reshape(-1, 3)
    density = 3.0 * (1 + 0.5 * np.sin(3 * xyz[:, 1])) * (np.linalg.norm(xyz, axis=1) > 0.3)
    velocity = np.stack([0.6 + 0.4 * xyz[:, 1], 0.1 * xyz[:, 0], 0 * xyz[:, 0]], axis=1)
    spin = np.stack([0 * xyz[:, 0], 0 * xyz[:, 0], -0.2 + 0.1 * xyz[:, 0]], axis=1)
    write_ave_chunk(path, ['Coord1', 'Coord2', 'Coord3', 'Ncount', 'density/number', 'vx', 'vy',
                           'vz', 'c_spin[1]', 'c_spin[2]', 'c_spin[3]'],
                    [(*p, n_ * spacing ** 3, n_, *v, *s_)
                     for p, n_, v, s_ in zip(xyz + centre, density, velocity, spin)])
    field = ft.Field(path)
    direct = float(np.sum(ft.shear_torque(xyz, velocity, spin)[:, 2] * density * spacing ** 3))
    check('field sum equals the sum over atoms at the bins', field.torque(), direct, 1e-9 * max(1, abs(direct)))
    check('field: bin spacing read', field.spacing, spacing, 1e-9)
    # density even in y about the colloid and a stream along x: no z torque
    sym = ft.Field(path)
    sym.count = 3.0 * np.ones_like(sym.count) * spacing ** 3
    sym.velocity = np.tile([0.6, 0, 0], (len(xyz), 1))
    sym.spin = np.zeros_like(sym.spin)
    check('uniform stream, uniform density: no torque', sym.torque(), 0.0, 1e-9)
    lone = ft.radial_density(sym)
    check('radial profile of a uniform field', float(lone(np.array(0.7))), 3.0, 1e-9)

# far from the neighbour the sampled Stokes field is its point value; a uniform fluid
flat = lambda r: np.full(np.shape(r), ft.BULK_DENSITY)  # noqa: E731
far = ft.stokes_sampling(8.0, flat, spacing=0.1)
check('Stokes sampling at l = 8: ratio to the point value', far['ratio'], 1.0, 0.03)
check('Stokes sampling: point spin is Faxen\'s 3 R U / (4 l^2)', far['faxen_spin'],
      0.75 * R / 64.0, 1e-12)
check('Stokes sampling, uniform density: the stream makes no torque', far['parts']['stream'], 0.0, 1e-9)

# a ring file written from Stokes flow itself (stream 0.6): the disturbance read back from it is
# Stokes flow's, inside the rings (bilinear interpolation) and beyond them (the stand-in)
with tempfile.TemporaryDirectory() as tmp:
    path = os.path.join(tmp, 'a.axial')
    stream, width, cx = 0.6, 0.05, 4.0
    radii = np.arange(width / 2, 3.0, width)
    axials = np.arange(-3.0 + width / 2, 3.0, width)
    rows = []
    for r_ in radii:    # LAMMPS's order does not matter to the reader
        for a_ in axials:
            u_, w_ = ft.stokes_disturbance(np.array([[a_, r_, 0.0]]), stream, R)
            rows.append((r_, a_ + cx, 1, 3, stream + u_[0, 0], u_[0, 1], w_[0, 2]))
    write_ave_chunk(path, ['Coord1', 'Coord2', 'Ncount', 'density/number', 'vx', 'v_avr', 'v_awphi'],
                    rows)
    axial = ft.AxialField(path, stream)
    points = np.array([[0.4, 0.5, -0.3], [-1.2, 0.1, 0.7], [0.0, -1.5, 0.0], [2.0, 0.0, 0.9]])
    got_u, got_w = axial.disturbance(points)
    want_u, want_w = ft.stokes_disturbance(points, 1.0, R)
    check('ring file: disturbance inside the rings', float(np.abs(got_u - want_u).max()), 0.0, 2e-3)
    check('ring file: spin inside the rings', float(np.abs(got_w - want_w).max()), 0.0, 2e-3)
    far_point = np.array([[4.0, 0.5, 0.5]])
    check('ring file: Stokes beyond the rings',
          float(np.abs(axial.disturbance(far_point)[0] - ft.stokes_disturbance(far_point, 1.0, R)[0]).max()),
          0.0, 1e-12)
    # (no fluid within 0.4 of either centre, where the stand-in's step at r = R would be smoothed)
    hollow = lambda r: np.where(np.asarray(r) > 0.4, ft.BULK_DENSITY, 0.0)  # noqa: E731
    same = ft.stokes_sampling(1.0, hollow, spacing=0.1, measured=axial)['ratio']
    check('sampling with the ring file of Stokes flow equals the Stokes sampling', same,
          ft.stokes_sampling(1.0, hollow, spacing=0.1)['ratio'], 0.005)

# A sphere at rest in a uniform stream of any direction, and held still in a linear flow
# (rotation and straining): no slip on its surface (incident + disturbance = 0 there)
V = np.array([0.3, -0.5, 0.8])
check('uniform stream along V: no slip',
      float(np.abs(V + ft.uniform_flow_disturbance(R * n, V, R)).max()), 0.0, 1e-12)
along_x = ft.uniform_flow_disturbance(R * 1.7 * n, np.array([U, 0.0, 0.0]), R)
check('uniform stream along x: Stokes disturbance',
      float(np.abs(along_x - ft.stokes_disturbance(R * 1.7 * n, U, R)[0]).max()), 0.0, 1e-12)
rotation = np.array([0.2, -0.4, 0.7])
strain = np.array([[0.3, 0.1, -0.2], [0.1, -0.5, 0.4], [-0.2, 0.4, 0.2]])    # symmetric, traceless
surface = R * n
incident = np.cross(rotation, surface) + surface @ strain.T
check('linear flow: no slip', float(np.abs(incident + ft.linear_flow_disturbance(surface, rotation, strain, R)).max()),
      0.0, 1e-12)
far = R * 40.0 * n
check('linear flow: disturbance decays (r^-2 at 40 R)',
      float(np.abs(ft.linear_flow_disturbance(far, rotation, strain, R)).max()), 0.0, 2e-3 * R)
# the numerical spin and gradient against the analytic ones of the Stokes disturbance
probe = np.array([[0.5, 0.3, -0.2], [-0.4, 0.6, 0.1]])
check('spin_of: half the curl', float(np.abs(ft.spin_of(lambda y: ft.stokes_disturbance(y, U, R)[0], probe)
                                             - ft.stokes_disturbance(probe, U, R)[1]).max()), 0.0, 1e-8)
G = ft.velocity_gradient(lambda y: y @ strain.T + np.cross(rotation, y), np.zeros(3))
check('velocity_gradient of a linear flow', float(np.abs(G - (strain + np.array(
    [[0, -rotation[2], rotation[1]], [rotation[2], 0, -rotation[0]], [-rotation[1], rotation[0], 0]]))).max()),
      0.0, 1e-9)
# Reflections: the continuum drag and torque factors of the pair converge to eq. (23)'s series
# (fifth order in R / l) and one reflection is the superposition of two lone spheres
for sep in (1.0, 1.5):
    f23, t23 = ft.eq23_factors(sep)
    reflected = ft.reflected_sampling(sep, lambda r: np.full_like(np.asarray(r, dtype=float), 3.0),
                                      reflections=4, spacing=0.1)
    check(f'l = {sep}: drag factor of four reflections against eq. (23)', reflected['incident_speed'], f23, 0.01)
    check(f'l = {sep}: torque factor of four reflections against eq. (23)', reflected['incident_spin'], t23, 0.01)
one1, one2 = ft.two_sphere_flow(1.0, reflections=1)
check('one reflection: sphere 2 is the lone Stokes disturbance about it',
      float(np.abs(one2(probe) - ft.stokes_disturbance(probe - np.array([0.0, 1.0, 0.0]), 1.0, R)[0]).max()), 0.0, 1e-12)
four1, four2 = ft.two_sphere_flow(1.0, reflections=4)
check('four reflections: no slip on sphere 1 (to the neglected curvature of the incident flow)',
      float(np.abs(1.0 * np.array([1.0, 0.0, 0.0]) + four1(R * n) + four2(R * n)).max()), 0.0, 0.02)

# inverse-variance weighting: two equal errors give the plain mean, error / sqrt(2)
mean, err, chi2 = ft.weighted_mean([1.0, 1.2], [0.1, 0.1])
check('weighted mean of two', mean, 1.1, 1e-12)
check('weighted mean: error', err, 0.1 / np.sqrt(2), 1e-12)
check('weighted mean: chi^2', chi2, 2.0, 1e-12)
mean, err, _ = ft.weighted_mean([1.0, 2.0], [0.1, 0.2])
check('weighted mean, unequal errors', mean, (1.0 / 0.01 + 2.0 / 0.04) / (1 / 0.01 + 1 / 0.04), 1e-12)

finish()
