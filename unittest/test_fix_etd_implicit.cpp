// fix etd scheme implicit: momentum, frozen atoms, the pair styles' conservative-only mode,
// restart continuity, the zero-mass limit, errors. Temperature at large steps is in
// test_equilibrium (label physics); rank-count agreement in test_ranks.
#include "lammps.h"
#include "lammps_fixture.h"
#include "neighbor.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>

using etdtest::Lammps;

namespace {

const std::string DATA = etdtest::work_file("etd_implicit_config.data");

void fluid(Lammps &l, double mass = 0.01)
{
  etdtest::write_random_data(DATA, 500, 5.0, 4321, 1, 1.0);
  l.cmds({"units lj", "atom_modify map array", "comm_modify vel yes",
          "neigh_modify every 1 delay 0 check yes", "read_data " + DATA,
          "mass 1 " + std::to_string(mass), "pair_style dpd/gen 1.0 1.0 555",
          "pair_coeff 1 1 18.75 4.5 0.5"});
}

double max_abs_diff(const std::vector<double> &a, const std::vector<double> &b)
{
  double worst = 0.0;
  for (size_t i = 0; i < a.size(); i++) worst = std::max(worst, std::fabs(a[i] - b[i]));
  return worst;
}

std::vector<double> total_momentum(Lammps &l, double mass)
{
  auto v = l.gather("v");
  std::vector<double> p(3, 0.0);
  for (size_t a = 0; a < v.size() / 3; a++)
    for (int k = 0; k < 3; k++) p[k] += mass * v[3 * a + k];
  return p;
}

}    // namespace

// The Pade update conserves momentum exactly; the solver's error is removed after each solve, so
// even a loose tolerance leaves only round-off. The diagonal scheme does not (test_fix_etd: its
// drift exceeds 0.01 over the same run).
TEST(FixEtdImplicit, ConservesMomentumAtAnyTolerance)
{
  for (const char *tol : {"1e-10", "1e-3"}) {
    Lammps l;
    fluid(l);
    l.cmds({"velocity all zero linear", "timestep 0.003",
            std::string("fix 1 all etd scheme implicit tol ") + tol, "run 300 post no"});
    // thermal momentum of one atom: sqrt(m kT) = 0.1, of the box: 2.2; without the correction
    // tol 1e-3 leaves about 1e-2 after 300 steps. The correction restores the old momentum
    // itself: correcting to the sum of the right-hand side instead left 1e-13 to 3e-11 on 2 and
    // 4 ranks (pairs across ranks cancel only to the rounding of their two images), 1e-14 here.
    for (double p : total_momentum(l, 0.01)) EXPECT_LT(std::fabs(p), 5e-13) << "tol " << tol;
    EXPECT_GT(l.fix_vector("1", 2), 1.0);    // mean CG iterations: the solver did work
  }
}

TEST(FixEtdImplicit, AtomsOutsideTheGroupKeepTheirVelocitiesAndDragTheFluid)
{
  Lammps l;
  fluid(l);
  l.cmds({"region wall block INF INF INF INF 0 1", "group wall region wall",
          "group mobile subtract all wall", "velocity mobile zero linear",
          "velocity wall set 5.0 0 0", "timestep 0.002", "fix 1 mobile etd scheme implicit"});
  auto x0 = l.gather("x"), v0 = l.gather("v");
  l.cmd("run 20 post no");
  auto x1 = l.gather("x"), v1 = l.gather("v");
  int frozen = 0;
  double fluid_momentum = 0.0;
  for (size_t a = 0; a < x0.size() / 3; a++) {
    if (x0[3 * a + 2] < 1.0) {
      frozen++;
      for (int k = 0; k < 3; k++) {
        EXPECT_EQ(x1[3 * a + k], x0[3 * a + k]);
        EXPECT_EQ(v1[3 * a + k], v0[3 * a + k]);
      }
    } else {
      fluid_momentum += 0.01 * v1[3 * a];
    }
  }
  EXPECT_GT(frozen, 50);
  // the moving wall pulls the fluid along x through the friction (thermal scale about 2)
  EXPECT_GT(fluid_momentum, 5.0);
}

