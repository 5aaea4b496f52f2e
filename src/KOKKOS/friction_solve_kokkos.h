// ETD-DPD: the implicit scheme's friction solve, (mass_weight M + friction_weight G) x = b, in
// Kokkos kernels: the block-Jacobi preconditioner, G applied atom by atom, and the same
// single-reduction conjugate gradients as conjugate_gradient.h, for translation (3 unknowns an
// atom). Pure Kokkos (no LAMMPS), so a unit test compares it with the CPU solve directly.
//
// Where the kernels run on the host (OpenMP, Serial), G is applied pair by pair, each pair once
// as the CPU solver applies it: the pairs come in runs of one atom i (the list's rows), and each
// thread adds its runs' shares into a copy of its own, which the next per-atom pass sums and
// clears. On a device, G is applied per owned atom over the pairs it takes part in (an incidence
// list built with the pairs), so no two threads write one atom. Every sum has a fixed order for
// a given thread count. Vectors over the partners (owned atoms, then one slot per remote atom,
// implicit_partners.h) have their slots filled through the caller's exchange, on the host, once
// per application of G (none on one rank).
#ifndef ETD_FRICTION_SOLVE_KOKKOS_H
#define ETD_FRICTION_SOLVE_KOKKOS_H

#include "friction_operator.h"
#include "friction_solve.h"
#include "kokkos_views.h"

#include <Kokkos_Core.hpp>

#include <functional>
#include <vector>

namespace etd {

template <class DeviceType> class FrictionSolveKokkos {
 public:
  using execution_space = typename DeviceType::execution_space;
  using Values = kk::Values<DeviceType>;
  using Indices = kk::Indices<DeviceType>;
  using Geometry = kk::Geometry<DeviceType>;
  // fills the slots [3 nowned, 3 npartners) of a host array of partner values from their owners
  using Exchange = std::function<void(double *)>;
  // sums count values (at most 9) over the ranks, in place
  using GlobalSum = std::function<void(double *, int)>;

  // Each thread's copy of a sum over the pairs, width values per atom (add_pair_shares());
  // take() sums one entry over the copies and clears it for the next sum
  struct Shares {
    Values copies;
    int threads = 0;
    std::size_t stride = 0;
    KOKKOS_INLINE_FUNCTION double take(std::size_t at) const
    {
      double sum = 0.0;
      for (int t = 0; t < threads; t++) {
        sum += copies(t * stride + at);
        copies(t * stride + at) = 0.0;
      }
      return sum;
    }
  };

  // whether the kernels run where the host's memory is (then G is applied pair by pair)
  static constexpr bool on_host =
      Kokkos::SpaceAccessibility<Kokkos::DefaultHostExecutionSpace,
                                 typename DeviceType::memory_space>::accessible;

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
    if constexpr (on_host) {
      kk::upload(partner_, pair_j_.data(), npairs);
      runs_on_host(pair_i_.data(), npairs);
    } else {
      incidence_on_host(pair_i_.data(), pair_j_.data(), npairs, nowned);
    }
  }

  // runs of consecutive pairs with the same i, from the pairs' i in host memory
  void runs_on_host(const int *pair_i, int npairs)
  {
    int runs = 0;
    for (int p = 0; p < npairs; p++)
      if (p == 0 || pair_i[p] != pair_i[p - 1]) runs++;
    kk::grow(run_atom_, runs);
    kk::grow(run_start_, runs + 1);
    int r = 0;
    for (int p = 0; p < npairs; p++)
      if (p == 0 || pair_i[p] != pair_i[p - 1]) {
        run_atom_(r) = pair_i[p];
        run_start_(r++) = p;
      }
    run_start_(runs) = npairs;
    nruns_ = runs;
    by_pairs_ = true;
  }

