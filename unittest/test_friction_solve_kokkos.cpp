// The implicit scheme's operator and solve in Kokkos kernels
// (src/KOKKOS/friction_operator_kokkos.h, friction_solve_kokkos.h) against the CPU solve
// (friction_solve.h) on one DPD cluster: from the block-Jacobi start and from a given start, with
// atoms held, and with remote partners (slots) filled by an exchange; the pairs handed over in
// device memory, and the step's right-hand side, against the host's; and the pairs' assembly in
// kernels (friction_pairs_kokkos.h) against the host assembly's rules. Run with the KOKKOS tests
// (label kokkos), on 1 and 2 threads.
#include "dpd_kernel.h"
#include "dpd_random.h"
#include "friction_operator.h"
#include "friction_pairs_kokkos.h"
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
  // the same for the kernels, which pack the values sent: this "rank" sends the slots' owners
  // to itself
  etd::FrictionSolveKokkos<Device>::Exchange kernel_exchange() const
  {
    const int slots = static_cast<int>(slot_owner.size());
    return {slot_owner.data(), slots, [slots](const double *sent, double *slot_values) {
              std::copy(sent, sent + 3 * slots, slot_values);
            }};
  }
};

struct Solves {
  std::vector<double> cpu, kokkos;
  etd::SolverResult cpu_result, kokkos_result;
};

