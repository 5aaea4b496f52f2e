// Unit tests of the dpd/fpm pair kernel (src/fpm_kernel.h), without LAMMPS: reduction to the
// dpd/gen kernel, pair antisymmetry and angular momentum, rigid motion, the friction diagonals
// as derivatives of the kernel, and the noise covariance against fluctuation-dissipation.
#include "dpd_kernel.h"
#include "dpd_random.h"
#include "fpm_kernel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace {

struct PairState {
  double del[3], v_ij[3], omega_i[3], omega_j[3];
  etd::FpmNoise noise;
  double r() const { return std::sqrt(del[0] * del[0] + del[1] * del[1] + del[2] * del[2]); }
};

PairState random_state(std::mt19937_64 &gen, double rc)
{
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::normal_distribution<double> g;
  PairState p;
  do {
    for (double &x : p.del) x = rc * u(gen);
  } while (p.r() >= rc || p.r() < 1e-3);
  for (int k = 0; k < 3; k++) {
    p.v_ij[k] = 2 * u(gen);
    p.omega_i[k] = 3 * u(gen);
    p.omega_j[k] = 3 * u(gen);
    p.noise.shear[k] = g(gen);
  }
  p.noise.central = g(gen);
  return p;
}

etd::FpmPairResult evaluate(const etd::FpmCoefficients &c, const PairState &p, double inv_sqrt_dt,
                            double special = 1.0)
{
  const double omega_sum[3] = {p.omega_i[0] + p.omega_j[0], p.omega_i[1] + p.omega_j[1],
                               p.omega_i[2] + p.omega_j[2]};
  return etd::fpm_pair(c, p.del, p.r(), p.v_ij, omega_sum, p.noise, inv_sqrt_dt, special);
}

}    // namespace

TEST(FpmKernel, ZeroShearFrictionIsTheDpdGenKernel)
{
  std::mt19937_64 gen(11);
  for (double s : {0.5, 1.0, 2.0, 0.37}) {
    etd::FpmCoefficients c;
    c.set(25.0, 4.5, 0.0, s, 1.3, 1.7);
    etd::PairCoefficients g;
    g.set(25.0, 4.5, s, 1.0, 1.3, 1.3, 1.7);
    for (int n = 0; n < 200; n++) {
      const PairState p = random_state(gen, 1.3);
      const double special = (n % 3 == 0) ? 0.5 : 1.0;
      const auto fpm = evaluate(c, p, 10.0, special);
      const double r = p.r();
      const double e_dot_v =
          (p.del[0] * p.v_ij[0] + p.del[1] * p.v_ij[1] + p.del[2] * p.v_ij[2]) / r;
      const auto ref = etd::pair_force(g, r * r, r, e_dot_v, p.noise.central, 10.0, special);
      for (int k = 0; k < 3; k++) {
        const double e = p.del[k] / r;
        EXPECT_NEAR(fpm.conservative[k], ref.conservative * e, 1e-13 * std::fabs(ref.conservative));
        EXPECT_NEAR(fpm.dissipative[k], ref.dissipative * e,
                    1e-13 * (1 + std::fabs(ref.dissipative)));
        EXPECT_NEAR(fpm.random[k], ref.random * e, 1e-13 * (1 + std::fabs(ref.random)));
        EXPECT_EQ(fpm.torque[k], 0.0);
      }
      EXPECT_NEAR(etd::fpm_energy(c, r, special), etd::pair_energy(g, r * r, r, special), 1e-13);
    }
  }
}

