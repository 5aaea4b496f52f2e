// Unit tests of the pure math: weights, pair kernel, energy, ETD coefficients, pair noise.
#include "dpd_kernel.h"
#include "dpd_random.h"
#include "etd_coefficients.h"
#include "normal_ziggurat.h"
#include "reference_weights.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <set>
#include <vector>

namespace {

// long double references: series for |z| <= 1, closed form beyond (cancellation is harmless
// with a 64-bit mantissa there)
long double phi1_reference(long double z)
{
  if (std::fabs(z) <= 1.0L) {
    long double term = 1.0L, sum = 1.0L;
    for (int k = 1; k < 40; ++k) {
      term *= z / (k + 1);
      sum += term;
    }
    return sum;
  }
  return std::expm1(z) / z;
}

long double phi2_reference(long double z)
{
  if (std::fabs(z) <= 1.0L) {
    long double term = 0.5L, sum = 0.5L;
    for (int k = 1; k < 40; ++k) {
      term *= z / (k + 2);
      sum += term;
    }
    return sum;
  }
  return (std::expm1(z) - z) / (z * z);
}

std::vector<double> z_grid()
{
  std::vector<double> zs = {0.0,    -1e-300, -1e-17, -1e-12, -1e-8, -1e-5, -1e-3,  -0.1,  -0.5,
                            -0.999, -1.0,    -1.001, -2.0,   -10.0, -50.0, -300.0, -700.0};
  for (double z = -1e-6; z > -700.0; z *= 1.37) zs.push_back(z);
  return zs;
}

}    // namespace

TEST(EtdCoefficients, Phi1AccurateFromZeroToMinus700)
{
  for (double z : z_grid()) {
    const long double ref = phi1_reference(z);
    EXPECT_NEAR(etd::phi1(z), static_cast<double>(ref), 1e-14 * std::fabs(static_cast<double>(ref)))
        << "z=" << z;
  }
  EXPECT_EQ(etd::phi1(0.0), 1.0);
}

TEST(EtdCoefficients, Phi2AccurateFromZeroToMinus700)
{
  for (double z : z_grid()) {
    const long double ref = phi2_reference(z);
    EXPECT_NEAR(etd::phi2(z), static_cast<double>(ref), 1e-14 * std::fabs(static_cast<double>(ref)))
        << "z=" << z;
  }
  EXPECT_EQ(etd::phi2(0.0), 0.5);
}

TEST(EtdCoefficients, ZeroFrictionIsExplicitEuler)
{
  for (int order : {1, 2}) {
    const auto c = etd::etd_coefficients(0.0, 0.01, order);
    EXPECT_EQ(c.decay, 1.0);
    if (order == 1) {
      EXPECT_EQ(c.current, 0.01);
      EXPECT_EQ(c.previous, 0.0);
    } else {    // Adams-Bashforth 2
      EXPECT_DOUBLE_EQ(c.current, 0.015);
      EXPECT_DOUBLE_EQ(c.previous, -0.005);
    }
  }
}

TEST(EtdCoefficients, MatchesPaperEquation7)
{
  // Mai-Duy et al. 2013, eq 7 written with c = -rate: coefficients of A(t) and A(t - dt)
  const double rate = 37.0, dt = 0.013, c = -rate, z = c * dt;
  const auto k = etd::etd_coefficients(rate, dt, 2);
  EXPECT_NEAR(k.current, ((z + 1) * std::exp(z) - 2 * z - 1) / (c * c * dt), 1e-15);
  EXPECT_NEAR(k.previous, (-std::exp(z) + z + 1) / (c * c * dt), 1e-15);
  const auto k1 = etd::etd_coefficients(rate, dt, 1);
  EXPECT_NEAR(k1.current, (std::exp(z) - 1) / c, 1e-15);
}

TEST(EtdCoefficients, ModelEquationOrders)
{
  // dv/dt = -lambda v + A(t), A = cos(t), v(0) = 1: exact solution known; stiff lambda = 50
  const double lambda = 50.0, T = 1.0;
  auto exact = [&](double t) {
    const double k = 1.0 / (lambda * lambda + 1.0);
    return (1.0 - lambda * k) * std::exp(-lambda * t) + k * (lambda * std::cos(t) + std::sin(t));
  };
  for (int order : {1, 2}) {
    double errors[3];
    int idx = 0;
    for (int n : {200, 400, 800}) {
      const double dt = T / n;
      double v = 1.0, previous = std::cos(0.0);
      for (int step = 0; step < n; step++) {
        const double forcing = std::cos(step * dt);
        const auto c = etd::etd_coefficients(lambda, dt, step == 0 ? 1 : order);
        v = c.decay * v + c.current * forcing + c.previous * previous;
        previous = forcing;
      }
      errors[idx++] = std::fabs(v - exact(T));
    }
    EXPECT_NEAR(std::log2(errors[1] / errors[2]), order, 0.1) << "order " << order;
  }
}