// While the implicit scheme runs, dpd/gen computes conservative forces only (compute dpd/split's
// D and R parts then come from the fix, zero before its first step); after unfix the full DPD
// force is back.
TEST(FixEtdImplicit, PairStyleLeavesFrictionAndNoiseToTheFix)
{
  Lammps l;
  fluid(l);
  l.cmds({"compute split all dpd/split", "timestep 0.002", "fix 1 all etd scheme implicit",
          "run 0 post no"});
  auto f = l.gather("f");
  auto split = l.gather_compute("split", 9);
  double dissipative_and_random = 0.0, mismatch = 0.0;
  for (size_t a = 0; a < f.size() / 3; a++)
    for (int k = 0; k < 3; k++) {
      dissipative_and_random += std::fabs(split[9 * a + 3 + k]) + std::fabs(split[9 * a + 6 + k]);
      mismatch = std::max(mismatch, std::fabs(f[3 * a + k] - split[9 * a + k]));
    }
  EXPECT_EQ(dissipative_and_random, 0.0);
  EXPECT_LT(mismatch, 1e-10);
  l.cmds({"unfix 1", "fix 2 all nve", "run 0 post no"});
  split = l.gather_compute("split", 9);
  dissipative_and_random = 0.0;
  for (size_t a = 0; a < split.size() / 9; a++)
    for (int k = 3; k < 9; k++) dissipative_and_random += std::fabs(split[9 * a + k]);
  EXPECT_GT(dissipative_and_random, 1.0);
}

// compute dpd/split under the implicit scheme: the dissipative and random parts are those of
// the fix's friction step, D = -G (v + v')/2 and R = B xi / sqrt(h), so that for every atom of
// the group m (v1 - v0) = h F0 + h (D + R) over one step (F0: the conservative forces at its
// start; the step leaves the friction step's output in v), and pairwise: D and R sum to zero over all atoms, the frozen ones
// (a wall moving at 5 along x) receiving what the fluid loses.
TEST(FixEtdImplicit, SplitReportsTheFrictionStepItTook)
{
  Lammps l;
  fluid(l);
  const double h = 0.002, m = 0.01;
  // atoms re-sorted (and, with ranks, exchanged) at every step: the recorded split follows them
  l.cmds({"atom_modify sort 1 0.5", "neigh_modify every 1 delay 0 check no",
          "region wall block INF INF INF INF 0 1", "group wall region wall",
          "group mobile subtract all wall", "velocity wall set 5.0 0 0", "timestep 0.002",
          "fix 1 mobile etd scheme implicit tol 1e-12", "compute split all dpd/split",
          "run 0 post no"});
  const auto v0 = l.gather("v"), f0 = l.gather("f"), x0 = l.gather("x");
  l.cmd("run 1 post no");
  const auto v1 = l.gather("v"), split = l.gather_compute("split", 9);
  double worst = 0.0, scale = 0.0, sum_d[3] = {0, 0, 0}, sum_r[3] = {0, 0, 0}, wall_drag = 0.0;
  double d_size = 0.0, r_size = 0.0;
  for (size_t a = 0; a < v0.size() / 3; a++) {
    const bool frozen = x0[3 * a + 2] < 1.0;
    for (int k = 0; k < 3; k++) {
      const double d = split[9 * a + 3 + k], r = split[9 * a + 6 + k];
      sum_d[k] += d;
      sum_r[k] += r;
      d_size = std::max(d_size, std::fabs(d));
      r_size = std::max(r_size, std::fabs(r));
      if (frozen) {
        if (k == 0) wall_drag += d + r;
        continue;
      }
      const double kick =
          m * (v1[3 * a + k] - v0[3 * a + k]) - h * f0[3 * a + k];
      worst = std::max(worst, std::fabs(kick - h * (d + r)));
      scale = std::max(scale, std::fabs(h * (d + r)));
    }
  }
  EXPECT_GT(d_size, 1.0);
  EXPECT_GT(r_size, 1.0);
  EXPECT_LT(worst, 1e-8 * scale) << "worst " << worst << " scale " << scale;
  for (int k = 0; k < 3; k++) {
    EXPECT_LT(std::fabs(sum_d[k]), 1e-9 * d_size) << k;
    EXPECT_LT(std::fabs(sum_r[k]), 1e-9 * r_size) << k;
  }
  // the fluid at rest brakes the wall moving along +x
  EXPECT_LT(wall_drag, 0.0);
}

