// ETD-DPD: pair_style dpd/gen, generalised DPD (see doc/pair_dpd_gen.rst): DPD's central law
// (pair_law.h) with conservative exponent p, dissipative exponent s and a cutoff of its own
// for friction and noise.
#ifndef ETD_PAIR_DPD_GEN_H
#define ETD_PAIR_DPD_GEN_H

#include "pair_dpd_style.h"

namespace LAMMPS_NS {

// pair_coeff I J a gamma s [cutoff] [exp_c p] [cut_d rcD]
struct PairDPDGenStyle {
  static constexpr const char *name = "dpd/gen";
  static constexpr const char *info =
      "ETD-DPD generalised DPD: exponent s, separate conservative/dissipative cutoffs";
  using Law = etd::DpdGenLaw;

  enum { A, GAMMA, S, EXP_C, CUTOFF, CUT_D };
  static constexpr etd::CoeffParam params[] = {
      {"a", "a", etd::CoeffArg::Required, etd::CoeffBound::Any, etd::DEFAULT_VALUE, 0.0, false,
       nullptr, "a0"},
      {"gamma", "gamma", etd::CoeffArg::Required, etd::CoeffBound::NonNegative, etd::DEFAULT_VALUE,
       0.0, false, nullptr, "gamma"},
      {"s", "dissipative exponent s", etd::CoeffArg::Required, etd::CoeffBound::Positive,
       etd::DEFAULT_VALUE, 2.0, false, nullptr, "s"},
      {"exp_c", "conservative exponent exp_c", etd::CoeffArg::Keyword, etd::CoeffBound::Positive,
       etd::DEFAULT_VALUE, 1.0, false, "p", "exp_c"},
      {"cutoff", "cutoff", etd::CoeffArg::Optional, etd::CoeffBound::Positive, etd::DEFAULT_CUTOFF,
       0.0, true, nullptr, nullptr},
      {"cut_d", "cut_d", etd::CoeffArg::Keyword, etd::CoeffBound::Positive, CUTOFF, 0.0, true,
       "rcD", "cut_d"},
  };

  static etd::PairCoefficients coefficients(const double *v, double kT)
  {
    etd::PairCoefficients c;
    c.set(v[A], v[GAMMA], v[S], v[EXP_C], v[CUTOFF], v[CUT_D], kT);
    return c;
  }
};

}    // namespace LAMMPS_NS

#endif