TEST(EtdCoefficients, OuNoiseFactor)
{
  EXPECT_DOUBLE_EQ(etd::ou_noise_factor(0.0), 1.0);
  const double z = -3.0;
  EXPECT_NEAR(etd::ou_noise_factor(z), std::sqrt((1 - std::exp(2 * z)) / (-2 * z)), 1e-15);
}

TEST(EtdCoefficients, SharedExpm1MatchesDirectFormulas)
{
  // the integrator's coefficients come from one expm1; they must equal the defining formulas
  const double dt = 0.01;
  for (double rate : {0.0, 1e-6, 0.3, 50.0, 99.9, 100.0, 270.0, 999.0, 5000.0, 70000.0}) {
    const double z = -rate * dt;
    for (int order : {1, 2}) {
      const auto c = etd::etd_coefficients(rate, dt, order);
      const double p2 = (order == 2) ? etd::phi2(z) : 0.0;
      EXPECT_NEAR(c.decay, std::exp(z), 1e-15 * std::max(1.0, rate * 1e-10) + 1e-15 * std::exp(z));
      EXPECT_NEAR(c.current, dt * (etd::phi1(z) + p2), 1e-14 * std::fabs(c.current));
      EXPECT_NEAR(c.previous, -dt * p2, 1e-14 * std::fabs(dt * p2));
      EXPECT_NEAR(c.noise_piecewise, dt * etd::phi1(z), 1e-14 * dt * etd::phi1(z));
      EXPECT_NEAR(c.noise_exact, dt * etd::ou_noise_factor(z),
                  1e-14 * dt * etd::ou_noise_factor(z));
    }
  }
}

TEST(EtdCoefficients, FirstOrderEffectiveStepIsTheFullUpdate)
{
  // v' = e^z v + dt phi1 (F + Gamma v)/m must equal v + (effective step) F/m for any v, F
  const double dt = 0.003, m = 0.01;
  for (double gamma : {0.0, 1e-9, 1e-3, 0.5, 7.0, 300.0, 2e5}) {
    const double rate = gamma / m;
    const auto c = etd::etd_coefficients(rate, dt, 1);
    const double h = etd::first_order_effective_step(rate, dt);
    EXPECT_LE(h, dt);
    EXPECT_GT(h, 0.0);
    for (double v : {-3.0, 0.0, 1.7})
      for (double force : {-40.0, 2.5}) {
        const double full = c.decay * v + c.current * (force + gamma * v) / m;
        const double cheap = v + h * force / m;
        EXPECT_NEAR(cheap, full,
                    1e-12 * (std::fabs(full) + std::fabs(v) + dt * std::fabs(force) / m))
            << "gamma=" << gamma << " v=" << v << " F=" << force;
      }
  }
  EXPECT_EQ(etd::first_order_effective_step(0.0, dt), dt);
}

TEST(Weights, DefinitionsAndCutoffs)
{
  EXPECT_DOUBLE_EQ(etdtest::dissipative_weight(0.3, 1.0, 2.0), 0.49);
  EXPECT_DOUBLE_EQ(etdtest::dissipative_weight(0.36, 1.0, 0.5), 0.8);
  EXPECT_DOUBLE_EQ(etdtest::random_weight(0.36, 1.0, 0.5), std::sqrt(0.8));
  EXPECT_DOUBLE_EQ(etdtest::conservative_weight(0.75, 1.0, 0.5), 0.5);
  EXPECT_EQ(etdtest::dissipative_weight(1.0, 1.0, 0.5), 0.0);
  EXPECT_EQ(etdtest::dissipative_weight(1.2, 1.0, 0.5), 0.0);
  for (double s : {0.25, 0.4244, 0.5, 1.0, 1.5, 2.0, 3.7})
    for (double q : {0.0, 0.01, 0.3, 0.99, 1.0})
      EXPECT_NEAR(etd::power_of(q, etd::classify_power(s), s), std::pow(q, s), 1e-15);
}

