"""The two-sphere torque of pair_style dpd/fpm from the fluid's fields (validation/fpm README
section 4.2; runs by validation/fpm/torque_field.sh).

A colloid held at rest feels from each fluid atom j the shear friction of the pair law
(src/kernels/fpm_kernel.h), which is linear in j's velocity v_j and spin w_j at fixed geometry.
Its mean dissipative torque is therefore the sum over small bins about the colloid of
  (mean number of atoms in the bin) x (pair torque at the bin's centre, its mean v and w),
exactly up to the bins' size. With that sum the measured torque is taken apart:

  measured field       the pair run's own density, velocity and spin (checks the sum against
                       the torque the run measured directly);
  without layering     the same velocities and spins, the density replaced by the superposition
                       of two lone colloids' radial profiles n(|x - c1|) n(|x - c2|) / n_bulk
                       (what is left if the fluid between the colloids had no structure of its
                       own); the difference is the layering's share;
  Stokes field         the pair law summed over the superposed density with the fluid moving as
                       Stokes flow past two spheres of radius R (one reflection: the stream plus
                       each sphere's disturbance) and spinning at half its vorticity, divided by
                       the same sum for a uniform rotation at the spin Stokes flow has at the
                       colloid's centre: how much the finite reach of the pair law (rc = 1 against
                       R = 0.27) weights the neighbour's near field above Faxen's point value.
  reflections          the same with the two spheres' flow on each other (method of reflections,
                       each sphere held still in the other's previous reflection, linearised about
                       its centre; four reflections reproduce eq. (23)'s drag and torque factors
                       within 0.6 %): the pair law's torque over the continuum's.
"""
import argparse
import math

import numpy as np
from scipy.interpolate import RegularGridInterpolator

from .fpm_analysis import batch_mean, eq23_factors, read_blocks, two_spheres
from .lammps_output import read_ave_chunk

# colloid-fluid shear friction of potentials/fpm_colloid_pan2008.in
GAMMA_S, EXPONENT, CUTOFF = 5.5, 0.5, 1.0
BULK_DENSITY = 3.0
PAPER_R = 0.2737


def shear_torque(offset, velocity, spin, gamma_s=GAMMA_S, s=EXPONENT, rc=CUTOFF):
    """Dissipative torque on a colloid at rest (no spin) at the origin from fluid atoms at
    `offset` (x_j - x_i, rows) moving with `velocity` and spinning with `spin`: the shear part
    of the pair law, T_i = -(r_ij / 2) x F_ij with F_ij = -gamma_S w [u_ij - (e . u_ij) e],
    u_ij = v_ij + (r_ij / 2) x (Omega_i + Omega_j), r_ij = x_i - x_j, w = (1 - r / rc)^s."""
    offset = np.atleast_2d(np.asarray(offset, dtype=float))
    velocity = np.atleast_2d(np.asarray(velocity, dtype=float))
    spin = np.atleast_2d(np.asarray(spin, dtype=float))
    r_ij = -offset
    r = np.linalg.norm(r_ij, axis=1)
    inside = (r < rc) & (r > 0.0)
    safe_r = np.where(inside, r, 1.0)
    e = r_ij / safe_r[:, None]
    weight = np.where(inside, np.clip(1.0 - safe_r / rc, 0.0, None) ** s, 0.0)
    v_ij = -velocity
    half = 0.5 * r_ij
    slip = v_ij + np.cross(half, spin)
    slip_perp = slip - np.sum(slip * e, axis=1)[:, None] * e
    force = -gamma_s * weight[:, None] * slip_perp
    return -np.cross(half, force)


class Field:
    """One fix ave/chunk file of in.fpm_periodic_drag (field yes), last block: bin centres
    relative to colloid 1 (the cube's centre), mean atoms per bin, mean velocity and spin."""

    def __init__(self, path):
        rows = read_ave_chunk(path).data[-1]
        centres = rows[:, 1:4]
        self.spacing = float(np.min(np.diff(np.unique(centres[:, 0]))))
        self.offset = centres - 0.5 * (centres.min(axis=0) + centres.max(axis=0))
        self.count = rows[:, 5] * self.spacing ** 3
        self.velocity = rows[:, 6:9]
        self.spin = rows[:, 9:12]

    def torque(self, count=None, velocity=None, spin=None, mask=None):
        """z torque on colloid 1 summed over the bins (optionally with another count, velocity
        or spin per bin, or over the bins in mask only)."""
        count = self.count if count is None else count
        t = shear_torque(self.offset, self.velocity if velocity is None else velocity,
                         self.spin if spin is None else spin)[:, 2] * count
        return float(np.sum(t if mask is None else t[mask]))