TEST(FpmKernel, PairIsAntisymmetricAndConservesAngularMomentum)
{
  std::mt19937_64 gen(12);
  etd::FpmCoefficients c;
  c.set(25.0, 3.5, 5.5, 0.5, 1.0, 1.0);
  for (int n = 0; n < 500; n++) {
    const PairState p = random_state(gen, 1.0);
    PairState swapped = p;
    for (int k = 0; k < 3; k++) {
      swapped.del[k] = -p.del[k];
      swapped.v_ij[k] = -p.v_ij[k];
      swapped.omega_i[k] = p.omega_j[k];
      swapped.omega_j[k] = p.omega_i[k];
    }
    const auto ij = evaluate(c, p, 7.0);
    const auto ji = evaluate(c, swapped, 7.0);
    double r_cross_f[3];
    const double f[3] = {ij.force(0), ij.force(1), ij.force(2)};
    etd::cross(p.del, f, r_cross_f);
    double scale = 0.0;
    for (int k = 0; k < 3; k++) scale = std::max(scale, std::fabs(f[k]) * p.r());
    for (int k = 0; k < 3; k++) {
      EXPECT_EQ(ji.force(k), -ij.force(k));
      EXPECT_EQ(ji.torque[k], ij.torque[k]);
      // r_i x F_ij + r_j x F_ji + T_i + T_j = r_ij x F_ij + 2 T
      EXPECT_NEAR(r_cross_f[k] + 2 * ij.torque[k], 0.0, 1e-14 * scale);
    }
  }
}

TEST(FpmKernel, RigidBodyMotionOfThePairIsNotDamped)
{
  // v_i = V + W x r_i, Omega_i = Omega_j = W: the mid-point surfaces move together
  std::mt19937_64 gen(13);
  etd::FpmCoefficients c;
  c.set(0.0, 4.5, 4.5, 0.5, 1.0, 0.0);
  for (int n = 0; n < 100; n++) {
    PairState p = random_state(gen, 1.0);
    etd::cross(p.omega_i, p.del, p.v_ij);    // W x (r_i - r_j)
    for (int k = 0; k < 3; k++) p.omega_j[k] = p.omega_i[k];
    const auto res = evaluate(c, p, 1.0);
    for (int k = 0; k < 3; k++) {
      EXPECT_NEAR(res.dissipative[k], 0.0, 1e-13);
      EXPECT_NEAR(res.torque[k], 0.0, 1e-13);
    }
  }
  // a spin alone is damped, and its drag lies in the plane normal to e
  PairState p{};
  p.del[0] = 0.6;
  p.omega_i[2] = 1.0;
  const auto res = evaluate(c, p, 1.0);
  EXPECT_NEAR(res.dissipative[1], 4.5 * std::sqrt(0.4) * 0.3,
              1e-14);    // -gS w (r/2 x) x (W z) = +y
  EXPECT_EQ(res.dissipative[0], 0.0);
  EXPECT_NEAR(res.torque[2], -4.5 * std::sqrt(0.4) * 0.09, 1e-14);    // opposes the spin
}

TEST(FpmKernel, FrictionDiagonalsAreTheKernelsDerivatives)
{
  // The dissipative force is linear in v_ij and Omega: the diagonals must equal minus the
  // derivative of F_i with respect to v_i and of T_i with respect to Omega_i.
  std::mt19937_64 gen(14);
  etd::FpmCoefficients c;
  c.set(25.0, 3.5, 5.5, 0.5, 1.2, 0.0);
  for (int n = 0; n < 100; n++) {
    PairState p = random_state(gen, 1.2);
    const auto base = evaluate(c, p, 1.0);
    const double r = p.r();
    const double e[3] = {p.del[0] / r, p.del[1] / r, p.del[2] / r};
    double trans[3], rot[3];
    etd::fpm_translational_friction(base.central_friction, base.shear_friction, e, trans);
    etd::fpm_rotational_friction(base.shear_friction, r * r, e, rot);
    for (int k = 0; k < 3; k++) {
      PairState dv = p, dw = p;
      dv.v_ij[k] += 1.0;
      dw.omega_i[k] += 1.0;
      const auto rv = evaluate(c, dv, 1.0), rw = evaluate(c, dw, 1.0);
      EXPECT_NEAR(-(rv.dissipative[k] - base.dissipative[k]), trans[k], 1e-12);
      EXPECT_NEAR(-(rw.torque[k] - base.torque[k]), rot[k], 1e-12);
      EXPECT_GE(trans[k], 0.0);
      EXPECT_GE(rot[k], 0.0);
    }
  }
}