TEST(PairKernel, PartsAndFluctuationDissipation)
{
  etd::PairCoefficients c;
  const double kT = 0.25;
  c.set(1750.0, 20.48, 0.25, 0.5, 1.0, 1.5, kT);    // Mai-Duy et al. 2013 colloid-solvent pair
  EXPECT_NEAR(c.sigma, 3.2, 1e-12);
  // inside both cutoffs
  double r = 0.6, ev = -0.7, theta = 0.3, isdt = 1.0 / std::sqrt(0.001);
  auto f = etd::pair_force(c, r * r, r, ev, theta, isdt);
  EXPECT_NEAR(f.conservative, 1750.0 * std::sqrt(0.4), 1e-10);
  EXPECT_NEAR(f.friction, 20.48 * std::pow(1 - 0.6 / 1.5, 0.25), 1e-12);
  EXPECT_NEAR(f.dissipative, -f.friction * ev, 1e-12);
  EXPECT_NEAR(f.random, 3.2 * std::pow(1 - 0.6 / 1.5, 0.125) * theta * isdt, 1e-10);
  // rcC < r < rcD: dissipative and random only
  r = 1.2;
  f = etd::pair_force(c, r * r, r, ev, theta, isdt);
  EXPECT_EQ(f.conservative, 0.0);
  EXPECT_GT(std::fabs(f.dissipative), 0.0);
  EXPECT_GT(std::fabs(f.random), 0.0);
  // rcD < r < rcC: conservative only
  etd::PairCoefficients d;
  d.set(25.0, 4.5, 2.0, 1.0, 1.5, 1.0, 1.0);
  f = etd::pair_force(d, r * r, r, ev, theta, isdt);
  EXPECT_NEAR(f.conservative, 25.0 * 0.2, 1e-12);
  EXPECT_EQ(f.dissipative, 0.0);
  EXPECT_EQ(f.random, 0.0);
  // special bonds: C and D by the factor, R by its square root
  const double sb = 0.36;
  r = 0.4;
  auto full = etd::pair_force(d, r * r, r, ev, theta, isdt);
  auto scaled = etd::pair_force(d, r * r, r, ev, theta, isdt, sb);
  EXPECT_NEAR(scaled.conservative, sb * full.conservative, 1e-12);
  EXPECT_NEAR(scaled.dissipative, sb * full.dissipative, 1e-12);
  EXPECT_NEAR(scaled.random, 0.6 * full.random, 1e-12);
}

TEST(PairKernel, DissipationIsTheKernelsFrictionAndNoise)
{
  // pair_dissipation is the one evaluation of gamma w_D and sigma w_R: pair_force uses it (the
  // same numbers, bit for bit) and they are the analytic weights, with sigma^2 = 2 gamma kT
  // giving noise^2 = 2 kT friction at any distance and special factor
  EXPECT_EQ(etd::special_root(1.0), 1.0);
  EXPECT_EQ(etd::special_root(0.36), std::sqrt(0.36));
  EXPECT_EQ(etd::special_root(0.0), 0.0);
  const double kT = 0.7, gamma = 4.5, rc_d = 1.3, ev = -0.8, theta = 1.1, isdt = 10.0;
  for (double s : {0.25, 0.4244, 0.5, 1.0, 1.5, 2.0, 3.7}) {
    etd::PairCoefficients c;
    c.set(25.0, gamma, s, 1.0, 1.0, rc_d, kT);
    for (double special : {1.0, 0.36, 0.0}) {
      for (double r = 0.013; r < rc_d; r += 0.0617) {
        const etd::PairDissipation d = etd::pair_dissipation(c, r, special);
        const etd::PairForce f = etd::pair_force(c, r * r, r, ev, theta, isdt, special);
        EXPECT_EQ(d.friction, f.friction) << "s=" << s << " r=" << r;
        EXPECT_EQ(d.noise * theta * isdt, f.random) << "s=" << s << " r=" << r;
        const double w_d = std::pow(1.0 - r / rc_d, s);
        EXPECT_NEAR(d.friction, special * gamma * w_d, 1e-14 * gamma);
        EXPECT_NEAR(d.noise, std::sqrt(special * 2.0 * gamma * kT * w_d), 1e-14 * c.sigma);
        EXPECT_NEAR(d.noise * d.noise, 2.0 * kT * d.friction, 1e-13 * gamma * kT);
      }
      // zero at the dissipative cutoff
      const etd::PairDissipation edge = etd::pair_dissipation(c, rc_d, special);
      EXPECT_EQ(edge.friction, 0.0);
      EXPECT_EQ(edge.noise, 0.0);
    }
  }
}

