// The implicit friction-noise step on its own (no LAMMPS): exact temperature at any step,
// momentum conservation, solver accuracy, and the zero-mass limit.
#include "conjugate_gradient.h"
#include "dpd_kernel.h"
#include "dpd_random.h"
#include "fpm_kernel.h"
#include "friction_operator.h"
#include "friction_solve.h"
#include "reference_weights.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace {

// Diagonal of G per atom and component: sum_j gamma w_D e_alpha^2 (the Jacobi preconditioner).
template <typename UpdateJ>
void accumulate_diagonal(const std::vector<etd::FrictionPair> &pairs, double *diag,
                                UpdateJ update_j)
{
  for (const etd::FrictionPair &p : pairs)
    for (int k = 0; k < 3; k++) {
      const double g = p.friction * p.e[k] * p.e[k];
      diag[3 * p.i + k] += g;
      if (update_j(p.j)) diag[3 * p.j + k] += g;
    }
}


// A dense DPD cluster: n = 4 in a periodic 3^3 box, s = 1/2, gamma = 4.5, kBT = 1.
struct Cluster {
  int natoms = 108;
  double box = 3.0, gamma = 4.5, kT = 1.0, s = 0.5;
  std::vector<double> x;
  std::vector<etd::FrictionPair> pairs;
  std::vector<double> noise_amplitude;    // sigma w_R per pair

  Cluster()
  {
    std::mt19937_64 gen(7);
    std::uniform_real_distribution<double> uniform(0.0, box);
    for (int k = 0; k < 3 * natoms; k++) x.push_back(uniform(gen));
    const double sigma = etd::noise_amplitude(gamma, kT);
    for (int i = 0; i < natoms; i++)
      for (int j = i + 1; j < natoms; j++) {
        double d[3], rsq = 0.0;
        for (int k = 0; k < 3; k++) {
          d[k] = x[3 * i + k] - x[3 * j + k];
          d[k] -= box * std::round(d[k] / box);    // minimum image
          rsq += d[k] * d[k];
        }
        if (rsq >= 1.0) continue;
        const double r = std::sqrt(rsq);
        etd::FrictionPair p{i,
                            j,
                            {float(d[0] / r), float(d[1] / r), float(d[2] / r)},
                            float(gamma * etdtest::dissipative_weight(r, 1.0, s))};
        pairs.push_back(p);
        noise_amplitude.push_back(sigma * etdtest::random_weight(r, 1.0, s));
      }
  }

  // noise amplitudes times fresh unit Gaussians for this step
  std::vector<double> noise(long step) const
  {
    etd::PairNoise generator(99, etd::NoiseStream::Integrator);
    std::vector<double> out = noise_amplitude;
    for (size_t n = 0; n < pairs.size(); n++)
      out[n] *= generator.gaussian(pairs[n].i + 1, pairs[n].j + 1, step);
    return out;
  }
};

const auto all_local = [](int) {
  return true;
};
const auto serial_sum = [](double *, int) {
};    // one rank: the local sums are the sums

// One Pade friction-noise step of length h for masses m; returns CG iterations.
int pade_step(const Cluster &c, double m, double h, long step, std::vector<double> &v,
              double tolerance = 1e-10)
{
  const int n = 3 * c.natoms;
  const auto &pairs = c.pairs;
  const auto noise = c.noise(step);
  std::vector<double> gv(n, 0.0), b(n), diag(n, 0.0), inv_diag(n);
  etd::accumulate_friction(pairs, v.data(), gv.data(), all_local);
  for (int k = 0; k < n; k++) b[k] = m * v[k] - 0.5 * h * gv[k];
  etd::accumulate_noise(pairs, noise, std::sqrt(h), b.data(), all_local);
  accumulate_diagonal(pairs, diag.data(), all_local);
  for (int k = 0; k < n; k++) inv_diag[k] = 1.0 / (m + 0.5 * h * diag[k]);
  auto apply = [&](const double *u, double *au) {
    for (int k = 0; k < n; k++) au[k] = m * u[k];
    std::vector<double> gu(n, 0.0);
    etd::accumulate_friction(pairs, u, gu.data(), all_local);
    for (int k = 0; k < n; k++) au[k] += 0.5 * h * gu[k];
  };
  std::vector<double> guess(n);
  for (int k = 0; k < n; k++) guess[k] = inv_diag[k] * b[k];
  const auto result = etd::conjugate_gradient(n, apply, serial_sum, inv_diag.data(), b.data(),
                                              guess.data(), tolerance, 500);
  EXPECT_TRUE(result.converged);
  v = guess;
  return result.iterations;
}

}    // namespace