// Overdamped: the solve is G v = F + B xi / sqrt(h), so D + R = -F (F at the start of the step)
// on the group's atoms, with the single solve and with the midpoint scheme.
TEST(FixEtdImplicit, OverdampedSplitBalancesTheForce)
{
  for (const std::string midpoint : {"yes", "no"}) {
    Lammps l;
    fluid(l);
    l.cmds({"region wall block INF INF INF INF 0 1", "group wall region wall",
            "group mobile subtract all wall", "timestep 0.001",
            "fix 1 mobile etd scheme implicit overdamped yes tol 1e-12 midpoint " + midpoint,
            "compute split all dpd/split", "run 0 post no"});
    const auto f0 = l.gather("f"), x0 = l.gather("x");
    l.cmd("run 1 post no");
    const auto split = l.gather_compute("split", 9);
    double worst = 0.0, scale = 0.0, r_size = 0.0;
    for (size_t a = 0; a < f0.size() / 3; a++) {
      if (x0[3 * a + 2] < 1.0) continue;
      for (int k = 0; k < 3; k++) {
        worst =
            std::max(worst, std::fabs(split[9 * a + 3 + k] + split[9 * a + 6 + k] + f0[3 * a + k]));
        scale = std::max(scale, std::fabs(f0[3 * a + k]));
        r_size = std::max(r_size, std::fabs(split[9 * a + 6 + k]));
      }
    }
    EXPECT_GT(r_size, 1.0) << "midpoint " << midpoint;
    EXPECT_LT(worst, 1e-7 * scale) << "midpoint " << midpoint << " worst " << worst;
  }
}

// The scheme keeps no state besides x and v, and its noise is keyed on the timestep.
TEST(FixEtdImplicit, RestartContinuesTheTrajectory)
{
  const std::string restart = etdtest::work_file("etd_implicit.restart");
  std::vector<double> v_ref;
  {
    Lammps l;
    fluid(l);
    l.cmds({"timestep 0.003", "fix 1 all etd scheme implicit tol 1e-12", "run 20 post no",
            "write_restart " + restart, "run 20 post no"});
    v_ref = l.gather("v");
  }
  Lammps l;
  l.cmds({"read_restart " + restart, "comm_modify vel yes",
          "neigh_modify every 1 delay 0 check yes", "fix 1 all etd scheme implicit tol 1e-12",
          "run 20 post no"});
  double scale = 0.0;
  for (double v : v_ref) scale = std::max(scale, std::fabs(v));
  EXPECT_LT(max_abs_diff(l.gather("v"), v_ref), 1e-8 * scale);
}

// Overdamped: in a periodic box without fixed atoms the translation is removed (mean velocity
// zero) and the atoms move by v dt; the solver reports its iterations.
TEST(FixEtdImplicit, OverdampedStepHasZeroMeanVelocityAndMoves)
{
  Lammps l;
  fluid(l);
  l.cmds({"timestep 0.001", "fix 1 all etd scheme implicit overdamped yes tol 1e-10"});
  auto x0 = l.gather("x");
  l.cmd("run 3 post no");
  auto v = l.gather("v");
  auto x1 = l.gather("x");
  double mean[3] = {0, 0, 0}, rms = 0.0;
  const size_t n = v.size() / 3;
  for (size_t a = 0; a < n; a++)
    for (int k = 0; k < 3; k++) {
      mean[k] += v[3 * a + k] / n;
      rms += v[3 * a + k] * v[3 * a + k] / (3 * n);
    }
  for (double m : mean) EXPECT_LT(std::fabs(m), 1e-8 * std::sqrt(rms));
  EXPECT_GT(max_abs_diff(x1, x0), 1e-4);
  EXPECT_GT(l.fix_vector("1", 0), 5.0);
  EXPECT_LT(l.fix_vector("1", 1), 1e-10);
}

