// ETD-DPD: the incidence list of the implicit scheme's pairs, for G applied atom by atom on a
// device (friction_operator_kokkos.h): per owned atom, the pairs it takes part in, in pair order,
// with the atom at each pair's other end and which end it is, so that no two threads write one
// atom and every atom's sum has the order of the pairs. Pure Kokkos.
#ifndef ETD_FRICTION_INCIDENCE_KOKKOS_H
#define ETD_FRICTION_INCIDENCE_KOKKOS_H

#include "kokkos_views.h"

#include <Kokkos_Core.hpp>

#include <vector>

namespace etd {

template <class DeviceType> class FrictionIncidenceKokkos {
 public:
  using execution_space = typename DeviceType::execution_space;
  using Values = kk::Values<DeviceType>;
  using Indices = kk::Indices<DeviceType>;
  using Geometry = kk::Geometry<DeviceType>;

  // the incidence list from the pairs' ends in host memory, in one pass: each atom's entries in
  // pair order (the pair, the atom at its other end, and which end the atom is)
  void build_on_host(const int *pair_i, const int *pair_j, int npairs, int nowned)
  {
    kk::grow(offsets_, nowned + 1);
    auto h_offsets = Kokkos::create_mirror_view(offsets_);
    for (int a = 0; a <= nowned; a++) h_offsets(a) = 0;
    for (int p = 0; p < npairs; p++) {
      h_offsets(pair_i[p] + 1)++;
      if (pair_j[p] < nowned) h_offsets(pair_j[p] + 1)++;
    }
    for (int a = 0; a < nowned; a++) h_offsets(a + 1) += h_offsets(a);
    const int entries = h_offsets(nowned);
    kk::grow(incidence_, entries);
    kk::grow(other_, entries);
    kk::grow(end_, entries);
    auto h_incidence = Kokkos::create_mirror_view(incidence_);
    auto h_other = Kokkos::create_mirror_view(other_);
    auto h_end = Kokkos::create_mirror_view(end_);
    fill_.assign(h_offsets.data(), h_offsets.data() + nowned);
    for (int p = 0; p < npairs; p++) {
      const int at_i = fill_[pair_i[p]]++;
      h_incidence(at_i) = p;
      h_other(at_i) = pair_j[p];
      h_end(at_i) = 1;
      if (pair_j[p] < nowned) {
        const int at_j = fill_[pair_j[p]]++;
        h_incidence(at_j) = p;
        h_other(at_j) = pair_i[p];
        h_end(at_j) = -1;
      }
    }
    Kokkos::deep_copy(offsets_, h_offsets);
    Kokkos::deep_copy(incidence_, h_incidence);
    Kokkos::deep_copy(other_, h_other);
    Kokkos::deep_copy(end_, h_end);
  }

  // the same from the pairs' ends in DeviceType's memory, in kernels: atomics, then each atom's
  // entries sorted back to pair order
  void build_in_kernels(const Indices &pair_i, const Indices &pair_j, int npairs, int nowned)
  {
    kk::grow(offsets_, nowned + 1);
    Kokkos::deep_copy(offsets_, 0);
    auto offsets = offsets_;
    Kokkos::parallel_for(
        "etd:incidence_count", Kokkos::RangePolicy<execution_space>(0, npairs),
        KOKKOS_LAMBDA(const int p) {
          Kokkos::atomic_inc(&offsets(pair_i(p) + 1));
          if (pair_j(p) < nowned) Kokkos::atomic_inc(&offsets(pair_j(p) + 1));
        });
    int entries = 0;
    Kokkos::parallel_scan(
        "etd:incidence_place", Kokkos::RangePolicy<execution_space>(0, nowned + 1),
        KOKKOS_LAMBDA(const int a, int &sum, const bool final) {
          sum += offsets(a);
          if (final) offsets(a) = sum;
        },
        entries);
    kk::grow(incidence_, entries);
    kk::grow(other_, entries);
    kk::grow(end_, entries);
    kk::grow(cursor_, nowned);
    auto cursor = cursor_;
    Kokkos::parallel_for(
        "etd:incidence_cursor", Kokkos::RangePolicy<execution_space>(0, nowned),
        KOKKOS_LAMBDA(const int a) { cursor(a) = offsets(a); });
    auto incidence = incidence_;
    auto other = other_;
    auto end = end_;
    Kokkos::parallel_for(
        "etd:incidence_fill", Kokkos::RangePolicy<execution_space>(0, npairs),
        KOKKOS_LAMBDA(const int p) {
          const int i = pair_i(p), j = pair_j(p);
          const int at_i = Kokkos::atomic_fetch_add(&cursor(i), 1);
          incidence(at_i) = p;
          other(at_i) = j;
          end(at_i) = 1;
          if (j < nowned) {
            const int at_j = Kokkos::atomic_fetch_add(&cursor(j), 1);
            incidence(at_j) = p;
            other(at_j) = i;
            end(at_j) = -1;
          }
        });
    // the atomics placed each atom's entries in any order: back to pair order (a pair with an
    // image of its own atom has both ends there, i's first), so that every sum has one order
    Kokkos::parallel_for(
        "etd:incidence_sort", Kokkos::RangePolicy<execution_space>(0, nowned),
        KOKKOS_LAMBDA(const int a) {
          for (int e = offsets(a) + 1; e < offsets(a + 1); e++) {
            const int p = incidence(e), o = other(e), side = end(e);
            int f = e;
            for (; f > offsets(a) && (incidence(f - 1) > p ||
                                      (incidence(f - 1) == p && end(f - 1) < side));
                 f--) {
              incidence(f) = incidence(f - 1);
              other(f) = other(f - 1);
              end(f) = end(f - 1);
            }
            incidence(f) = p;
            other(f) = o;
            end(f) = side;
          }
        });
  }

  // out_a = mass_weight m_a u_a + friction_weight (G u)_a for atom a (u over the partners).
  // A pair's share on either of its atoms is gamma w_D (e . (u_a - u_other)) e: the sign of e
  // cancels, so each atom reads only its own entries.
  KOKKOS_INLINE_FUNCTION static void apply_atom(int a, const Values &u, const Values &inertia,
                                                const Indices &offsets, const Indices &incidence,
                                                const Indices &other, const Geometry &geometry,
                                                double mass_weight, double friction_weight,
                                                double out[3])
  {
    const double ua0 = u(3 * a), ua1 = u(3 * a + 1), ua2 = u(3 * a + 2);
    double sum0 = 0.0, sum1 = 0.0, sum2 = 0.0;
    for (int e = offsets(a); e < offsets(a + 1); e++) {
      const int p = incidence(e), o = other(e);
      const double e0 = geometry(p, 0), e1 = geometry(p, 1), e2 = geometry(p, 2);
      const double projected = geometry(p, 3) *
          (e0 * (ua0 - u(3 * o)) + e1 * (ua1 - u(3 * o + 1)) + e2 * (ua2 - u(3 * o + 2)));
      sum0 += projected * e0;
      sum1 += projected * e1;
      sum2 += projected * e2;
    }
    out[0] = mass_weight * inertia(3 * a) * ua0 + friction_weight * sum0;
    out[1] = mass_weight * inertia(3 * a + 1) * ua1 + friction_weight * sum1;
    out[2] = mass_weight * inertia(3 * a + 2) * ua2 + friction_weight * sum2;
  }

  // per owned atom (offsets: nowned + 1), its pairs, their other atoms and which end of each
  // it is (1: i, -1: j)
  const Indices &offsets() const { return offsets_; }
  const Indices &incidence() const { return incidence_; }
  const Indices &other() const { return other_; }
  const Indices &end() const { return end_; }
  std::size_t memory_usage() const
  {
    return kk::bytes_of(offsets_, incidence_, other_, end_, cursor_) +
        sizeof(int) * fill_.capacity();
  }

 private:
  Indices offsets_, incidence_, other_, end_, cursor_;
  std::vector<int> fill_;
};

}    // namespace etd

#endif