TEST(FrictionOperator, SymmetricPositiveSemidefiniteWithTranslationNullSpace)
{
  Cluster c;
  const int n = 3 * c.natoms;
  std::mt19937_64 gen(3);
  std::normal_distribution<double> normal;
  std::vector<double> u(n), w(n), gu(n, 0.0), gw(n, 0.0), uniform(n), gt(n, 0.0);
  for (int k = 0; k < n; k++) {
    u[k] = normal(gen);
    w[k] = normal(gen);
    uniform[k] = (k % 3 == 1) ? 2.5 : 0.0;
  }
  etd::accumulate_friction(c.pairs, u.data(), gu.data(), all_local);
  etd::accumulate_friction(c.pairs, w.data(), gw.data(), all_local);
  etd::accumulate_friction(c.pairs, uniform.data(), gt.data(), all_local);
  double wgu = 0, ugw = 0, ugu = 0;
  for (int k = 0; k < n; k++) {
    wgu += w[k] * gu[k];
    ugw += u[k] * gw[k];
    ugu += u[k] * gu[k];
  }
  EXPECT_NEAR(wgu, ugw, 1e-10 * std::fabs(wgu));
  EXPECT_GT(ugu, 0.0);
  for (double g : gt) EXPECT_EQ(g, 0.0);    // a uniform translation costs no friction
}

// The run-by-run kernel the fix uses gives the pair-by-pair sum, for 3 and 6 values per atom
// (only the first 3 touched), with and without the j shares (ghosts of another rank)
TEST(FrictionOperator, RunByRunKernelIsThePairByPairSum)
{
  Cluster c;
  std::vector<etd::PairRun> runs;
  etd::find_runs(c.pairs, runs);
  ASSERT_GT(runs.size(), 10u);
  ASSERT_LT(runs.size(), c.pairs.size());    // some runs hold several pairs
  int covered = 0;
  for (const etd::PairRun &run : runs) {
    for (int k = run.begin; k < run.end; k++) ASSERT_EQ(c.pairs[k].i, run.i);
    covered += run.end - run.begin;
  }
  EXPECT_EQ(covered, static_cast<int>(c.pairs.size()));
  std::mt19937_64 gen(11);
  std::normal_distribution<double> normal;
  const auto even_j_only = [](int j) {
    return j % 2 == 0;
  };
  for (int stride : {3, 6}) {
    const int n = stride * c.natoms;
    std::vector<double> u(n);
    for (double &value : u) value = normal(gen);
    // variant 1 also adds a scaled G u to values already there (what the solver does with M u)
    for (int variant = 0; variant < 2; variant++) {
      const double scale = variant == 0 ? 1.0 : -0.75;
      std::vector<double> by_pairs(n, 0.0), by_runs(n, 0.0), start(n, 0.0);
      if (variant == 1)
        for (int k = 0; k < n; k++) start[k] = by_runs[k] = 0.1 * (k % 7) - 0.3;
      if (variant == 0) {
        etd::accumulate_friction(c.pairs, u.data(), by_pairs.data(), all_local, stride);
        if (stride == 3)
          etd::accumulate_friction_by_runs<3>(c.pairs, runs, u.data(), by_runs.data(), all_local);
        else
          etd::accumulate_friction_by_runs<6>(c.pairs, runs, u.data(), by_runs.data(), all_local);
      } else {
        etd::accumulate_friction(c.pairs, u.data(), by_pairs.data(), even_j_only, stride);
        if (stride == 3)
          etd::accumulate_friction_by_runs<3>(c.pairs, runs, u.data(), by_runs.data(), even_j_only,
                                              scale);
        else
          etd::accumulate_friction_by_runs<6>(c.pairs, runs, u.data(), by_runs.data(), even_j_only,
                                              scale);
      }
      double largest = 0.0;
      for (double value : by_pairs) largest = std::max(largest, std::fabs(value));
      ASSERT_GT(largest, 1.0);
      for (int k = 0; k < n; k++) {
        EXPECT_NEAR(by_runs[k], start[k] + scale * by_pairs[k], 1e-12 * largest)
            << "stride " << stride << " value " << k;
        if (stride == 6 && k % 6 >= 3) EXPECT_EQ(by_runs[k], start[k]);
      }
    }
  }
}

