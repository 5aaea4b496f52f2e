// ETD-DPD: what the Kokkos kernels of the implicit scheme share (friction_pairs_kokkos.h,
// friction_operator_kokkos.h, friction_solve_kokkos.h) and the pair style's kernel uses too: the
// views a step's pairs live in, growing a work view, moving arrays between the host and
// DeviceType's memory, and the noise's ziggurat tables in device memory. Pure Kokkos (no LAMMPS).
#ifndef ETD_KOKKOS_VIEWS_H
#define ETD_KOKKOS_VIEWS_H

#include "dpd_random.h"
#include "normal_ziggurat.h"

#include <Kokkos_Core.hpp>

#include <cstddef>
#include <functional>

namespace etd {
namespace kk {

template <class DeviceType> using Indices = Kokkos::View<int *, DeviceType>;
template <class DeviceType> using Values = Kokkos::View<double *, DeviceType>;
// per pair: e0, e1, e2 (unit vector from j to i) and gamma w_D, as FrictionPair holds them
template <class DeviceType>
using Geometry = Kokkos::View<float *[4], Kokkos::LayoutRight, DeviceType>;

// at least n entries, reallocated (uninitialised) only when it has fewer: work views keep their
// memory from step to step
template <class View> void grow(View &view, std::size_t n)
{
  if (view.extent(0) < n)
    view = View(Kokkos::view_alloc(Kokkos::WithoutInitializing, "etd:kernels"), n);
}

// Runs body(k) for k in [0, n) on the host's threads (Kokkos's default host execution space),
// a kernel labelled label: the runner of the host loops that take chunks (CellPairSearch's
// slabs, the pair style's rows)
inline std::function<void(int, const std::function<void(int)> &)> host_chunk_runner(
    const char *label)
{
  return [label](int n, const std::function<void(int)> &body) {
    Kokkos::parallel_for(label, Kokkos::RangePolicy<Kokkos::DefaultHostExecutionSpace>(0, n),
                         [&](const int k) { body(k); });
  };
}

// the bytes the views hold (their allocations, which work views keep from step to step)
template <class... Views> std::size_t bytes_of(const Views &...views)
{
  return (std::size_t{0} + ... + (views.span() * sizeof(typename Views::value_type)));
}

// the first n entries of view from a host array (grown to hold them)
template <class View, typename T> void upload(View &view, const T *host, int n)
{
  grow(view, n);
  if (n == 0) return;
  Kokkos::View<const T *, Kokkos::HostSpace, Kokkos::MemoryTraits<Kokkos::Unmanaged>> given(host, n);
  Kokkos::deep_copy(Kokkos::subview(view, Kokkos::make_pair(0, n)), given);
}

// the first n entries of view into a host array
template <class View> void download(const View &view, double *host, int n)
{
  Kokkos::View<double *, Kokkos::HostSpace, Kokkos::MemoryTraits<Kokkos::Unmanaged>> out(host, n);
  Kokkos::deep_copy(out, Kokkos::subview(view, Kokkos::make_pair(0, n)));
}

// noise drawing with a copy of Boost's ziggurat tables in DeviceType's memory (kept in tables),
// for kernels that cannot read the host's
template <class DeviceType>
PairNoise noise_with_device_tables(PairNoise noise, Kokkos::View<double *, DeviceType> &tables)
{
  const ZigguratTables host = ZigguratTables::host();
  constexpr int N = ZigguratTables::NORMAL_SIZE, E = ZigguratTables::EXPONENTIAL_SIZE;
  Kokkos::View<double *, Kokkos::HostSpace> staged("ziggurat tables (host)", 2 * N + 2 * E);
  for (int k = 0; k < N; k++) {
    staged(k) = host.normal_x[k];
    staged(N + k) = host.normal_y[k];
  }
  for (int k = 0; k < E; k++) {
    staged(2 * N + k) = host.exponential_x[k];
    staged(2 * N + E + k) = host.exponential_y[k];
  }
  tables = Kokkos::View<double *, DeviceType>("ziggurat tables", 2 * N + 2 * E);
  Kokkos::deep_copy(tables, staged);
  const double *d = tables.data();
  noise.use_tables({d, d + N, d + 2 * N, d + 2 * N + E});
  return noise;
}

}    // namespace kk
}    // namespace etd

#endif
