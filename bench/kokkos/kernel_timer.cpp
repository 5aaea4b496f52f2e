// A Kokkos Tools library that times every kernel by its label: wall time and count of the
// parallel_for, parallel_reduce and parallel_scan launches and of the deep copies, printed to
// stderr (most time first) when Kokkos finalizes. Kernels run one after another on the host
// backends, so each launch is timed from its begin to its end.
//   g++ -O2 -shared -fPIC bench/kokkos/kernel_timer.cpp -o kernel_timer.so
//   KOKKOS_TOOLS_LIBS=$PWD/kernel_timer.so lmp -k on t 1 -sf kk -in in.case
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace {
using Clock = std::chrono::steady_clock;
std::map<std::string, std::pair<double, long>> totals;    // label: seconds, launches
std::vector<std::pair<std::string, Clock::time_point>> open_launches;
std::uint64_t next_id = 1;

void begin(const char *label, std::uint64_t *id)
{
  *id = next_id++;
  open_launches.emplace_back(label, Clock::now());
}
void end()
{
  if (open_launches.empty()) return;
  auto &total = totals[open_launches.back().first];
  total.first += std::chrono::duration<double>(Clock::now() - open_launches.back().second).count();
  total.second++;
  open_launches.pop_back();
}
}    // namespace

extern "C" {
void kokkosp_init_library(int, std::uint64_t, std::uint32_t, void *) {}
void kokkosp_finalize_library()
{
  std::vector<std::pair<double, std::string>> rows;
  for (const auto &[label, total] : totals)
    rows.emplace_back(total.first, label + " x" + std::to_string(total.second));
  std::sort(rows.rbegin(), rows.rend());
  for (const auto &[seconds, label] : rows)
    std::fprintf(stderr, "kernel %10.4f s  %s\n", seconds, label.c_str());
}
void kokkosp_begin_parallel_for(const char *label, std::uint32_t, std::uint64_t *id)
{
  begin(label, id);
}
void kokkosp_end_parallel_for(std::uint64_t)
{
  end();
}
void kokkosp_begin_parallel_reduce(const char *label, std::uint32_t, std::uint64_t *id)
{
  begin(label, id);
}
void kokkosp_end_parallel_reduce(std::uint64_t)
{
  end();
}
void kokkosp_begin_parallel_scan(const char *label, std::uint32_t, std::uint64_t *id)
{
  begin(label, id);
}
void kokkosp_end_parallel_scan(std::uint64_t)
{
  end();
}
void kokkosp_begin_deep_copy(void *, const char *, const void *, void *, const char *, const void *,
                             std::uint64_t)
{
  std::uint64_t id;
  begin("deep_copy", &id);
}
void kokkosp_end_deep_copy()
{
  end();
}
}
