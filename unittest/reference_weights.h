// ETD-DPD test support: the DPD weights straight from their definitions, (1 - r/rc)^exponent
// with std::pow, as references for the kernels' evaluations.
#ifndef ETD_TEST_REFERENCE_WEIGHTS_H
#define ETD_TEST_REFERENCE_WEIGHTS_H

#include <cmath>

namespace etdtest {

// Weight (1 - r/rc)^exponent inside the cutoff, zero outside.
inline double cutoff_weight(double r, double rc, double exponent)
{
  if (r >= rc) return 0.0;
  return std::pow(1.0 - r / rc, exponent);
}

inline double conservative_weight(double r, double rc_c, double p)
{
  return cutoff_weight(r, rc_c, p);
}
inline double dissipative_weight(double r, double rc_d, double s)
{
  return cutoff_weight(r, rc_d, s);
}
inline double random_weight(double r, double rc_d, double s)
{
  return cutoff_weight(r, rc_d, 0.5 * s);
}

}    // namespace etdtest

#endif