def radial_density(field, width=0.05, rmax=1.0):
    """Number density about a lone colloid against distance (shells of `width` up to rmax,
    bulk beyond): a function of r."""
    r = np.linalg.norm(field.offset, axis=1)
    edges = np.arange(0.0, rmax + 0.5 * width, width)
    counts, _ = np.histogram(r, edges, weights=field.count)
    volume, _ = np.histogram(r, edges, weights=np.full(len(r), field.spacing ** 3))
    density = np.where(volume > 0, counts / np.where(volume > 0, volume, 1.0), BULK_DENSITY)
    mids = 0.5 * (edges[1:] + edges[:-1])

    def n(x):
        return np.where(x < rmax, np.interp(x, mids, density), BULK_DENSITY)
    return n


def superposed_density(offset, lone_density, l):
    """Two lone colloids' profiles multiplied (colloid 1 at the origin, colloid 2 at +l along
    y), over the bulk density: the fluid's density without a structure of its own between them."""
    other = offset - np.array([0.0, l, 0.0])
    return lone_density(np.linalg.norm(offset, axis=1)) * \
        lone_density(np.linalg.norm(other, axis=1)) / BULK_DENSITY


def stokes_disturbance(x, U, R):
    """Velocity and spin (half the vorticity) that a sphere of radius R at rest at the origin
    adds to a uniform stream U along x (Stokes flow); the fluid inside the sphere is at rest
    (disturbance -U there, spin 0)."""
    r = np.linalg.norm(x, axis=1)
    out = r < R
    r = np.where(out, 1.0, r)
    xhat = np.array([1.0, 0.0, 0.0])
    along = x[:, 0]
    u = -0.75 * R * U * (xhat / r[:, None] + x * (along / r ** 3)[:, None]) \
        - 0.25 * R ** 3 * U * (xhat / r[:, None] ** 3 - 3.0 * x * (along / r ** 5)[:, None])
    spin = 0.75 * R * U * np.cross(x, xhat) / r[:, None] ** 3
    u[out] = -U * xhat
    spin[out] = 0.0
    return u, spin


def _rotation_taking_x_to(direction):
    """The rotation matrix that takes the unit vector along x to `direction` (a unit vector)."""
    a = np.array([1.0, 0.0, 0.0])
    v, c = np.cross(a, direction), float(a @ direction)
    if np.linalg.norm(v) < 1e-14:
        return np.eye(3) if c > 0.0 else np.diag([-1.0, -1.0, 1.0])
    vx = np.array([[0.0, -v[2], v[1]], [v[2], 0.0, -v[0]], [-v[1], v[0], 0.0]])
    return np.eye(3) + vx + vx @ vx / (1.0 + c)


def uniform_flow_disturbance(x, V, R):
    """What a sphere of radius R at rest at the origin adds to a uniform stream V (any
    direction): stokes_disturbance turned from x to V."""
    speed = float(np.linalg.norm(V))
    if speed == 0.0:
        return np.zeros_like(x)
    turn = _rotation_taking_x_to(np.asarray(V, dtype=float) / speed)
    u, _ = stokes_disturbance(x @ turn, speed, R)
    return u @ turn.T


def linear_flow_disturbance(x, rotation, strain, R):
    """What a sphere of radius R at rest, not rotating, at the origin adds to the linear flow
    rotation x r + strain . r (strain symmetric and traceless): the rotlet -R^3 rotation x r / r^3
    and the straining flow's -5/2 R^3 (r.E.r) r / r^5 - R^5 / 2 (2 E.r / r^5 - 5 (r.E.r) r / r^7)
    (no slip on the sphere). Zero inside it."""
    r = np.linalg.norm(x, axis=1)
    inside = r < R * (1.0 - 1e-12)    # (points on the surface, up to rounding, are outside)
    r = np.where(inside, 1.0, r)[:, None]
    rEr = np.einsum('ni,ij,nj->n', x, strain, x)[:, None]
    u = -R ** 3 * np.cross(rotation, x) / r ** 3 - 2.5 * R ** 3 * rEr * x / r ** 5 \
        - 0.5 * R ** 5 * (2.0 * (x @ np.asarray(strain).T) / r ** 5 - 5.0 * rEr * x / r ** 7)
    u[inside] = 0.0
    return u


