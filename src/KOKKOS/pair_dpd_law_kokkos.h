// ETD-DPD: the KOKKOS variant of a central pair style of the package (pair_style dpd/gen/kk).
//
// The pair loop runs as a Kokkos kernel over LAMMPS's Kokkos half neighbor list, with the same
// law (pair_law.h) and the same counter-based noise keyed on atom IDs as the CPU style, so its
// forces equal the CPU style's to round-off (summation order) and its trajectories follow them.
// The style asks for a half list whatever the package's `neigh` setting: one Gaussian per pair
// is the loop's main cost, and a full list would draw each twice. Under `neigh full` (a GPU's
// default) the kernel adds to j atomically, as under `neigh half` with threads or a GPU. With
// newton off (also a GPU's default) a pair with a ghost is computed on both ranks, each for its
// own atom, and energy and virial take half of it, as LAMMPS's ev_tally does.
// Coefficients, pair_coeff, restart and write_data are the CPU style's (the class derives from
// it, as LAMMPS's dpd/kk derives from dpd).
//
// The per-atom extras that fix etd's diagonal scheme and compute dpd/split ask of the style (the
// diagonal friction, the force split) are summed in the kernel too, then handed over in the
// host arrays of the CPU style, whose reverse communication adds the ghosts' parts. What the
// implicit scheme asks (the conservative force alone, a newton-off list) the style serves with
// the CPU loop on the host for that run: it asks LAMMPS for a host neighbor list and reads and
// writes the host copies of the atom arrays, which LAMMPS's KOKKOS package syncs around it.
// Those fixes and computes run on the host in any case.
//
// The noise is Boost.Random's ziggurat as normal_ziggurat.h writes it for host and device, its
// tables copied to the device's memory, so a GPU draws the numbers the host draws.
#ifndef ETD_PAIR_DPD_LAW_KOKKOS_H
#define ETD_PAIR_DPD_LAW_KOKKOS_H

#include "pair_dpd_style.h"

#include "atom_sort_schedule.h"

#include "kokkos_pair_views.h"
#include "kokkos_type.h"
#include "pair_kokkos.h"

#include <type_traits>