TEST(PairKernel, DissipativeWeights)
{
  for (double s : {0.25, 0.4244, 0.5, 1.0, 1.5, 2.0, 3.7})
    for (double q : {0.0, 0.01, 0.3, 0.99, 1.0}) {
      const etd::DissipativeWeights w =
          etd::dissipative_weights(q, etd::classify_power(s), etd::classify_power(0.5 * s), s);
      EXPECT_NEAR(w.random, std::pow(q, 0.5 * s), 1e-15);
      EXPECT_NEAR(w.dissipative, std::pow(q, s), 1e-15);
      EXPECT_EQ(w.dissipative, w.random * w.random);    // for s = 2 too: w_R is q there
    }
}

TEST(PairKernel, EnergyIsIntegralOfConservativeForce)
{
  for (double p : {1.0, 0.5, 0.25, 1.7}) {
    etd::PairCoefficients c;
    c.set(18.75, 4.5, 0.5, p, 1.3, 0.9, 1.0);
    for (double r = 0.05; r < 1.29; r += 0.0731) {
      const double h = 1e-6;
      const double fd = -(etd::pair_energy(c, (r + h) * (r + h), r + h) -
                          etd::pair_energy(c, (r - h) * (r - h), r - h)) /
          (2 * h);
      const auto f = etd::pair_force(c, r * r, r, 0.0, 0.0, 1.0);
      EXPECT_NEAR(fd, f.conservative, 1e-6 * (1 + std::fabs(f.conservative)))
          << "p=" << p << " r=" << r;
    }
    EXPECT_EQ(etd::pair_energy(c, 1.3 * 1.3, 1.3), 0.0);
  }
}

// The ziggurat written for host and device draws what Boost.Random's does from the same words:
// every result equal to the bit, and the same number of words used. 4 million draws reach the
// normal's tail (beyond 3.44, about 2,300 times) and the exponential's shifted tail within it.
TEST(NormalZiggurat, DrawsWhatBoostDrawsFromTheSameWords)
{
  const etd::ZigguratTables tables = etd::ZigguratTables::host();
  std::mt19937_64 boost_words(20261127), our_words(20261127);
  boost::random::normal_distribution<double> normal;
  long tails = 0;
  for (int k = 0; k < 4000000; k++) {
    const double expected = normal(boost_words);
    const double drawn = etd::unit_normal(our_words, tables);
    ASSERT_EQ(std::memcmp(&expected, &drawn, sizeof(double)), 0) << "draw " << k;
    tails += std::fabs(drawn) > tables.normal_x[1];
  }
  EXPECT_EQ(boost_words(), our_words());
  EXPECT_GT(tails, 1500);
  boost::random::exponential_distribution<double> exponential;
  for (int k = 0; k < 1000000; k++) {
    const double expected = exponential(boost_words);
    const double drawn = etd::ziggurat::unit_exponential(our_words, tables);
    ASSERT_EQ(std::memcmp(&expected, &drawn, sizeof(double)), 0) << "draw " << k;
  }
}

// Words chosen to take the rare branches, each of which the random draws reach seldom or never:
// a wedge whose uniform rounds to 1 and is drawn again (a word of all ones), and layer 0 beyond
// the tail's start (low byte 0 or 1, abscissa near 1), once with bit 11 set, which Boost clears.
TEST(NormalZiggurat, RareWordsTakeTheRareBranches)
{
  struct Words {
    std::vector<std::uint64_t> list;
    size_t next = 0;
    std::uint64_t operator()() { return list[next++ % list.size()]; }
    using result_type = std::uint64_t;
    static constexpr std::uint64_t min() { return 0; }
    static constexpr std::uint64_t max() { return ~std::uint64_t(0); }
  };
  const etd::ZigguratTables tables = etd::ZigguratTables::host();
  boost::random::normal_distribution<double> normal;
  const std::uint64_t ones = ~std::uint64_t(0);
  const std::vector<std::vector<std::uint64_t>> cases = {
      {0xffffffffffffff02ULL, ones, 0x8000000000000000ULL, 0x123456789abcdef0ULL},
      {0xffffffffffffff00ULL, ones, 0x8000000000000000ULL, 0x4000000000000002ULL},
      {0xfffffffffffff801ULL, 0x7777777777777777ULL, 0x3333333333333333ULL}};
  for (const auto &list : cases) {
    Words boost_words{list}, our_words{list};
    const double expected = normal(boost_words);
    const double drawn = etd::unit_normal(our_words, tables);
    EXPECT_EQ(std::memcmp(&expected, &drawn, sizeof(double)), 0) << list[0];
    EXPECT_EQ(boost_words.next, our_words.next) << list[0];
    EXPECT_GE(our_words.next, 3u) << list[0];    // the branch was taken: more than one draw
  }
}

