// ETD-DPD: fix etd/kk, the KOKKOS variant of fix etd scheme diagonal. Its default step (order 1,
// piecewise noise, no momentum correction: x += dt v, then v += dt phi1(z) F/m per component
// with the friction diagonal of the pair style) runs in Kokkos kernels on the atoms' device
// arrays; it needs the friction diagonal from a KOKKOS pair style (dpd/gen/kk) that is the only
// DPD style. Other options run the CPU fix's step on the host (a WARNING at init names why),
// with the same results. The kernels split the atoms among threads by index; the pair style's
// kernel, which always runs with them, keeps the atoms sorted (atom_sort_schedule.h).
// fix etd/kk scheme implicit: fix_etd_implicit_kokkos.h.
#ifndef ETD_FIX_ETD_DIAGONAL_KOKKOS_H
#define ETD_FIX_ETD_DIAGONAL_KOKKOS_H

#include "fix_etd_diagonal.h"

#include "kokkos_type.h"
#include "lammpsplugin.h"

namespace LAMMPS_NS {

template <class DeviceType> class FixETDDiagonalKokkos : public FixETDDiagonal {
 public:
  using device_type = DeviceType;
  using AT = ArrayTypes<DeviceType>;

  FixETDDiagonalKokkos(class LAMMPS *, int, char **);
  void init() override;
  void initial_integrate(int) override;
  void final_integrate() override;
  double memory_usage() override;

 private:
  bool on_device =
      false;    // this run's step runs in the kernels (else the CPU fix's, on the host)
  std::string host_reason() const;    // why not ("" where it can)
  // the pair style's friction diagonal where DeviceType reads it
  Kokkos::View<double **, Kokkos::LayoutRight, DeviceType> friction_on_device(int nlocal);
  Kokkos::View<double **, Kokkos::LayoutRight, DeviceType> d_friction_copy;
};

// Registers fix etd/kk, etd/kk/device and etd/kk/host with LAMMPS.
void register_fix_etd_kokkos(lammpsplugin_t plugin, lammpsplugin_regfunc register_plugin,
                             void *lmp);

}    // namespace LAMMPS_NS

#endif
