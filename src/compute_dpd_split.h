// ETD-DPD: compute dpd/split, the conservative / dissipative / random parts of the pair force
// (and of the torque, dpd/fpm).
#ifndef ETD_COMPUTE_DPD_SPLIT_H
#define ETD_COMPUTE_DPD_SPLIT_H

#include "compute.h"

namespace etd {
class DpdPairInterface;
class DpdFrictionIntegrator;
}    // namespace etd

namespace LAMMPS_NS {

class ComputeDPDSplit : public Compute {
 public:
  ComputeDPDSplit(class LAMMPS *, int, char **);
  ~ComputeDPDSplit() override;
  void init() override;
  void compute_vector() override;
  void compute_peratom() override;
  double memory_usage() override;

 private:
  etd::DpdPairInterface *dpd_style;
  etd::DpdFrictionIntegrator *implicit;    // fix etd scheme implicit: it supplies D and R
  const char *implicit_id;
  int nvalues;    // 9 (force) or 15 (force and torque)
  int nmax;
  double **per_atom;
  void copy_split();
};

}    // namespace LAMMPS_NS

#endif