// The Pade step keeps <m v^2> = kBT per component however large h is against m/gamma: from a
// Maxwell-Boltzmann start (total momentum zero, which removes one degree of freedom in N per
// component: expected (N-1)/N kBT), 2,000-8,000 steps of 108 atoms, about 0.3-0.7 % standard
// error (20,000 steps gave 0.9901, 0.9880, 0.9879 against 0.9907); tolerance 1.5 %. (From rest the stiffest modes would take about h lambda_max / 2 steps to
// heat up: the Pade factor (1 - x)/(1 + x) tends to -1, it is A- but not L-stable.)
// Momentum is conserved to the solver tolerance.
TEST(FrictionOperator, PadeStepHoldsTemperatureAtAnyStep)
{
  Cluster c;
  const double m = 0.01;
  const double relaxation = m / c.gamma;
  for (double ratio : {0.5, 10.0, 100.0}) {
    const double h = ratio * relaxation;
    // at h = 100 m/gamma the stiffest modes decorrelate only over about 60 steps (Pade factor
    // near -1), so that case runs longer
    const long steps = (ratio > 50.0) ? 8000 : 2050;
    std::vector<double> v(3 * c.natoms, 0.0);
    std::mt19937_64 gen(11);
    std::normal_distribution<double> maxwell(0.0, std::sqrt(c.kT / m));
    double mean[3] = {0, 0, 0};
    for (int k = 0; k < 3 * c.natoms; k++) {
      v[k] = maxwell(gen);
      mean[k % 3] += v[k] / c.natoms;
    }
    for (int k = 0; k < 3 * c.natoms; k++) v[k] -= mean[k % 3];
    double sum = 0.0;
    long samples = 0;
    int iterations = 0;
    for (long step = 0; step < steps; step++) {
      iterations = pade_step(c, m, h, step, v);
      double momentum[3] = {0, 0, 0};
      for (int k = 0; k < 3 * c.natoms; k++) momentum[k % 3] += m * v[k];
      // thermal scale of the total momentum: sqrt(N m kBT) = 1.04; the solver leaves ~1e-8
      for (double p : momentum) ASSERT_NEAR(p, 0.0, 1e-6);
      if (step < 50) continue;
      for (double vk : v) sum += m * vk * vk;
      samples += 3 * c.natoms;
    }
    const double kT = sum / samples;
    std::printf("Pade step h = %g m/gamma: <m v^2> = %.4f kBT, %d CG iterations\n", ratio, kT,
                iterations);
    EXPECT_NEAR(kT, c.kT * (c.natoms - 1) / c.natoms, 0.015) << "h = " << ratio << " m/gamma";
  }
}