// The overdamped step moves every atom by dt times the velocity it reports, whether it is the
// single solve at x_n or the midpoint (predictor-corrector) scheme; the two differ (the
// corrector's mobility is the midpoint's).
TEST(FixEtdImplicit, OverdampedStepMovesByTheStepTimesItsVelocity)
{
  std::vector<std::vector<double>> velocities;
  for (const std::string midpoint : {"yes", "no"}) {
    Lammps l;
    fluid(l);
    l.cmds({"timestep 0.001",
            "fix 1 all etd scheme implicit overdamped yes tol 1e-10 midpoint " + midpoint,
            "run 0 post no"});
    const auto x0 = l.gather("x");
    l.cmd("run 1 post no");
    const auto x1 = l.gather("x"), v = l.gather("v");
    double worst = 0.0;
    for (size_t k = 0; k < x0.size(); k++)
      if (std::fabs(x1[k] - x0[k]) < 1.0)
        worst = std::max(worst, std::fabs(x1[k] - x0[k] - 0.001 * v[k]));
    EXPECT_LT(worst, 1e-12) << "midpoint " << midpoint;
    velocities.push_back(v);
  }
  EXPECT_GT(max_abs_diff(velocities[0], velocities[1]), 1e-6);
}

// Starting CG from the old velocities (start velocity) solves the same system: with a tight
// tolerance the trajectory is the block-Jacobi start's. Where the old velocities already solve
// it (a cold fluid in uniform translation: G v = 0), that start needs no iteration, while the
// block-Jacobi start, which divides each atom's velocity by 1 + h G_ii / 2m, does. A cold fluid
// (no conservative force, T = 0) so that the prescribed flow is the only motion.
TEST(FixEtdImplicit, StartFromOldVelocitiesSolvesTheSameSystem)
{
  auto one_step = [](const std::string &velocity, const std::string &options, double *iterations) {
    Lammps l;
    etdtest::write_random_data(DATA, 500, 5.0, 4321, 1, 1.0);
    l.cmds({"units lj", "atom_modify map array", "comm_modify vel yes",
            "neigh_modify every 1 delay 0 check yes", "read_data " + DATA, "mass 1 0.001",
            "pair_style dpd/gen 0.0 1.0 555", "pair_coeff 1 1 0.0 4.5 0.5",
            "variable wave atom sin(2.0*PI*z/5.0)", "velocity all set " + velocity,
            "timestep 0.001", "fix 1 all etd scheme implicit " + options, "run 1 post no"});
    if (iterations) *iterations = l.fix_vector("1", 0);
    return l.gather("v");
  };
  const auto v_jacobi = one_step("v_wave 0.0 0.0", "tol 1e-12", nullptr);
  const auto v_start = one_step("v_wave 0.0 0.0", "tol 1e-12 start velocity", nullptr);
  double scale = 0.0;
  for (double v : v_jacobi) scale = std::max(scale, std::fabs(v));
  EXPECT_LT(max_abs_diff(v_jacobi, v_start), 1e-9 * scale);
  EXPECT_GT(scale, 0.1);
  double it_start = -1.0, it_jacobi = -1.0;
  const auto v_moved = one_step("1.0 0.0 0.0", "tol 1e-10 start velocity", &it_start);
  one_step("1.0 0.0 0.0", "tol 1e-10", &it_jacobi);
  EXPECT_EQ(it_start, 0.0);
  EXPECT_GT(it_jacobi, 2.0);
  for (size_t k = 0; k < v_moved.size(); k++)
    ASSERT_NEAR(v_moved[k], k % 3 == 0 ? 1.0 : 0.0, 1e-12);
}

