// How much it costs this machine's cores to share data: two passes over the same arrays, the
// second reading what the first wrote, with both passes split alike among the threads (each
// reads what it wrote itself) or split differently (half of it was written by the other core).
// Threads share memory and MPI ranks do not, so where the second case is much slower, threaded
// runs lose against ranks in a way the kernels cannot change.
//   g++ -O2 -fopenmp bench/kokkos/sharing_probe.cpp -o sharing_probe && OMP_PROC_BIND=false ./sharing_probe
#include <omp.h>

#include <chrono>
#include <cstdio>
#include <vector>

int main()
{
  const long n = 288000;    // three vectors of 2.3 MB, as the solve's over 24,000 atoms
  std::vector<double> a(n, 1.0), b(n, 2.0), c(n, 0.0);
  for (const bool split_alike : {true, false})
    for (const int threads : {1, 2}) {
      omp_set_num_threads(threads);
      const int repeats = 4000;
      const auto start = std::chrono::steady_clock::now();
      for (int r = 0; r < repeats; r++) {
#pragma omp parallel for schedule(static)
        for (long i = 0; i < n; i++) c[i] = a[i] + 0.5 * b[i] + 0.1 * c[i];
        if (split_alike) {
#pragma omp parallel for schedule(static)
          for (long i = 0; i < n; i++) a[i] = 0.3 * c[i] + 0.2 * a[i];
        } else {
#pragma omp parallel for schedule(static, 384)
          for (long i = 0; i < n; i++) a[i] = 0.3 * c[i] + 0.2 * a[i];
        }
      }
      const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::printf("%-18s %d thread(s): %.3f ms for the two passes\n",
                  split_alike ? "split alike" : "split differently", threads,
                  1e3 * seconds / repeats);
    }
  return 0;
}