TEST(FrictionOperator, ConjugateGradientSolvesToTolerance)
{
  Cluster c;
  const int n = 3 * c.natoms;
  const double m = 0.001, h = 0.01;
  std::vector<double> diag(n, 0.0), inv_diag(n), b(n), x(n, 0.0);
  accumulate_diagonal(c.pairs, diag.data(), all_local);
  for (int k = 0; k < n; k++) {
    inv_diag[k] = 1.0 / (m + 0.5 * h * diag[k]);
    b[k] = std::sin(k);
  }
  auto apply = [&](const double *u, double *au) {
    std::vector<double> gu(n, 0.0);
    etd::accumulate_friction(c.pairs, u, gu.data(), all_local);
    for (int k = 0; k < n; k++) au[k] = m * u[k] + 0.5 * h * gu[k];
  };
  const auto result = etd::conjugate_gradient(n, apply, serial_sum, inv_diag.data(), b.data(),
                                              x.data(), 1e-12, 1000);
  ASSERT_TRUE(result.converged);
  std::vector<double> ax(n);
  apply(x.data(), ax.data());
  double err = 0, norm = 0;
  for (int k = 0; k < n; k++) {
    err += (ax[k] - b[k]) * (ax[k] - b[k]);
    norm += b[k] * b[k];
  }
  EXPECT_LT(std::sqrt(err / norm), 1e-12);
  EXPECT_LE(result.relative_residual, 1e-12);
}

// The single-reduction solver: one global sum per iteration (plus the start's and at most one
// confirmation), the iterations of textbook preconditioned CG (written out here), and a start
// product supplied by the caller gives the same solution as the solver's own A x0.
TEST(FrictionOperator, ConjugateGradientNeedsOneReductionPerIteration)
{
  Cluster c;
  const int n = 3 * c.natoms;
  const double m = 0.001, h = 0.01;
  std::vector<double> diag(n, 0.0), inv_diag(n), b(n);
  accumulate_diagonal(c.pairs, diag.data(), all_local);
  for (int k = 0; k < n; k++) {
    inv_diag[k] = 1.0 / (m + 0.5 * h * diag[k]);
    b[k] = std::cos(0.7 * k);
  }
  auto apply = [&](const double *u, double *au) {
    std::vector<double> gu(n, 0.0);
    etd::accumulate_friction(c.pairs, u, gu.data(), all_local);
    for (int k = 0; k < n; k++) au[k] = m * u[k] + 0.5 * h * gu[k];
  };
  int reductions = 0;
  auto counting_sum = [&](double *, int) {
    reductions++;
  };
  for (double tolerance : {1e-4, 1e-8}) {
    std::vector<double> x(n, 0.0);
    reductions = 0;
    const auto result = etd::conjugate_gradient(n, apply, counting_sum, inv_diag.data(), b.data(),
                                                x.data(), tolerance, 1000);
    ASSERT_TRUE(result.converged);
    EXPECT_LE(reductions, result.iterations + 2) << "tol " << tolerance;
    // textbook Jacobi-preconditioned CG from zero
    std::vector<double> y(n, 0.0), r = b, z(n), p(n), ap(n);
    double rz = 0.0, bb = 0.0;
    for (int k = 0; k < n; k++) {
      z[k] = inv_diag[k] * r[k];
      p[k] = z[k];
      rz += r[k] * z[k];
      bb += b[k] * b[k];
    }
    int textbook = 0;
    for (double rr = bb; rr > tolerance * tolerance * bb; textbook++) {
      apply(p.data(), ap.data());
      double pap = 0.0;
      for (int k = 0; k < n; k++) pap += p[k] * ap[k];
      const double alpha = rz / pap;
      double rz_new = 0.0;
      rr = 0.0;
      for (int k = 0; k < n; k++) {
        y[k] += alpha * p[k];
        r[k] -= alpha * ap[k];
        z[k] = inv_diag[k] * r[k];
        rz_new += r[k] * z[k];
        rr += r[k] * r[k];
      }
      for (int k = 0; k < n; k++) p[k] = z[k] + rz_new / rz * p[k];
      rz = rz_new;
    }
    EXPECT_NEAR(result.iterations, textbook, 1) << "tol " << tolerance;
    // the same start with its product supplied
    std::vector<double> start(n), product(n);
    for (int k = 0; k < n; k++) start[k] = 0.1 * std::sin(k);
    apply(start.data(), product.data());
    std::vector<double> x1 = start, x2 = start;
    const auto own = etd::conjugate_gradient(n, apply, serial_sum, inv_diag.data(), b.data(),
                                             x1.data(), tolerance, 1000);
    const auto given = etd::conjugate_gradient(n, apply, serial_sum, inv_diag.data(), b.data(),
                                               x2.data(), tolerance, 1000, nullptr,
                                               etd::NoProjection(), nullptr, product.data());
    EXPECT_EQ(own.iterations, given.iterations);
    for (int k = 0; k < n; k++) EXPECT_NEAR(x1[k], x2[k], 1e-12 * (1.0 + std::fabs(x1[k])));
  }
}