TEST(FixEtdImplicit, BadInputGivesClearErrors)
{
  etdtest::expect_errors(
      {
          {{"fix 1 all etd scheme explicit"}, "scheme must be diagonal or implicit"},
          {{"fix 1 all etd scheme implicit tol 0"}, "tol must be between 0 and 1"},
          {{"fix 1 all etd scheme implicit tol 2"}, "tol must be between 0 and 1"},
          {{"fix 1 all etd scheme implicit maxiter 0"}, "maxiter must be a positive integer"},
          {{"fix 1 all etd scheme implicit start old"}, "start must be velocity or jacobi"},
          {{"fix 1 all etd scheme implicit overdamped yes start velocity"},
           "start velocity needs overdamped no"},
          {{"fix 1 all etd scheme implicit overdamped maybe"}, "overdamped must be yes or no"},
          {{"fix 1 all etd scheme implicit overdamped yes midpoint 1"},
           "midpoint must be yes or no"},
          {{"fix 1 all etd scheme implicit order 2"}, "keyword order belongs to scheme diagonal"},
          {{"fix 1 all etd scheme implicit tol"}, "keyword tol needs a value"},
          {{"fix 1 all etd scheme implicit colour red"}, "unknown keyword colour"},
          {{"fix 1 all etd overdamped yes"}, "unknown keyword overdamped"},
          {{"pair_style zero 1.0", "pair_coeff * *", "fix 1 all etd scheme implicit", "run 0"},
           "requires pair style dpd/gen"},
          {{"fix 1 all etd scheme implicit", "run_style respa 2 2", "run 0"}, "respa"},
      },
      [](Lammps &l) {
        fluid(l);
      });
}

