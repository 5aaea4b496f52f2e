// ETD-DPD: the implicit scheme's friction operator in Kokkos kernels, for translation (3 unknowns
// an atom): the step's pairs, the right-hand sides they give (the inertial step's, the
// overdamped step's terms), and A u = mass_weight M u + friction_weight G u, on which the solve
// (friction_solve_kokkos.h) builds. Pure Kokkos (no LAMMPS), so a unit test compares it with
// the CPU solver directly.
//
// Where the kernels run on the host (OpenMP, Serial), G is applied pair by pair, each pair once
// as the CPU solver applies it, each thread into a copy of its own (friction_pair_sums_kokkos.h).
// On a device, G is applied per owned atom over the pairs it takes part in (an incidence list
// built with the pairs, friction_incidence_kokkos.h), so no two threads write one atom. Every
// sum has a fixed order for a given thread count. Vectors over the partners (owned atoms, then
// one slot per remote atom, implicit_partners.h) have their slots filled through the caller's
// exchange once per application of G (none on one rank): the values sent are packed in a
// kernel, and only they and the slots' values pass through the host.
#ifndef ETD_FRICTION_OPERATOR_KOKKOS_H
#define ETD_FRICTION_OPERATOR_KOKKOS_H

#include "friction_incidence_kokkos.h"
#include "friction_operator.h"
#include "friction_pair_sums_kokkos.h"
#include "kokkos_views.h"

#include <Kokkos_Core.hpp>

#include <cmath>
#include <functional>
#include <vector>