// Zero-mass limit: the Pade step with m -> 0 and the overdamped solve G v = B xi / sqrt(h) give
// the same velocities (translation removed), so the inertial scheme connects to the overdamped one.
TEST(FrictionOperator, ZeroMassLimitMatchesOverdampedSolve)
{
  Cluster c;
  const int n = 3 * c.natoms;
  const double h = 0.001;
  const auto &pairs = c.pairs;
  const auto noise = c.noise(5);
  std::vector<double> b(n, 0.0), diag(n, 0.0), inv_diag(n), overdamped(n, 0.0);
  etd::accumulate_noise(pairs, noise, 1.0 / std::sqrt(h), b.data(), all_local);
  accumulate_diagonal(pairs, diag.data(), all_local);
  for (int k = 0; k < n; k++) inv_diag[k] = 1.0 / diag[k];
  auto apply_g = [&](const double *u, double *gu) {
    for (int k = 0; k < n; k++) gu[k] = 0.0;
    etd::accumulate_friction(pairs, u, gu, all_local);
  };
  auto result = etd::conjugate_gradient(n, apply_g, serial_sum, inv_diag.data(), b.data(),
                                        overdamped.data(), 1e-12, 2000);
  ASSERT_TRUE(result.converged);
  std::vector<double> differences;
  for (double m : {1e-4, 1e-6}) {
    // from rest: (M + h/2 G) v' = sqrt(h) B xi, i.e. v' = 2 (G + 2M/h)^-1 B xi / sqrt(h); as m -> 0
    // half of v' is the overdamped velocity
    std::vector<double> v(n, 0.0);
    std::vector<double> rhs(n, 0.0), x(n, 0.0), id(n);
    etd::accumulate_noise(pairs, noise, std::sqrt(h), rhs.data(), all_local);
    for (int k = 0; k < n; k++) id[k] = 1.0 / (m + 0.5 * h * diag[k]);
    auto apply_a = [&](const double *u, double *au) {
      std::vector<double> gu(n, 0.0);
      etd::accumulate_friction(pairs, u, gu.data(), all_local);
      for (int k = 0; k < n; k++) au[k] = m * u[k] + 0.5 * h * gu[k];
    };
    ASSERT_TRUE(etd::conjugate_gradient(n, apply_a, serial_sum, id.data(), rhs.data(), x.data(),
                                        1e-12, 5000)
                    .converged);
    double mean_a[3] = {0, 0, 0}, mean_o[3] = {0, 0, 0};
    for (int k = 0; k < n; k++) {
      mean_a[k % 3] += x[k] / c.natoms;
      mean_o[k % 3] += overdamped[k] / c.natoms;
    }
    double diff = 0, norm = 0;
    for (int k = 0; k < n; k++) {
      const double a = 0.5 * (x[k] - mean_a[k % 3]), o = overdamped[k] - mean_o[k % 3];
      diff += (a - o) * (a - o);
      norm += o * o;
    }
    differences.push_back(std::sqrt(diff / norm));
    std::printf("m = %g: relative difference to the overdamped velocities %.2e\n", m,
                differences.back());
  }
  // the difference is O(m): (2M/h) against the smallest eigenvalues of G
  EXPECT_LT(differences[1], differences[0] / 50.0);
  EXPECT_LT(differences[1], 0.005);
}