// Overdamped Couette flow: frozen walls (z < 1 moving at -U, z > 9 at +U; periodic, so the
// walls also shear against each other across the boundary) drive the fluid between them;
// without inertia the mean velocity profile is linear at once. 2,000 atoms, 200 steps of 0.002
// (the overdamped velocity noise falls as 1/sqrt(dt)), 8 bins: the bin means scatter by about
// 0.15 against U = 5 (collective fluctuations make it more than the atom count suggests).
TEST(FixEtdImplicit, OverdampedCouetteFlowIsLinear)
{
  const std::string data = etdtest::work_file("etd_implicit_couette.data");
  etdtest::write_random_data(data, 2000, 8.0, 97, 1, 0.0);
  Lammps l;
  const double U = 5.0;
  l.cmds({"units lj", "atom_modify map array", "comm_modify vel yes",
          "neigh_modify every 1 delay 0 check yes", "read_data " + data,
          "change_box all z final 0 10 remap", "mass 1 0.01", "pair_style dpd/gen 1.0 1.0 555",
          "pair_coeff 1 1 18.75 4.5 0.5", "region bottom block INF INF INF INF INF 1.0",
          "region top block INF INF INF INF 9.0 INF", "group bottom region bottom",
          "group top region top", "group walls union bottom top", "group fluid subtract all walls",
          "velocity bottom set -5.0 0 0", "velocity top set 5.0 0 0", "timestep 0.002",
          "fix 1 fluid etd scheme implicit", "run 100 post no", "unfix 1",
          // (from random positions the zero-mass friction system is singular: start overdamped
          // runs from a configuration equilibrated with inertia)
          "fix 1 fluid etd scheme implicit overdamped yes", "run 20 post no"});
  // Each step's overdamped velocities are a fresh draw given the positions, and the fluid's
  // collective (centre-of-mass) mode is held only by the few wall pairs, so the fluid's mean
  // velocity scatters by several units from sample to sample. The checks below are therefore
  // against the standard errors measured from the samples themselves.
  const int nbins = 8, nsamples = 200;
  std::vector<double> sum(nbins, 0.0), count(nbins, 0.0), bin_sq(nbins, 0.0);
  double mean_sum = 0.0, mean_sq = 0.0;
  for (int sample = 0; sample < nsamples; sample++) {
    l.cmd("run 1 post no");
    auto x = l.gather("x"), v = l.gather("v");
    std::vector<double> s_sum(nbins, 0.0), s_count(nbins, 0.0);
    for (size_t a = 0; a < x.size() / 3; a++) {
      const double z = x[3 * a + 2];
      if (z <= 1.0 || z >= 9.0) continue;
      const int bin = std::min(nbins - 1, int((z - 1.0) / 8.0 * nbins));
      s_sum[bin] += v[3 * a];
      s_count[bin] += 1.0;
    }
    double all_sum = 0.0, all_count = 0.0;
    for (int b = 0; b < nbins; b++) {
      sum[b] += s_sum[b];
      count[b] += s_count[b];
      const double bin_mean = s_sum[b] / std::max(1.0, s_count[b]);
      bin_sq[b] += bin_mean * bin_mean;
      all_sum += s_sum[b];
      all_count += s_count[b];
    }
    mean_sum += all_sum / all_count;
    mean_sq += (all_sum / all_count) * (all_sum / all_count);
  }
  // least-squares line through the bin means
  double sz = 0, su = 0, szz = 0, szu = 0;
  std::vector<double> zc(nbins), u(nbins);
  for (int b = 0; b < nbins; b++) {
    zc[b] = 1.0 + (b + 0.5) * 8.0 / nbins;
    u[b] = sum[b] / count[b];
    sz += zc[b];
    su += u[b];
    szz += zc[b] * zc[b];
    szu += zc[b] * u[b];
  }
  const double slope = (nbins * szu - sz * su) / (nbins * szz - sz * sz);
  const double intercept = (su - slope * sz) / nbins;
  // standard errors of the fluid's mean velocity and of each bin's mean, from the samples
  auto standard_error = [&](double total, double squares) {
    const double mean = total / nsamples;
    return std::sqrt(std::max(0.0, squares / nsamples - mean * mean) / (nsamples - 1));
  };
  const double error_of_mean = standard_error(mean_sum, mean_sq);
  double worst = 0.0, worst_in_errors = 0.0;
  for (int b = 0; b < nbins; b++) {
    const double deviation = std::fabs(u[b] - (intercept + slope * zc[b]));
    const double error = standard_error(u[b] * nsamples, bin_sq[b]);
    worst = std::max(worst, deviation);
    worst_in_errors = std::max(worst_in_errors, deviation / error);
    if (etdtest::world_rank() == 0)
      std::printf("  z %.2f u %.3f +- %.3f line %.3f n %.0f\n", zc[b], u[b], error,
                  intercept + slope * zc[b], count[b]);
  }
  if (etdtest::world_rank() == 0)
    std::printf(
        "overdamped Couette: slope %.3f (walls 2U/8 = %.3f), u(5) = %.3f (fluid mean velocity "
        "+- %.3f), worst bin %.3f (%.1f standard errors)\n",
        slope, 2 * U / 8, intercept + 5.0 * slope, error_of_mean, worst, worst_in_errors);
  EXPECT_GT(slope, 0.5 * 2 * U / 8);    // the walls drive the fluid
  EXPECT_LT(slope, 1.2 * 2 * U / 8);    // but cannot shear it faster than they move
  // antisymmetric about the middle, within 4 standard errors of the fluid's mean velocity
  // (about 0.25 here)
  EXPECT_LT(std::fabs(intercept + 5.0 * slope), 4.0 * error_of_mean);
  EXPECT_LT(error_of_mean, 0.5);      // and that error is small against the walls' 5
  EXPECT_LT(worst_in_errors, 4.0);    // linear: no bin off the line by more than its noise
}

