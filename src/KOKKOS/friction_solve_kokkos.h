// ETD-DPD: the implicit scheme's friction solve, (mass_weight M + friction_weight G) x = b, in
// Kokkos kernels: the block-Jacobi preconditioner and the same single-reduction conjugate
// gradients as conjugate_gradient.h, for translation (3 unknowns an atom), over the operator of
// friction_operator_kokkos.h (the step's pairs, their right-hand sides, A applied). Pure Kokkos
// (no LAMMPS), so a unit test compares it with the CPU solve directly. Every sum has a fixed
// order for a given thread count.
#ifndef ETD_FRICTION_SOLVE_KOKKOS_H
#define ETD_FRICTION_SOLVE_KOKKOS_H

#include "friction_operator_kokkos.h"
#include "friction_solve.h"

#include <Kokkos_Core.hpp>

#include <functional>

namespace etd {

template <class DeviceType> class FrictionSolveKokkos : public FrictionOperatorKokkos<DeviceType> {
 public:
  using Operator = FrictionOperatorKokkos<DeviceType>;
  using typename Operator::execution_space;
  using typename Operator::Values;
  using typename Operator::Indices;
  using typename Operator::Geometry;
  using typename Operator::Exchange;
  // sums count values (at most 9) over the ranks, in place
  using GlobalSum = std::function<void(double *, int)>;
  using typename Operator::PairSums;
  using typename Operator::Incidence;
  using Operator::apply;

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
    set_exchange(exchange);
    global_sum_ = &global_sum;
    kk::upload(inertia_, inertia, n);
    kk::upload(b_, b, n);
    kk::upload(mobile_, mobile, nowned_);
    for (Values *v : {&r_, &p_, &w_, &s_}) kk::grow(*v, n);
    for (Values *v : {&z_, &x_}) kk::grow(*v, 3 * npartners_);
    kk::grow(inverse_, 6 * nowned_);
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

  std::size_t memory_usage() const
  {
    return Operator::memory_usage() + kk::bytes_of(mobile_, inverse_, held_, r_, z_, p_, s_);
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

  // each atom's block of mass_weight M + friction_weight G, inverted (zero where held): its
  // 6 distinct values (the inverse is symmetric; the CG's passes are bound by memory traffic),
  // and whether any unknown of this rank is held (where none is, the passes skip held_)
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
    const auto shares = sums_.template shares<6>();
    int nheld = 0;
    Kokkos::parallel_reduce(
        "etd:precondition_setup", Kokkos::RangePolicy<execution_space>(0, nowned_),
        KOKKOS_LAMBDA(const int a, int &held_here) {
          double block[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
          if (by_pairs) {
            shares.take(a, block);
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
          const int upper[6] = {0, 1, 2, 4, 5, 8};    // xx xy xz yy yz zz
          for (int k = 0; k < 6; k++) inverse(6 * a + k) = m[upper[k]];
          for (int k = 0; k < 3; k++) {
            const bool is_held = m[4 * k] == 0.0;
            held(3 * a + k) = is_held ? 1.0 : 0.0;
            held_here += is_held;
          }
        },
        nheld);
    any_held_ = nheld > 0;
  }

  // x from start (or the block-Jacobi solution), then r = b - A x on the solved unknowns
  void start_vector(const double *start, const double *start_friction, int n)
  {
    auto x = x_;
    auto b = b_;
    auto inverse = inverse_;
    auto held = held_;
    const bool any_held = any_held_;
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
            block_product(a, inverse, held, any_held, ba, x);
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

  // out_k = (M_a^-1 v)_k of atom a's inverted block (its 6 values), 0 where the unknown is held
  KOKKOS_INLINE_FUNCTION static void block_product(int a, const Values &inverse,
                                                   const Values &held, bool any_held,
                                                   const double v[3], const Values &out)
  {
    // row k's three entries among xx xy xz yy yz zz
    constexpr int entry[3][3] = {{0, 1, 2}, {1, 3, 4}, {2, 4, 5}};
    const int block = 6 * a;
    for (int k = 0; k < 3; k++) {
      out(3 * a + k) = (!any_held || held(3 * a + k) == 0.0)
          ? inverse(block + entry[k][0]) * v[0] + inverse(block + entry[k][1]) * v[1] +
              inverse(block + entry[k][2]) * v[2]
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
    const bool any_held = any_held_;
    Kokkos::parallel_for(
        "etd:precondition", Kokkos::RangePolicy<execution_space>(0, nowned_),
        KOKKOS_LAMBDA(const int a) {
          const double ra[3] = {r(3 * a), r(3 * a + 1), r(3 * a + 2)};
          block_product(a, inverse, held, any_held, ra, z);
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
    const bool any_held = any_held_;
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
          block_product(a, inverse, held, any_held, ra, z);
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
    bool any_held;    // else held is all zero and not read
    bool applied;    // w already holds A z (projected)
    bool by_pairs;   // else A z from the pairs' shares (by pairs) or the incidence list
    typename Operator::template Shares<3> shares;
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
      else if (by_pairs) {
        shares.take(a, az);
        for (int k = 0; k < 3; k++) az[k] += mass_weight * inertia(3 * a + k) * z(3 * a + k);
      }
      else
        Incidence::apply_atom(a, z, inertia, offsets, incidence, other, geometry, mass_weight,
                   friction_weight, az);
      for (int k = 0; k < 3; k++) {
        const int d = 3 * a + k;
        const double wd = (!any_held || held(d) == 0.0) ? az[k] : 0.0;
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
                        geometry_, mass_weight_, friction_weight_, with_b, any_held_, deflate_,
                        by_pairs_, sums_.template shares<3>()};
    Kokkos::View<double *, Kokkos::HostSpace, Kokkos::MemoryTraits<Kokkos::Unmanaged>> result(
        sums, cg_detail::NSUMS);
    Kokkos::parallel_reduce("etd:apply_and_sum", Kokkos::RangePolicy<execution_space>(0, nowned_),
                            functor, result);
    global_sum(sums, with_b ? cg_detail::NSUMS : cg_detail::BB);
  }

 private:
  using Operator::nowned_;
  using Operator::npartners_;
  using Operator::by_pairs_;
  using Operator::sums_;
  using Operator::incidence_;
  using Operator::geometry_;
  using Operator::mass_weight_;
  using Operator::friction_weight_;
  using Operator::inertia_;
  using Operator::b_;
  using Operator::x_;
  using Operator::w_;
  using Operator::fill_slots;
  using Operator::set_exchange;

  const GlobalSum *global_sum_ = nullptr;
  bool deflate_ = false;
  double active_[3] = {0.0, 0.0, 0.0};    // per component, the unknowns solved over all ranks
  Indices mobile_;
  Values inverse_, held_;    // held_: 1 on unknowns held at their start
  bool any_held_ = false;    // any unknown of this rank held (precondition_setup())
  Values r_, z_, p_, s_;     // z_ over the partners: G acts on it
};

}    // namespace etd

#endif