def velocity_gradient(velocity, point, h=1e-5):
    """G[i, j] = d u_i / d x_j of a velocity function at one point (central differences)."""
    G = np.zeros((3, 3))
    for j in range(3):
        step = np.zeros(3)
        step[j] = h
        G[:, j] = (velocity((point + step)[None])[0] - velocity((point - step)[None])[0]) / (2.0 * h)
    return G


def spin_of(velocity, x, h=1e-5):
    """Half the curl of a velocity function at the rows of x (central differences)."""
    d = []
    for j in range(3):
        step = np.zeros(3)
        step[j] = h
        d.append((velocity(x + step) - velocity(x - step)) / (2.0 * h))    # d[j][:, i] = du_i/dx_j
    return 0.5 * np.stack([d[1][:, 2] - d[2][:, 1], d[2][:, 0] - d[0][:, 2], d[0][:, 1] - d[1][:, 0]], axis=1)


def _response(incident, R):
    """A fixed, non-rotating sphere's disturbance in `incident` linearised at its centre (the
    origin): its value there, its rotation and its strain."""
    origin = np.zeros(3)
    V = incident(origin[None])[0]
    G = velocity_gradient(incident, origin)
    strain, spin = 0.5 * (G + G.T), 0.5 * (G - G.T)
    rotation = np.array([spin[2, 1], spin[0, 2], spin[1, 0]])
    return lambda y: uniform_flow_disturbance(y, V, R) + linear_flow_disturbance(y, rotation, strain, R)


def two_sphere_flow(l, R=PAPER_R, reflections=4):
    """Stokes flow about two fixed, non-rotating spheres of radius R at the origin and at +l
    along y in a unit stream along x, by the method of reflections: each sphere's k-th
    reflection answers the other's (k-1)-th, taken as linear about its centre. Returns the
    disturbances of sphere 1 and of sphere 2 as functions of position (zero inside the
    spheres). One reflection is stokes_sampling's superposition."""
    centre2 = np.array([0.0, l, 0.0])
    mirror = np.diag([1.0, -1.0, 1.0])    # the pair's mirror plane y = l / 2 takes one to the other
    first = lambda y: stokes_disturbance(y, 1.0, R)[0]  # noqa: E731
    parts = [first]
    for _ in range(1, reflections):
        previous = parts[-1]
        parts.append(_response(lambda y, f=previous: f((y - centre2) @ mirror) @ mirror, R))

    def sphere1(y):
        return sum(part(y) for part in parts)

    def sphere2(y):
        return sphere1((y - centre2) @ mirror) @ mirror
    return sphere1, sphere2


def reflected_sampling(l, lone_density, R=PAPER_R, reflections=4, spacing=0.05):
    """The pair law summed over the two-sphere Stokes flow of two_sphere_flow (spin = half its
    curl) with the superposed density, over the same sum for a uniform rotation at the spin the
    flow incident on colloid 1 (the stream and colloid 2's disturbance) has at its centre, with
    the lone density: the torque the pair law gives over Faxen's. Also the continuum's own
    incident velocity and spin at colloid 1 (drag / 6 pi mu R U and torque / 8 pi mu R^3 U),
    to set against eq. (23)'s f(l) and its torque factor."""
    sphere1, sphere2 = two_sphere_flow(l, R, reflections)
    centre2 = np.array([0.0, l, 0.0])
    x, volume = _cube_grid(spacing)

    def velocity(y):
        return np.tile([1.0, 0.0, 0.0], (len(y), 1)) + sphere1(y) + sphere2(y)
    inside = (np.linalg.norm(x, axis=1) < R) | (np.linalg.norm(x - centre2, axis=1) < R)
    u, w = velocity(x), spin_of(velocity, x)
    u[inside], w[inside] = 0.0, 0.0
    total = shear_torque(x, u, w)[:, 2] @ (superposed_density(x, lone_density, l) * volume)

    def incident(y):
        return np.tile([1.0, 0.0, 0.0], (len(y), 1)) + sphere2(y)
    origin = np.zeros((1, 3))
    spin = spin_of(incident, origin)[0]
    point = _uniform_rotation_torque(x, spin, lone_density, volume)
    return dict(total=float(total), point=float(point), ratio=float(total / point),
                incident_speed=float(incident(origin)[0, 0]), incident_spin=float(spin[2]))


