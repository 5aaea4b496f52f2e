// ETD-DPD: the pair kernel of PairDPDLawKokkos (pair_dpd_law_kokkos.h): what one listed atom's
// row does on the device (the law's forces, the extras, the tallies), included by
// pair_dpd_law_kokkos_impl.h.
#ifndef ETD_PAIR_DPD_LAW_KOKKOS_KERNEL_H
#define ETD_PAIR_DPD_LAW_KOKKOS_KERNEL_H

#include "pair_dpd_law_kokkos.h"

#include <cmath>

namespace LAMMPS_NS {

template <class DeviceType, class Style>
template <int NEIGHFLAG, int EVFLAG, int FRICTION, int SPLIT>
KOKKOS_INLINE_FUNCTION void
PairDPDLawKokkos<DeviceType, Style>::operator()(TagPairLaw<NEIGHFLAG, EVFLAG, FRICTION, SPLIT>,
                                                const int &ii) const
{
  EV_FLOAT ev;
  this->template operator()<NEIGHFLAG, EVFLAG, FRICTION, SPLIT>(
      TagPairLaw<NEIGHFLAG, EVFLAG, FRICTION, SPLIT>(), ii, ev);
}

// Forces on j go through scatter views (duplicated per thread with OpenMP and HALFTHREAD, plain
// with HALF). The accessors of the extras are made only where the kernel sums them: made for
// every atom but unused, they cost the kernel its gain from a second thread.
template <class DeviceType, class Style>
template <int NEIGHFLAG, int EVFLAG, int FRICTION, int SPLIT>
KOKKOS_INLINE_FUNCTION void
PairDPDLawKokkos<DeviceType, Style>::operator()(TagPairLaw<NEIGHFLAG, EVFLAG, FRICTION, SPLIT>,
                                                const int &ii, EV_FLOAT &ev) const
{
  using Dup = NeedDup_v<NEIGHFLAG, DeviceType>;
  using Atomic = AtomicDup_v<NEIGHFLAG, DeviceType>;
  auto v_f = ScatterViewHelper<Dup, decltype(dup_f), decltype(ndup_f)>::get(dup_f, ndup_f);
  auto a_f = v_f.template access<Atomic>();
  int none = 0;
  const auto with_split = [&](auto &a_friction) {
    if constexpr (SPLIT != 0) {
      auto v_split = ScatterViewHelper<Dup, decltype(dup_split), decltype(ndup_split)>::get(
          dup_split, ndup_split);
      auto a_split = v_split.template access<Atomic>();
      pair_loop<NEIGHFLAG, EVFLAG, FRICTION, SPLIT>(ii, ev, a_f, a_friction, a_split);
    } else {
      pair_loop<NEIGHFLAG, EVFLAG, FRICTION, SPLIT>(ii, ev, a_f, a_friction, none);
    }
  };
  if constexpr (FRICTION != 0) {
    auto v_friction = ScatterViewHelper<Dup, decltype(dup_friction), decltype(ndup_friction)>::get(
        dup_friction, ndup_friction);
    auto a_friction = v_friction.template access<Atomic>();
    with_split(a_friction);
  } else {
    with_split(none);
  }
}

// One atom i and its half-list neighbours: the CPU loop's body (PairDPDBase::eval) with the
// law evaluated the same way.
template <class DeviceType, class Style>
template <int NEIGHFLAG, int EVFLAG, int FRICTION, int SPLIT, class Forces, class Friction,
          class Split>
KOKKOS_INLINE_FUNCTION void
PairDPDLawKokkos<DeviceType, Style>::pair_loop(const int ii, EV_FLOAT &ev, Forces &a_f,
                                               Friction &a_friction, Split &a_split) const
{
  const int i = d_ilist[ii];
  const double xi[3] = {x(i, 0), x(i, 1), x(i, 2)};
  const double vi[3] = {v(i, 0), v(i, 1), v(i, 2)};
  const int itype = type(i);
  const tagint tagi = tag(i);
  const etd::PairStep step{noise_kk, timestep_kk, inv_sqrt_dt};
  double fi[3] = {0.0, 0.0, 0.0};
  double gi[3] = {0.0, 0.0, 0.0};    // i's diagonal friction
  double si[Base::FORCE_SPLIT_VALUES] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};

