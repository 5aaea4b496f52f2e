// ETD-DPD: the transverse current of a particle configuration in Fourier space,
//   J(k) = sum_j v_j exp(i k . r_j),   k = (2 pi j / L_a) along box axis a,  j = 1..K,
// and its two components perpendicular to k. Pure function (no LAMMPS) for the compute and
// its tests.
//
// Layout of the result (12 K values), for axis a = x, y, z, wave index j = 1..K, transverse
// component t = the two other axes in cyclic order (x: y, z; y: z, x; z: x, y), part p = Re, Im:
//   index = 4 (K a + j - 1) + 2 t + p
#ifndef ETD_TRANSVERSE_CURRENT_H
#define ETD_TRANSVERSE_CURRENT_H

#include <cmath>
#include <vector>

namespace etd {

inline int transverse_current_index(int nwave, int axis, int j, int transverse, int part)
{
  return 4 * (nwave * axis + j - 1) + 2 * transverse + part;
}

// Adds one atom at position x (relative to the box origin) with velocity v to the sums in
// `current` (12 K values). e^(i k_j x) is built by complex multiplication from e^(i k_1 x): one
// sincos per axis and atom instead of K.
inline void add_transverse_current(const double x[3], const double v[3], const double prd[3],
                                   int nwave, double *current)
{
  const double two_pi = 6.283185307179586476925;
  for (int axis = 0; axis < 3; axis++) {
    const double phase = two_pi * x[axis] / prd[axis];
    const double c1 = std::cos(phase), s1 = std::sin(phase);
    const double v_t0 = v[(axis + 1) % 3];
    const double v_t1 = v[(axis + 2) % 3];
    double c = c1, s = s1;
    double *out = current + 4 * nwave * axis;
    for (int j = 1; j <= nwave; j++) {
      out[0] += v_t0 * c;
      out[1] += v_t0 * s;
      out[2] += v_t1 * c;
      out[3] += v_t1 * s;
      out += 4;
      const double c_next = c * c1 - s * s1;
      s = s * c1 + c * s1;
      c = c_next;
    }
  }
}

}    // namespace etd

#endif
