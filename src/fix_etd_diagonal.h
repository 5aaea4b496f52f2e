// ETD-DPD: fix etd ... scheme diagonal (the default), exponential time differencing with each
// atom's diagonal of the friction (see doc/fix_etd.rst).
#ifndef ETD_FIX_ETD_DIAGONAL_H
#define ETD_FIX_ETD_DIAGONAL_H

#include "fix.h"

#include "neighbor_safety.h"

#include <vector>

namespace etd {
class DpdPairInterface;
}

namespace LAMMPS_NS {

class FixETDDiagonal : public Fix {
 public:
  FixETDDiagonal(class LAMMPS *, int, char **);
  ~FixETDDiagonal() override;
  int setmask() override;
  void init() override;
  void setup(int) override;
  void post_run() override;
  void set_arrays(int) override;
  void initial_integrate(int) override;
  void final_integrate() override;
  void reset_dt() override;
  double compute_vector(int) override;

  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;
  double memory_usage() override;

  enum class Noise { Piecewise, Exact };

 protected:    // read by the KOKKOS variant (KOKKOS/fix_etd_diagonal_kokkos.h)
  int order;
  Noise noise;
  bool conserve_momentum;
  double dt;
  std::vector<etd::DpdPairInterface *> dpd_styles;

 private:
  etd::NeighborSafety neighbor_safety;
  double fingerprint_at_end = -1.0;    // order 2: velocity_fingerprint() at the end of the last run
  double velocity_fingerprint() const;
  bool needs_random_part() const { return order == 2 || noise == Noise::Exact; }
  void update_angular_velocities();    // pair styles with rotation (dpd/fpm)
  bool rotation_checked = false;
  int rotation_active = 0;
  double **previous_forcing;        // [nmax][4]: A_(n-1) per component, and 1 where it is valid
  double momentum_correction[3];    // last correction applied (output)
};

}    // namespace LAMMPS_NS

#endif
