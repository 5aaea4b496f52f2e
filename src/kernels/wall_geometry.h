// ETD-DPD: wall boundary conditions as pure functions (no LAMMPS), used by
// fix wall/cylinder/bounce and fix wall/thermal/layer.
#ifndef ETD_DPD_WALL_GEOMETRY_H
#define ETD_DPD_WALL_GEOMETRY_H

#include <cmath>

namespace etd {

// Bounce-back reflection on a cylinder surface.
//
// Coordinates are relative to the cylinder axis; component `axis` runs along it, the other two
// span the cross-section. The particle moved by dt * v during this step and is now at `rel`;
// it crossed the surface if it left the fluid side (inside: r < R, outside: r > R). Bounce-back
// sends it back the way it came: it travels to the surface (fraction t of the step), its
// velocity becomes 2 u_wall - v (the wall is at rest here: -v), and it covers the rest of the
// step, (1 - t) dt, backwards, which ends at rel - 2 (1 - t) dt v. Where that point is not on
// the fluid side (a near-tangent path on a short chord) or the start of the step was not on it
// either (the particle was put there), the particle is put on the surface's fluid side at
// relative distance `margin` along the radius instead.
struct CylinderBounce {
  bool crossed = false;             // the particle was on the wall side and has been moved back
  bool projected = false;           // ... by the radial fall-back rather than along its path
  double x[3] = {0.0, 0.0, 0.0};    // new position relative to the axis
  double v[3] = {0.0, 0.0, 0.0};    // new velocity
};

inline bool on_fluid_side(double r2, double radius, bool fluid_inside)
{
  return fluid_inside ? r2 <= radius * radius : r2 >= radius * radius;
}

inline CylinderBounce cylinder_bounce(const double rel[3], const double v[3], double dt, int axis,
                                      double radius, bool fluid_inside, double margin = 1e-9)
{
  CylinderBounce out;
  for (int k = 0; k < 3; k++) {
    out.x[k] = rel[k];
    out.v[k] = v[k];
  }
  const int b = (axis + 1) % 3, c = (axis + 2) % 3;
  const double r2 = rel[b] * rel[b] + rel[c] * rel[c];
  if (on_fluid_side(r2, radius, fluid_inside)) return out;
  out.crossed = true;
  for (int k = 0; k < 3; k++) out.v[k] = -v[k];

  // start of the step p0 = rel - D, D = dt v; solve |p0 + t D|^2 = R^2 in the cross-section
  const double d_b = dt * v[b], d_c = dt * v[c];
  const double p_b = rel[b] - d_b, p_c = rel[c] - d_c;
  const double qa = d_b * d_b + d_c * d_c;
  const double qb = 2.0 * (p_b * d_b + p_c * d_c);
  const double qc = p_b * p_b + p_c * p_c - radius * radius;
  const double disc = qb * qb - 4.0 * qa * qc;
  const bool started_on_fluid_side = fluid_inside ? qc <= 0.0 : qc >= 0.0;
  if (qa > 0.0 && disc >= 0.0 && started_on_fluid_side) {
    const double root = std::sqrt(disc);
    // leaving the inside: the larger root; entering the cylinder from outside: the smaller one
    // (written without cancellation)
    double t;
    if (fluid_inside)
      t = (qb <= 0.0) ? (-qb + root) / (2.0 * qa) : (-2.0 * qc) / (qb + root);
    else
      t = (qb >= 0.0) ? (-qb - root) / (2.0 * qa) : (2.0 * qc) / (-qb + root);
    if (t < 0.0) t = 0.0;
    if (t > 1.0) t = 1.0;
    for (int k = 0; k < 3; k++) out.x[k] = rel[k] - 2.0 * (1.0 - t) * dt * v[k];
    const double n2 = out.x[b] * out.x[b] + out.x[c] * out.x[c];
    const bool strictly = fluid_inside ? n2 < radius * radius : n2 > radius * radius;
    if (strictly) return out;
  }
  // fall-back: onto the fluid side of the surface along the radius (axial coordinate kept)
  out.projected = true;
  for (int k = 0; k < 3; k++) out.x[k] = rel[k];
  const double r = std::sqrt(r2);
  const double target = fluid_inside ? radius * (1.0 - margin) : radius * (1.0 + margin);
  if (r > 0.0) {
    out.x[b] = rel[b] * target / r;
    out.x[c] = rel[c] * target / r;
  } else {    // on the axis of an obstacle cylinder: any direction will do
    out.x[b] = target;
    out.x[c] = 0.0;
  }
  return out;
}

// Near-wall layer of a plane wall at `wall` along one coordinate: the fluid lies above a
// lower wall (x > wall) and below an upper one (x < wall); the layer is the fluid within
// `thickness` of the plane, the plane included.
inline bool in_wall_layer(double x, double wall, double thickness, bool lower_wall)
{
  return lower_wall ? (x >= wall && x < wall + thickness) : (x <= wall && x > wall - thickness);
}

// A velocity component drawn from the wall's Maxwellian: wall velocity plus a Gaussian of
// variance kT / m (unit Gaussian `g`).
inline double wall_maxwellian(double wall_velocity, double kT, double mass, double g)
{
  return wall_velocity + std::sqrt(kT / mass) * g;
}

}    // namespace etd

#endif