TEST(FrictionOperator, BlockInverseAndItsSingularFallback)
{
  const double block[6] = {2.0, 3.0, 4.0, 0.5, -0.3, 0.2};    // xx yy zz xy xz yz
  double inverse[9];
  ASSERT_TRUE(etd::invert_block(block, 0.7, 1.5, inverse));
  const double full[9] = {0.7 + 3.0, 0.75, -0.45, 0.75, 0.7 + 4.5, 0.3, -0.45, 0.3, 0.7 + 6.0};
  for (int r = 0; r < 3; r++)
    for (int c = 0; c < 3; c++) {
      double product = 0.0;
      for (int k = 0; k < 3; k++) product += full[3 * r + k] * inverse[3 * k + c];
      EXPECT_NEAR(product, r == c ? 1.0 : 0.0, 1e-14);
    }
  // one partner along x, no mass: rank one, falls back to the diagonal (only x is held)
  const double rank_one[6] = {4.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  ASSERT_TRUE(etd::invert_block(rank_one, 0.0, 1.0, inverse));
  EXPECT_DOUBLE_EQ(inverse[0], 0.25);
  EXPECT_EQ(inverse[4], 0.0);
  EXPECT_EQ(inverse[8], 0.0);
  const double nothing[6] = {0, 0, 0, 0, 0, 0};
  EXPECT_FALSE(etd::invert_block(nothing, 0.0, 1.0, inverse));
}

// The 6-unknown operator of dpd/fpm pairs is the pair kernel's friction: G q gives minus the
// dissipative force on i and minus the torque on i and j (fpm_pair at zero noise), for
// translation and rotation alike; it is symmetric, positive semidefinite and blind to a rigid
// translation; its blocks are the diagonal of G.
TEST(FrictionOperator, FpmPairOperatorIsTheKernelsFriction)
{
  std::mt19937_64 gen(11);
  std::normal_distribution<double> normal(0.0, 1.0);
  etd::FpmCoefficients c;
  c.set(25.0, 3.5, 5.5, 0.5, 1.0, 1.0);
  const double del[3] = {0.31, -0.42, 0.27};
  const double r = std::sqrt(del[0] * del[0] + del[1] * del[1] + del[2] * del[2]);
  const double w = std::pow(1.0 - r, 0.5);
  etd::FpmFrictionPair p;
  p.i = 0;
  p.j = 1;
  for (int k = 0; k < 3; k++) p.e[k] = static_cast<float>(del[k] / r);
  p.half_r = static_cast<float>(0.5 * r);
  p.central = static_cast<float>(c.gamma_c * w);
  p.shear = static_cast<float>(c.gamma_s * w);
  const std::vector<etd::FpmFrictionPair> pairs = {p};
  auto all = [](int) {
    return true;
  };

  std::vector<double> q(12), gq(12, 0.0);
  for (double &value : q) value = normal(gen);
  etd::accumulate_fpm_friction(pairs, q.data(), gq.data(), all);
  // the kernel with the pair's (rounded) geometry
  const double e[3] = {p.e[0], p.e[1], p.e[2]};
  const double d[3] = {e[0] * 2 * p.half_r, e[1] * 2 * p.half_r, e[2] * 2 * p.half_r};
  const double v_ij[3] = {q[0] - q[6], q[1] - q[7], q[2] - q[8]};
  const double spin[3] = {q[3] + q[9], q[4] + q[10], q[5] + q[11]};
  etd::FpmCoefficients exact = c;
  const etd::FpmPairResult kernel =
      etd::fpm_pair(exact, d, 2 * p.half_r, v_ij, spin, etd::FpmNoise(), 1.0);
  const double scale = p.central / kernel.central_friction;    // float rounding of gamma w
  for (int k = 0; k < 3; k++) {
    EXPECT_NEAR(gq[k], -kernel.dissipative[k] * scale,
                1e-5 * std::fabs(kernel.dissipative[k]) + 1e-6);
    EXPECT_NEAR(gq[6 + k], kernel.dissipative[k] * scale,
                1e-5 * std::fabs(kernel.dissipative[k]) + 1e-6);
    EXPECT_NEAR(gq[3 + k], -kernel.torque[k] * scale, 1e-5 * std::fabs(kernel.torque[k]) + 1e-6);
    EXPECT_NEAR(gq[9 + k], -kernel.torque[k] * scale, 1e-5 * std::fabs(kernel.torque[k]) + 1e-6);
  }
  // a weight on G (what the solver adds into M q) scales every component
  std::vector<double> weighted(12, 1.0);
  etd::accumulate_fpm_friction(pairs, q.data(), weighted.data(), all, 0.3);
  for (int k = 0; k < 12; k++)
    EXPECT_NEAR(weighted[k], 1.0 + 0.3 * gq[k], 1e-12 * (1.0 + std::fabs(gq[k])));
  // symmetric and positive semidefinite
  std::vector<double> y(12), gy(12, 0.0);
  for (double &value : y) value = normal(gen);
  etd::accumulate_fpm_friction(pairs, y.data(), gy.data(), all);
  double q_gy = 0.0, y_gq = 0.0, q_gq = 0.0;
  for (int k = 0; k < 12; k++) {
    q_gy += q[k] * gy[k];
    y_gq += y[k] * gq[k];
    q_gq += q[k] * gq[k];
  }
  EXPECT_NEAR(q_gy, y_gq, 1e-12 * (std::fabs(q_gy) + 1.0));
  EXPECT_GE(q_gq, 0.0);
  // a rigid translation is not damped
  std::vector<double> translation = {0.3, -1.2, 0.7, 0, 0, 0, 0.3, -1.2, 0.7, 0, 0, 0}, gt(12, 0.0);
  etd::accumulate_fpm_friction(pairs, translation.data(), gt.data(), all);
  for (double value : gt) EXPECT_NEAR(value, 0.0, 1e-12);
  // the blocks are the diagonal 3x3 parts of G: probe them with unit vectors
  std::vector<double> blocks(24, 0.0);
  etd::accumulate_fpm_blocks(pairs, blocks.data(), all);
  const int order[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}};
  for (int part = 0; part < 2; part++)
    for (int b = 0; b < 6; b++) {
      std::vector<double> unit(12, 0.0), column(12, 0.0);
      unit[3 * part + order[b][1]] = 1.0;
      etd::accumulate_fpm_friction(pairs, unit.data(), column.data(), all);
      EXPECT_NEAR(blocks[6 * part + b], column[3 * part + order[b][0]], 1e-6) << part << " " << b;
    }
}