// dpd/fpm with rotation has no zero-mass form here: overdamped yes is refused, as is an atom
// without moment of inertia
TEST(FixEtdImplicit, FpmRefusesOverdampedAndZeroInertia)
{
  const std::vector<std::string> box = {"units lj",
                                        "atom_style sphere",
                                        "comm_modify vel yes",
                                        "neigh_modify every 1 delay 0 check yes",
                                        "region box block 0 5 0 5 0 5",
                                        "create_box 1 box",
                                        "create_atoms 1 single 1 1 1",
                                        "create_atoms 1 single 1.5 1 1",
                                        "pair_style dpd/fpm 1.0 1.0 123",
                                        "pair_coeff 1 1 25 4.5 4.5 0.5"};
  {
    Lammps l;
    auto cmds = box;
    cmds.insert(cmds.end(), {"fix 1 all etd scheme implicit overdamped yes", "run 1"});
    const std::string message = l.error_of(cmds);
    EXPECT_NE(message.find("overdamped yes is not available with pair style dpd/fpm"),
              std::string::npos)
        << message;
  }
  {
    Lammps l;
    auto cmds = box;
    cmds.insert(cmds.end(), {"set atom 2 diameter 0.0", "fix 1 all etd scheme implicit", "run 1"});
    const std::string message = l.error_of(cmds);
    EXPECT_NE(message.find("atom 2 has zero moment of inertia"), std::string::npos) << message;
  }
}

// LAMMPS 29Sep2021's default neigh_modify delay 10 lets the atoms of a thermalised m = 0.01
// fluid run about 1.3 beyond their list in the 10 unchecked steps at dt = 0.003 (kBT rose to
// 1.04-1.07 before this check): every scheme stops with an ERROR naming neigh_modify. The
// zero-mass scheme has no speed to bound, so it needs checks every step whatever the step. A
// step at which the fastest atom stays within half the skin over the unchecked steps is
// accepted with the default settings.
TEST(FixEtdImplicit, RefusesNeighborSettingsThatLetAtomsOutrunTheSkin)
{
  struct Case {
    std::string fix, timestep, neigh, expected;
  };
  const std::vector<Case> cases = {
      {"etd scheme implicit", "0.003", "neigh_modify every 1 delay 10 check yes",
       "lets atoms outrun the neighbor skin"},
      {"etd scheme implicit", "0.003", "neigh_modify every 2 delay 0 check yes",
       "lets atoms outrun the neighbor skin"},
      {"etd", "0.003", "neigh_modify every 1 delay 10 check yes",
       "lets atoms outrun the neighbor skin"},
      {"etd scheme implicit overdamped yes", "0.0001", "neigh_modify every 1 delay 10 check yes",
       "a zero-mass step has no speed to bound"},
      {"etd scheme implicit", "0.003", "neigh_modify every 1 delay 0 check no", ""},
      {"etd scheme implicit", "0.00001", "neigh_modify every 1 delay 10 check yes", ""},
  };
  for (const auto &c : cases) {
    Lammps l;
    fluid(l);
    l.cmds({"velocity all create 1.0 5 mom yes dist gaussian", "timestep " + c.timestep});
    const std::string message = l.error_of({c.neigh, "fix 1 all " + c.fix, "run 2 post no"});
    if (c.expected.empty()) {
      EXPECT_EQ(message, "") << c.fix << " dt " << c.timestep << ", " << c.neigh;
      continue;
    }
    EXPECT_NE(message.find(c.expected), std::string::npos)
        << c.fix << ", " << c.neigh << " gave: '" << message << "'";
    EXPECT_NE(message.find("neigh_modify every 1 delay 0 check yes"), std::string::npos) << message;
  }
}

