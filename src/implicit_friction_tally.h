// ETD-DPD: what the implicit scheme's friction step reports besides the velocities: the virial
// of its dissipative and random pair forces (pressure, stress/atom) and their per-atom split
// for compute dpd/split.
#ifndef ETD_IMPLICIT_FRICTION_TALLY_H
#define ETD_IMPLICIT_FRICTION_TALLY_H

#include "implicit_pair_assembly.h"

#include <vector>

namespace etd {

// Virial of the step's dissipative and random pair forces, sum over pairs of r_ij F_ij (F on i,
// at the velocities u given on all partners, the random force sigma w_R theta / sqrt(dt) in
// both schemes). A pair that crosses ranks is held by both: each counts half. Per atom (vatom,
// nullptr when no stress/atom compute wants it): half to each of the pair's atoms.
void tally_friction_virial(const FrictionPairAssembly &assembly, const double *u, int nlocal,
                           double dt, double virial[6], double **vatom);

// The kinetic stress the step's drifts carry beyond the m c c of the velocities it leaves, for
// one atom: an atom drifts half a step with c - h and half with c + h (the step's friction
// output and the next step's kicked velocity, h = (dt/2) F/m of the step's end), so the
// momentum it carries across a plane averages to m (c c + h h) over each step's drifts, and
// m c c of the friction step's output c misses m (c h + h c + 2 h h). w: xx yy zz xy xz yz, as
// LAMMPS orders a virial; c peculiar (the streaming velocity removed).
inline void drift_kinetic_stress(double mass, const double c[3], const double h[3], double w[6])
{
  const int a[6] = {0, 1, 2, 0, 0, 1}, b[6] = {0, 1, 2, 1, 2, 2};
  for (int k = 0; k < 6; k++)
    w[k] = mass * (c[a[k]] * h[b[k]] + h[a[k]] * c[b[k]] + 2.0 * h[a[k]] * h[b[k]]);
}

// Per owned atom, D = -G u - the moving images' constant part (u on all partners) into
// split[i][0..2] and R = random_scale * random_force into split[i][3..5]; gu is work space.
void record_friction_split(const FrictionPairAssembly &assembly, const double *u, int nlocal,
                           const std::vector<double> &random_force, double random_scale,
                           std::vector<double> &gu, double **split);

}    // namespace etd

#endif
