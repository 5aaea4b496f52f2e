// The implicit scheme's solve in Kokkos kernels (src/KOKKOS/friction_solve_kokkos.h) against the
// CPU solve (friction_solve.h) on one DPD cluster: from the block-Jacobi start and from a given
// start, with atoms held, and with remote partners (slots) filled by an exchange. Run with the
// KOKKOS tests (label kokkos), on 1 and 2 threads.
#include "friction_operator.h"
#include "friction_solve.h"
#include "friction_solve_kokkos.h"
#include "reference_weights.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <random>
#include <vector>

namespace {

class KokkosEnvironment : public ::testing::Environment {
 public:
  void SetUp() override
  {
    const char *threads = std::getenv("ETD_KOKKOS_THREADS");
    Kokkos::InitializationSettings settings;
    if (threads) settings.set_num_threads(std::atoi(threads));
    Kokkos::initialize(settings);
  }
  void TearDown() override { Kokkos::finalize(); }
};
const auto *const environment = ::testing::AddGlobalTestEnvironment(new KokkosEnvironment);

using Device = Kokkos::DefaultExecutionSpace::device_type;

// a pair's share on j is kept where j is owned (a remote partner's is its owner's)
const auto owned_only = [](int natoms) {
  return [natoms](int j) { return j < natoms; };
};

// A DPD cluster, n = 4 in a periodic 3^3 box, gamma = 4.5, s = 1/2. With slots, each pair across
// the box's boundary is held twice, from each end, with the other end as a remote partner (a
// slot whose owner is the atom itself), as two ranks hold a pair that crosses between them.
struct Cluster {
  int natoms = 108;
  double box = 3.0;
  std::vector<etd::FrictionPair> pairs;
  std::vector<int> slot_owner;    // per slot, the owned atom it stands for
  explicit Cluster(bool with_slots)
  {
    std::mt19937_64 gen(7);
    std::uniform_real_distribution<double> uniform(0.0, box);
    std::vector<double> x;
    for (int k = 0; k < 3 * natoms; k++) x.push_back(uniform(gen));
    for (int i = 0; i < natoms; i++)
      for (int j = i + 1; j < natoms; j++) {
        double d[3], rsq = 0.0;
        bool crosses = false;
        for (int k = 0; k < 3; k++) {
          d[k] = x[3 * i + k] - x[3 * j + k];
          const double image = box * std::round(d[k] / box);
          crosses = crosses || image != 0.0;
          d[k] -= image;
          rsq += d[k] * d[k];
        }
        if (rsq >= 1.0) continue;
        const double r = std::sqrt(rsq);
        const float friction = float(4.5 * etdtest::dissipative_weight(r, 1.0, 0.5));
        const float e[3] = {float(d[0] / r), float(d[1] / r), float(d[2] / r)};
        if (!(with_slots && crosses)) {
          pairs.push_back({i, j, {e[0], e[1], e[2]}, friction});
          continue;
        }
        slot_owner.push_back(j);
        pairs.push_back({i, natoms + int(slot_owner.size()) - 1, {e[0], e[1], e[2]}, friction});
        slot_owner.push_back(i);
        pairs.push_back({j, natoms + int(slot_owner.size()) - 1, {-e[0], -e[1], -e[2]}, friction});
      }
    // the list's order: pairs of one atom i together
    std::stable_sort(pairs.begin(), pairs.end(),
                     [](const etd::FrictionPair &a, const etd::FrictionPair &b) { return a.i < b.i; });
  }
  int partners() const { return natoms + int(slot_owner.size()); }
  void exchange(double *values) const
  {
    for (size_t s = 0; s < slot_owner.size(); s++)
      for (int k = 0; k < 3; k++) values[3 * (natoms + s) + k] = values[3 * slot_owner[s] + k];
  }
};

struct Solves {
  std::vector<double> cpu, kokkos;
  etd::SolverResult cpu_result, kokkos_result;
};

// both solvers on (M + h/2 G) x = b, m = 0.01, h = 0.003
Solves solve_both(const Cluster &c, const std::vector<int> &mobile, bool with_start)
{
  const int n = 3 * c.natoms;
  const double h = 0.003;
  std::vector<double> inertia(n, 0.01), rhs, start(3 * c.partners(), 0.0);
  std::mt19937_64 gen(11);
  std::normal_distribution<double> normal;
  for (int k = 0; k < n; k++) rhs.push_back(normal(gen));
  for (int k = 0; k < n; k++) start[k] = mobile[k / 3] ? 0.3 * normal(gen) : 0.0;
  c.exchange(start.data());
  const auto keep_j = owned_only(c.natoms);
  std::vector<double> start_friction(n, 0.0), blocks(6 * c.natoms, 0.0), operand;
  etd::accumulate_friction(c.pairs, start.data(), start_friction.data(), keep_j);
  etd::accumulate_blocks(c.pairs, blocks.data(), keep_j, 6);

  etd::FrictionSystem sys;
  sys.n = n;
  sys.inertia = inertia.data();
  sys.blocks = blocks.data();
  sys.mass_weight = 1.0;
  sys.friction_weight = 0.5 * h;
  auto apply = [&](const double *u, double *out, double weight) {
    operand.assign(3 * c.partners(), 0.0);
    for (int k = 0; k < n; k++) operand[k] = mobile[k / 3] ? u[k] : 0.0;
    c.exchange(operand.data());
    std::vector<double> gu(n, 0.0);
    etd::accumulate_friction(c.pairs, operand.data(), gu.data(), keep_j);
    for (int k = 0; k < n; k++) out[k] += weight * gu[k];
  };
  const auto serial_sum = [](double *, int) {};
  etd::FrictionSolveWorkspace work;
  Solves s;
  s.cpu_result = etd::solve_friction_system(
      sys, [&](int a) { return mobile[a] != 0; }, apply, serial_sum, rhs.data(), s.cpu, 1e-10,
      500, work, with_start ? start.data() : nullptr,
      with_start ? start_friction.data() : nullptr);

  etd::FrictionSolveKokkos<Device> kernels;
  kernels.set_pairs(c.pairs, c.natoms, c.partners());
  s.kokkos.assign(n, 0.0);
  const etd::FrictionSolveKokkos<Device>::Exchange exchange = [&](double *v) { c.exchange(v); };
  s.kokkos_result = kernels.solve(inertia.data(), mobile.data(), rhs.data(), 1.0, 0.5 * h, 1e-10,
                                  500, exchange, serial_sum, s.kokkos.data(),
                                  with_start ? start.data() : nullptr,
                                  with_start ? start_friction.data() : nullptr);
  return s;
}

void expect_same(const Solves &s)
{
  ASSERT_TRUE(s.cpu_result.converged);
  ASSERT_TRUE(s.kokkos_result.converged);
  // the reductions sum in another order: the iterates agree to rounding, so the counts to one
  EXPECT_NEAR(s.kokkos_result.iterations, s.cpu_result.iterations, 1);
  double worst = 0.0, scale = 0.0;
  for (size_t k = 0; k < s.cpu.size(); k++) {
    worst = std::max(worst, std::fabs(s.kokkos[k] - s.cpu[k]));
    scale = std::max(scale, std::fabs(s.cpu[k]));
  }
  EXPECT_LT(worst, 1e-12 * scale) << "largest difference " << worst << " of " << scale;
}

}    // namespace