  // the incidence list from the pairs' ends in host memory, in one pass: each atom's entries in
  // pair order (the pair, the atom at its other end, and which end the atom is)
  void incidence_on_host(const int *pair_i, const int *pair_j, int npairs, int nowned)
  {
    by_pairs_ = false;
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
      partner_ = pair_j;
      if (rows) {
        run_atom_ = *rows;
        run_start_ = *row_start;
        nruns_ = nrows;
        by_pairs_ = true;
      } else {
        runs_on_host(pair_i.data(), npairs);
      }
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
    auto offsets = offsets_;
    auto incidence = incidence_;
    auto other = other_;
    auto end = end_;
    auto geometry = geometry_;
    auto inertia_view = inertia_;
    auto given = x_;
    auto friction = w_;
    auto kick = kick_;
    auto image = image_;
    const Values offset = moving ? *image_offsets : Values();
    if (by_pairs_) {
      // per pair: G u, the impulse and (moving images) the images' friction, + on i, - on j
      const int width = moving ? 9 : 6;
      if (moving)
        add_pair_shares(StepShares{given, noise, offset, geometry, root, moving});
      else
        add_friction_shares<6>(given, 1.0, noise, root);
      const Shares shares = shares_of(width);
      Kokkos::parallel_for(
          "etd:pair_terms", Kokkos::RangePolicy<execution_space>(0, nowned_),
          KOKKOS_LAMBDA(const int a) {
            for (int k = 0; k < 3; k++) {
              const int d = 3 * a + k;
              friction(d) = shares.take(width * a + k);
              kick(d) = shares.take(width * a + 3 + k);
              if (moving) image(d) = shares.take(9 * a + 6 + k);
            }
          });
      return;
    }
    Kokkos::parallel_for(
        "etd:pair_terms", Kokkos::RangePolicy<execution_space>(0, nowned_),
        KOKKOS_LAMBDA(const int a) {
          double g[3];
          apply_atom(a, given, inertia_view, offsets, incidence, other, geometry, 0.0, 1.0, g);
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

  // Solves over the 3 nowned unknowns; atoms with mobile[a] = 0, or with neither mass nor
  // friction, are held at zero. inertia, b, x: 3 nowned values; start (optional): the start
  // over the owned atoms (else the block-Jacobi solution); start_friction (optional, with
  // start): G start, which saves one application of G. deflate: the uniform translation (G's
  // null space where nothing is held and M = 0) is removed from b, every product, every
  // preconditioned residual and the solution. As solve_friction_system().
  SolverResult solve(const double *inertia, const int *mobile, const double *b, double mass_weight,
                     double friction_weight, double tolerance, int max_iterations,
                     const Exchange &exchange, const GlobalSum &global_sum, double *x,
                     const double *start = nullptr, const double *start_friction = nullptr,
                     bool deflate = false)
  {
    const int n = 3 * nowned_;
    mass_weight_ = mass_weight;
    friction_weight_ = friction_weight;
    exchange_ = &exchange;
    global_sum_ = &global_sum;
    kk::upload(inertia_, inertia, n);
    kk::upload(b_, b, n);
    kk::upload(mobile_, mobile, nowned_);
    for (Values *v : {&r_, &p_, &w_, &s_}) kk::grow(*v, n);
    for (Values *v : {&z_, &x_}) kk::grow(*v, 3 * npartners_);
    kk::grow(inverse_, 9 * nowned_);
    kk::grow(held_, n);
    Kokkos::deep_copy(p_, 0.0);
    Kokkos::deep_copy(s_, 0.0);
    Kokkos::deep_copy(z_, 0.0);
    Kokkos::deep_copy(x_, 0.0);
    precondition_setup();
    count_active(deflate);
    if (deflate_ && active_[0] + active_[1] + active_[2] > 0.0) remove_mean(b_);
    start_vector(start, start_friction, n);

    double sums[cg_detail::NSUMS];
    precondition();
    apply_and_reduce(true, sums, global_sum);
    SolverResult result;
    if (sums[cg_detail::BB] == 0.0) {
      Kokkos::deep_copy(x_, 0.0);
      result.converged = true;
    } else {
      // the vector work of an iteration, in kernels (the update also preconditions: z = P r)
      struct Ops {
        FrictionSolveKokkos &solver;
        const GlobalSum &global_sum;
        void update(double alpha, double beta) { solver.update_and_precondition(alpha, beta); }
        double residual_norm2() const { return solver.residual_norm2(); }
        void next_sums(double *out) { solver.apply_and_reduce(false, out, global_sum); }
      } ops{*this, global_sum};
      result = cg_detail::iterate(ops, global_sum, sums, tolerance, max_iterations);
    }
    remove_mean(x_);
    kk::download(x_, x, n);
    return result;
  }

  // Deflation: per component, how many unknowns are solved (not held) over all ranks (a
  // reduction only where the solve deflates)
  void count_active(bool deflate)
  {
    deflate_ = deflate;
    for (double &count : active_) count = 0.0;
    if (!deflate) return;
    auto held = held_;
    Kokkos::View<double *, Kokkos::HostSpace, Kokkos::MemoryTraits<Kokkos::Unmanaged>> counts(
        active_, 3);
    Kokkos::parallel_reduce(
        "etd:deflate_count", Kokkos::RangePolicy<execution_space>(0, nowned_),
        ComponentSums{held, held, true}, counts);
    (*global_sum_)(active_, 3);
  }

  // The per-component mean over the solved unknowns (those not held) subtracted from them, where
  // the solve deflates (as remove_mean in solve_friction_system())
  void remove_mean(const Values &vector) const
  {
    if (!deflate_) return;
    auto held = held_;
    double sums[3] = {0.0, 0.0, 0.0};
    Kokkos::View<double *, Kokkos::HostSpace, Kokkos::MemoryTraits<Kokkos::Unmanaged>> result(
        sums, 3);
    Kokkos::parallel_reduce(
        "etd:deflate_sum", Kokkos::RangePolicy<execution_space>(0, nowned_),
        ComponentSums{vector, held, false}, result);
    (*global_sum_)(sums, 3);
    double mean[3];
    for (int k = 0; k < 3; k++) mean[k] = active_[k] > 0.0 ? sums[k] / active_[k] : 0.0;
    const double m0 = mean[0], m1 = mean[1], m2 = mean[2];
    auto values = vector;
    Kokkos::parallel_for(
        "etd:deflate", Kokkos::RangePolicy<execution_space>(0, nowned_),
        KOKKOS_LAMBDA(const int a) {
          if (held(3 * a) == 0.0) values(3 * a) -= m0;
          if (held(3 * a + 1) == 0.0) values(3 * a + 1) -= m1;
          if (held(3 * a + 2) == 0.0) values(3 * a + 2) -= m2;
        });
  }

  // per component, the sum of a vector (or with count, how many) over the unknowns not held
  struct ComponentSums {
    using value_type = double[];
    using size_type = int;
    int value_count = 3;
    Values values, held;
    bool count;
    ComponentSums(const Values &v, const Values &h, bool c) : values(v), held(h), count(c) {}
    KOKKOS_INLINE_FUNCTION void init(double *sums) const
    {
      for (int k = 0; k < 3; k++) sums[k] = 0.0;
    }
    KOKKOS_INLINE_FUNCTION void join(double *sums, const double *other) const
    {
      for (int k = 0; k < 3; k++) sums[k] += other[k];
    }
    KOKKOS_INLINE_FUNCTION void operator()(const int a, double *sums) const
    {
      for (int k = 0; k < 3; k++)
        if (held(3 * a + k) == 0.0) sums[k] += count ? 1.0 : values(3 * a + k);
    }
  };

  // (The kernels and their launchers are public: CUDA requires a kernel's functor type and the
  // function enclosing an extended device lambda to be.)

  // each atom's block of mass_weight M + friction_weight G, inverted (zero where held)
  void precondition_setup()
  {
    auto offsets = offsets_;
    auto incidence = incidence_;
    auto geometry = geometry_;
    auto inertia = inertia_;
    auto mobile = mobile_;
    auto inverse = inverse_;
    auto held = held_;
    const double mass_weight = mass_weight_, friction_weight = friction_weight_;
    const bool by_pairs = by_pairs_;
    if (by_pairs)    // gamma w_D e e^T, the same on both ends
      add_pair_shares(BlockShares{geometry});
    const Shares shares = shares_of(6);
    Kokkos::parallel_for(
        "etd:precondition_setup", Kokkos::RangePolicy<execution_space>(0, nowned_),
        KOKKOS_LAMBDA(const int a) {
          double block[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
          if (by_pairs) {
            for (int k = 0; k < 6; k++) block[k] = shares.take(6 * a + k);
          } else {
            for (int e = offsets(a); e < offsets(a + 1); e++) {
              const int p = incidence(e);
              const double g = geometry(p, 3), e0 = geometry(p, 0), e1 = geometry(p, 1),
                           e2 = geometry(p, 2);
              block[0] += g * e0 * e0;
              block[1] += g * e1 * e1;
              block[2] += g * e2 * e2;
              block[3] += g * e0 * e1;
              block[4] += g * e0 * e2;
              block[5] += g * e1 * e2;
            }
          }
          double m[9] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
          if (mobile(a)) invert_block(block, mass_weight * inertia(3 * a), friction_weight, m);
          for (int k = 0; k < 9; k++) inverse(9 * a + k) = m[k];
          for (int k = 0; k < 3; k++) held(3 * a + k) = (m[4 * k] != 0.0) ? 0.0 : 1.0;
        });
  }

  // x from start (or the block-Jacobi solution), then r = b - A x on the solved unknowns
  void start_vector(const double *start, const double *start_friction, int n)
  {
    auto x = x_;
    auto b = b_;
    auto inverse = inverse_;
    auto held = held_;
    if (start) {
      kk::upload(w_, start, n);    // w_ as scratch
      auto given = w_;
      Kokkos::parallel_for(
          "etd:start", Kokkos::RangePolicy<execution_space>(0, n),
          KOKKOS_LAMBDA(const int k) { x(k) = held(k) == 0.0 ? given(k) : 0.0; });
    } else {
      Kokkos::parallel_for(
          "etd:start_jacobi", Kokkos::RangePolicy<execution_space>(0, nowned_),
          KOKKOS_LAMBDA(const int a) {
            const double ba[3] = {b(3 * a), b(3 * a + 1), b(3 * a + 2)};
            block_product(a, inverse, held, ba, x);
          });
    }
    auto r = r_;
    auto inertia = inertia_;
    auto mobile = mobile_;
    const double mass_weight = mass_weight_, friction_weight = friction_weight_;
    if (start && start_friction) {
      kk::upload(s_, start_friction, n);    // s_ as scratch, zeroed below
      auto gx = s_;
      auto given = w_;
      Kokkos::parallel_for(
          "etd:start_residual", Kokkos::RangePolicy<execution_space>(0, n),
          KOKKOS_LAMBDA(const int k) {
            const double ax = mobile(k / 3)
                ? mass_weight * inertia(k) * given(k) + friction_weight * gx(k)
                : 0.0;
            r(k) = held(k) == 0.0 ? b(k) - ax : 0.0;
          });
      Kokkos::deep_copy(s_, 0.0);
      return;
    }
    if (deflate_ || by_pairs_) {    // (with deflation x and A x projected, as the CPU solve does)
      remove_mean(x_);
      apply(x_, w_);
      remove_mean(w_);
      auto ax = w_;
      Kokkos::parallel_for(
          "etd:start_residual", Kokkos::RangePolicy<execution_space>(0, n),
          KOKKOS_LAMBDA(const int k) { r(k) = held(k) == 0.0 ? b(k) - ax(k) : 0.0; });
      return;
    }
    fill_slots(x_);
    auto offsets = offsets_;
    auto incidence = incidence_;
    auto other = other_;
    auto geometry = geometry_;
    Kokkos::parallel_for(
        "etd:start_residual", Kokkos::RangePolicy<execution_space>(0, nowned_),
        KOKKOS_LAMBDA(const int a) {
          double ax[3];
          apply_atom(a, x, inertia, offsets, incidence, other, geometry, mass_weight,
                     friction_weight, ax);
          for (int k = 0; k < 3; k++)
            r(3 * a + k) = held(3 * a + k) == 0.0 ? b(3 * a + k) - ax[k] : 0.0;
        });
  }

  // out = A u over the owned atoms (u over the partners: its slots filled here)
  void apply(Values &u, const Values &out)
  {
    fill_slots(u);
    auto given = u;
    auto offsets = offsets_;
    auto incidence = incidence_;
    auto other = other_;
    auto geometry = geometry_;
    auto inertia = inertia_;
    const double mass_weight = mass_weight_, friction_weight = friction_weight_;
    if (by_pairs_) {
      add_friction_shares(u, friction_weight);
      const Shares shares = shares_of(3);
      Kokkos::parallel_for(
          "etd:apply", Kokkos::RangePolicy<execution_space>(0, 3 * nowned_),
          KOKKOS_LAMBDA(const int d) {
            out(d) = mass_weight * inertia(d) * given(d) + shares.take(d);
          });
      return;
    }
    Kokkos::parallel_for(
        "etd:apply", Kokkos::RangePolicy<execution_space>(0, nowned_), KOKKOS_LAMBDA(const int a) {
          double au[3];
          apply_atom(a, given, inertia, offsets, incidence, other, geometry, mass_weight,
                     friction_weight, au);
          for (int k = 0; k < 3; k++) out(3 * a + k) = au[k];
        });
  }

  // out_k = (M_a^-1 v)_k of atom a's inverted block, 0 where the unknown is held
  KOKKOS_INLINE_FUNCTION static void block_product(int a, const Values &inverse,
                                                   const Values &held, const double v[3],
                                                   const Values &out)
  {
    for (int k = 0; k < 3; k++) {
      const int row = 9 * a + 3 * k;
      out(3 * a + k) = held(3 * a + k) == 0.0
          ? inverse(row) * v[0] + inverse(row + 1) * v[1] + inverse(row + 2) * v[2]
          : 0.0;
    }
  }

  // z = P r (block-Jacobi), over the owned atoms
  void precondition()
  {
    auto z = z_;
    auto r = r_;
    auto inverse = inverse_;
    auto held = held_;
    Kokkos::parallel_for(
        "etd:precondition", Kokkos::RangePolicy<execution_space>(0, nowned_),
        KOKKOS_LAMBDA(const int a) {
          const double ra[3] = {r(3 * a), r(3 * a + 1), r(3 * a + 2)};
          block_product(a, inverse, held, ra, z);
        });
    remove_mean(z_);
  }

  // p = z + beta p, s = w + beta s, x += alpha p, r -= alpha s, then z = P r for the next
  // iteration: one pass over the atoms (each parallel region costs a fork and a join)
  void update_and_precondition(double alpha, double beta)
  {
    auto p = p_;
    auto s = s_;
    auto x = x_;
    auto r = r_;
    auto z = z_;
    auto w = w_;
    auto inverse = inverse_;
    auto held = held_;
    Kokkos::parallel_for(
        "etd:cg_update", Kokkos::RangePolicy<execution_space>(0, nowned_),
        KOKKOS_LAMBDA(const int a) {
          double ra[3];
          for (int k = 0; k < 3; k++) {
            const int d = 3 * a + k;
            p(d) = z(d) + beta * p(d);
            s(d) = w(d) + beta * s(d);
            x(d) += alpha * p(d);
            ra[k] = r(d) - alpha * s(d);
            r(d) = ra[k];
          }
          block_product(a, inverse, held, ra, z);
        });
    remove_mean(z_);
  }

  double residual_norm2() const
  {
    auto r = r_;
    double sum = 0.0;
    Kokkos::parallel_reduce(
        "etd:residual", Kokkos::RangePolicy<execution_space>(0, 3 * nowned_),
        KOKKOS_LAMBDA(const int k, double &partial) { partial += r(k) * r(k); }, sum);
    return sum;
  }

  // w = A z (zero on held unknowns) and the iteration's sums in one pass over the atoms, summed
  // over ranks: A z from the incidence list, or the pairs' shares of a pass before it (by pairs),
  // or w itself (deflated: applied and projected before it)
  struct ApplyAndSum {
    using value_type = double[];
    using size_type = int;
    int value_count = cg_detail::NSUMS;
    Values z, w, r, s, b, inertia, held;
    Indices offsets, incidence, other;
    Geometry geometry;
    double mass_weight, friction_weight;
    bool with_b;
    bool applied;    // w already holds A z (projected)
    bool by_pairs;   // else A z from the pairs' shares (by pairs) or the incidence list
    Shares shares;
    KOKKOS_INLINE_FUNCTION void init(double *sums) const
    {
      for (int k = 0; k < cg_detail::NSUMS; k++) sums[k] = 0.0;
    }
    KOKKOS_INLINE_FUNCTION void join(double *sums, const double *other) const
    {
      for (int k = 0; k < cg_detail::NSUMS; k++) sums[k] += other[k];
    }
    KOKKOS_INLINE_FUNCTION void operator()(const int a, double *sums) const
    {
      using namespace cg_detail;
      double az[3];
      if (applied)
        for (int k = 0; k < 3; k++) az[k] = w(3 * a + k);
      else if (by_pairs)
        for (int k = 0; k < 3; k++)
          az[k] = mass_weight * inertia(3 * a + k) * z(3 * a + k) + shares.take(3 * a + k);
      else
        apply_atom(a, z, inertia, offsets, incidence, other, geometry, mass_weight,
                   friction_weight, az);
      for (int k = 0; k < 3; k++) {
        const int d = 3 * a + k;
        const double wd = held(d) == 0.0 ? az[k] : 0.0;
        w(d) = wd;
        const double rd = r(d), zd = z(d), sd = s(d);
        sums[RZ] += rd * zd;
        sums[WZ] += wd * zd;
        sums[RR] += rd * rd;
        sums[RW] += rd * wd;
        sums[RS] += rd * sd;
        sums[WW] += wd * wd;
        sums[WS] += wd * sd;
        sums[SS] += sd * sd;
        if (with_b) sums[BB] += b(d) * b(d);
      }
    }
  };
  void apply_and_reduce(bool with_b, double sums[cg_detail::NSUMS], const GlobalSum &global_sum)
  {
    // with deflation A z is projected before the sums read it: a pass of its own
    if (deflate_) {
      apply(z_, w_);
      remove_mean(w_);
    } else {
      fill_slots(z_);
      if (by_pairs_) add_friction_shares(z_, friction_weight_);
    }
    ApplyAndSum functor{cg_detail::NSUMS, z_, w_, r_, s_, b_, inertia_, held_, offsets_,
                        incidence_, other_, geometry_, mass_weight_, friction_weight_,
                        with_b, deflate_, by_pairs_, shares_of(3)};
    Kokkos::View<double *, Kokkos::HostSpace, Kokkos::MemoryTraits<Kokkos::Unmanaged>> result(
        sums, cg_detail::NSUMS);
    Kokkos::parallel_reduce("etd:apply_and_sum", Kokkos::RangePolicy<execution_space>(0, nowned_),
                            functor, result);
    global_sum(sums, with_b ? cg_detail::NSUMS : cg_detail::BB);
  }

  Shares shares_of(int width) const
  {
    return {copies_, threads_, static_cast<std::size_t>(width) * nowned_};
  }

  // The runs of thread t's block of threads blocks with about equal numbers of pairs: the first
  // run starting at or after t npairs / threads (run_start ascends)
  KOKKOS_INLINE_FUNCTION static int first_run(const Indices &run_start, int nruns, int t,
                                              int threads)
  {
    const long target = static_cast<long>(t) * run_start(nruns) / threads;
    int lo = 0, hi = nruns;    // the first r with run_start(r) >= target, in [0, nruns]
    while (lo < hi) {
      const int mid = (lo + hi) / 2;
      if (run_start(mid) < target)
        lo = mid + 1;
      else
        hi = mid;
    }
    return lo;
  }

  // A pair's shares (add_pair_shares) under moving images: on i, G u, the impulse sqrt(h)
  // noise e and the images' friction; on j the opposite
  struct StepShares {
    static constexpr int width = 9, j_sign = -1;
    static constexpr const char *label = "etd:step_shares";
    Values u, noise, offset;
    Geometry geometry;
    double root_h;
    bool moving;
    KOKKOS_FORCEINLINE_FUNCTION void operator()(int p, int i, int j, double *to_i) const
    {
      const double e[3] = {geometry(p, 0), geometry(p, 1), geometry(p, 2)};
      const double projected = geometry(p, 3) *
          (e[0] * (u(3 * i) - u(3 * j)) + e[1] * (u(3 * i + 1) - u(3 * j + 1)) +
           e[2] * (u(3 * i + 2) - u(3 * j + 2)));
      const double amount = root_h * noise(p);
      double image = 0.0;
      if (moving)
        image = geometry(p, 3) *
            (e[0] * (0.0 - offset(3 * p)) + e[1] * (0.0 - offset(3 * p + 1)) +
             e[2] * (0.0 - offset(3 * p + 2)));
      for (int k = 0; k < 3; k++) {
        to_i[k] = projected * e[k];
        to_i[3 + k] = amount * e[k];
        to_i[6 + k] = image * e[k];
      }
    }
  };
  // the preconditioner's blocks: gamma w_D e e^T (xx yy zz xy xz yz), the same on both ends
  struct BlockShares {
    static constexpr int width = 6, j_sign = 1;
    static constexpr const char *label = "etd:block_shares";
    Geometry geometry;
    KOKKOS_FORCEINLINE_FUNCTION void operator()(int p, int, int, double *to_i) const
    {
      const double g = geometry(p, 3), e0 = geometry(p, 0), e1 = geometry(p, 1),
                   e2 = geometry(p, 2);
      to_i[0] = g * e0 * e0;
      to_i[1] = g * e1 * e1;
      to_i[2] = g * e2 * e2;
      to_i[3] = g * e0 * e1;
      to_i[4] = g * e0 * e2;
      to_i[5] = g * e1 * e2;
    }
  };

  // For each run of pairs (atom i) on the host's threads, share(p, i, j, to_i) gives pair p's
  // Share::width values on i, and j's are Share::j_sign times them: i's summed over the run and then added (the
  // CPU solver's order), j's added where j is owned, each thread into its own copy. Every entry
  // must be taken (Shares::take) before the next sum.
  template <class Share> void add_pair_shares(const Share &share)
  {
    constexpr int Width = Share::width, JSign = Share::j_sign;
    // one block of runs per thread (about equal numbers of pairs), block t into copy t (the
    // same sums whichever thread runs it; no per-run token)
    const int threads = execution_space().concurrency();
    threads_ = threads;
    const std::size_t stride = static_cast<std::size_t>(Width) * nowned_;
    if (copies_.extent(0) < threads * stride)    // (zeroed, as take() leaves it)
      copies_ = Values("etd:pair_shares", threads * stride);
    auto copies = copies_;
    auto run_atom = run_atom_;
    auto run_start = run_start_;
    auto partner = partner_;
    const int nowned = nowned_, nruns = nruns_;
    Kokkos::parallel_for(
        Share::label, Kokkos::RangePolicy<execution_space>(0, threads),
        KOKKOS_LAMBDA(const int t) {
          double *copy = copies.data() + t * stride;
          const int last = first_run(run_start, nruns, t + 1, threads);
          for (int r = first_run(run_start, nruns, t, threads); r < last; r++) {
            const int i = run_atom(r);
            double sum[Width];
            for (int k = 0; k < Width; k++) sum[k] = 0.0;
            for (int p = run_start(r); p < run_start(r + 1); p++) {
              const int j = partner(p);
              double to_i[Width];
              share(p, i, j, to_i);
              for (int k = 0; k < Width; k++) sum[k] += to_i[k];
              if (j < nowned)
                for (int k = 0; k < Width; k++) {
                  if (JSign > 0)
                    copy[Width * j + k] += to_i[k];
                  else
                    copy[Width * j + k] -= to_i[k];
                }
            }
            for (int k = 0; k < Width; k++) copy[Width * i + k] += sum[k];
          }
        });
  }

  // weight G u pair by pair, as accumulate_friction_by_runs() sums it (u over the partners):
  // add_pair_shares written out, u_i and i's sum held through the run (the solve's hot loop).
  // With the noise (Width 6), also the impulse root_h sum (+-) noise e, after G u's 3 values.
  template <int Width = 3>
  void add_friction_shares(const Values &u, double weight, const Values &noise = Values(),
                           double root_h = 0.0)
  {
    static_assert(Width == 3 || Width == 6, "G u, or G u and the impulse");
    const int threads = execution_space().concurrency();
    threads_ = threads;
    const std::size_t stride = Width * static_cast<std::size_t>(nowned_);
    if (copies_.extent(0) < threads * stride)    // (zeroed, as take() leaves it)
      copies_ = Values("etd:pair_shares", threads * stride);
    auto copies = copies_;
    auto run_atom = run_atom_;
    auto run_start = run_start_;
    auto partner = partner_;
    auto geometry = geometry_;
    const int nowned = nowned_, nruns = nruns_;
    Kokkos::parallel_for(
        "etd:friction_shares", Kokkos::RangePolicy<execution_space>(0, threads),
        KOKKOS_LAMBDA(const int t) {
          double *copy = copies.data() + t * stride;
          const double *given = u.data();
          const int last = first_run(run_start, nruns, t + 1, threads);
          for (int r = first_run(run_start, nruns, t, threads); r < last; r++) {
            const int i = run_atom(r);
            const double ui0 = given[3 * i], ui1 = given[3 * i + 1], ui2 = given[3 * i + 2];
            double sum0 = 0.0, sum1 = 0.0, sum2 = 0.0, kick0 = 0.0, kick1 = 0.0, kick2 = 0.0;
            for (int p = run_start(r); p < run_start(r + 1); p++) {
              const int j = partner(p);
              const double e0 = geometry(p, 0), e1 = geometry(p, 1), e2 = geometry(p, 2);
              const double projected = weight * geometry(p, 3) *
                  (e0 * (ui0 - given[3 * j]) + e1 * (ui1 - given[3 * j + 1]) +
                   e2 * (ui2 - given[3 * j + 2]));
              const double f0 = projected * e0, f1 = projected * e1, f2 = projected * e2;
              sum0 += f0;
              sum1 += f1;
              sum2 += f2;
              if (j < nowned) {
                copy[Width * j] -= f0;
                copy[Width * j + 1] -= f1;
                copy[Width * j + 2] -= f2;
              }
              if (Width == 6) {    // (not if constexpr: CUDA lambdas may not first capture there)
                const double amount = root_h * noise(p);
                const double k0 = amount * e0, k1 = amount * e1, k2 = amount * e2;
                kick0 += k0;
                kick1 += k1;
                kick2 += k2;
                if (j < nowned) {
                  copy[6 * j + 3] -= k0;
                  copy[6 * j + 4] -= k1;
                  copy[6 * j + 5] -= k2;
                }
              }
            }
            copy[Width * i] += sum0;
            copy[Width * i + 1] += sum1;
            copy[Width * i + 2] += sum2;
            if (Width == 6) {
              copy[6 * i + 3] += kick0;
              copy[6 * i + 4] += kick1;
              copy[6 * i + 5] += kick2;
            }
          }
        });
  }

 private:
  int nowned_ = 0, npartners_ = 0;
  // by pairs: each pair's partner, and the runs (atom, first pair; nruns_ + 1 starts)
  bool by_pairs_ = false;
  Indices partner_, run_atom_, run_start_;
  int nruns_ = 0;
  Values copies_;    // each thread's copy of a sum over the pairs (Shares)
  int threads_ = 1;
  double mass_weight_ = 1.0, friction_weight_ = 0.0;
  const Exchange *exchange_ = nullptr;
  const GlobalSum *global_sum_ = nullptr;
  bool deflate_ = false;
  double active_[3] = {0.0, 0.0, 0.0};    // per component, the unknowns solved over all ranks
  Geometry geometry_;     // e0, e1, e2, gamma w_D per pair
  // per owned atom, its pairs, their other atoms and which end of each it is (1: i, -1: j)
  Indices offsets_, incidence_, other_, end_, cursor_;
  std::vector<int> fill_, pair_i_, pair_j_;
  Indices mobile_;
  Values inertia_, b_, inverse_, held_;    // held_: 1 on unknowns held at their start
  Values r_, z_, p_, w_, s_, x_;           // z_ and x_ over the partners: G acts on them
  Values kick_, image_;                    // pair_terms(): the impulse, the images' friction


  // a partner vector's slots from their owners (through the host); every rank calls it, with
  // slots or without, since the exchange is collective
  void fill_slots(Values &vector) const
  {
    auto host = Kokkos::create_mirror_view(vector);
    Kokkos::deep_copy(host, vector);
    (*exchange_)(host.data());
    Kokkos::deep_copy(vector, host);
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
};

}    // namespace etd

#endif
