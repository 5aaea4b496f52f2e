// fix etd: exact reduction without friction, convergence order, restart, frozen atoms, momentum,
// errors.
#include "lammps_fixture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using etdtest::Lammps;

namespace {

const std::string DATA = etdtest::work_file("etd_config.data");

void fluid(Lammps &l, const std::string &pair_coeff, double mass = 0.01, double T = 1.0,
           int natoms = 500, double L = 5.0)
{
  etdtest::write_random_data(DATA, natoms, L, 1234, 1, 1.0);
  l.cmds({"units lj", "atom_modify map array", "comm_modify vel yes",
          "neigh_modify every 1 delay 0 check yes", "read_data " + DATA,
          "mass 1 " + std::to_string(mass), "pair_style dpd/gen " + std::to_string(T) + " 1.0 555",
          pair_coeff});
}

double max_abs_diff(const std::vector<double> &a, const std::vector<double> &b)
{
  double worst = 0.0;
  for (size_t i = 0; i < a.size(); i++) worst = std::max(worst, std::fabs(a[i] - b[i]));
  return worst;
}

}    // namespace

TEST(FixEtd, ZeroFrictionIsExplicitEuler)
{
  Lammps l;
  fluid(l, "pair_coeff 1 1 18.75 0.0 0.5", 0.5, 0.0);
  l.cmds({"timestep 0.003", "fix 1 all etd", "run 0 post no"});
  auto x0 = l.gather("x"), v0 = l.gather("v");
  l.cmd("run 1 post no");
  auto x1 = l.gather("x"), v1 = l.gather("v"), f1 = l.gather("f");
  for (size_t i = 0; i < x0.size(); i++) {
    const double expected_x = x0[i] + 0.003 * v0[i];
    // positions may have been wrapped into the box: compare modulo the box length
    double dx = std::fmod(x1[i] - expected_x + 7.5, 5.0) - 2.5;
    EXPECT_NEAR(dx, 0.0, 1e-13);
    EXPECT_DOUBLE_EQ(v1[i], v0[i] + 0.003 * (f1[i] / 0.5));
  }
}

// Deterministic (T = 0) runs to t = 0.016 with dt = h; returns final velocities
static std::vector<double> deterministic_run(int order, double h)
{
  Lammps l;
  fluid(l, "pair_coeff 1 1 18.75 4.5 0.5", 0.01, 0.0, 250, 4.0);
  char step[64];
  std::snprintf(step, sizeof step, "timestep %.17g", h);
  l.cmds({"neighbor 1.0 bin", step, "fix 1 all etd order " + std::to_string(order),
          "run " + std::to_string(static_cast<int>(std::lround(0.016 / h))) + " post no"});
  return l.gather("v");
}

TEST(FixEtd, ConvergenceOrderByStepRefinement)
{
  // With the paper's step order (x += v dt first, forces at the new x and old v) the positions
  // are advanced by explicit Euler, so the whole scheme converges at first order for both
  // velocity formulas; order 2 only lowers the error constant. The formulas' own orders are
  // checked on the model equation in test_math (EtdCoefficients.ModelEquationOrders).
  double finest[2];
  for (int order : {1, 2}) {
    const auto reference = deterministic_run(order, 0.016 / 1280);
    std::vector<double> errors;
    for (int n : {40, 80, 160})
      errors.push_back(max_abs_diff(deterministic_run(order, 0.016 / n), reference));
    const double p1 = std::log2(errors[0] / errors[1]), p2 = std::log2(errors[1] / errors[2]);
    std::printf("order %d: errors %.3e %.3e %.3e, observed orders %.2f %.2f\n", order, errors[0],
                errors[1], errors[2], p1, p2);
    EXPECT_NEAR(p1, 1.0, 0.25);
    EXPECT_NEAR(p2, 1.0, 0.25);
    finest[order - 1] = errors[2];
  }
  EXPECT_LT(finest[1], 0.6 * finest[0]);
}