TEST(FrictionSolveKokkos, MatchesTheCpuSolveFromTheJacobiStart)
{
  const Cluster c(false);
  expect_same(solve_both(c, std::vector<int>(c.natoms, 1), false));
}

TEST(FrictionSolveKokkos, MatchesTheCpuSolveFromAGivenStart)
{
  const Cluster c(false);
  expect_same(solve_both(c, std::vector<int>(c.natoms, 1), true));
}

TEST(FrictionSolveKokkos, HeldAtomsStayAtZero)
{
  const Cluster c(false);
  std::vector<int> mobile(c.natoms, 1);
  for (int a = 0; a < c.natoms; a += 5) mobile[a] = 0;
  const Solves s = solve_both(c, mobile, true);
  expect_same(s);
  for (int a = 0; a < c.natoms; a += 5)
    for (int k = 0; k < 3; k++) EXPECT_EQ(s.kokkos[3 * a + k], 0.0);
}

TEST(FrictionSolveKokkos, RemotePartnersFilledByTheExchange)
{
  const Cluster c(true);
  ASSERT_GT(c.slot_owner.size(), 10u);
  expect_same(solve_both(c, std::vector<int>(c.natoms, 1), false));
  // and the same system without slots (each crossing pair held once) has the same solution
  const Cluster plain(false);
  const Solves with_slots = solve_both(c, std::vector<int>(c.natoms, 1), true);
  const Solves without = solve_both(plain, std::vector<int>(plain.natoms, 1), true);
  for (size_t k = 0; k < without.cpu.size(); k++)
    EXPECT_NEAR(with_slots.kokkos[k], without.cpu[k], 1e-8 * (1.0 + std::fabs(without.cpu[k])));
}
