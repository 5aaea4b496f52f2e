// ETD-DPD: pair_style dpd/fpm, DPD with central and shear drag, angular velocities and torques
// (see doc/pair_dpd_fpm.rst): the law of fpm_kernel.h.
#ifndef ETD_PAIR_DPD_FPM_H
#define ETD_PAIR_DPD_FPM_H

#include "fpm_kernel.h"
#include "pair_dpd_style.h"

namespace LAMMPS_NS {

// pair_coeff I J a gamma_C gamma_S s [cutoff]
struct PairDPDFPMStyle {
  static constexpr const char *name = "dpd/fpm";
  static constexpr const char *info =
      "ETD-DPD FPM-style DPD: central and shear drag, angular velocities and torques";
  using Law = etd::FpmLaw;

  enum { A, GAMMA_C, GAMMA_S, S, CUTOFF };
  static constexpr etd::CoeffParam params[] = {
      {"a", "a", etd::CoeffArg::Required, etd::CoeffBound::Any, etd::DEFAULT_VALUE, 0.0, false,
       nullptr, "a0"},
      {"gamma_C", "gamma_C", etd::CoeffArg::Required, etd::CoeffBound::NonNegative,
       etd::DEFAULT_VALUE, 0.0, false, nullptr, "gamma_c"},
      {"gamma_S", "gamma_S", etd::CoeffArg::Required, etd::CoeffBound::NonNegative,
       etd::DEFAULT_VALUE, 0.0, false, nullptr, "gamma_s"},
      {"s", "dissipative exponent s", etd::CoeffArg::Required, etd::CoeffBound::Positive,
       etd::DEFAULT_VALUE, 2.0, false, nullptr, "s"},
      {"cutoff", "cutoff", etd::CoeffArg::Optional, etd::CoeffBound::Positive, etd::DEFAULT_CUTOFF,
       0.0, true, nullptr, nullptr},
  };

  static etd::FpmCoefficients coefficients(const double *v, double kT)
  {
    etd::FpmCoefficients c;
    c.set(v[A], v[GAMMA_C], v[GAMMA_S], v[S], v[CUTOFF], kT);
    return c;
  }
};

}    // namespace LAMMPS_NS

#endif
