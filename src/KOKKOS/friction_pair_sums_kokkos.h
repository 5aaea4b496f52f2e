// ETD-DPD: sums over the implicit scheme's pairs on the host's threads, each pair once, as the
// CPU solver sums them (friction_operator.h): the pairs come in runs of one atom i (the list's
// rows), each thread takes a block of runs with about equal numbers of pairs and adds their
// shares into a copy of its own (i's summed over its run first, then j's where j is owned), and
// the next per-atom pass sums the copies and clears them (Shares::take). Every sum has a fixed
// order for a given thread count. A thread's copy holds only the chunks of 64 atoms its block
// touches (sorted atoms: its own share and the pairs across its edges), so memory and the
// summing pass's reads grow with the atoms, not with atoms times threads. For the Kokkos
// backends that run on the host (OpenMP, Serial; friction_operator_kokkos.h applies G through
// an incidence list on a device). Pure Kokkos.
#ifndef ETD_FRICTION_PAIR_SUMS_KOKKOS_H
#define ETD_FRICTION_PAIR_SUMS_KOKKOS_H

#include "kokkos_views.h"

#include <Kokkos_Core.hpp>

#include <cstddef>

namespace etd {

template <class DeviceType> class PairSumsKokkos {
 public:
  using execution_space = typename DeviceType::execution_space;
  using Values = kk::Values<DeviceType>;
  using Indices = kk::Indices<DeviceType>;
  using Geometry = kk::Geometry<DeviceType>;

  // Atoms in chunks of 64: a thread's copy holds a chunk's values at a slot of its own, width
  // values per atom, only where its block touches the chunk (the layout: lay_out())
  static constexpr int chunk_bits = 6, chunk_size = 1 << chunk_bits;

  // Where each thread's copy keeps an atom's values: thread t's chunks are numbered from 0
  // (slots(t nchunks + chunk), -1 where its block writes none of the chunk's atoms: its values
  // there are zero) after the first(t) slots of the threads before it
  struct Layout {
    Indices slots, first;
    int threads = 0, nchunks = 0;
  };
  // the first of atom a's Width values in the copies, its chunk at the given slot
  template <int Width> KOKKOS_FORCEINLINE_FUNCTION static long position(long slot, int a)
  {
    return (slot * chunk_size + (a & (chunk_size - 1))) * Width;
  }

  // Each thread's copy of a sum over the pairs, Width values per atom (add());
  // take() sums atom a's Width values over the copies into out and clears them for the next sum
  template <int Width> struct Shares {
    Values copies;
    Layout layout;
    KOKKOS_INLINE_FUNCTION void take(int a, double *out) const
    {
      for (int k = 0; k < Width; k++) out[k] = 0.0;
      const int chunk = a >> chunk_bits;
      double *values = copies.data();
      for (int t = 0; t < layout.threads; t++) {
        const int slot = layout.slots(t * layout.nchunks + chunk);
        if (slot < 0) continue;    // (the copy's values are zero: the sums are the same to the bit)
        double *at = values + position<Width>(static_cast<long>(layout.first(t)) + slot, a);
        for (int k = 0; k < Width; k++) {
          out[k] += at[k];
          at[k] = 0.0;
        }
      }
    }
  };

  // The pairs' runs: run r holds the pairs [run_start(r), run_start(r + 1)) of atom
  // run_atom(r), its i; partner: each pair's j (views kept, not copied)
  void set_runs(const Indices &partner, const Indices &run_atom, const Indices &run_start,
                int nruns)
  {
    partner_ = partner;
    run_atom_ = run_atom;
    run_start_ = run_start;
    nruns_ = nruns;
    laid_out_for_ = -1;
  }

  // the runs of consecutive pairs with the same i, from the pairs' i in host memory
  void find_runs(const Indices &partner, const int *pair_i, int npairs)
  {
    partner_ = partner;
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
    laid_out_for_ = -1;
  }

  // the copies of the last sum, Width values for each atom
  template <int Width> Shares<Width> shares() const { return {copies_, layout_}; }

  // how many values the threads' copies hold (for the widest sum so far)
  std::size_t copies_size() const { return copies_.extent(0); }
  // the bytes of the copies and their layout (the runs are mostly the pairs' own views)
  std::size_t memory_usage() const { return kk::bytes_of(copies_, layout_.slots, layout_.first); }

  // What a sum's kernel reads (blocks_of()): the runs and each thread's copy
  struct Blocks {
    Values copies;
    Layout layout;
    Indices run_atom, run_start, partner;
    int nruns, threads;
    // the first run of block t (t = threads: past the last)
    KOKKOS_INLINE_FUNCTION int first_run(int t) const
    {
      return PairSumsKokkos::first_run(run_start, nruns, t, threads);
    }
    // thread t's copy, for the atoms its block writes (held in locals: the kernel's stores
    // could otherwise alias them, and they would be loaded again for every pair)
    template <int Width> struct Copy {
      double *values;
      const int *slots;
      long first;
      KOKKOS_FORCEINLINE_FUNCTION double *at(int a) const
      {
        return values + position<Width>(first + slots[a >> chunk_bits], a);
      }
    };
    template <int Width> KOKKOS_INLINE_FUNCTION Copy<Width> copy(int t) const
    {
      return {copies.data(), layout.slots.data() + t * layout.nchunks, layout.first(t)};
    }
  };

  // The runs of thread t's block of threads blocks with about equal numbers of pairs: the first
  // run starting at or after t npairs / threads (run_start ascends)
  template <class Starts>
  KOKKOS_INLINE_FUNCTION static int first_run(const Starts &run_start, int nruns, int t,
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

  // A pair's shares (add()) under moving images: on i, G u, the impulse sqrt(h)
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
  // Share::width values on i, and j's are Share::j_sign times them: i's summed over
  // the run and then added (the CPU solver's order), j's added where j (a partner index) is one
  // of the nowned owned atoms, each thread into its own copy. Every entry must be taken
  // (Shares::take) before the next sum.
  template <class Share> void add(const Share &share, int nowned)
  {
    constexpr int Width = Share::width, JSign = Share::j_sign;
    const Blocks blocks = blocks_of(Width, nowned);
    Kokkos::parallel_for(
        Share::label, Kokkos::RangePolicy<execution_space>(0, blocks.threads),
        KOKKOS_LAMBDA(const int t) {
          const auto copy = blocks.template copy<Width>(t);
          const int last = blocks.first_run(t + 1);
          for (int r = blocks.first_run(t); r < last; r++) {
            const int i = blocks.run_atom(r);
            double sum[Width];
            for (int k = 0; k < Width; k++) sum[k] = 0.0;
            for (int p = blocks.run_start(r); p < blocks.run_start(r + 1); p++) {
              const int j = blocks.partner(p);
              double to_i[Width];
              share(p, i, j, to_i);
              for (int k = 0; k < Width; k++) sum[k] += to_i[k];
              if (j < nowned) {
                double *to_j = copy.at(j);
                for (int k = 0; k < Width; k++) {
                  if (JSign > 0)
                    to_j[k] += to_i[k];
                  else
                    to_j[k] -= to_i[k];
                }
              }
            }
            double *at_i = copy.at(i);
            for (int k = 0; k < Width; k++) at_i[k] += sum[k];
          }
        });
  }

  // weight G u pair by pair, as accumulate_friction_by_runs() sums it (u over the partners):
  // add() written out, u_i and i's sum held through the run (the solve's hot loop).
  // With the noise (Width 6), also the impulse root_h sum (+-) noise e, after G u's 3 values.
  template <int Width = 3>
  void add_friction(const Geometry &geometry, const Values &u, double weight, int nowned,
                    const Values &noise = Values(), double root_h = 0.0)
  {
    static_assert(Width == 3 || Width == 6, "G u, or G u and the impulse");
    const Blocks blocks = blocks_of(Width, nowned);
    Kokkos::parallel_for(
        "etd:friction_shares", Kokkos::RangePolicy<execution_space>(0, blocks.threads),
        KOKKOS_LAMBDA(const int t) {
          const auto copy = blocks.template copy<Width>(t);
          const double *given = u.data();
          // (locals: the stores into copy could alias the lambda's captured doubles, which
          // would then be loaded again for every pair)
          const double scale = weight, root = root_h;
          const int owned = nowned;
          const int last = blocks.first_run(t + 1);
          for (int r = blocks.first_run(t); r < last; r++) {
            const int i = blocks.run_atom(r);
            const double ui0 = given[3 * i], ui1 = given[3 * i + 1], ui2 = given[3 * i + 2];
            double sum0 = 0.0, sum1 = 0.0, sum2 = 0.0, kick0 = 0.0, kick1 = 0.0, kick2 = 0.0;
            for (int p = blocks.run_start(r); p < blocks.run_start(r + 1); p++) {
              const int j = blocks.partner(p);
              const double e0 = geometry(p, 0), e1 = geometry(p, 1), e2 = geometry(p, 2);
              const double projected = scale * geometry(p, 3) *
                  (e0 * (ui0 - given[3 * j]) + e1 * (ui1 - given[3 * j + 1]) +
                   e2 * (ui2 - given[3 * j + 2]));
              const double f0 = projected * e0, f1 = projected * e1, f2 = projected * e2;
              sum0 += f0;
              sum1 += f1;
              sum2 += f2;
              double *to_j = nullptr;
              if (j < owned) {
                to_j = copy.at(j);
                to_j[0] -= f0;
                to_j[1] -= f1;
                to_j[2] -= f2;
              }
              if (Width == 6) {    // (not if constexpr: CUDA lambdas may not first capture there)
                const double amount = root * noise(p);
                const double k0 = amount * e0, k1 = amount * e1, k2 = amount * e2;
                kick0 += k0;
                kick1 += k1;
                kick2 += k2;
                if (j < owned) {
                  to_j[3] -= k0;
                  to_j[4] -= k1;
                  to_j[5] -= k2;
                }
              }
            }
            double *at_i = copy.at(i);
            at_i[0] += sum0;
            at_i[1] += sum1;
            at_i[2] += sum2;
            if (Width == 6) {
              at_i[3] += kick0;
              at_i[4] += kick1;
              at_i[5] += kick2;
            }
          }
        });
  }

  // Each thread's slots: the chunks of the atoms its block writes (its runs' i and their owned
  // j), numbered in chunk order (public: CUDA requires it of a function enclosing a kernel)
  void lay_out(int nowned)
  {
    const int threads = execution_space().concurrency();
    const int nchunks = (nowned + chunk_size - 1) >> chunk_bits;
    kk::grow(layout_.slots, static_cast<std::size_t>(threads) * nchunks + 1);
    kk::grow(layout_.first, threads);
    layout_.threads = threads;
    layout_.nchunks = nchunks;
    const Layout layout = layout_;
    const Indices run_atom = run_atom_, run_start = run_start_, partner = partner_;
    const int nruns = nruns_;
    Kokkos::parallel_for(
        "etd:pair_sums_layout", Kokkos::RangePolicy<execution_space>(0, threads),
        KOKKOS_LAMBDA(const int t) {
          int *slots = layout.slots.data() + t * nchunks;
          if (threads == 1) {    // (one copy: every chunk, no pass over the pairs)
            for (int c = 0; c < nchunks; c++) slots[c] = c;
            layout.first(t) = nchunks;
            return;
          }
          for (int c = 0; c < nchunks; c++) slots[c] = -1;
          const int last = first_run(run_start, nruns, t + 1, threads);
          for (int r = first_run(run_start, nruns, t, threads); r < last; r++) {
            slots[run_atom(r) >> chunk_bits] = 0;
            for (int p = run_start(r); p < run_start(r + 1); p++)
              if (partner(p) < nowned) slots[partner(p) >> chunk_bits] = 0;
          }
          int count = 0;
          for (int c = 0; c < nchunks; c++)
            if (slots[c] == 0) slots[c] = count++;
          layout.first(t) = count;    // (its count, made the first slot below)
        });
    auto h_first = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), layout_.first);
    int total = 0;
    for (int t = 0; t < threads; t++) {
      const int count = h_first(t);
      h_first(t) = total;
      total += count;
    }
    Kokkos::deep_copy(layout_.first, h_first);
    slots_in_use_ = total;
    laid_out_for_ = nowned;
  }

 private:
  Indices partner_, run_atom_, run_start_;
  int nruns_ = 0;
  Values copies_;    // each thread's copy of a sum over the pairs (Shares), at its slots
  Layout layout_;
  int laid_out_for_ = -1;    // the nowned of layout_ (-1: the runs changed since)
  int slots_in_use_ = 0;     // over all threads' copies

  // The copies (laid out for the runs and nowned owned atoms), with the runs, for a sum's
  // kernel: one block of runs per thread (about equal numbers of pairs), block t into copy t
  // (the same sums whichever thread runs it; no per-run token)
  Blocks blocks_of(int width, int nowned)
  {
    if (laid_out_for_ != nowned || layout_.threads != execution_space().concurrency())
      lay_out(nowned);
    // (zeroed where they grow, as take() leaves them)
    const std::size_t size = static_cast<std::size_t>(slots_in_use_) * chunk_size * width;
    if (copies_.extent(0) < size) copies_ = Values("etd:pair_shares", size);
    return {copies_, layout_, run_atom_, run_start_, partner_, nruns_, layout_.threads};
  }
};

}    // namespace etd

#endif