TEST(FpmKernel, NoiseCovarianceIsTwoKTTimesTheFrictionMatrix)
{
  // 40,000 draws of the counter-based noise for one pair geometry: the random force has
  // covariance 2 kBT w [gamma_C e e + gamma_S (1 - e e)] / dt (fluctuation-dissipation with the
  // dissipative matrix), zero mean; relative standard error of each variance about 0.7 %.
  const double kT = 1.3, gc = 3.5, gs = 5.5, s = 0.5, dt = 0.01;
  etd::FpmCoefficients c;
  c.set(0.0, gc, gs, s, 1.0, kT);
  const etd::PairNoise noise(2024, etd::NoiseStream::PairScalar);
  PairState p{};
  p.del[0] = 0.3;
  p.del[1] = -0.4;
  p.del[2] = 0.2;
  const double r = p.r();
  const double e[3] = {p.del[0] / r, p.del[1] / r, p.del[2] / r};
  const double w = std::pow(1 - r, s);
  double sum[3] = {0, 0, 0}, cov[3][3] = {{0}};
  const int n = 40000;
  for (int step = 0; step < n; step++) {
    double theta[4];
    noise.gaussians4(17, 5, step, 0, theta);
    p.noise.central = theta[0];
    for (int k = 0; k < 3; k++) p.noise.shear[k] = theta[k + 1];
    const auto res = evaluate(c, p, 1.0 / std::sqrt(dt));
    for (int a = 0; a < 3; a++) {
      sum[a] += res.random[a];
      for (int b = 0; b < 3; b++) cov[a][b] += res.random[a] * res.random[b];
    }
  }
  const double scale = 2 * kT * w / dt * std::max(gc, gs);
  for (int a = 0; a < 3; a++) {
    EXPECT_NEAR(sum[a] / n, 0.0, 5 * std::sqrt(scale / n));
    for (int b = 0; b < 3; b++) {
      const double expected = 2 * kT * w / dt * (gc * e[a] * e[b] + gs * ((a == b) - e[a] * e[b]));
      EXPECT_NEAR(cov[a][b] / n, expected, 5 * scale * std::sqrt(2.0 / n)) << a << b;
    }
  }
}

TEST(FpmKernel, CentralNoiseIsTheDpdGenNumber)
{
  // gamma_S = 0 reproduces dpd/gen at any temperature: the first of the four Gaussians is the
  // scalar theta dpd/gen draws for the same seed, pair and step
  const etd::PairNoise noise(99, etd::NoiseStream::PairScalar);
  for (int step = 0; step < 50; step++) {
    double theta[4];
    noise.gaussians4(3, 8 + step, step, 0, theta);
    EXPECT_EQ(theta[0], noise.gaussian(8 + step, 3, step));
  }
}

TEST(FpmKernel, DissipationAndRandomForceAreThePairsOwn)
{
  // fpm_dissipation and fpm_random_force are the one evaluation of the frictions and the random
  // force, shared by fpm_pair and fix etd's implicit scheme: fpm_pair's numbers bit for bit, and
  // the analytic ones, gamma_X w, sqrt(w) and sqrt(w) [sigma_C theta_C e + sigma_S theta_A x e]
  std::mt19937_64 gen(15);
  const double kT = 1.3, gc = 3.5, gs = 5.5, rc = 1.2, isdt = 10.0;
  for (double s : {0.5, 0.4244, 1.0, 2.0}) {
    etd::FpmCoefficients c;
    c.set(25.0, gc, gs, s, rc, kT);
    for (int n = 0; n < 200; n++) {
      const PairState p = random_state(gen, rc);
      const double special = (n % 3 == 0) ? 0.36 : 1.0;
      const double r = p.r();
      const auto pair = evaluate(c, p, isdt, special);
      const etd::FpmDissipation d = etd::fpm_dissipation(c, r, special);
      EXPECT_EQ(d.central, pair.central_friction);
      EXPECT_EQ(d.shear, pair.shear_friction);
      const double rinv = 1.0 / r;    // e as fpm_pair forms it
      const double e[3] = {p.del[0] * rinv, p.del[1] * rinv, p.del[2] * rinv};
      const etd::FpmRandomForce random = etd::fpm_random_force(c, e, d.noise * isdt, p.noise);
      for (int k = 0; k < 3; k++)
        EXPECT_EQ(random.central * e[k] + random.shear[k], pair.random[k]);

      const double w = std::pow(1.0 - r / rc, s);
      EXPECT_NEAR(d.central, special * gc * w, 1e-14 * gc);
      EXPECT_NEAR(d.shear, special * gs * w, 1e-14 * gs);
      EXPECT_NEAR(d.noise, std::sqrt(special * w), 1e-14);
      const double amplitude = std::sqrt(special * w) * isdt;
      EXPECT_NEAR(random.central, amplitude * std::sqrt(2 * kT * gc) * p.noise.central,
                  1e-13 * amplitude * (1 + std::fabs(p.noise.central)));
      const double *a = p.noise.shear;
      const double axial_cross_e[3] = {a[1] * e[2] - a[2] * e[1], a[2] * e[0] - a[0] * e[2],
                                       a[0] * e[1] - a[1] * e[0]};
      double along_e = 0.0;
      for (int k = 0; k < 3; k++) {
        EXPECT_NEAR(random.shear[k], amplitude * std::sqrt(2 * kT * gs) * axial_cross_e[k],
                    1e-13 * amplitude * 10);
        along_e += random.shear[k] * e[k];
      }
      EXPECT_NEAR(along_e, 0.0, 1e-13 * amplitude * 10);    // the shear noise is normal to e
    }
  }
  // zero friction and noise at the cutoff
  etd::FpmCoefficients c;
  c.set(25.0, gc, gs, 0.5, rc, kT);
  const etd::FpmDissipation edge = etd::fpm_dissipation(c, rc);
  EXPECT_EQ(edge.central, 0.0);
  EXPECT_EQ(edge.shear, 0.0);
  EXPECT_EQ(edge.noise, 0.0);
}

