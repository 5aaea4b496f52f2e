// ETD-DPD: the definitions of PairDPDLawKokkos (pair_dpd_law_kokkos.h), included by the one
// source file that instantiates them for the package's styles.
#ifndef ETD_PAIR_DPD_LAW_KOKKOS_IMPL_H
#define ETD_PAIR_DPD_LAW_KOKKOS_IMPL_H

#include "pair_dpd_law_kokkos.h"
#include "pair_dpd_law_kokkos_kernel.h"

#include "kokkos_views.h"

#include "atom_kokkos.h"
#include "atom_masks.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "kokkos.h"
#include "memory_kokkos.h"
#include "neigh_list_kokkos.h"
#include "neigh_request.h"
#include "neighbor.h"
#include "update.h"

#include <cmath>

namespace LAMMPS_NS {

template <class DeviceType, class Style>
PairDPDLawKokkos<DeviceType, Style>::PairDPDLawKokkos(LAMMPS *lmp) :
    Base(lmp), host_loop(false), neighflag(0), newton_pair_kk(1), nlocal_kk(0),
    special_lj_kk{1.0, 1.0, 1.0, 1.0}, timestep_kk(0),
    inv_sqrt_dt(0.0), need_dup(0)
{
  this->kokkosable = 1;
  this->atomKK = (AtomKokkos *) this->atom;
  this->execution_space = ExecutionSpaceFromDevice<DeviceType>::space;
  this->datamask_read = EMPTY_MASK;
  this->datamask_modify = EMPTY_MASK;
}

template <class DeviceType, class Style> PairDPDLawKokkos<DeviceType, Style>::~PairDPDLawKokkos()
{
  if (this->copymode) return;
  this->memoryKK->destroy_kokkos(k_eatom, this->eatom);
  this->memoryKK->destroy_kokkos(k_vatom, this->vatom);
  // cutsq's rows live in k_cutsq: it is released here, before the base class would free them
  this->memoryKK->destroy_kokkos(k_cutsq, this->cutsq);
}

template <class DeviceType, class Style> void PairDPDLawKokkos<DeviceType, Style>::allocate()
{
  Base::allocate();
  const int n = this->atom->ntypes;
  this->memory->destroy(this->cutsq);
  this->memoryKK->create_kokkos(k_cutsq, this->cutsq, n + 1, n + 1, "pair:cutsq");
  d_cutsq = k_cutsq.template view<DeviceType>();
  k_params = Kokkos::DualView<Coefficients **, Kokkos::LayoutRight, DeviceType>(
      "PairDPDLawKokkos::params", n + 1, n + 1);
  params = k_params.template view<DeviceType>();
}

template <class DeviceType, class Style> void PairDPDLawKokkos<DeviceType, Style>::init_style()
{
  Base::init_style();
  copy_ziggurat_tables();
  host_loop = false;
  // a half list in any case (see the header): under neigh full the kernel adds atomically
  neighflag = this->lmp->kokkos->neighflag == HALF ? HALF : HALFTHREAD;
  this->neigh_request->set_kokkos_host(std::is_same_v<DeviceType, LMPHostType> &&
                                       !std::is_same_v<DeviceType, LMPDeviceType>);
  this->neigh_request->set_kokkos_device(std::is_same_v<DeviceType, LMPDeviceType>);
  this->execution_space = ExecutionSpaceFromDevice<DeviceType>::space;
  this->datamask_read = EMPTY_MASK;
  this->datamask_modify = EMPTY_MASK;
}

// The noise of the style (its seed) with the ziggurat's tables where DeviceType reads them.
template <class DeviceType, class Style>
void PairDPDLawKokkos<DeviceType, Style>::copy_ziggurat_tables()
{
  noise_kk = this->noise;
  if constexpr (!reads_host_memory)
    noise_kk = etd::kk::noise_with_device_tables(this->noise, d_ziggurat_tables);
}

// A host neighbor list and host arrays for this run: LAMMPS syncs all of an atom's data to the
// host before the style computes (datamask ALL) and marks it modified there after.
template <class DeviceType, class Style> void PairDPDLawKokkos<DeviceType, Style>::use_host_loop()
{
  if (host_loop) return;
  host_loop = true;
  this->neigh_request->set_kokkos_host(0);
  this->neigh_request->set_kokkos_device(0);
  this->execution_space = Host;
  this->datamask_read = ALL_MASK;
  this->datamask_modify = ALL_MASK;
  // the conservative-only loop (fix etd's implicit scheme) on the host's threads
  this->run_in_chunks(Kokkos::DefaultHostExecutionSpace().concurrency(),
                      etd::kk::host_chunk_runner("etd:pair_loop"));
}

template <class DeviceType, class Style>
void PairDPDLawKokkos<DeviceType, Style>::request_conservative_only()
{
  use_host_loop();
  Base::request_conservative_only();
}
template <class DeviceType, class Style>
void PairDPDLawKokkos<DeviceType, Style>::request_newton_off_list()
{
  use_host_loop();
  Base::request_newton_off_list();
}

template <class DeviceType, class Style>
double PairDPDLawKokkos<DeviceType, Style>::init_one(int i, int j)
{
  const double range = Base::init_one(i, j);
  k_params.view_host()(i, j) = this->table[i * this->stride + j];
  k_params.view_host()(j, i) = this->table[j * this->stride + i];
  k_params.modify_host();
  // (LAMMPS's host copy, which the CPU loop also reads as cutsq)
  k_cutsq.view_host()(i, j) = k_cutsq.view_host()(j, i) = range * range;
  k_cutsq.modify_host();
  return range;
}

template <class DeviceType, class Style>
void PairDPDLawKokkos<DeviceType, Style>::compute(int eflag, int vflag)
{
  if (host_loop)
    Base::compute(eflag, vflag);
  else
    compute_on_device(eflag, vflag);
}

// A duplicated scatter view of view (one copy per thread), kept from one compute to the next
// while the shape holds and zeroed there: allocated anew at every compute, its pages fault in on
// every thread at every step, which cost a second thread much of its gain.
template <class Duplicated, class View> void keep_duplicated(Duplicated &dup, const View &view)
{
  const auto first = dup.subview();
  if (dup.is_allocated() && first.extent(0) == view.extent(0) && first.extent(1) == view.extent(1))
    dup.reset();
  else
    dup = Kokkos::Experimental::create_scatter_view<KKScatterSum, KKScatterDuplicated>(view);
}

template <class DeviceType, class Style>
void PairDPDLawKokkos<DeviceType, Style>::compute_on_device(int eflag, int vflag)
{
  this->ev_init(eflag, vflag, 0);
  // (host threads only: a device's kernel runs one thread per atom and takes LAMMPS's period,
  // as dpd/kk does; bench/kokkos/README.md, "On a GPU")
  if (etd::kk::AtomSortSchedule::splits_by_index<typename DeviceType::execution_space>())
    sorting.keep_due(this->atom, this->update->ntimestep);
  bind_atoms();
  make_scatter_views();
  const bool extras = this->prepare_extras();
  extras_to_device(extras);

  EV_FLOAT ev;
  this->copymode = 1;
  if (neighflag == HALF)
    launch<HALF>(this->list->inum, ev);
  else
    launch<HALFTHREAD>(this->list->inum, ev);
  if (need_dup) Kokkos::Experimental::contribute(f, dup_f);
  extras_to_host(extras);

  if (this->eflag_global) this->eng_vdwl += ev.evdwl;
  if (this->vflag_global)
    for (int k = 0; k < 6; k++) this->virial[k] += ev.v[k];
  if (this->vflag_fdotr) pair_virial_fdotr_compute(this);
  per_atom_tallies_to_host();
  this->copymode = 0;
  this->atomKK->modified(this->execution_space,
                         this->evflag ? (F_MASK | ENERGY_MASK | VIRIAL_MASK) : F_MASK);
  if (need_dup) {
    dup_eatom = {};
    dup_vatom = {};
  }
  // the ghosts' parts of the extras onto their owners, on the host arrays
  this->finish_extras(extras);
}

// This compute's per-atom tallies (as requested), the atoms' arrays in DeviceType's memory, the
// scalars the kernel reads, and LAMMPS's Kokkos list
template <class DeviceType, class Style> void PairDPDLawKokkos<DeviceType, Style>::bind_atoms()
{
  if (this->eflag_atom) {
    this->memoryKK->destroy_kokkos(k_eatom, this->eatom);
    this->memoryKK->create_kokkos(k_eatom, this->eatom, this->maxeatom, "pair:eatom");
    d_eatom = k_eatom.template view<DeviceType>();
  }
  if (this->vflag_atom) {
    this->memoryKK->destroy_kokkos(k_vatom, this->vatom);
    this->memoryKK->create_kokkos(k_vatom, this->vatom, this->maxvatom, "pair:vatom");
    d_vatom = k_vatom.template view<DeviceType>();
  }
  this->atomKK->sync(this->execution_space,
                     X_MASK | V_MASK | F_MASK | TYPE_MASK | TAG_MASK | ENERGY_MASK | VIRIAL_MASK);
  x = this->atomKK->k_x.template view<DeviceType>();
  v = this->atomKK->k_v.template view<DeviceType>();
  f = this->atomKK->k_f.template view<DeviceType>();
  type = this->atomKK->k_type.template view<DeviceType>();
  tag = this->atomKK->k_tag.template view<DeviceType>();
  k_cutsq.template sync<DeviceType>();
  k_params.template sync<DeviceType>();
  for (int k = 0; k < 4; k++) special_lj_kk[k] = this->force->special_lj[k];
  timestep_kk = this->update->ntimestep;
  newton_pair_kk = this->force->newton_pair;
  nlocal_kk = this->atom->nlocal;
  inv_sqrt_dt = 1.0 / std::sqrt(this->update->dt);

  auto *k_list = static_cast<NeighListKokkos<DeviceType> *>(this->list);
  d_numneigh = k_list->d_numneigh;
  d_neighbors = k_list->d_neighbors;
  d_ilist = k_list->d_ilist;
}

// The scatter views the kernel adds forces and tallies through: duplicated per thread where
// threads share a half list (as KokkosLMP::need_dup, for the kernel's own flag: the package's
// may be FULL), else atomic or plain
template <class DeviceType, class Style>
void PairDPDLawKokkos<DeviceType, Style>::make_scatter_views()
{
  need_dup = neighflag == HALFTHREAD &&
      std::is_same_v<NeedDup_v<HALFTHREAD, DeviceType>, Kokkos::Experimental::ScatterDuplicated>;
  if (need_dup) {
    keep_duplicated(dup_f, f);
    dup_eatom =
        Kokkos::Experimental::create_scatter_view<KKScatterSum, KKScatterDuplicated>(d_eatom);
    dup_vatom =
        Kokkos::Experimental::create_scatter_view<KKScatterSum, KKScatterDuplicated>(d_vatom);
  } else {
    ndup_f = Kokkos::Experimental::create_scatter_view<KKScatterSum, KKScatterNonDuplicated>(f);
    ndup_eatom =
        Kokkos::Experimental::create_scatter_view<KKScatterSum, KKScatterNonDuplicated>(d_eatom);
    ndup_vatom =
        Kokkos::Experimental::create_scatter_view<KKScatterSum, KKScatterNonDuplicated>(d_vatom);
  }
}

// the per-atom energy and virial, summed over the threads' copies, into LAMMPS's host arrays
template <class DeviceType, class Style>
void PairDPDLawKokkos<DeviceType, Style>::per_atom_tallies_to_host()
{
  if (this->eflag_atom) {
    if (need_dup) Kokkos::Experimental::contribute(d_eatom, dup_eatom);
    k_eatom.template modify<DeviceType>();
    // sync_host() reaches LAMMPS's own host array (eatom, and vatom below); in LAMMPS 4Jul2026
    // sync<LMPHostType>() syncs only the TransformView's Kokkos views, not that array
    k_eatom.sync_host();
  }
  if (this->vflag_atom) {
    if (need_dup) Kokkos::Experimental::contribute(d_vatom, dup_vatom);
    k_vatom.template modify<DeviceType>();
    k_vatom.sync_host();
  }
}

// The extras' views for the kernel: the host arrays that prepare_extras() sized and zeroed
// themselves where the kernel reads host memory, else zeroed device arrays of their shape.
template <class DeviceType, class Style>
void PairDPDLawKokkos<DeviceType, Style>::extras_to_device(bool extras)
{
  const int rows = this->nmax_extras;
  const auto view_of = [&](bool wanted, double **host, int columns, ExtrasView &device,
                           const char *name) {
    if (!extras || !wanted) {
      device = ExtrasView();
    } else if constexpr (reads_host_memory) {
      device = ExtrasView(&host[0][0], rows, columns);
    } else {
      // a label is a std::string: View takes no const char * (the host branch above hid this)
      if (static_cast<int>(device.extent(0)) != rows)
        device = ExtrasView(std::string(name), rows, columns);
      Kokkos::deep_copy(device, 0.0);
    }
  };
  view_of(this->want_friction, this->friction, Base::FRICTION_VALUES, d_friction, "pair:friction");
  view_of(this->want_split, this->split, this->split_values, d_split, "pair:split");
  if (need_dup) {
    keep_duplicated(dup_friction, d_friction);
    keep_duplicated(dup_split, d_split);
  } else {
    ndup_friction =
        Kokkos::Experimental::create_scatter_view<KKScatterSum, KKScatterNonDuplicated>(d_friction);
    ndup_split =
        Kokkos::Experimental::create_scatter_view<KKScatterSum, KKScatterNonDuplicated>(d_split);
  }
}

template <class DeviceType, class Style>
void PairDPDLawKokkos<DeviceType, Style>::extras_to_host(bool extras)
{
  if (!extras) return;
  if (need_dup) {
    if (this->want_friction) Kokkos::Experimental::contribute(d_friction, dup_friction);
    if (this->want_split) Kokkos::Experimental::contribute(d_split, dup_split);
  }
  if constexpr (!reads_host_memory) {
    using HostView = Kokkos::View<double **, Kokkos::LayoutRight, Kokkos::HostSpace>;
    const int rows = this->nmax_extras;
    if (this->want_friction)
      Kokkos::deep_copy(HostView(&this->friction[0][0], rows, Base::FRICTION_VALUES), d_friction);
    if (this->want_split)
      Kokkos::deep_copy(HostView(&this->split[0][0], rows, this->split_values), d_split);
  }
}

// LAMMPS's memory line: the CPU style's arrays and what the kernel keeps beside them, the
// threads' copies of the forces and extras (one per unique token of the space: its concurrency
// on the host backends) and, in a device's memory, the extras
template <class DeviceType, class Style> double PairDPDLawKokkos<DeviceType, Style>::memory_usage()
{
  const auto copies = [](const auto &duplicated) {
    if (!duplicated.is_allocated()) return 0.0;
    return static_cast<double>(etd::kk::bytes_of(duplicated.subview())) *
        typename DeviceType::execution_space().concurrency();
  };
  double bytes = Base::memory_usage() + copies(dup_f) + copies(dup_friction) + copies(dup_split);
  if constexpr (!reads_host_memory) bytes += etd::kk::bytes_of(d_friction, d_split);
  return bytes;
}

template <class DeviceType, class Style>
template <int NEIGHFLAG>
void PairDPDLawKokkos<DeviceType, Style>::launch(int inum, EV_FLOAT &ev)
{
  if (this->want_friction && this->want_split)
    launch_with<NEIGHFLAG, 1, 1>(inum, ev);
  else if (this->want_friction)
    launch_with<NEIGHFLAG, 1, 0>(inum, ev);
  else if (this->want_split)
    launch_with<NEIGHFLAG, 0, 1>(inum, ev);
  else
    launch_with<NEIGHFLAG, 0, 0>(inum, ev);
}

template <class DeviceType, class Style>
template <int NEIGHFLAG, int FRICTION, int SPLIT>
void PairDPDLawKokkos<DeviceType, Style>::launch_with(int inum, EV_FLOAT &ev)
{
  if (this->evflag)
    Kokkos::parallel_reduce(
        Kokkos::RangePolicy<DeviceType, TagPairLaw<NEIGHFLAG, 1, FRICTION, SPLIT>>(0, inum), *this,
        ev);
  else
    Kokkos::parallel_for(
        Kokkos::RangePolicy<DeviceType, TagPairLaw<NEIGHFLAG, 0, FRICTION, SPLIT>>(0, inum), *this);
}

template <class DeviceType, class Style> Pair *create_pair_style_kokkos(LAMMPS *lmp)
{
  return new PairDPDLawKokkos<DeviceType, Style>(lmp);
}

template <class Style>
void register_pair_style_kokkos(lammpsplugin_t plugin, lammpsplugin_regfunc register_plugin,
                                void *lmp)
{
  static const std::string kk = std::string(Style::name) + "/kk";
  static const std::string device = kk + "/device";
  static const std::string host = kk + "/host";
  static const std::string info = std::string(Style::info) + " (KOKKOS)";
  plugin.style = "pair";
  plugin.info = info.c_str();
  plugin.creator.v1 = (lammpsplugin_factory1 *) &create_pair_style_kokkos<LMPDeviceType, Style>;
  plugin.name = kk.c_str();
  (*register_plugin)(&plugin, lmp);
  plugin.name = device.c_str();
  (*register_plugin)(&plugin, lmp);
  plugin.creator.v1 = (lammpsplugin_factory1 *) &create_pair_style_kokkos<LMPHostType, Style>;
  plugin.name = host.c_str();
  (*register_plugin)(&plugin, lmp);
}

}    // namespace LAMMPS_NS

#endif