namespace etd {

template <class DeviceType> class FrictionOperatorKokkos {
 public:
  using execution_space = typename DeviceType::execution_space;
  using Values = kk::Values<DeviceType>;
  using Indices = kk::Indices<DeviceType>;
  using Geometry = kk::Geometry<DeviceType>;
  // How a partner vector's slots [3 nowned, 3 npartners) are filled from their owners
  // (PartnerExchange::swap): the owned atoms whose values other ranks need, in order, and
  // swap(their values, the slots' values), 3 values an atom, host arrays, collective among the
  // partners. Only these values cross between DeviceType's memory and the host; a rank with
  // nothing sent and no slots (one rank) skips it.
  struct Exchange {
    const int *sent = nullptr;
    int nsent = 0;
    std::function<void(const double *, double *)> swap;
  };
  using PairSums = PairSumsKokkos<DeviceType>;
  template <int Width> using Shares = typename PairSums::template Shares<Width>;
  using Incidence = FrictionIncidenceKokkos<DeviceType>;

  // whether the kernels run where the host's memory is (then G is applied pair by pair)
  static constexpr bool on_host =
      Kokkos::SpaceAccessibility<Kokkos::DefaultHostExecutionSpace,
                                 typename DeviceType::memory_space>::accessible;

  // the bytes its views and host buffers hold (the pairs handed to it by the host, G's sums or
  // incidence list, the vectors of the right-hand sides and of the solve); the geometry kept
  // from pairs already in DeviceType's memory is counted by their owner
  std::size_t memory_usage() const
  {
    const std::size_t own_geometry = geometry_.use_count() > 1 ? 0 : kk::bytes_of(geometry_);
    return sums_.memory_usage() + incidence_.memory_usage() + own_geometry +
        kk::bytes_of(partner_, sent_, sent_values_, inertia_, b_, x_, w_, kick_, image_) +
        sizeof(int) * (pair_i_.capacity() + pair_j_.capacity()) +
        sizeof(double) * (sent_host_.capacity() + slots_host_.capacity());
  }

  // The step's pairs (i owned, j a partner index; as FrictionPairAssembly holds them, the pairs
  // of one atom i together) over nowned owned atoms and npartners partners; their runs, or the
  // incidence list, are found here, on the host.
  void set_pairs(const std::vector<FrictionPair> &pairs, int nowned, int npartners)
  {
    nowned_ = nowned;
    npartners_ = npartners;
    const int npairs = static_cast<int>(pairs.size());
    kk::grow(geometry_, npairs);
    auto h_geometry = Kokkos::create_mirror_view(geometry_);
    pair_i_.resize(npairs);
    pair_j_.resize(npairs);
    for (int p = 0; p < npairs; p++) {
      const FrictionPair &pair = pairs[p];
      for (int k = 0; k < 3; k++) h_geometry(p, k) = pair.e[k];
      h_geometry(p, 3) = pair.friction;
      pair_i_[p] = pair.i;
      pair_j_[p] = pair.j;
    }
    Kokkos::deep_copy(geometry_, h_geometry);
    by_pairs_ = on_host;
    if constexpr (on_host) {
      kk::upload(partner_, pair_j_.data(), npairs);
      sums_.find_runs(partner_, pair_i_.data(), npairs);
    } else {
      incidence_.build_on_host(pair_i_.data(), pair_j_.data(), npairs, nowned);
    }
  }

  // The step's pairs already in DeviceType's memory (friction_pairs_kokkos.h), the views kept,
  // not copied. Where the kernels run on the host, G is applied by the pairs' runs: rows
  // (optional) gives them, row r the pairs [row_start(r), row_start(r + 1)) of atom rows(r)
  // (else they are found from pair_i). On a device the incidence list is built in kernels, each
  // atom's entries in pair order.
  void set_pairs(const Indices &pair_i, const Indices &pair_j, const Geometry &geometry,
                 int npairs, int nowned, int npartners, const Indices *rows = nullptr,
                 const Indices *row_start = nullptr, int nrows = 0)
  {
    if constexpr (on_host) {
      nowned_ = nowned;
      npartners_ = npartners;
      geometry_ = geometry;
      by_pairs_ = true;
      if (rows)
        sums_.set_runs(pair_j, *rows, *row_start, nrows);
      else
        sums_.find_runs(pair_j, pair_i.data(), npairs);
    } else {
      set_pairs_in_kernels(pair_i, pair_j, geometry, npairs, nowned, npartners);
    }
  }

  // the same, the incidence list built in kernels (a GPU's path; public for its test)
  void set_pairs_in_kernels(const Indices &pair_i, const Indices &pair_j,
                            const Geometry &geometry, int npairs, int nowned, int npartners)
  {
    nowned_ = nowned;
    npartners_ = npartners;
    geometry_ = geometry;
    by_pairs_ = false;
    incidence_.build_in_kernels(pair_i, pair_j, npairs, nowned);
  }

  // The friction step's right-hand side over the owned atoms, b = M v - (h/2) G u +
  // sqrt(h) sum_pairs (+-) noise e (+ on the pair's i, - on its j), with u given on all partners
  // and the pairs' noise sigma w_R theta; with gu (optional) also G u. Under moving images
  // (image_offsets: 3 per pair, the velocity of the pair's ghost image on top of its owner's)
  // b also holds -h G_offset, the friction of the images' velocities. Host arrays: inertia, v,
  // b, gu 3 nowned values, u 3 npartners.
  void step_rhs(const double *inertia, const double *v, const double *u, const Values &noise,
                double h, double *b, double *gu, const Values *image_offsets = nullptr)
  {
    const int n = 3 * nowned_;
    kk::upload(inertia_, inertia, n);
    kk::upload(b_, v, n);    // b_ holds v until it is overwritten with b
    kk::upload(x_, u, 3 * npartners_);
    const bool moving = image_offsets != nullptr;
    pair_terms(noise, std::sqrt(h), image_offsets);
    auto inertia_view = inertia_;
    auto rhs = b_;
    auto friction = w_;
    auto kick = kick_;
    auto image = image_;
    const double half_h = 0.5 * h;
    Kokkos::parallel_for(
        "etd:step_rhs", Kokkos::RangePolicy<execution_space>(0, n), KOKKOS_LAMBDA(const int d) {
          rhs(d) = inertia_view(d) * rhs(d) - half_h * friction(d) + kick(d);
          if (moving) rhs(d) -= h * image(d);
        });
    kk::download(b_, b, n);
    if (gu) kk::download(w_, gu, n);
  }

  // The overdamped step's terms over the owned atoms, into host arrays of 3 nowned values: gu =
  // G u (u given on all partners), kick = root sum_pairs (+-) noise e and, under moving images
  // (image_offsets), image = G_offset, the friction of the images' velocities (else untouched)
  void friction_terms(const double *u, const Values &noise, double root, double *gu,
                      double *kick, double *image, const Values *image_offsets = nullptr)
  {
    const int n = 3 * nowned_;
    kk::upload(x_, u, 3 * npartners_);
    pair_terms(noise, root, image_offsets);
    kk::download(w_, gu, n);
    kk::download(kick_, kick, n);
    if (image_offsets) kk::download(image_, image, n);
  }

  // Per owned atom from u in x_ (on all partners): w_ = G u, kick_ = root sum_pairs (+-) noise e
  // (+ on the pair's i, - on its j; noise: sigma w_R theta per pair) and, under moving images
  // (image_offsets: 3 per pair, the velocity of the pair's ghost image on top of its owner's),
  // image_ = G_offset, gamma w_D (e . (0 - offset)) e summed in pair order (as
  // FrictionPairAssembly::build() sums it)
  void pair_terms(const Values &noise, double root, const Values *image_offsets)
  {
    const int n = 3 * nowned_;
    kk::grow(w_, n);
    kk::grow(kick_, n);
    const bool moving = image_offsets != nullptr;
    if (moving) kk::grow(image_, n);
    auto offsets = incidence_.offsets();
    auto incidence = incidence_.incidence();
    auto other = incidence_.other();
    auto end = incidence_.end();
    auto geometry = geometry_;
    auto inertia_view = inertia_;
    auto given = x_;
    auto friction = w_;
    auto kick = kick_;
    auto image = image_;
    const Values offset = moving ? *image_offsets : Values();
    if (by_pairs_) {
      // per pair: G u, the impulse and (moving images) the images' friction, + on i, - on j
      if (moving)
        sums_.add(typename PairSums::StepShares{given, noise, offset, geometry, root, moving},
                  nowned_);
      else
        sums_.template add_friction<6>(geometry_, given, 1.0, nowned_, noise, root);
      const auto shares6 = sums_.template shares<6>();
      const auto shares9 = sums_.template shares<9>();
      Kokkos::parallel_for(
          "etd:pair_terms", Kokkos::RangePolicy<execution_space>(0, nowned_),
          KOKKOS_LAMBDA(const int a) {
            double values[9];
            if (moving)
              shares9.take(a, values);
            else
              shares6.take(a, values);
            for (int k = 0; k < 3; k++) {
              const int d = 3 * a + k;
              friction(d) = values[k];
              kick(d) = values[3 + k];
              if (moving) image(d) = values[6 + k];
            }
          });
      return;
    }
    Kokkos::parallel_for(
        "etd:pair_terms", Kokkos::RangePolicy<execution_space>(0, nowned_),
        KOKKOS_LAMBDA(const int a) {
          double g[3];
          Incidence::apply_atom(a, given, inertia_view, offsets, incidence, other, geometry, 0.0, 1.0, g);
          double impulse[3] = {0.0, 0.0, 0.0};
          for (int e = offsets(a); e < offsets(a + 1); e++) {
            const int p = incidence(e);
            const double amount = root * noise(p);
            for (int k = 0; k < 3; k++)
              impulse[k] += end(e) > 0 ? amount * geometry(p, k) : -(amount * geometry(p, k));
          }
          double image_friction[3] = {0.0, 0.0, 0.0};
          if (moving)
            for (int e = offsets(a); e < offsets(a + 1); e++) {
              const int p = incidence(e);
              const double o[3] = {offset(3 * p), offset(3 * p + 1), offset(3 * p + 2)};
              if (o[0] == 0.0 && o[1] == 0.0 && o[2] == 0.0) continue;
              const double projected = geometry(p, 3) *
                  (geometry(p, 0) * (0.0 - o[0]) + geometry(p, 1) * (0.0 - o[1]) +
                   geometry(p, 2) * (0.0 - o[2]));
              for (int k = 0; k < 3; k++)
                if (end(e) > 0)
                  image_friction[k] += projected * geometry(p, k);
                else
                  image_friction[k] -= projected * geometry(p, k);
            }
          for (int k = 0; k < 3; k++) {
            const int d = 3 * a + k;
            friction(d) = g[k];
            kick(d) = impulse[k];
            if (moving) image(d) = image_friction[k];
          }
        });
  }

  // out = A u over the owned atoms (u over the partners: its slots filled here)
  void apply(Values &u, const Values &out)
  {
    fill_slots(u);
    auto given = u;
    auto offsets = incidence_.offsets();
    auto incidence = incidence_.incidence();
    auto other = incidence_.other();
    auto geometry = geometry_;
    auto inertia = inertia_;
    const double mass_weight = mass_weight_, friction_weight = friction_weight_;
    if (by_pairs_) {
      sums_.add_friction(geometry_, u, friction_weight, nowned_);
      const auto shares = sums_.template shares<3>();
      Kokkos::parallel_for(
          "etd:apply", Kokkos::RangePolicy<execution_space>(0, nowned_),
          KOKKOS_LAMBDA(const int a) {
            double gu[3];
            shares.take(a, gu);
            for (int k = 0; k < 3; k++) {
              const int d = 3 * a + k;
              out(d) = mass_weight * inertia(d) * given(d) + gu[k];
            }
          });
      return;
    }
    Kokkos::parallel_for(
        "etd:apply", Kokkos::RangePolicy<execution_space>(0, nowned_), KOKKOS_LAMBDA(const int a) {
          double au[3];
          Incidence::apply_atom(a, given, inertia, offsets, incidence, other, geometry, mass_weight,
                     friction_weight, au);
          for (int k = 0; k < 3; k++) out(3 * a + k) = au[k];
        });
  }

  // the exchange of the solve to come: its list of atoms sent into DeviceType's memory
  void set_exchange(const Exchange &exchange)
  {
    exchange_ = &exchange;
    kk::upload(sent_, exchange.sent, exchange.nsent);
  }

  // A partner vector's slots from their owners: the values sent packed in a kernel, then
  // through the host (the exchange is collective: every rank with values to send or slots to
  // fill takes part)
  void fill_slots(const Values &vector)
  {
    const int nsent = exchange_->nsent, nslots = npartners_ - nowned_;
    if (nsent == 0 && nslots == 0) return;
    kk::grow(sent_values_, 3 * nsent);
    auto sent = sent_;
    auto packed = sent_values_;
    auto given = vector;
    Kokkos::parallel_for(
        "etd:pack_sent", Kokkos::RangePolicy<execution_space>(0, nsent), KOKKOS_LAMBDA(const int q) {
          for (int k = 0; k < 3; k++) packed(3 * q + k) = given(3 * sent(q) + k);
        });
    sent_host_.resize(3 * nsent);
    slots_host_.resize(3 * nslots);
    kk::download(sent_values_, sent_host_.data(), 3 * nsent);
    exchange_->swap(sent_host_.data(), slots_host_.data());
    Kokkos::View<const double *, Kokkos::HostSpace, Kokkos::MemoryTraits<Kokkos::Unmanaged>>
        slots(slots_host_.data(), 3 * nslots);
    Kokkos::deep_copy(Kokkos::subview(vector, Kokkos::make_pair(3 * nowned_, 3 * npartners_)),
                      slots);
  }

 protected:
  int nowned_ = 0, npartners_ = 0;
  // G applied by pairs (the host's threads: sums_) or by atoms (a device: incidence_)
  bool by_pairs_ = false;
  PairSums sums_;
  Incidence incidence_;
  Indices partner_;    // each pair's j, where the host set_pairs() gives the pairs
  Geometry geometry_;  // e0, e1, e2, gamma w_D per pair
  std::vector<int> pair_i_, pair_j_;
  // A's weights, and the exchange that fills a partner vector's slots (the solve's)
  double mass_weight_ = 1.0, friction_weight_ = 0.0;
  const Exchange *exchange_ = nullptr;
  Indices sent_;                                 // the exchange's atoms sent
  Values sent_values_;                           // their values, packed
  std::vector<double> sent_host_, slots_host_;   // those and the slots' values on the host
  // shared with the solve, over the owned atoms (x_ over the partners): for the right-hand
  // sides b_ holds v, then b; x_ holds u and w_ G u; in the solve x_ is the solution and w_ A z
  Values inertia_, b_, x_, w_;
  Values kick_, image_;    // pair_terms(): the impulse, the images' friction
};

}    // namespace etd

#endif