// The solve the implicit fix performs, as one function: the inertial system to tolerance from
// either start, a start with its G product given agreeing with one without, held blocks kept at
// zero, and in the zero-mass limit the translation projected out of the solution.
namespace {
struct SolveSetup {
  Cluster c;
  int n = 3 * c.natoms;
  std::vector<double> inertia = std::vector<double>(n, 0.01), blocks, rhs;
  SolveSetup()
  {
    blocks.assign(2 * n, 0.0);
    etd::accumulate_blocks(c.pairs, blocks.data(), all_local, 6);
    std::mt19937_64 gen(11);
    std::normal_distribution<double> normal;
    for (int k = 0; k < n; k++) rhs.push_back(normal(gen));
  }
  // out += weight G u
  void apply_friction(const double *u, double *out, double weight) const
  {
    std::vector<double> gu(n, 0.0);
    etd::accumulate_friction(c.pairs, u, gu.data(), all_local);
    for (int k = 0; k < n; k++) out[k] += weight * gu[k];
  }
  double relative_residual(const etd::FrictionSystem &sys, const std::vector<double> &x,
                           const std::vector<double> &b) const
  {
    std::vector<double> ax(n);
    for (int k = 0; k < n; k++) ax[k] = sys.mass_weight * inertia[k] * x[k];
    apply_friction(x.data(), ax.data(), sys.friction_weight);
    double rr = 0.0, bb = 0.0;
    for (int k = 0; k < n; k++) {
      rr += (ax[k] - b[k]) * (ax[k] - b[k]);
      bb += b[k] * b[k];
    }
    return std::sqrt(rr / bb);
  }
};
}    // namespace