// A run in which LAMMPS counted dangerous builds ends with a WARNING that says so; a run with a
// skin wide enough for the step ends without one. The implicit scheme asks for a rebuild one
// step early where its next friction step would take an atom beyond half the skin, so at a
// skin of 0.6 (atoms move up to about 0.13 a step here) it neither outruns its list nor has
// dangerous builds. The diagonal scheme (no early rebuilds) at 0.02 shows LAMMPS's own count.
// (The implicit scheme at 0.02 stops: MissingPairIsAnError below.)
TEST(FixEtdImplicit, RunWithDangerousBuildsEndsWithAWarning)
{
  struct Case {
    std::string fix, skin;
    bool warned;
  };
  for (const Case &c : {Case{"etd scheme implicit", "0.6", false}, Case{"etd", "0.02", true}}) {
    const std::string log = etdtest::work_file("etd_implicit_danger_np" +
                                               std::to_string(etdtest::world_size()) + ".log");
    bool dangerous =
        false;    // LAMMPS's own count, read from its Neighbor (not from its log wording)
    {
      Lammps l;
      fluid(l);
      l.cmds({"log " + log, "neighbor " + c.skin + " bin",
              "velocity all create 1.0 5 mom yes dist gaussian",
              "timestep " + std::string(c.fix == "etd" ? "0.001" : "0.003"), "fix 1 all " + c.fix,
              "run 50"});
      dangerous = l.lmp->neighbor->ndanger > 0;
    }
    if (etdtest::world_rank() != 0) continue;    // (rank 0 writes the log)
    const std::string text = etdtest::read_file(log);
    const bool warned =
        text.find("dangerous neighbor list builds in this run") != std::string::npos;
    EXPECT_EQ(warned, c.warned) << c.fix << ", skin " << c.skin;
    if (c.fix == "etd") EXPECT_TRUE(dangerous) << "the diagonal scheme at skin 0.02";
    if (!c.warned) EXPECT_FALSE(dangerous) << c.fix << ", skin " << c.skin;
  }
}

// Two atoms and a friction step half a drift after the list was built (neighbor_safety.h): at
// 1.35 apart they are beyond the list's reach (rc 1 + skin 0.3); closing at 40 + 40 they are
// 0.95 apart at the first friction step (0.2 each in half a step of 0.01), within the cutoff
// but unlisted: the run stops with an ERROR naming the skin. Moving apart at the same speeds,
// their displacements add up to more than the skin just the same, but no pair can be missing:
// the run goes on, and ends without a warning.
void two_fast_atoms(Lammps &l, double speed, double second_speed)
{
  l.cmds({"units lj", "atom_modify map array", "comm_modify vel yes",
          "neigh_modify every 1 delay 0 check yes", "region box block 0 10 0 10 0 10",
          "create_box 1 box", "create_atoms 1 single 4.325 5 5", "create_atoms 1 single 5.675 5 5",
          "mass 1 1.0", "pair_style dpd/gen 1.0 1.0 555", "pair_coeff 1 1 18.75 4.5 0.5",
          "neighbor 0.3 bin", "group first id 1", "group second id 2",
          "velocity first set " + std::to_string(speed) + " 0 0",
          "velocity second set " + std::to_string(second_speed) + " 0 0", "timestep 0.01",
          "fix 1 all etd scheme implicit"});
}

TEST(FixEtdImplicit, MissingPairIsAnError)
{
  // closing at 40 + 40; then one atom at rest and one at 100 (half a step: 0.5, more than the
  // whole skin, so every atom, even one that has not moved, must be among those checked)
  for (const auto &speeds :
       {std::array<double, 2>{40.0, -40.0}, std::array<double, 2>{100.0, 0.0}}) {
    Lammps l;
    two_fast_atoms(l, speeds[0], speeds[1]);
    const std::string message = l.error_of("run 1");
    EXPECT_NE(message.find("1 pair(s) within the friction cutoff missing from the neighbor list"),
              std::string::npos)
        << speeds[0] << " " << speeds[1] << ": " << message;
    EXPECT_NE(message.find("use a larger skin"), std::string::npos) << message;
  }
  {
    const std::string log = etdtest::work_file("etd_implicit_apart_np" +
                                               std::to_string(etdtest::world_size()) + ".log");
    {
      Lammps l;
      two_fast_atoms(l, -40.0, 40.0);
      l.cmds({"log " + log, "run 3"});
      const auto x = l.gather("x");
      ASSERT_EQ(x.size(), 6u);
      EXPECT_GT(std::fabs(x[0] - x[3]), 1.35 + 2 * 3 * 0.4 - 1e-9) << "moved apart freely";
    }
    if (etdtest::world_rank() == 0) {
      const std::string text = etdtest::read_file(log);
      EXPECT_EQ(text.find("WARNING"), std::string::npos) << text;
    }
  }
}