class AxialField:
    """One fix ave/chunk file of in.fpm_periodic_drag (axial yes): the flow about one colloid in
    rings about the flow axis (x) through its centre, last block, as the disturbance it adds to
    the stream it meets, per unit of that stream. Beyond the rings (|x| or radius above their
    range less one bin) the Stokes disturbance of radius R stands in."""

    def __init__(self, path, stream, R=PAPER_R):
        rows = read_ave_chunk(path).data[-1]
        c1, c2 = rows[:, 1], rows[:, 2]
        radial, axial = (c1, c2) if c1.min() >= 0.0 and c1.max() < c2.max() - c2.min() else (c2, c1)
        r_centres, a_centres = np.unique(radial), np.unique(axial)
        a_centres = a_centres - 0.5 * (a_centres.min() + a_centres.max())
        shape = (len(a_centres), len(r_centres))
        order = np.lexsort((radial, axial))    # axial major, radial minor

        def grid(column):
            return rows[order, column].reshape(shape)
        self.stream, self.R = stream, R
        self.reach = (a_centres.max(), r_centres.max())
        self.count = grid(3)
        kwargs = dict(bounds_error=False, fill_value=None)
        self.vx = RegularGridInterpolator((a_centres, r_centres), grid(5) / stream - 1.0, **kwargs)
        self.vr = RegularGridInterpolator((a_centres, r_centres), grid(6) / stream, **kwargs)
        self.wphi = RegularGridInterpolator((a_centres, r_centres), grid(7) / stream, **kwargs)

    def disturbance(self, x):
        """Velocity and spin the colloid (at the origin) adds at x, per unit stream along x."""
        axial = x[:, 0]
        radius = np.hypot(x[:, 1], x[:, 2])
        safe = np.where(radius > 0.0, radius, 1.0)
        rhat = np.stack([np.zeros_like(axial), x[:, 1] / safe, x[:, 2] / safe], axis=1)
        phihat = np.stack([np.zeros_like(axial), -rhat[:, 2], rhat[:, 1]], axis=1)
        point = np.stack([axial, radius], axis=1)
        u = self.vx(point)[:, None] * np.array([1.0, 0.0, 0.0]) + self.vr(point)[:, None] * rhat
        w = self.wphi(point)[:, None] * phihat
        outside = (np.abs(axial) > self.reach[0]) | (radius > self.reach[1])
        if np.any(outside):
            us, ws = stokes_disturbance(x[outside], 1.0, self.R)
            u[outside], w[outside] = us, ws
        return u, w


def _cube_grid(spacing):
    """Bin centres filling the cube of side 2 (the pair law's reach) about colloid 1, and the
    bins' volume."""
    g = np.arange(-1.0 + 0.5 * spacing, 1.0, spacing)
    return np.stack(np.meshgrid(g, g, g, indexing='ij'), axis=-1).reshape(-1, 3), spacing ** 3


def _uniform_rotation_torque(x, spin, lone_density, volume):
    """The pair law's torque on colloid 1 from fluid with a lone colloid's density rotating
    uniformly at `spin` (Faxen's point value, as the pair law weights it)."""
    return shear_torque(x, np.cross(spin, x), np.tile(spin, (len(x), 1)))[:, 2] @ \
        (lone_density(np.linalg.norm(x, axis=1)) * volume)