TEST(FixEtd, RestartContinuesExactlyWithOrder2State)
{
  const std::string restart = etdtest::work_file("etd.restart");
  std::vector<double> x_ref, v_ref;
  {
    Lammps l;
    fluid(l, "pair_coeff 1 1 18.75 4.5 0.5");
    l.cmds({"timestep 0.001", "fix 1 all etd order 2", "run 30 post no", "write_restart " + restart,
            "run 30 post no"});
    x_ref = l.gather("x");
    v_ref = l.gather("v");
  }
  {
    // without order-2 state the continuation must differ: the test can fail
    Lammps l;
    l.cmds({"plugin load " + std::string(ETD_PLUGIN_PATH), "read_restart " + restart,
            "comm_modify vel yes", "neigh_modify every 1 delay 0 check yes",
            "fix 1 all etd order 1", "run 30 post no"});
    EXPECT_GT(max_abs_diff(l.gather("v"), v_ref), 1e-8);
  }
  Lammps l;
  l.cmds({"read_restart " + restart, "comm_modify vel yes",
          "neigh_modify every 1 delay 0 check yes", "fix 1 all etd order 2", "run 30 post no"});
  EXPECT_LT(max_abs_diff(l.gather("x"), x_ref), 1e-12);
  EXPECT_LT(max_abs_diff(l.gather("v"), v_ref), 1e-10);
}

TEST(FixEtd, AtomsOutsideTheGroupDoNotMove)
{
  Lammps l;
  fluid(l, "pair_coeff 1 1 18.75 4.5 0.5");
  l.cmds({"region wall block INF INF INF INF 0 1", "group wall region wall",
          "group mobile subtract all wall", "velocity wall set 0.5 0 0", "timestep 0.001",
          "fix 1 mobile etd"});
  auto x0 = l.gather("x"), v0 = l.gather("v");
  l.cmd("run 10 post no");
  auto x1 = l.gather("x"), v1 = l.gather("v");
  int frozen = 0;
  for (size_t a = 0; a < x0.size() / 3; a++)
    if (x0[3 * a + 2] < 1.0) {
      frozen++;
      for (int k = 0; k < 3; k++) {
        EXPECT_EQ(x1[3 * a + k], x0[3 * a + k]);
        EXPECT_EQ(v1[3 * a + k], v0[3 * a + k]);
      }
    }
  EXPECT_GT(frozen, 50);
}

TEST(FixEtd, PerAtomMassesAreUsed)
{
  // the same fluid with per-type mass 0.01 and with per-atom masses 0.01 gives one trajectory
  std::vector<double> v_type, v_atom;
  {
    Lammps l;
    fluid(l, "pair_coeff 1 1 18.75 4.5 0.5");
    l.cmds({"timestep 0.001", "fix 1 all etd order 2", "run 10 post no"});
    v_type = l.gather("v");
  }
  Lammps l;
  fluid(l, "pair_coeff 1 1 18.75 4.5 0.5", 7.0);    // per-type mass 7 must be ignored
  l.cmds({"fix masses all property/atom rmass", "set group all mass 0.01", "timestep 0.001",
          "fix 1 all etd order 2", "run 10 post no"});
  EXPECT_LT(max_abs_diff(l.gather("v"), v_type), 1e-12);
}

TEST(FixEtd, MomentumConserveOptionRemovesTheDrift)
{
  auto total_momentum = [](Lammps &l) {
    auto v = l.gather("v");
    double p[3] = {0, 0, 0};
    for (size_t a = 0; a < v.size() / 3; a++)
      for (int k = 0; k < 3; k++) p[k] += 0.01 * v[3 * a + k];
    return std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
  };
  double drift[2];
  for (int conserve = 0; conserve < 2; conserve++) {
    Lammps l;
    fluid(l, "pair_coeff 1 1 18.75 4.5 0.5");
    l.cmds({"velocity all zero linear", "timestep 0.002",
            std::string("fix 1 all etd momentum ") + (conserve ? "conserve" : "none"),
            "run 500 post no"});
    drift[conserve] = total_momentum(l);
  }
  // thermal momentum scale of one atom: sqrt(m kT) = 0.1
  EXPECT_GT(drift[0], 0.01);
  EXPECT_LT(drift[1], 1e-10);
}