  // as in the CPU loop (close_neighbors.h): the neighbours within the cutoff are gathered
  // first, without a branch, then the work is done on those alone; in chunks, so that the
  // scratch is a small array of the thread's own
  constexpr int CHUNK = 64;
  int close[CHUNK];
  const int jnum = d_numneigh[i];
  for (int first = 0; first < jnum; first += CHUNK) {
    const int last = first + CHUNK < jnum ? first + CHUNK : jnum;
    int nclose = 0;
    for (int jj = first; jj < last; jj++) {
      const int entry = d_neighbors(i, jj);
      const int j = entry & NEIGHMASK;
      const double dx = xi[0] - x(j, 0), dy = xi[1] - x(j, 1), dz = xi[2] - x(j, 2);
      close[nclose] = entry;
      nclose += (dx * dx + dy * dy + dz * dz < d_cutsq(itype, type(j))) ? 1 : 0;
    }
    for (int c = 0; c < nclose; c++) {
      int j = close[c];
      const double factor = special_lj_kk[(j >> SBBITS) & 3];
      j &= NEIGHMASK;
      etd::PairGeometry g;
      g.del[0] = xi[0] - x(j, 0);
      g.del[1] = xi[1] - x(j, 1);
      g.del[2] = xi[2] - x(j, 2);
      g.rsq = g.del[0] * g.del[0] + g.del[1] * g.del[1] + g.del[2] * g.del[2];
      g.r = std::sqrt(g.rsq);
      if (g.r < Base::MIN_DISTANCE) continue;
      g.rinv = 1.0 / g.r;
      g.special = factor;

      const int jtype = type(j);
      const Coefficients &c_ij = params(itype, jtype);
      const double vj[3] = {v(j, 0), v(j, 1), v(j, 2)};
      Law pair(c_ij, g);
      const etd::PairMotion motion{vi, vj, nullptr, nullptr, tagi, tag(j)};
      pair.template evaluate<1>(motion, step);
      // newton off: a ghost's share is computed by its owner's rank
      const bool update_j = newton_pair_kk || j < nlocal_kk;
      for (int k = 0; k < 3; k++) fi[k] += pair.force[k];
      if (update_j)
        for (int k = 0; k < 3; k++) a_f(j, k) -= pair.force[k];
      if constexpr (FRICTION != 0) {
        double gt[3], gr[3];
        pair.friction_diagonal(gt, gr);
        for (int k = 0; k < 3; k++) gi[k] += gt[k];
        if (update_j)
          for (int k = 0; k < 3; k++) a_friction(j, k) += gt[k];
      }
      if constexpr (SPLIT != 0) {
        double parts[3][3], torque_parts[2][3];
        pair.split(parts, torque_parts);
        for (int p = 0; p < 3; p++)
          for (int k = 0; k < 3; k++) si[3 * p + k] += parts[p][k];
        if (update_j)
          for (int p = 0; p < 3; p++)
            for (int k = 0; k < 3; k++) a_split(j, 3 * p + k) -= parts[p][k];
      }
      if (EVFLAG) {
        const bool energy = this->eflag_global || this->eflag_atom;
        const double evdwl = energy ? Law::energy(c_ij, g.rsq, g.r, g.special) : 0.0;
        if (this->eflag_global) ev.evdwl += update_j ? evdwl : 0.5 * evdwl;
        if (this->eflag_atom || this->vflag_either)
          this->template ev_tally<NEIGHFLAG>(ev, i, j, update_j, evdwl, pair.fpair, g.del[0],
                                             g.del[1], g.del[2]);
      }
    }
  }
  for (int k = 0; k < 3; k++) a_f(i, k) += fi[k];
  if constexpr (FRICTION != 0)
    for (int k = 0; k < 3; k++) a_friction(i, k) += gi[k];
  if constexpr (SPLIT != 0)
    for (int m = 0; m < Base::FORCE_SPLIT_VALUES; m++) a_split(i, m) += si[m];
}

// Per-atom energy (half to each of i and j) and the virial of a central pair force; j's half
// only where j's share is computed here (update_j), as LAMMPS's ev_tally with newton off.
template <class DeviceType, class Style>
template <int NEIGHFLAG>
KOKKOS_INLINE_FUNCTION void
PairDPDLawKokkos<DeviceType, Style>::ev_tally(EV_FLOAT &ev, int i, int j, bool update_j,
                                              double epair, double fpair, double delx,
                                              double dely, double delz) const
{
  if (this->eflag_atom) {
    auto v_eatom = ScatterViewHelper<NeedDup_v<NEIGHFLAG, DeviceType>, decltype(dup_eatom),
                                     decltype(ndup_eatom)>::get(dup_eatom, ndup_eatom);
    auto a_eatom = v_eatom.template access<AtomicDup_v<NEIGHFLAG, DeviceType>>();
    a_eatom[i] += 0.5 * epair;
    if (update_j) a_eatom[j] += 0.5 * epair;
  }
  if (!this->vflag_either) return;
  const double w[6] = {delx * delx * fpair, dely * dely * fpair, delz * delz * fpair,
                       delx * dely * fpair, delx * delz * fpair, dely * delz * fpair};
  if (this->vflag_global) {
    const double share = update_j ? 1.0 : 0.5;
    for (int k = 0; k < 6; k++) ev.v[k] += share * w[k];
  }
  if (this->vflag_atom) {
    auto v_vatom = ScatterViewHelper<NeedDup_v<NEIGHFLAG, DeviceType>, decltype(dup_vatom),
                                     decltype(ndup_vatom)>::get(dup_vatom, ndup_vatom);
    auto a_vatom = v_vatom.template access<AtomicDup_v<NEIGHFLAG, DeviceType>>();
    for (int k = 0; k < 6; k++) {
      a_vatom(i, k) += 0.5 * w[k];
      if (update_j) a_vatom(j, k) += 0.5 * w[k];
    }
  }
}

}    // namespace LAMMPS_NS

#endif