namespace LAMMPS_NS {

template <class DeviceType, class Style> class PairDPDLawKokkos : public PairDPDStyle<Style> {
 public:
  using Base = PairDPDStyle<Style>;
  using Law = typename Style::Law;
  using Coefficients = typename Law::Coefficients;
  using device_type = DeviceType;
  using AT = ArrayTypes<DeviceType>;
  using Views = KokkosPairViews<DeviceType>;
  using value_type = EV_FLOAT;
  static_assert(Law::central && !Law::rotation,
                "the Kokkos pair loop is written for central laws without rotation");
  // DeviceType reads host memory: the kernel reads the ziggurat's tables and writes the extras
  // where they are (else they are copied to and from device memory)
  static constexpr bool reads_host_memory =
      Kokkos::SpaceAccessibility<typename DeviceType::memory_space, Kokkos::HostSpace>::accessible;

  explicit PairDPDLawKokkos(class LAMMPS *);
  ~PairDPDLawKokkos() override;

  void init_style() override;
  double init_one(int i, int j) override;
  void compute(int eflag, int vflag) override;
  double memory_usage() override;

  // what the implicit scheme asks of the style: served by the host loop
  void request_conservative_only() override;
  void request_newton_off_list() override;
  // fix etd's own pair search: for the host loop (the implicit scheme's), which reads pairs as
  // the CPU style does; the kernel reads LAMMPS's Kokkos list
  bool use_external_pairs(const etd::ExternalPairs *source) override
  {
    return host_loop && Base::use_external_pairs(source);
  }

  // FRICTION, SPLIT: the kernel also sums the diagonal friction, the force split
  template <int NEIGHFLAG, int EVFLAG, int FRICTION, int SPLIT> struct TagPairLaw {
  };
  template <int NEIGHFLAG, int EVFLAG, int FRICTION, int SPLIT>
  KOKKOS_INLINE_FUNCTION void operator()(TagPairLaw<NEIGHFLAG, EVFLAG, FRICTION, SPLIT>,
                                         const int &ii) const;
  template <int NEIGHFLAG, int EVFLAG, int FRICTION, int SPLIT>
  KOKKOS_INLINE_FUNCTION void operator()(TagPairLaw<NEIGHFLAG, EVFLAG, FRICTION, SPLIT>,
                                         const int &ii, EV_FLOAT &ev) const;

  // the views LAMMPS's f dot r virial reads
  typename Views::x_randomread x;
  typename Views::f_array f;

 protected:
  void allocate() override;

 private:
  bool host_loop;    // this run is served by the CPU loop (see the header)
  etd::kk::AtomSortSchedule sorting;    // the kernel splits the atoms among threads by index
  int neighflag;
  int newton_pair_kk;    // forces on ghosts are summed back to their owners
  int nlocal_kk;
  double special_lj_kk[4];
  etd::PairNoise
      noise_kk;    // the style's noise, with the ziggurat's tables in DeviceType's memory
  Kokkos::View<double *, DeviceType> d_ziggurat_tables;
  bigint timestep_kk;
  double inv_sqrt_dt;
  int need_dup;

  void use_host_loop();
  void copy_ziggurat_tables();
  void compute_on_device(int eflag, int vflag);
  void bind_atoms();
  void make_scatter_views();
  void per_atom_tallies_to_host();
  template <int NEIGHFLAG> void launch(int inum, EV_FLOAT &ev);
  template <int NEIGHFLAG, int FRICTION, int SPLIT> void launch_with(int inum, EV_FLOAT &ev);
  void extras_to_device(bool extras);
  void extras_to_host(bool extras);

  template <int NEIGHFLAG, int EVFLAG, int FRICTION, int SPLIT, class Forces, class Friction,
            class Split>
  KOKKOS_INLINE_FUNCTION void pair_loop(const int ii, EV_FLOAT &ev, Forces &a_f,
                                        Friction &a_friction, Split &a_split) const;
  template <int NEIGHFLAG>
  KOKKOS_INLINE_FUNCTION void ev_tally(EV_FLOAT &ev, int i, int j, bool update_j, double epair,
                                       double fpair, double delx, double dely, double delz) const;

  using KKDeviceType = typename KKDevice<DeviceType>::value;
  template <typename DataType, typename Layout>
  using DupScatterView =
      KKScatterView<DataType, Layout, KKDeviceType, KKScatterSum, KKScatterDuplicated>;
  template <typename DataType, typename Layout>
  using NonDupScatterView =
      KKScatterView<DataType, Layout, KKDeviceType, KKScatterSum, KKScatterNonDuplicated>;

  DupScatterView<double *[3], typename Views::f_layout> dup_f;
  DupScatterView<double *, typename Views::eatom_layout> dup_eatom;
  DupScatterView<double *[6], typename Views::vatom_layout> dup_vatom;
  NonDupScatterView<double *[3], typename Views::f_layout> ndup_f;
  NonDupScatterView<double *, typename Views::eatom_layout> ndup_eatom;
  NonDupScatterView<double *[6], typename Views::vatom_layout> ndup_vatom;

  typename Views::v_randomread v;
  typename AT::t_int_1d_randomread type;
  typename AT::t_tagint_1d_randomread tag;
  typename AT::t_neighbors_2d d_neighbors;
  typename AT::t_int_1d_randomread d_ilist;
  typename AT::t_int_1d_randomread d_numneigh;

  typename Views::cutsq_dual k_cutsq;
  typename Views::cutsq d_cutsq;
  Kokkos::DualView<Coefficients **, Kokkos::LayoutRight, DeviceType> k_params;
  typename Kokkos::DualView<Coefficients **, Kokkos::LayoutRight, DeviceType>::t_dev_const_um
      params;

  // the extras: views of the CPU style's host arrays where DeviceType reads host memory, else
  // device arrays copied to them after the kernel
  using ExtrasView = Kokkos::View<double **, Kokkos::LayoutRight, DeviceType>;
  ExtrasView d_friction, d_split;
  DupScatterView<double **, Kokkos::LayoutRight> dup_friction, dup_split;
  NonDupScatterView<double **, Kokkos::LayoutRight> ndup_friction, ndup_split;

  typename Views::eatom_dual k_eatom;
  typename Views::vatom_dual k_vatom;
  typename Views::eatom d_eatom;
  typename Views::vatom d_vatom;

  friend void pair_virial_fdotr_compute<PairDPDLawKokkos>(PairDPDLawKokkos *);
};

// Registers Style's /kk, /kk/device and /kk/host variants with LAMMPS.
template <class Style>
void register_pair_style_kokkos(lammpsplugin_t plugin, lammpsplugin_regfunc register_plugin,
                                void *lmp);

}    // namespace LAMMPS_NS

#endif