// both solvers on (M + h/2 G) x = b, m = 0.01, h = 0.003; with zero_mass on G x = b (the
// overdamped limit), deflated where no atom is held (G is then singular in the translation)
Solves solve_both(const Cluster &c, const std::vector<int> &mobile, bool with_start,
                  bool zero_mass = false)
{
  const int n = 3 * c.natoms;
  const double h = 0.003;
  const double mass_weight = zero_mass ? 0.0 : 1.0, friction_weight = zero_mass ? 1.0 : 0.5 * h;
  const bool deflate = zero_mass && std::count(mobile.begin(), mobile.end(), 0) == 0;
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
  sys.mass_weight = mass_weight;
  sys.friction_weight = friction_weight;
  sys.deflate = deflate;
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
  const etd::FrictionSolveKokkos<Device>::Exchange exchange = c.kernel_exchange();
  s.kokkos_result = kernels.solve(inertia.data(), mobile.data(), rhs.data(), mass_weight,
                                  friction_weight, 1e-10, 500, exchange, serial_sum,
                                  s.kokkos.data(), with_start ? start.data() : nullptr,
                                  with_start ? start_friction.data() : nullptr, deflate);
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

// The overdamped limit: G x = b with nothing held is singular in the uniform translation, which
// both solvers remove; without the deflation the kernels' solution keeps b's mean drift (checked
// by leaving it out), and the CPU solve's has none
TEST(FrictionSolveKokkos, ZeroMassSolveIsDeflatedAsTheCpuSolve)
{
  const Cluster c(false);
  const Solves s = solve_both(c, std::vector<int>(c.natoms, 1), false, true);
  expect_same(s);
  for (int k = 0; k < 3; k++) {
    double mean = 0.0;
    for (int a = 0; a < c.natoms; a++) mean += s.kokkos[3 * a + k];
    EXPECT_NEAR(mean / c.natoms, 0.0, 1e-12);
  }
  // with slots (remote partners filled by the exchange) too
  const Cluster sliced(true);
  expect_same(solve_both(sliced, std::vector<int>(sliced.natoms, 1), false, true));
}

// and with atoms held at rest, which fix the translation: no deflation, held atoms at zero
TEST(FrictionSolveKokkos, ZeroMassSolveWithHeldAtoms)
{
  const Cluster c(false);
  std::vector<int> mobile(c.natoms, 1);
  for (int a = 0; a < c.natoms; a += 7) mobile[a] = 0;
  const Solves s = solve_both(c, mobile, false, true);
  expect_same(s);
  for (int a = 0; a < c.natoms; a += 7)
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

namespace {

// the pairs of a cluster in device memory, as friction_pairs_kokkos.h hands them over
struct DevicePairs {
  etd::FrictionSolveKokkos<Device>::Indices i, j;
  etd::FrictionSolveKokkos<Device>::Geometry geometry;
  explicit DevicePairs(const std::vector<etd::FrictionPair> &pairs)
      : i("i", pairs.size()), j("j", pairs.size()), geometry("geometry", pairs.size())
  {
    auto hi = Kokkos::create_mirror_view(i);
    auto hj = Kokkos::create_mirror_view(j);
    auto hg = Kokkos::create_mirror_view(geometry);
    for (size_t p = 0; p < pairs.size(); p++) {
      hi(p) = pairs[p].i;
      hj(p) = pairs[p].j;
      for (int k = 0; k < 3; k++) hg(p, k) = pairs[p].e[k];
      hg(p, 3) = pairs[p].friction;
    }
    Kokkos::deep_copy(i, hi);
    Kokkos::deep_copy(j, hj);
    Kokkos::deep_copy(geometry, hg);
  }
};

}    // namespace

// Pairs handed over in device memory: applied by their runs where the kernels run on the host
// (the runs found from the pairs' i, or given as the assembly's rows), the same solution as the
// host set_pairs(), bit for bit; and by the incidence list built in kernels (a GPU's path:
// atomics, then each atom's entries sorted back to pair order), the same to round-off (sums in
// another order). With slots, and with an atom's pair with its own periodic image, whose two
// ends are one atom.
TEST(FrictionSolveKokkos, PairsInDeviceMemoryGiveTheSameSolve)
{
  Cluster c(true);
  c.pairs.push_back({5, 5, {0.6f, 0.8f, 0.0f}, 1.5f});    // atom 5 and its own image
  std::stable_sort(c.pairs.begin(), c.pairs.end(),
                   [](const etd::FrictionPair &a, const etd::FrictionPair &b) { return a.i < b.i; });
  const int n = 3 * c.natoms;
  std::vector<double> inertia(n, 0.01), rhs(n);
  std::mt19937_64 gen(3);
  std::normal_distribution<double> normal;
  for (double &b : rhs) b = normal(gen);
  const std::vector<int> mobile(c.natoms, 1);
  const auto serial_sum = [](double *, int) {};
  const etd::FrictionSolveKokkos<Device>::Exchange exchange = c.kernel_exchange();
  // the rows as the assembly gives them: one per atom, in order, empty ones included
  using Indices = etd::FrictionSolveKokkos<Device>::Indices;
  Indices rows("rows", c.natoms), row_start("row_start", c.natoms + 1);
  {
    auto h_rows = Kokkos::create_mirror_view(rows);
    auto h_start = Kokkos::create_mirror_view(row_start);
    int p = 0;
    for (int a = 0; a < c.natoms; a++) {
      h_rows(a) = a;
      h_start(a) = p;
      while (p < int(c.pairs.size()) && c.pairs[p].i == a) p++;
    }
    h_start(c.natoms) = p;
    Kokkos::deep_copy(rows, h_rows);
    Kokkos::deep_copy(row_start, h_start);
  }
  std::vector<double> x[4];
  for (int path = 0; path < 4; path++) {
    etd::FrictionSolveKokkos<Device> kernels;
    const DevicePairs pairs(c.pairs);
    const int npairs = int(c.pairs.size());
    if (path == 1)
      kernels.set_pairs(pairs.i, pairs.j, pairs.geometry, npairs, c.natoms, c.partners());
    else if (path == 2)
      kernels.set_pairs(pairs.i, pairs.j, pairs.geometry, npairs, c.natoms, c.partners(), &rows,
                        &row_start, c.natoms);
    else if (path == 3)
      kernels.set_pairs_in_kernels(pairs.i, pairs.j, pairs.geometry, npairs, c.natoms,
                                   c.partners());
    else
      kernels.set_pairs(c.pairs, c.natoms, c.partners());
    x[path].assign(n, 0.0);
    kernels.solve(inertia.data(), mobile.data(), rhs.data(), 1.0, 0.0015, 1e-10, 500, exchange,
                  serial_sum, x[path].data());
  }
  double scale = 0.0;
  for (int k = 0; k < n; k++) scale = std::max(scale, std::fabs(x[0][k]));
  for (int path = 1; path < 4; path++)
    for (int k = 0; k < n; k++)
      if (path < 3)
        ASSERT_EQ(x[path][k], x[0][k]) << "path " << path << ", unknown " << k;
      else
        ASSERT_NEAR(x[path][k], x[0][k], 1e-12 * scale) << "path " << path << ", unknown " << k;
}

// b = M v - h/2 G u + sqrt(h) sum_pairs (+-) noise e against the host's sums, applied by the
// pairs' runs (the host's threads) and by the incidence list (a GPU's path)
class RightHandSide : public ::testing::TestWithParam<bool> {};
INSTANTIATE_TEST_SUITE_P(FrictionSolveKokkos, RightHandSide, ::testing::Values(false, true));
TEST_P(RightHandSide, MatchesTheHostSums)
{
  const bool incidence = GetParam();
  const Cluster c(true);
  const int n = 3 * c.natoms;
  const double h = 0.004;
  std::mt19937_64 gen(5);
  std::normal_distribution<double> normal;
  std::vector<double> inertia(n, 0.01), v(n), u(3 * c.partners()), noise(c.pairs.size());
  for (double &value : v) value = normal(gen);
  for (int k = 0; k < n; k++) u[k] = v[k];
  c.exchange(u.data());
  for (double &value : noise) value = normal(gen);
  const auto keep_j = owned_only(c.natoms);
  std::vector<double> gu(n, 0.0), impulse(n, 0.0), expected(n);
  etd::accumulate_friction(c.pairs, u.data(), gu.data(), keep_j);
  etd::accumulate_noise(c.pairs, noise, std::sqrt(h), impulse.data(), keep_j);
  for (int k = 0; k < n; k++) expected[k] = inertia[k] * v[k] - 0.5 * h * gu[k] + impulse[k];

  etd::FrictionSolveKokkos<Device> kernels;
  const DevicePairs pairs(c.pairs);
  if (incidence)
    kernels.set_pairs_in_kernels(pairs.i, pairs.j, pairs.geometry, int(c.pairs.size()), c.natoms,
                                 c.partners());
  else
    kernels.set_pairs(pairs.i, pairs.j, pairs.geometry, int(c.pairs.size()), c.natoms,
                      c.partners());
  etd::FrictionSolveKokkos<Device>::Values noise_view("noise", noise.size());
  auto h_noise = Kokkos::create_mirror_view(noise_view);
  for (size_t p = 0; p < noise.size(); p++) h_noise(p) = noise[p];
  Kokkos::deep_copy(noise_view, h_noise);
  std::vector<double> b(n), friction(n);
  kernels.step_rhs(inertia.data(), v.data(), u.data(), noise_view, h, b.data(), friction.data());
  for (int k = 0; k < n; k++) {
    EXPECT_NEAR(b[k], expected[k], 1e-12 * (1.0 + std::fabs(expected[k]))) << "unknown " << k;
    EXPECT_NEAR(friction[k], gu[k], 1e-12 * (1.0 + std::fabs(gu[k]))) << "unknown " << k;
  }

  // moving images: every third pair's other end moves on top of its owner (fix deform ...
  // remap v); b less h G_offset, summed as the host assembly sums it, in pair order
  std::vector<double> offsets(3 * c.pairs.size(), 0.0), image_friction(n, 0.0);
  for (size_t p = 0; p < c.pairs.size(); p += 3)
    for (int k = 0; k < 3; k++) offsets[3 * p + k] = normal(gen);
  for (size_t p = 0; p < c.pairs.size(); p += 3)
    etd::accumulate_image_offset(c.pairs[p], &offsets[3 * p], image_friction.data(), keep_j);
  etd::FrictionSolveKokkos<Device>::Values offset_view("offsets", offsets.size());
  auto h_offsets = Kokkos::create_mirror_view(offset_view);
  for (size_t k = 0; k < offsets.size(); k++) h_offsets(k) = offsets[k];
  Kokkos::deep_copy(offset_view, h_offsets);
  kernels.step_rhs(inertia.data(), v.data(), u.data(), noise_view, h, b.data(), friction.data(),
                   &offset_view);
  double largest = 0.0;
  for (int k = 0; k < n; k++) {
    const double moved = expected[k] - h * image_friction[k];
    EXPECT_NEAR(b[k], moved, 1e-12 * (1.0 + std::fabs(moved))) << "unknown " << k;
    EXPECT_NEAR(friction[k], gu[k], 1e-12 * (1.0 + std::fabs(gu[k]))) << "unknown " << k;
    largest = std::max(largest, std::fabs(h * image_friction[k]));
  }
  EXPECT_GT(largest, 1e-3);    // (the images' friction is a visible part of b)
}

// The pairs' assembly in kernels against its rules written out here: a half list of candidates
// (some beyond the cutoff, one weighted by a special-bond factor, one excluded), two types whose
// cross pair has no friction, atoms outside the group, and ghosts: an image of another owned
// atom (newton off: kept from the lower ID's end only) and a remote atom's image (a slot)
TEST(FrictionPairsKokkos, AssemblesThePairsTheHostRulesGive)
{
  const int nlocal = 40, nall = 44;
  std::mt19937_64 gen(9);
  std::uniform_real_distribution<double> uniform(0.0, 2.0);
  std::vector<double> x(3 * nall);
  for (double &value : x) value = uniform(gen);
  for (int k = 0; k < 3; k++) {    // the special-bond pairs (4, 5) and (6, 8) within the cutoff
    x[3 * 5 + k] = x[3 * 4 + k] + (k == 0 ? 0.3 : 0.0);
    x[3 * 8 + k] = x[3 * 6 + k] + (k == 1 ? 0.4 : 0.0);
  }
  std::vector<int> type(nall, 1), mask(nall, 1), tag(nall);
  for (int a = 0; a < nall; a++) tag[a] = a + 1;
  type[7] = type[19] = 2;
  mask[3] = mask[11] = 0;    // outside the group (groupbit 1)
  // ghosts 40, 41: images of owned atoms 2 and 30; 42, 43: of remote atoms (slots 40, 41)
  const std::vector<int> ghost_partner = {2, 30, 40, 41};
  tag[40] = tag[2];
  tag[41] = tag[30];
  tag[42] = 101;
  tag[43] = 102;
  const int sb = 30, mask_bits = (1 << sb) - 1;
  std::vector<std::vector<int>> neighbors(nlocal);
  for (int i = 0; i < nlocal; i++)
    for (int j = i + 1; j < nall; j++) neighbors[i].push_back(j);
  neighbors[4][0] |= 1 << sb;    // special factor 0.5
  neighbors[6][1] |= 2 << sb;    // special factor 0: excluded
  std::vector<int> ilist(nlocal), numneigh(nlocal);
  std::vector<int *> firstneigh(nlocal);
  for (int i = 0; i < nlocal; i++) {
    ilist[i] = i;
    numneigh[i] = int(neighbors[i].size());
    firstneigh[i] = neighbors[i].data();
  }
  const double special[4] = {1.0, 0.5, 0.0, 1.0};
  etd::PairCoefficients same, cross;
  same.set(25.0, 4.5, 0.5, 1.0, 1.0, 0.9, 1.0);
  cross.set(25.0, 0.0, 2.0, 1.0, 1.0, 1.0, 1.0);    // no friction: no pairs
  const std::vector<const etd::PairCoefficients *> table = {nullptr, nullptr, nullptr,
                                                            nullptr, &same,   &cross,
                                                            nullptr, &cross,  &same};
  const etd::PairNoise noise(77, etd::NoiseStream::Integrator);
  const std::int64_t step = 12;

  // moving images (fix deform ... remap v): each ghost's count of box vectors from its owner;
  // ghost 41 lies outside the deforming group (bit 2), so its image has no velocity of its own
  std::vector<double> image(6 * nall, 0.0);
  image[6 * 40 + 1] = 1.0;                          // one box vector y up
  image[6 * 41 + 0] = -1.0;                         // (outside the deforming group)
  image[6 * 42 + 1] = -1.0, image[6 * 42 + 2] = 1.0;
  image[6 * 43 + 5] = 2.0;
  const double rate[6] = {0.0, 0.0, 0.0, 0.1, 0.2, 0.5};    // h_rate: xy, xz, yz tilt rates
  std::vector<int> deform_mask = mask;
  for (int a = 0; a < nall; a++) deform_mask[a] = mask[a] | (a == 41 ? 0 : 2);

  for (const bool copy_list : {false, true})
  for (const bool moving : {false, true}) {
    SCOPED_TRACE(copy_list ? "the list copied into compressed rows (a GPU's path)"
                           : "the list read in place");
    SCOPED_TRACE(moving ? "moving images" : "images at rest");
    etd::FrictionPairsKokkos<Device> kernels;
    kernels.copy_the_list(copy_list);
    kernels.set_coefficients(table, 3, noise);
    etd::FrictionPairsKokkos<Device>::Input in;
    in.nlocal = nlocal;
    in.nall = nall;
    in.inum = nlocal;
    in.ilist = ilist.data();
    in.numneigh = numneigh.data();
    in.firstneigh = firstneigh.data();
    in.neighbor_mask = mask_bits;
    in.special_shift = sb;
    in.special = special;
    in.x = x.data();
    in.type = type.data();
    in.mask = moving ? deform_mask.data() : mask.data();
    in.ghost_partner = ghost_partner.data();
    if (moving) {
      in.image = image.data();
      for (int k = 0; k < 6; k++) in.image_rate[k] = rate[k];
      in.deform_groupbit = 2;
    }
    in.groupbit = 1;
    in.newton_off = true;
    in.step = step;
    in.cutsq_max = 0.81;
    const bool fixed = kernels.build(in, tag.data());
    std::vector<etd::FrictionPair> pairs;
    std::vector<double> pair_noise, distance, offsets;
    kernels.copy_to_host(pairs, pair_noise, distance, &offsets);
    EXPECT_EQ(offsets.size(), moving ? 3 * pairs.size() : 0u);
    EXPECT_EQ(kernels.offsets() != nullptr, moving);
    int moving_pairs = 0;

    // the rules
    size_t p = 0;
    int special_pairs = 0, image_pairs = 0, slot_pairs = 0;
    bool expect_fixed = false;
    for (int i = 0; i < nlocal; i++)
      for (const int j_bits : neighbors[i]) {
        const int j = j_bits & mask_bits;
        const double factor = special[(j_bits >> sb) & 3];
        const double d[3] = {x[3 * i] - x[3 * j], x[3 * i + 1] - x[3 * j + 1],
                             x[3 * i + 2] - x[3 * j + 2]};
        const double rsq = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        const int partner = j < nlocal ? j : ghost_partner[j - nlocal];
        if (rsq >= 0.81 || factor == 0.0 || (!mask[i] && !mask[j]) || type[i] != type[j]) continue;
        if (j >= nlocal && partner < nlocal && tag[i] >= tag[partner]) continue;
        ASSERT_LT(p, pairs.size());
        const double r = std::sqrt(rsq);
        const etd::PairDissipation w = etd::pair_dissipation(same, r, factor);
        EXPECT_EQ(pairs[p].i, i);
        EXPECT_EQ(pairs[p].j, partner);
        for (int k = 0; k < 3; k++) EXPECT_EQ(pairs[p].e[k], float(d[k] * (1.0 / r)));
        EXPECT_EQ(pairs[p].friction, float(w.friction));
        EXPECT_EQ(pair_noise[p], w.noise * noise.gaussian(tag[i], tag[j], step));
        EXPECT_EQ(distance[p], r);
        if (moving) {
          // v_image - v_owner = n_x rate_x-vector + ...: (n0 r0 + n5 r5 + n4 r4, n1 r1 + n3 r3, n2 r2)
          double expected[3] = {0.0, 0.0, 0.0};
          if (j >= nlocal && j != 41) {
            const double *m = &image[6 * j];
            expected[0] = m[0] * rate[0] + m[5] * rate[5] + m[4] * rate[4];
            expected[1] = m[1] * rate[1] + m[3] * rate[3];
            expected[2] = m[2] * rate[2];
          }
          for (int k = 0; k < 3; k++) EXPECT_EQ(offsets[3 * p + k], expected[k]) << "pair " << p;
          moving_pairs += expected[0] != 0.0 || expected[1] != 0.0 || expected[2] != 0.0;
        }
        expect_fixed = expect_fixed || !mask[i] || !mask[j];
        special_pairs += factor == 0.5;
        image_pairs += j >= nlocal && partner < nlocal;
        slot_pairs += partner >= nlocal;
        p++;
      }
    EXPECT_EQ(p, pairs.size());
    EXPECT_EQ(fixed, expect_fixed);
    EXPECT_TRUE(expect_fixed);
    // (the configuration has each kind of pair the rules treat apart)
    EXPECT_GT(pairs.size(), 50u);
    EXPECT_EQ(special_pairs, 1);
    EXPECT_GT(image_pairs, 0);
    EXPECT_GT(slot_pairs, 0);
    if (moving) EXPECT_GT(moving_pairs, 2);
  }
}

// The host threads' blocks of runs (friction_pair_sums_kokkos.h): for 1 to 7 threads every run
// with pairs falls in exactly one block, in order, and no block holds more than its share of the
// pairs and one run (the first half of the runs long, the second short, as no equal split of
// the runs would give); runs without pairs (an atom's empty row) anywhere
TEST(PairSumsKokkos, BlocksCoverEveryRunOnceWithTheirShareOfPairs)
{
  using PairSums = etd::PairSumsKokkos<Device>;
  std::mt19937_64 gen(13);
  std::uniform_int_distribution<int> long_run(5, 9), short_run(0, 1);
  std::vector<int> lengths;
  for (int r = 0; r < 300; r++)
    lengths.push_back(r % 17 == 0 ? 0 : (r < 150 ? long_run(gen) : short_run(gen)));
  lengths.push_back(0);
  const int nruns = int(lengths.size());
  PairSums::Indices run_start("run_start", nruns + 1);
  auto h_start = Kokkos::create_mirror_view(run_start);
  h_start(0) = 0;
  for (int r = 0; r < nruns; r++) h_start(r + 1) = h_start(r) + lengths[r];
  Kokkos::deep_copy(run_start, h_start);
  const int npairs = h_start(nruns);
  for (int threads = 1; threads <= 7; threads++) {
    std::vector<int> owner(nruns, -1);
    int previous_last = 0;
    for (int t = 0; t < threads; t++) {
      const int first = PairSums::first_run(h_start, nruns, t, threads);
      const int last = PairSums::first_run(h_start, nruns, t + 1, threads);
      EXPECT_EQ(first, previous_last) << threads << " threads, block " << t;
      previous_last = last;
      for (int r = first; r < last; r++) owner[r] = t;
      EXPECT_LE(h_start(last) - h_start(first), npairs / threads + 1 + 9)
          << threads << " threads, block " << t;
    }
    for (int r = 0; r < nruns; r++)
      if (lengths[r] > 0) EXPECT_GE(owner[r], 0) << threads << " threads, run " << r;
  }
}

// each atom's 3 values of a sum over the pairs, taken from the threads' copies (on the host)
template <class Shares>
Kokkos::View<double *, Kokkos::HostSpace> taken(const Shares &shares, int nowned)
{
  Kokkos::View<double *, Device> got("got", 3 * nowned);
  Kokkos::parallel_for(
      Kokkos::RangePolicy<Kokkos::DefaultExecutionSpace>(0, nowned), KOKKOS_LAMBDA(const int a) {
        double values[3];
        shares.take(a, values);
        for (int k = 0; k < 3; k++) got(3 * a + k) = values[k];
      });
  return Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), got);
}

