// ETD-DPD: sums over the implicit scheme's pairs on the host's threads, each pair once, as the
// CPU solver sums them (friction_operator.h): the pairs come in runs of one atom i (the list's
// rows), each thread takes a block of runs with about equal numbers of pairs and adds their
// shares into a copy of its own (i's summed over its run first, then j's where j is owned), and
// the next per-atom pass sums the copies and clears them (Shares::take). Every sum has a fixed
// order for a given thread count. For the Kokkos backends that run on the host (OpenMP, Serial;
// friction_operator_kokkos.h applies G through an incidence list on a device). Pure Kokkos.
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

  // Each thread's copy of a sum over the pairs, width values per atom (add());
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

  // The pairs' runs: run r holds the pairs [run_start(r), run_start(r + 1)) of atom
  // run_atom(r), its i; partner: each pair's j (views kept, not copied)
  void set_runs(const Indices &partner, const Indices &run_atom, const Indices &run_start,
                int nruns)
  {
    partner_ = partner;
    run_atom_ = run_atom;
    run_start_ = run_start;
    nruns_ = nruns;
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
  }

  // the copies of the last sum, width values for each of nowned atoms
  Shares shares(int width, int nowned) const
  {
    return {copies_, threads_, static_cast<std::size_t>(width) * nowned};
  }

  // What a sum's kernel reads (blocks_of()): the runs and each thread's copy
  struct Blocks {
    Values copies;
    Indices run_atom, run_start, partner;
    int nruns, threads;
    std::size_t stride;
    KOKKOS_INLINE_FUNCTION double *copy(int t) const { return copies.data() + t * stride; }
    // the first run of block t (t = threads: past the last)
    KOKKOS_INLINE_FUNCTION int first_run(int t) const
    {
      return PairSumsKokkos::first_run(run_start, nruns, t, threads);
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
          double *copy = blocks.copy(t);
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
          double *copy = blocks.copy(t);
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
              if (j < owned) {
                copy[Width * j] -= f0;
                copy[Width * j + 1] -= f1;
                copy[Width * j + 2] -= f2;
              }
              if (Width == 6) {    // (not if constexpr: CUDA lambdas may not first capture there)
                const double amount = root * noise(p);
                const double k0 = amount * e0, k1 = amount * e1, k2 = amount * e2;
                kick0 += k0;
                kick1 += k1;
                kick2 += k2;
                if (j < owned) {
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
  Indices partner_, run_atom_, run_start_;
  int nruns_ = 0;
  Values copies_;    // each thread's copy of a sum over the pairs (Shares)
  int threads_ = 1;

  // The copies for width values per atom on each thread (zeroed where they grow, as take()
  // leaves them), with the runs, for a sum's kernel: one block of runs per thread (about equal
  // numbers of pairs), block t into copy t (the same sums whichever thread runs it; no per-run
  // token)
  Blocks blocks_of(int width, int nowned)
  {
    threads_ = execution_space().concurrency();
    const std::size_t stride = static_cast<std::size_t>(width) * nowned;
    if (copies_.extent(0) < threads_ * stride)
      copies_ = Values("etd:pair_shares", threads_ * stride);
    return {copies_, run_atom_, run_start_, partner_, nruns_, threads_, stride};
  }
};

}    // namespace etd

#endif
