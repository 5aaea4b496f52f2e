// ETD-DPD: pair_style dpd/gen, generalised DPD (see doc/pair_dpd_gen.rst).
#ifndef ETD_PAIR_DPD_GEN_H
#define ETD_PAIR_DPD_GEN_H

#include "dpd_kernel.h"
#include "pair_dpd_base.h"

#include <vector>

namespace LAMMPS_NS {

class PairDPDGen : public PairDPDBase {
 public:
  PairDPDGen(class LAMMPS *);
  ~PairDPDGen() override;
  void compute(int, int) override;
  void coeff(int, char **) override;
  double init_one(int, int) override;
  void write_data(FILE *) override;
  void write_data_all(FILE *) override;
  double single(int, int, int, int, double, double, double, double &) override;
  void *extract(const char *, int &) override;

  const etd::PairCoefficients *dpd_coefficients(int i, int j) override;
  const etd::PairCoefficients &coefficients(int i, int j) const { return coeffs[i * stride + j]; }

 protected:
  // user input per type pair (upper triangle as set, mirrored in init_one); cut is the base's
  double **a0, **gamma, **exponent_d, **exponent_c, **cut_d;
  int **cut_d_set;

  std::vector<etd::PairCoefficients> coeffs;    // (ntypes+1)^2, filled by init_one
  int stride;

  void allocate() override;
  void write_type_pair(FILE *, int, int) override;
  void read_type_pair(FILE *, int, int) override;
  template <int EVFLAG, int FRICTION, int SPLIT, int DISSIPATIVE> void eval();
};

}    // namespace LAMMPS_NS

#endif