TEST(FrictionSolve, InertialSystemToToleranceFromEitherStart)
{
  SolveSetup s;
  etd::FrictionSystem sys;
  sys.n = s.n;
  sys.inertia = s.inertia.data();
  sys.blocks = s.blocks.data();
  sys.mass_weight = 1.0;
  sys.friction_weight = 0.5 * 0.003;
  auto apply = [&](const double *u, double *out, double w) {
    s.apply_friction(u, out, w);
  };
  const auto mobile = [](int) {
    return true;
  };
  etd::FrictionSolveWorkspace work;
  std::vector<double> cold, warm, warm_product;
  const etd::SolverResult a = etd::solve_friction_system(sys, mobile, apply, serial_sum,
                                                         s.rhs.data(), cold, 1e-10, 500, work);
  ASSERT_TRUE(a.converged);
  EXPECT_LT(s.relative_residual(sys, cold, s.rhs), 1e-9);
  // a start near the answer, with and without its G product supplied
  std::vector<double> start = cold, start_friction(s.n, 0.0);
  for (int k = 0; k < s.n; k++) start[k] *= 1.0 + 0.01 * std::sin(k);
  s.apply_friction(start.data(), start_friction.data(), 1.0);
  const etd::SolverResult b = etd::solve_friction_system(
      sys, mobile, apply, serial_sum, s.rhs.data(), warm, 1e-10, 500, work, start.data());
  const etd::SolverResult c =
      etd::solve_friction_system(sys, mobile, apply, serial_sum, s.rhs.data(), warm_product, 1e-10,
                                 500, work, start.data(), start_friction.data());
  ASSERT_TRUE(b.converged && c.converged);
  EXPECT_LT(b.iterations, a.iterations) << "a start 1 % from the answer should save iterations";
  EXPECT_EQ(b.iterations, c.iterations);
  for (int k = 0; k < s.n; k++) {
    EXPECT_NEAR(warm[k], cold[k], 1e-8 * (1.0 + std::fabs(cold[k])));
    EXPECT_NEAR(warm_product[k], warm[k], 1e-10 * (1.0 + std::fabs(warm[k])));
  }
}

TEST(FrictionSolve, HeldBlocksStayZeroAndZeroMassLimitIsDeflated)
{
  SolveSetup s;
  auto apply = [&](const double *u, double *out, double w) {
    s.apply_friction(u, out, w);
  };
  etd::FrictionSolveWorkspace work;
  etd::FrictionSystem sys;
  sys.n = s.n;
  sys.inertia = s.inertia.data();
  sys.blocks = s.blocks.data();
  sys.mass_weight = 1.0;
  sys.friction_weight = 0.01;
  // every seventh atom outside the group: its velocity stays exactly zero
  const auto some_held = [](int block) {
    return block % 7 != 0;
  };
  std::vector<double> x;
  ASSERT_TRUE(etd::solve_friction_system(sys, some_held, apply, serial_sum, s.rhs.data(), x, 1e-10,
                                         500, work)
                  .converged);
  for (int b = 0; b < s.n / 3; b += 7)
    for (int k = 0; k < 3; k++) EXPECT_EQ(x[3 * b + k], 0.0) << "held atom " << b;

  // zero mass, all mobile: G is singular along the translation, which the solve removes from
  // the right-hand side and the solution; what is left solves G x = b - mean(b)
  sys.mass_weight = 0.0;
  sys.friction_weight = 1.0;
  sys.deflate = true;
  const auto mobile = [](int) {
    return true;
  };
  ASSERT_TRUE(
      etd::solve_friction_system(sys, mobile, apply, serial_sum, s.rhs.data(), x, 1e-10, 2000, work)
          .converged);
  std::vector<double> centred = s.rhs;
  for (int k = 0; k < 3; k++) {
    double mean_b = 0.0, mean_x = 0.0;
    for (int a = 0; a < s.n / 3; a++) {
      mean_b += s.rhs[3 * a + k] / (s.n / 3);
      mean_x += x[3 * a + k] / (s.n / 3);
    }
    EXPECT_NEAR(mean_x, 0.0, 1e-12);
    for (int a = 0; a < s.n / 3; a++) centred[3 * a + k] -= mean_b;
  }
  EXPECT_LT(s.relative_residual(sys, x, centred), 1e-8);
}
