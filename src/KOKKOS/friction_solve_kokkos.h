// ETD-DPD: the implicit scheme's friction solve, (mass_weight M + friction_weight G) x = b, in
// Kokkos kernels: the block-Jacobi preconditioner, G applied, and the same single-reduction
// conjugate gradients as conjugate_gradient.h, for translation (3 unknowns an atom); with the
// step's right-hand sides. Pure Kokkos (no LAMMPS), so a unit test compares it with the CPU solve
// directly.
//
// Where the kernels run on the host (OpenMP, Serial), G is applied pair by pair, each pair once
// as the CPU solver applies it, each thread into a copy of its own (friction_pair_sums_kokkos.h).
// On a device, G is applied per owned atom over the pairs it takes part in (an incidence list
// built with the pairs, friction_incidence_kokkos.h), so no two threads write one atom. Every
// sum has a fixed order for a given thread count. Vectors over the partners (owned atoms, then
// one slot per remote atom, implicit_partners.h) have their slots filled through the caller's
// exchange, on the host, once per application of G (none on one rank).
#ifndef ETD_FRICTION_SOLVE_KOKKOS_H
#define ETD_FRICTION_SOLVE_KOKKOS_H

#include "friction_incidence_kokkos.h"
#include "friction_operator.h"
#include "friction_pair_sums_kokkos.h"
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
  using PairSums = PairSumsKokkos<DeviceType>;
  using Shares = typename PairSums::Shares;
  using Incidence = FrictionIncidenceKokkos<DeviceType>;

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
      const int width = moving ? 9 : 6;
      if (moving)
        sums_.add(typename PairSums::StepShares{given, noise, offset, geometry, root, moving},
                  nowned_);
      else
        sums_.template add_friction<6>(geometry_, given, 1.0, nowned_, noise, root);
      const Shares shares = sums_.shares(width, nowned_);
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
    if (deflate) component_sums(ComponentSums{held_, held_, true}, active_);
  }

  // The per-component mean over the solved unknowns (those not held) subtracted from them, where
  // the solve deflates (as remove_mean in solve_friction_system())
  void remove_mean(const Values &vector) const
  {
    if (!deflate_) return;
    auto held = held_;
    double sums[3] = {0.0, 0.0, 0.0};
    component_sums(ComponentSums{vector, held, false}, sums);
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

  // a ComponentSums reduction over the owned atoms, summed over the ranks, into out[3]
  void component_sums(const ComponentSums &sums, double out[3]) const
  {
    Kokkos::View<double *, Kokkos::HostSpace, Kokkos::MemoryTraits<Kokkos::Unmanaged>> result(
        out, 3);
    Kokkos::parallel_reduce(sums.count ? "etd:deflate_count" : "etd:deflate_sum",
                            Kokkos::RangePolicy<execution_space>(0, nowned_), sums, result);
    (*global_sum_)(out, 3);
  }

  // (The kernels and their launchers are public: CUDA requires a kernel's functor type and the
  // function enclosing an extended device lambda to be.)

  // each atom's block of mass_weight M + friction_weight G, inverted (zero where held)
  void precondition_setup()
  {
    auto offsets = incidence_.offsets();
    auto incidence = incidence_.incidence();
    auto geometry = geometry_;
    auto inertia = inertia_;
    auto mobile = mobile_;
    auto inverse = inverse_;
    auto held = held_;
    const double mass_weight = mass_weight_, friction_weight = friction_weight_;
    const bool by_pairs = by_pairs_;
    if (by_pairs)    // gamma w_D e e^T, the same on both ends
      sums_.add(typename PairSums::BlockShares{geometry}, nowned_);
    const Shares shares = sums_.shares(6, nowned_);
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
    auto offsets = incidence_.offsets();
    auto incidence = incidence_.incidence();
    auto other = incidence_.other();
    auto geometry = geometry_;
    Kokkos::parallel_for(
        "etd:start_residual", Kokkos::RangePolicy<execution_space>(0, nowned_),
        KOKKOS_LAMBDA(const int a) {
          double ax[3];
          Incidence::apply_atom(a, x, inertia, offsets, incidence, other, geometry, mass_weight,
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
    auto offsets = incidence_.offsets();
    auto incidence = incidence_.incidence();
    auto other = incidence_.other();
    auto geometry = geometry_;
    auto inertia = inertia_;
    const double mass_weight = mass_weight_, friction_weight = friction_weight_;
    if (by_pairs_) {
      sums_.add_friction(geometry_, u, friction_weight, nowned_);
      const Shares shares = sums_.shares(3, nowned_);
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
          Incidence::apply_atom(a, given, inertia, offsets, incidence, other, geometry, mass_weight,
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
        Incidence::apply_atom(a, z, inertia, offsets, incidence, other, geometry, mass_weight,
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
      if (by_pairs_) sums_.add_friction(geometry_, z_, friction_weight_, nowned_);
    }
    ApplyAndSum functor{cg_detail::NSUMS, z_, w_, r_, s_, b_, inertia_, held_,
                        incidence_.offsets(), incidence_.incidence(), incidence_.other(),
                        geometry_, mass_weight_, friction_weight_, with_b, deflate_,
                        by_pairs_, sums_.shares(3, nowned_)};
    Kokkos::View<double *, Kokkos::HostSpace, Kokkos::MemoryTraits<Kokkos::Unmanaged>> result(
        sums, cg_detail::NSUMS);
    Kokkos::parallel_reduce("etd:apply_and_sum", Kokkos::RangePolicy<execution_space>(0, nowned_),
                            functor, result);
    global_sum(sums, with_b ? cg_detail::NSUMS : cg_detail::BB);
  }

 private:
  int nowned_ = 0, npartners_ = 0;
  // G applied by pairs (the host's threads: sums_) or by atoms (a device: incidence_)
  bool by_pairs_ = false;
  PairSums sums_;
  Incidence incidence_;
  Indices partner_;    // each pair's j, where the host set_pairs() gives the pairs
  double mass_weight_ = 1.0, friction_weight_ = 0.0;
  const Exchange *exchange_ = nullptr;
  const GlobalSum *global_sum_ = nullptr;
  bool deflate_ = false;
  double active_[3] = {0.0, 0.0, 0.0};    // per component, the unknowns solved over all ranks
  Geometry geometry_;     // e0, e1, e2, gamma w_D per pair
  std::vector<int> pair_i_, pair_j_;
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

};

}    // namespace etd

#endif
