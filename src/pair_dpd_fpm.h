// ETD-DPD: pair_style dpd/fpm, DPD with central and shear drag, angular velocities and torques
// (see doc/pair_dpd_fpm.rst).
#ifndef ETD_PAIR_DPD_FPM_H
#define ETD_PAIR_DPD_FPM_H

#include "dpd_friction_provider.h"
#include "dpd_random.h"
#include "fpm_kernel.h"
#include "pair.h"

#include <vector>

namespace LAMMPS_NS {

class PairDPDFPM : public Pair, public etd::DpdExtrasProvider {
 public:
  PairDPDFPM(class LAMMPS *);
  ~PairDPDFPM() override;
  void compute(int, int) override;
  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  double init_one(int, int) override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void write_restart_settings(FILE *) override;
  void read_restart_settings(FILE *) override;
  void write_data(FILE *) override;
  void write_data_all(FILE *) override;
  double single(int, int, int, int, double, double, double, double &) override;
  void *extract(const char *, int &) override;
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;
  double memory_usage() override;

  // the translational and rotational diagonals come together: whoever integrates translation
  // with the friction diagonal needs the rotational one for the angular velocities too
  void request_diagonal_friction() override { want_friction = true; }
  void request_force_split() override { want_split = true; }
  double **diagonal_friction() override { return friction; }
  double **force_split() override { return split; }
  double **rotational_friction() override { return rot_friction; }

  const etd::FpmCoefficients &coefficients(int i, int j) const { return coeffs[i * stride + j]; }
  const etd::FpmCoefficients *fpm_coefficients(int i, int j) override;
  std::uint64_t noise_seed() const override { return static_cast<std::uint64_t>(seed); }
  void request_conservative_only() override { conservative_only = true; }

 protected:
  double temperature, cut_global;
  int seed;
  etd::PairNoise noise;

  // user input per type pair (upper triangle as set, mirrored in init_one)
  double **a0, **gamma_c, **gamma_s, **exponent_d, **cut;

  std::vector<etd::FpmCoefficients> coeffs;    // (ntypes+1)^2, filled by init_one
  int stride;

  bool want_friction, want_split;
  bool conservative_only;    // friction, noise and torques left to fix etd's implicit scheme
  double **friction;        // [nmax][3] translational diagonal
  double **rot_friction;    // [nmax][3] rotational diagonal
  double **split;           // [nmax][9]
  int nmax_extras;

  void allocate();
  void grow_extras();
  template <int EVFLAG, int EXTRAS, int DISSIPATIVE> void eval();
};

}    // namespace LAMMPS_NS

#endif