def stokes_sampling(l, lone_density, R=PAPER_R, spacing=0.05, measured=None):
    """The pair law summed over Stokes flow about the pair (one reflection) with the superposed
    density, by parts (stream, colloid 1's disturbance, colloid 2's), and over a uniform
    rotation at Stokes flow's spin at colloid 1's centre with the lone density; their ratio.
    With measured (an AxialField), each colloid's disturbance is instead the measured flow
    about a lone colloid (the pair law's own near field)."""
    x, volume = _cube_grid(spacing)
    U = 1.0
    count = superposed_density(x, lone_density, l) * volume
    c2 = np.array([0.0, l, 0.0])
    stream = np.tile([U, 0.0, 0.0], (len(x), 1))
    disturbance = measured.disturbance if measured else (lambda y: stokes_disturbance(y, U, R))
    u1, w1 = disturbance(x)
    u2, w2 = disturbance(x - c2)
    zero = np.zeros_like(x)
    parts = {'stream': shear_torque(x, stream, zero)[:, 2] @ count,
             'colloid 1': shear_torque(x, u1, w1)[:, 2] @ count,
             'colloid 2': shear_torque(x, u2, w2)[:, 2] @ count}
    total = sum(parts.values())
    point_spin = stokes_disturbance(-c2[None, :], U, R)[1][0]
    point = _uniform_rotation_torque(x, point_spin, lone_density, volume)
    return dict(parts=parts, total=float(total), point=float(point), ratio=float(total / point),
                faxen_spin=float(point_spin[2]))


def pair_summary(l, field, lone_density, measured, min_fraction=0.1):
    """Measured torque on colloid 1 (mean dissipative part, its error) against the sums over
    the pair run's field: whole, the share of the bins within the cutoff of colloid 2, and with
    the layer-free density (bins where fewer than min_fraction of the superposed density's
    atoms were seen are left out of both sums of that comparison: their velocity is unknown)."""
    t_field = field.torque()
    near_other = np.linalg.norm(field.offset - np.array([0.0, l, 0.0]), axis=1) < CUTOFF
    n_sup = superposed_density(field.offset, lone_density, l) * field.spacing ** 3
    seen = field.count >= min_fraction * n_sup
    t_seen = field.torque(mask=seen)
    t_sup = field.torque(count=n_sup, mask=seen)
    return dict(l=l, measured=measured[0], measured_err=measured[1], field=t_field,
                near_other=field.torque(mask=near_other), field_seen=t_seen, layer_free=t_sup,
                layering=t_seen - t_sup, unseen_fraction=float(n_sup[~seen].sum() / n_sup.sum()))


def measured_torque(drag_path):
    """Mean and batch error of colloid 1's dissipative z torque (column 10 of the .drag file)."""
    return batch_mean(read_blocks(drag_path)[:, 9])


def weighted_mean(values, errors):
    """Inverse-variance weighted mean, its error and chi^2 about it."""
    v, e = np.asarray(values, dtype=float), np.asarray(errors, dtype=float)
    w = 1.0 / e ** 2
    mean = float(np.sum(w * v) / np.sum(w))
    return mean, float(1.0 / math.sqrt(np.sum(w))), float(np.sum(w * (v - mean) ** 2))