TEST(FixEtd, BadInputGivesClearErrors)
{
  etdtest::expect_errors(
      {
          {{"fix 1 all etd order 3"}, "order must be 1 or 2"},
          {{"fix 1 all etd noise gaussian"}, "noise must be piecewise or exact"},
          {{"fix 1 all etd momentum maybe"}, "momentum must be none or conserve"},
          {{"fix 1 all etd order"}, "keyword order needs a value"},
          {{"fix 1 all etd colour red"}, "unknown keyword colour"},
          {{"pair_style zero 1.0", "pair_coeff * *", "fix 1 all etd", "run 0"},
           "requires pair style dpd/gen"},
          {{"fix 1 all etd", "run_style respa 2 2", "run 0"}, "respa"},
      },
      [](Lammps &l) {
        fluid(l, "pair_coeff 1 1 18.75 4.5 0.5");
      });
}

TEST(FixEtd, HybridOverlayWithAnotherStyleMatchesThePlainStyle)
{
  // Inside pair hybrid/overlay fix etd must find dpd/gen's friction; a `zero` sub-style adds no
  // force, so the trajectory equals the plain dpd/gen one (same noise keys) to round-off. The
  // second sub-style's forces would enter as explicit forcing.
  std::vector<double> v_plain, v_hybrid;
  for (int hybrid = 0; hybrid < 2; hybrid++) {
    Lammps l;
    fluid(l, "pair_coeff 1 1 18.75 4.5 0.5");
    if (hybrid)
      l.cmds({"pair_style hybrid/overlay dpd/gen 1.0 1.0 555 zero 1.0",
              "pair_coeff 1 1 dpd/gen 18.75 4.5 0.5", "pair_coeff 1 1 zero"});
    l.cmds({"timestep 0.001", "fix 1 all etd order 2", "run 20 post no"});
    (hybrid ? v_hybrid : v_plain) = l.gather("v");
  }
  double scale = 0.0;
  for (double v : v_plain) scale = std::max(scale, std::fabs(v));
  EXPECT_GT(scale, 1.0);
  EXPECT_LT(max_abs_diff(v_plain, v_hybrid), 1e-10 * scale);
}

// Order 2 extrapolates from the previous step's forcing A_(n-1), which belongs to the velocities
// of that step. After velocity set between runs the history is dropped: the first step equals
// that of a fix defined afresh (no history); without a velocity change the run continues with
// it (the same as one run; test_combinations). Atoms created between runs start without one.
TEST(FixEtd, OrderTwoDropsItsHistoryWhenVelocitiesChangeBetweenRuns)
{
  std::vector<std::vector<double>> results;
  for (const bool fresh : {false, true}) {
    Lammps l;
    fluid(l, "pair_coeff 1 1 18.75 4.5 0.5");
    l.cmds({"timestep 0.001", "fix 1 all etd order 2", "run 20 post no", "velocity all scale 0.5"});
    if (fresh) l.cmds({"unfix 1", "fix 1 all etd order 2"});
    l.cmd("run 1 post no");
    results.push_back(l.gather("v"));
  }
  EXPECT_LT(max_abs_diff(results[0], results[1]), 1e-12);
  // and the history did matter: kept (no velocity change), the step differs from a fresh fix's
  std::vector<std::vector<double>> continued;
  for (const bool fresh : {false, true}) {
    Lammps l;
    fluid(l, "pair_coeff 1 1 18.75 4.5 0.5");
    l.cmds({"timestep 0.001", "fix 1 all etd order 2", "run 20 post no"});
    if (fresh) l.cmds({"unfix 1", "fix 1 all etd order 2"});
    l.cmd("run 1 post no");
    continued.push_back(l.gather("v"));
  }
  EXPECT_GT(max_abs_diff(continued[0], continued[1]), 1e-6);
  // created atoms: no garbage history (a new atom's first step is finite)
  Lammps created;
  fluid(created, "pair_coeff 1 1 18.75 4.5 0.5");
  created.cmds({"timestep 0.001", "fix 1 all etd order 2", "run 20 post no",
                "create_atoms 1 random 20 5 NULL", "run 5 post no"});
  for (double v : created.gather("v")) ASSERT_TRUE(std::isfinite(v));
}