TEST(FpmKernel, ZeroShearDissipationIsTheDpdGenOne)
{
  // gamma_S = 0: the central friction and noise of dpd/gen's pair_dissipation
  for (double s : {0.5, 2.0, 0.37})
    for (double special : {1.0, 0.5}) {
      etd::FpmCoefficients c;
      c.set(25.0, 4.5, 0.0, s, 1.3, 1.7);
      etd::PairCoefficients g;
      g.set(25.0, 4.5, s, 1.0, 1.3, 1.3, 1.7);
      for (double r = 0.01; r < 1.3; r += 0.0437) {
        const etd::FpmDissipation f = etd::fpm_dissipation(c, r, special);
        const etd::PairDissipation d = etd::pair_dissipation(g, r, special);
        EXPECT_EQ(f.central, d.friction);
        EXPECT_EQ(f.shear, 0.0);
        EXPECT_NEAR(f.noise * c.sigma_c, d.noise, 1e-14 * g.sigma);
        const double e[3] = {0.6, 0.0, -0.8};
        etd::FpmNoise theta;
        theta.central = 0.7;
        theta.shear[0] = -1.2;
        theta.shear[1] = 0.4;
        theta.shear[2] = 2.0;
        const etd::FpmRandomForce random = etd::fpm_random_force(c, e, f.noise, theta);
        EXPECT_NEAR(random.central, d.noise * theta.central, 1e-14 * g.sigma);
        for (int k = 0; k < 3; k++) EXPECT_EQ(random.shear[k], 0.0);
      }
    }
}

TEST(FpmKernel, TorqueOfTheForcePartsAddsUpToThePairTorque)
{
  // compute dpd/split torque yes: -(r_ij/2) x F of the dissipative and of the random part add up
  // to the pair's torque; the conservative part makes none
  std::mt19937_64 gen(23);
  etd::FpmCoefficients c;
  c.set(25.0, 4.5, 6.0, 0.5, 1.2, 1.3);
  for (int n = 0; n < 200; n++) {
    const PairState p = random_state(gen, 1.2);
    const auto pr = evaluate(c, p, 10.0);
    double dissipative[3], random[3], conservative[3];
    etd::fpm_pair_torque(p.del, pr.dissipative, dissipative);
    etd::fpm_pair_torque(p.del, pr.random, random);
    etd::fpm_pair_torque(p.del, pr.conservative, conservative);
    for (int k = 0; k < 3; k++) {
      EXPECT_NEAR(dissipative[k] + random[k], pr.torque[k], 1e-12 * (1 + std::fabs(pr.torque[k])));
      EXPECT_NEAR(conservative[k], 0.0, 1e-12 * (1 + std::fabs(pr.conservative[k])));
    }
  }
}
