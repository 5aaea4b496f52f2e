// ETD-DPD: pair_style dpd/fpm, DPD with central and shear drag, angular velocities and torques
// (see doc/pair_dpd_fpm.rst).
#ifndef ETD_PAIR_DPD_FPM_H
#define ETD_PAIR_DPD_FPM_H

#include "fpm_kernel.h"
#include "pair_dpd_base.h"

#include <vector>

namespace LAMMPS_NS {

class PairDPDFPM : public PairDPDBase {
 public:
  PairDPDFPM(class LAMMPS *);
  ~PairDPDFPM() override;
  void compute(int, int) override;
  void coeff(int, char **) override;
  void init_style() override;
  double init_one(int, int) override;
  void write_data(FILE *) override;
  void write_data_all(FILE *) override;
  double single(int, int, int, int, double, double, double, double &) override;
  void *extract(const char *, int &) override;

  const etd::FpmCoefficients *fpm_coefficients(int i, int j) override;
  const etd::FpmCoefficients &coefficients(int i, int j) const { return coeffs[i * stride + j]; }

 protected:
  // user input per type pair (upper triangle as set, mirrored in init_one); cut is the base's
  double **a0, **gamma_c, **gamma_s, **exponent_d;

  std::vector<etd::FpmCoefficients> coeffs;    // (ntypes+1)^2, filled by init_one
  int stride;

  void allocate() override;
  void write_type_pair(FILE *, int, int) override;
  void read_type_pair(FILE *, int, int) override;
  template <int EVFLAG, int EXTRAS, int DISSIPATIVE> void eval();
};

}    // namespace LAMMPS_NS

#endif
