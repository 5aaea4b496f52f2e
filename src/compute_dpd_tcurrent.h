// ETD-DPD: compute dpd/tcurrent, the transverse current J_perp(k) = sum_j v_perp,j exp(i k r_j)
// for k = 2 pi j / L along each box axis, sampled for transverse-current autocorrelations.
#ifndef ETD_COMPUTE_DPD_TCURRENT_H
#define ETD_COMPUTE_DPD_TCURRENT_H

#include "compute.h"

#include <vector>

namespace LAMMPS_NS {

class ComputeDPDTCurrent : public Compute {
 public:
  ComputeDPDTCurrent(class LAMMPS *, int, char **);
  ~ComputeDPDTCurrent() override;
  void init() override;
  void compute_vector() override;

 private:
  int nwave;                    // K: wave numbers 2 pi j / L, j = 1..K, per axis
  std::vector<double> local;    // this rank's sums before the reduction
};

}    // namespace LAMMPS_NS

#endif