TEST(PairNoise, SymmetricKeyedAndIndependent)
{
  etd::PairNoise a(12345), b(12345), other_seed(12346);
  EXPECT_EQ(a.gaussian(7, 3, 100), a.gaussian(3, 7, 100));
  EXPECT_EQ(a.gaussian(7, 3, 100), b.gaussian(7, 3, 100));
  EXPECT_NE(a.gaussian(7, 3, 100), a.gaussian(7, 3, 101));
  EXPECT_NE(a.gaussian(7, 3, 100), a.gaussian(7, 4, 100));
  EXPECT_NE(a.gaussian(7, 3, 100), other_seed.gaussian(7, 3, 100));
  etd::PairNoise matrix(12345, etd::NoiseStream::PairMatrix);
  EXPECT_NE(a.gaussian(7, 3, 100), matrix.gaussian(7, 3, 100));
}

TEST(PairNoise, LargeAtomIdsStaySymmetricAndDistinct)
{
  // IDs of 2^32 and more (64-bit LAMMPS IDs) do not fit the packed counter word: they must still
  // give one draw per pair, the same from both ends, and not repeat a small-ID pair's draw
  etd::PairNoise a(12345);
  const std::int64_t big = (std::int64_t(1) << 32) + 3;
  EXPECT_EQ(a.gaussian(big, 7, 100), a.gaussian(7, big, 100));
  EXPECT_NE(a.gaussian(big, 7, 100), a.gaussian(big + 1, 7, 100));
  EXPECT_NE(a.gaussian(big, 7, 100), a.gaussian(big, 7, 101));
  EXPECT_NE(a.gaussian(big, 7, 100), a.gaussian(3, 7, 100));
  // the packed word keeps both IDs: (1, 2^31) and (2^31, 1) are one pair, (1, 2) another
  EXPECT_EQ(a.gaussian(1, std::int64_t(1) << 31, 5), a.gaussian(std::int64_t(1) << 31, 1, 5));
  EXPECT_NE(a.gaussian(1, std::int64_t(1) << 31, 5), a.gaussian(1, 2, 5));
  // groups of four start with the scalar draw on either generator (dpd/fpm with zero shear
  // friction is dpd/gen): packed IDs, a large ID, a timestep beyond the packed 2^48
  const std::int64_t late = std::int64_t(1) << 50;
  const std::int64_t cases[3][3] = {{3, 7, 100}, {big, 7, 100}, {3, 7, late}};
  for (const auto &c : cases) {
    double theta[4];
    a.gaussians4(c[0], c[1], c[2], 0, theta);
    EXPECT_EQ(theta[0], a.gaussian(c[1], c[0], c[2]));
    EXPECT_NE(theta[1], theta[0]);
    double other_group[4];
    a.gaussians4(c[0], c[1], c[2], 1, other_group);
    EXPECT_NE(other_group[0], theta[0]);
  }
  EXPECT_NE(a.gaussian(3, 7, late), a.gaussian(3, 7, late + 1));
}

TEST(PairNoise, UnitGaussianMoments)
{
  // 400k draws: standard errors of mean, variance and kurtosis are 0.0016, 0.0022 and 0.0077
  etd::PairNoise noise(2024);
  const int n = 400000;
  double s1 = 0, s2 = 0, s4 = 0, lag = 0, prev = 0;
  long inner = 0, tail = 0;
  for (int k = 0; k < n; k++) {
    const double g = noise.gaussian(k % 997 + 1, k / 997 + 2000, k % 13);
    s1 += g;
    s2 += g * g;
    s4 += g * g * g * g;
    lag += g * prev;
    prev = g;
    inner += std::fabs(g) < 0.5;
    tail += std::fabs(g) > 2.0;
  }
  // shape, not just moments: P(|g| < 0.5) = 0.382925, P(|g| > 2) = 0.045500 (binomial errors
  // 0.00077 and 0.00033)
  EXPECT_NEAR(double(inner) / n, 0.382925, 5 * 0.00077);
  EXPECT_NEAR(double(tail) / n, 0.045500, 5 * 0.00033);
  const double mean = s1 / n, var = s2 / n - mean * mean;
  EXPECT_NEAR(mean, 0.0, 5 * 0.0016);
  EXPECT_NEAR(var, 1.0, 5 * 0.0022);
  EXPECT_NEAR(s4 / n, 3.0, 5 * 0.0077);
  EXPECT_NEAR(lag / n, 0.0, 5 * 0.0016);
}