def combined_runs(l, g, paths, L=8.0, nfluid=1534):
    """Each two-sphere run's dissipative torque / eq. (23) (fpm_analysis.two_spheres, half the
    difference of the two colloids) and their weighted mean."""
    ratios = []
    for path in paths:
        r = two_spheres(path, L, g, nfluid, l)
        ratios.append((r['TD'] / r['T_the'], r['TDerr'] / r['T_the']))
    return ratios, weighted_mean(*zip(*ratios))


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    p.add_argument('--lone', help='field file of one colloid alone (l = 0)')
    p.add_argument('--runs', nargs='+', action='append', default=[], metavar='L G FILE',
                   help='separation, body force and the .drag files of independent two-sphere runs '
                        '(cube of side 8, 1,534 fluid atoms): each one\'s dissipative torque / eq. (23) '
                        'and their weighted mean')
    p.add_argument('--axial', nargs=2, metavar=('FILE', 'STREAM'),
                   help='ring file of one colloid alone (axial yes) and the stream it meets '
                        '(its drag over 6 pi mu R): the sampling ratio with its measured flow too')
    p.add_argument('--pair', nargs=3, action='append', default=[], metavar=('L', 'FIELD', 'DRAG'),
                   help='separation, field file and .drag file of a two-colloid run')
    a = p.parse_args(argv)
    for spec in a.runs:
        ratios, (mean, err, chi2) = combined_runs(float(spec[0]), float(spec[1]), spec[2:])
        print(f'l = {spec[0]}: dissipative torque / eq. (23) per run ' + ', '.join(
            f'{v:.3f} +- {e:.3f}' for v, e in ratios) + f'; weighted {mean:.3f} +- {err:.3f} '
            f'(chi^2 {chi2:.1f} for {len(ratios) - 1} degrees of freedom)')
    if not a.lone:
        return 0
    lone = Field(a.lone)
    n = radial_density(lone)
    print('lone colloid: density at r = ' + ', '.join(
        f'{r:.2f}: {float(n(np.array(r))):.2f}' for r in (0.3, 0.4, 0.5, 0.6, 0.8, 0.95)))
    print(f'lone colloid: torque summed over its field {lone.torque():+.4f} (zero by symmetry)')
    print('| l | measured dissipative torque on colloid 1 | summed over the field | of it, bins '
          'within rc of colloid 2 | seen bins, measured density | seen bins, layer-free density '
          '| layering share | Stokes-field sampling / point value |')
    print('|---|---|---|---|---|---|---|---|')
    summaries = {}
    stokes = {l: stokes_sampling(l, n) for l in sorted({float(l) for l, _, _ in a.pair})}
    for l, field_path, drag_path in a.pair:
        l = float(l)
        s = pair_summary(l, Field(field_path), n, measured_torque(drag_path))
        summaries.setdefault(l, []).append(s)
        st = stokes[l]
        print(f'| {l:g} | {s["measured"]:.4f} +- {s["measured_err"]:.4f} | {s["field"]:.4f} '
              f'({s["field"] / s["measured"]:.3f}) | {s["near_other"]:.4f} | {s["field_seen"]:.4f} '
              f'| {s["layer_free"]:.4f} | {s["layering"] / s["field_seen"]:+.3f} '
              f'(unseen {s["unseen_fraction"]:.3f}) | {st["ratio"]:.3f} |')
    for l, runs in summaries.items():
        if len(runs) > 1:
            # over independent runs: the field sums against the measured torques, and the layering
            field = sum(r['field'] for r in runs)
            measured = sum(r['measured'] for r in runs)
            error = math.sqrt(sum(r['measured_err'] ** 2 for r in runs))
            layering = sum(r['layering'] for r in runs) / sum(r['field_seen'] for r in runs)
            print(f'l = {l:g}, {len(runs)} runs: summed over the fields / measured '
                  f'{field / measured:.3f} +- {error / measured:.3f}; layering share {layering:+.3f}')
    axial = AxialField(a.axial[0], float(a.axial[1])) if a.axial else None
    for l in sorted(summaries):
        if axial:
            sm = stokes_sampling(float(l), n, measured=axial)
            print(f'measured lone flow, l = {l:g}: parts ' + ', '.join(
                f'{k} {v:+.4f}' for k, v in sm['parts'].items())
                + f'; total {sm["total"]:.4f}, ratio to the point value {sm["ratio"]:.3f}')
        st = stokes[l]
        print(f'Stokes field, l = {l:g}: parts ' + ', '.join(f'{k} {v:+.4f}' for k, v in st['parts'].items())
              + f'; total {st["total"]:.4f}, uniform rotation at the point spin '
              f'{st["faxen_spin"]:.4f}: {st["point"]:.4f}, ratio {st["ratio"]:.3f}')
    if summaries:
        # the two-sphere Stokes flow by reflections: how far they have converged, the continuum
        # against eq. (23), and the pair law's torque over the continuum's, which is what the
        # measured dissipative torque / eq. (23) at u_eff is to be set against
        print('| l | reflections | continuum drag factor (eq. 23) | continuum torque factor (eq. 23) '
              '| pair law / continuum torque | the same against eq. (23)\'s torque over drag |')
        print('|---|---|---|---|---|---|')
        for l in sorted(summaries):
            f23, t23 = eq23_factors(float(l))
            for count in (1, 2, 3, 4):
                r = reflected_sampling(float(l), n, reflections=count)
                against = r['ratio'] * (r['incident_spin'] / r['incident_speed']) / (t23 / f23)
                print(f'| {l:g} | {count} | {r["incident_speed"]:.4f} ({f23:.4f}) | {r["incident_spin"]:.4f} '
                      f'({t23:.4f}) | {r["ratio"]:.3f} | {against:.3f} |')
    return 0