// The threads' copies (friction_pair_sums_kokkos.h) sum G u pair by pair as one thread would,
// the same values to rounding, and hold only the chunks of atoms each thread's block touches:
// with partners near in index (sorted atoms), about one copy of the atoms in all, not one per
// thread. Then pairs with partners anywhere, fewer owned atoms (a new layout): the sums again,
// so the copies were left zero and the layout follows the runs.
TEST(PairSumsKokkos, CopiesHoldTheChunksTheThreadsTouch)
{
  using PairSums = etd::PairSumsKokkos<Device>;
  const int threads = Kokkos::DefaultExecutionSpace().concurrency();
  std::mt19937_64 gen(29);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  PairSums sums;
  for (const int band : {40, 0}) {    // 0: partners anywhere
    const int nowned = band ? 2000 : 1500, npartners = nowned + 100;
    std::uniform_int_distribution<int> offset(1, band ? band : npartners - 1);
    std::vector<int> pair_i, pair_j;
    for (int i = 0; i < nowned; i++)
      for (int n = 0; n < 5; n++) {
        pair_i.push_back(i);
        pair_j.push_back(band ? std::min(i + offset(gen), npartners - 1)
                              : (i + offset(gen)) % npartners);
      }
    const int npairs = int(pair_i.size());
    PairSums::Indices partner("partner", npairs);
    PairSums::Geometry geometry("geometry", npairs);
    PairSums::Values u("u", 3 * npartners);
    auto h_partner = Kokkos::create_mirror_view(partner);
    auto h_geometry = Kokkos::create_mirror_view(geometry);
    auto h_u = Kokkos::create_mirror_view(u);
    std::vector<double> expect(3 * nowned, 0.0);
    for (int k = 0; k < 3 * npartners; k++) h_u(k) = uniform(gen);
    const double weight = 0.7;
    for (int p = 0; p < npairs; p++) {
      h_partner(p) = pair_j[p];
      double e[3], norm = 0.0;
      for (double &c : e) norm += (c = uniform(gen)) * c;
      for (int k = 0; k < 3; k++) h_geometry(p, k) = float(e[k] / std::sqrt(norm));
      h_geometry(p, 3) = float(1.0 + uniform(gen));
      const int i = pair_i[p], j = pair_j[p];
      double projected = 0.0;
      for (int k = 0; k < 3; k++)
        projected += double(h_geometry(p, k)) * (h_u(3 * i + k) - h_u(3 * j + k));
      projected *= weight * double(h_geometry(p, 3));
      for (int k = 0; k < 3; k++) {
        expect[3 * i + k] += projected * double(h_geometry(p, k));
        if (j < nowned) expect[3 * j + k] -= projected * double(h_geometry(p, k));
      }
    }
    Kokkos::deep_copy(partner, h_partner);
    Kokkos::deep_copy(geometry, h_geometry);
    Kokkos::deep_copy(u, h_u);
    sums.find_runs(partner, pair_i.data(), npairs);
    for (int pass = 0; pass < 2; pass++) {    // the second: the copies were left zero
      sums.add_friction(geometry, u, weight, nowned);
      auto h_got = taken(sums.shares<3>(), nowned);
      for (int d = 0; d < 3 * nowned; d++)
        ASSERT_NEAR(h_got(d), expect[d], 1e-12 * (1.0 + std::abs(expect[d])))
            << "band " << band << ", pass " << pass << ", value " << d;
    }
    const std::size_t chunks = (nowned + 63) / 64;
    if (band)    // each thread's own chunks and one across each edge of its block
      EXPECT_LE(sums.copies_size(), (chunks + 2 * threads) * 64 * 3) << threads << " threads";
  }
}
