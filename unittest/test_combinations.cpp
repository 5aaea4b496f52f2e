// fix etd with the LAMMPS commands users combine it with (doc/fix_etd.rst, "Combinations"):
// each scheme (diagonal; implicit; implicit overdamped; implicit with dpd/fpm) either gives the
// trajectory it gives without the command, keeps kBT and momentum, or stops with an ERROR that
// names the combination. Runs on 1, 2 and 4 ranks (rank-count agreement itself: test_ranks).
#include "lammps_fixture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using etdtest::Lammps;

namespace {

struct Scheme {
  std::string name, fix;
  bool sphere;    // dpd/fpm: atom_style sphere, angular velocities
};

bool diagonal(const Scheme &s)
{
  return s.fix.find("implicit") == std::string::npos;
}

const std::vector<Scheme> SCHEMES = {
    {"diagonal", "etd", false},
    {"diagonal order 2", "etd order 2", false},
    {"implicit", "etd scheme implicit tol 1e-10", false},
    {"overdamped", "etd scheme implicit overdamped yes tol 1e-10", false},
    {"fpm implicit", "etd scheme implicit tol 1e-10", true},
};

const std::string DATA = etdtest::work_file("combinations.data");
const std::string SPHERE_DATA = etdtest::work_file("combinations_sphere.data");

// 648 atoms in a box of 6 (n = 3), two types, m = 0.01 (dpd/fpm: diameter 1), timestep 0.001
// (0.0002 for the diagonal scheme, 0.0005 overdamped): every scheme's own regime
std::vector<std::string> system(const Scheme &s, const std::string &before_read = "")
{
  std::vector<std::string> c = {"units lj", "atom_modify map array", "comm_modify vel yes",
                                "neigh_modify every 1 delay 0 check yes"};
  if (s.sphere) c.insert(c.begin() + 1, "atom_style sphere");
  if (!before_read.empty()) c.push_back(before_read);
  c.push_back("read_data " + (s.sphere ? SPHERE_DATA : DATA));
  if (s.sphere) {
    c.insert(c.end(),
             {"set group all mass 0.01", "pair_style dpd/fpm 1.0 1.0 77",
              "pair_coeff * * 25 4.5 4.5 0.5"});
  } else {
    c.insert(c.end(),
             {"mass * 0.01", "pair_style dpd/gen 1.0 1.0 77", "pair_coeff * * 25 4.5 0.5"});
  }
  const double dt = diagonal(s) ? 0.0002 : (s.name == "overdamped" ? 0.0005 : 0.001);
  c.push_back("timestep " + std::to_string(dt));
  return c;
}

double etdtest_natoms = 0.0;    // atoms of the last state() taken

std::vector<double> state(Lammps &l, bool sphere)
{
  etdtest_natoms = static_cast<double>(l.natoms());
  auto x = l.gather("x");
  auto v = l.gather("v");
  x.insert(x.end(), v.begin(), v.end());
  if (sphere) {
    auto w = l.gather("omega");
    x.insert(x.end(), w.begin(), w.end());
  }
  return x;
}

// Largest difference relative to the largest magnitude of the reference, positions (the first
// 3N values, N = atoms) by their nearest periodic image: runs that rebuild their neighbor lists
// at other steps wrap atoms into the box at other steps.
double relative_difference(const std::vector<double> &a, const std::vector<double> &b,
                           double box = 6.0)
{
  if (a.size() != b.size()) return 1e300;
  const size_t positions = 3 * (static_cast<size_t>(std::lround(etdtest_natoms)));
  double scale = 0.0, worst = 0.0;
  for (double v : b) scale = std::max(scale, std::fabs(v));
  for (size_t i = 0; i < a.size(); i++) {
    double d = a[i] - b[i];
    if (i < positions) d -= box * std::round(d / box);
    worst = std::max(worst, std::fabs(d));
  }
  return worst / scale;
}

// The same 20 steps with and without the given commands; 'middle' runs between two halves
std::vector<double> twenty_steps(const Scheme &s, const std::vector<std::string> &before,
                                 const std::vector<std::string> &middle,
                                 const std::string &before_read = "")
{
  Lammps l;
  l.cmds(system(s, before_read));
  l.cmds(before);
  l.cmds({"fix 1 all " + s.fix, "run 10 post no"});
  l.cmds(middle);
  l.cmd("run 10 post no");
  return state(l, s.sphere);
}

// Summation orders differ (neighbor order, decomposition); the implicit schemes agree to their
// solver tolerance (1e-10 here; the zero-mass scheme's nearly singular G amplifies it to about
// 1e-5 of its velocities), the diagonal one to round-off.
double agree(const Scheme &s)
{
  return s.name == "overdamped" ? 1e-4 : 1e-7;
}

class Combinations : public ::testing::Test {
 protected:
  void SetUp() override
  {
    etdtest::write_random_data(DATA, 648, 6.0, 2357, 2, 1.0);
    etdtest::write_random_sphere_data(SPHERE_DATA, 648, 6.0, 2357, 2, 1.0, 2.0, 1.0);
  }
};

}    // namespace

TEST_F(Combinations, BalanceAndFixBalanceMidRunKeepTheTrajectory)
{
  for (const Scheme &s : SCHEMES) {
    const auto plain = twenty_steps(s, {}, {});
    const auto balanced = twenty_steps(s, {}, {"balance 1.0 shift xy 5 1.05"});
    const auto fix_balanced = twenty_steps(s, {"fix lb all balance 3 1.0 shift xyz 5 1.05"}, {});
    EXPECT_LT(relative_difference(balanced, plain), agree(s)) << s.name << ": balance";
    EXPECT_LT(relative_difference(fix_balanced, plain), agree(s)) << s.name << ": fix balance";
  }
}

TEST_F(Combinations, ProcessorGridsGiveTheSameTrajectory)
{
  const int ranks = etdtest::world_size();
  if (ranks == 1) GTEST_SKIP() << "one rank has one grid";
  for (const Scheme &s : SCHEMES) {
    const auto along_x = twenty_steps(s, {}, {}, "processors " + std::to_string(ranks) + " 1 1");
    const auto along_z = twenty_steps(s, {}, {}, "processors 1 1 " + std::to_string(ranks));
    EXPECT_LT(relative_difference(along_z, along_x), agree(s)) << s.name;
  }
}

TEST_F(Combinations, AtomSortingKeepsTheTrajectory)
{
  for (const Scheme &s : SCHEMES) {
    const auto unsorted = twenty_steps(s, {}, {}, "atom_modify sort 0 0.0");
    const auto sorted = twenty_steps(s, {}, {}, "atom_modify sort 1 0.7");
    EXPECT_LT(relative_difference(sorted, unsorted), agree(s)) << s.name;
  }
}

// run N start/stop and run every split a run without changing it (the diagonal scheme's
// order-2 history and the implicit scheme's partners survive the set-up between the pieces)
TEST_F(Combinations, RunStartStopAndRunEveryContinueTheRun)
{
  for (const Scheme &s : SCHEMES) {
    std::vector<std::vector<double>> results;
    for (const std::vector<std::string> &runs :
         {std::vector<std::string>{"run 20 post no"},
          {"run 10 start 0 stop 20 post no", "run 10 start 0 stop 20 post no"},
          {"variable k equal 1", "run 20 post no every 5 \"variable k equal 2\""}}) {
      Lammps l;
      l.cmds(system(s));
      l.cmd("fix 1 all " + s.fix);
      l.cmds(runs);
      results.push_back(state(l, s.sphere));
    }
    EXPECT_LT(relative_difference(results[1], results[0]), agree(s)) << s.name << ": start/stop";
    EXPECT_LT(relative_difference(results[2], results[0]), agree(s)) << s.name << ": every";
  }
}

TEST_F(Combinations, RestartContinuesTheRun)
{
  for (const Scheme &s : SCHEMES) {
    const std::string restart = etdtest::work_file("combinations.restart");
    const auto whole = twenty_steps(s, {}, {});
    {
      Lammps first;
      first.cmds(system(s));
      first.cmds({"fix 1 all " + s.fix, "run 10 post no", "write_restart " + restart});
    }
    Lammps second;
    second.cmds({"plugin load " + std::string(ETD_PLUGIN_PATH), "read_restart " + restart,
                 "comm_modify vel yes", "neigh_modify every 1 delay 0 check yes",
                 s.sphere ? "pair_coeff * * 25 4.5 4.5 0.5" : "pair_coeff * * 25 4.5 0.5",
                 "fix 1 all " + s.fix, "run 10 post no"});
    EXPECT_LT(relative_difference(state(second, s.sphere), whole), agree(s)) << s.name;
  }
}

// larger ghost shells and excluded type pairs: an excluded pair has neither force nor friction,
// as one whose coefficients are zero
TEST_F(Combinations, CommCutoffAndNeighborExclusionsKeepTheTrajectory)
{
  for (const Scheme &s : SCHEMES) {
    const auto plain = twenty_steps(s, {}, {});
    const auto wide = twenty_steps(s, {"comm_modify cutoff 3.5"}, {});
    EXPECT_LT(relative_difference(wide, plain), agree(s)) << s.name << ": comm_modify cutoff";
    // (without the 1-2 pairs the zero-mass friction system of this sparse fluid is singular)
    if (s.name == "overdamped") continue;
    const std::string zero_pair = s.sphere ? "pair_coeff 1 2 0 0 0 0.5" : "pair_coeff 1 2 0 0 0.5";
    const auto excluded = twenty_steps(s, {"neigh_modify exclude type 1 2"}, {});
    const auto zeroed = twenty_steps(s, {zero_pair}, {});
    EXPECT_LT(relative_difference(excluded, zeroed), agree(s))
        << s.name << ": neigh_modify exclude";
  }
}

// velocity set / create between runs, and atoms deleted and created between runs: the fix
// carries on (no stale per-atom state), momentum stays conserved by the implicit schemes and
// the temperature returns to the thermostat's
TEST_F(Combinations, VelocityChangesAndAtomsCreatedOrDeletedBetweenRuns)
{
  for (const Scheme &s : SCHEMES) {
    Lammps l;
    l.cmds(system(s));
    l.cmds({"velocity all create 1.0 4 mom yes dist gaussian", "fix 1 all " + s.fix,
            "run 50 post no", "velocity all set 0.0 0.0 0.0", "run 50 post no",
            "group gone id 1:648:10", "delete_atoms group gone", "create_atoms 1 random 40 19 NULL",
            s.sphere ? "set type 1 mass 0.01" : "mass * 0.01", "velocity all zero linear",
            "compute mobile all temp", "fix average all ave/time 1 1 1 c_mobile ave running",
            "run 300 post no"});
    const double kt = l.fix_scalar("average");
    const auto v = l.gather("v");
    double p[3] = {0.0, 0.0, 0.0};
    for (size_t a = 0; a < v.size() / 3; a++)
      for (int k = 0; k < 3; k++) p[k] += 0.01 * v[3 * a + k];    // (every atom's mass)
    std::printf(
        "%s after velocity set, delete and create: kBT %.4f (running mean), momentum %.1e\n",
        s.name.c_str(), kt, std::fabs(p[0]) + std::fabs(p[1]) + std::fabs(p[2]));
    EXPECT_TRUE(std::isfinite(kt)) << s.name;
    if (!diagonal(s))    // exact momentum: the implicit schemes
      for (double pk : p) EXPECT_LT(std::fabs(pk), 1e-11) << s.name;
    if (s.name != "overdamped") EXPECT_NEAR(kt, 1.0, 0.15) << s.name;    // reheated from 0
  }
}

// fix etd on part of the atoms and another integrator on the rest: the diagonal scheme takes
// its forces from the pair style, which stays complete, so both parts keep kBT; the implicit
// scheme would leave the others without friction and noise, and refuses.
TEST_F(Combinations, SubgroupWithAnotherIntegratorOnTheRest)
{
  for (const Scheme &s : SCHEMES) {
    Lammps l;
    l.cmds(system(s));
    l.cmds({"group etd type 1", "group rest type 2",
            "velocity all create 1.0 4 mom yes dist gaussian", "fix 1 etd " + s.fix,
            s.sphere ? "fix 2 rest nve/sphere" : "fix 2 rest nve"});
    if (!diagonal(s)) {
      const std::string message = l.error_of("run 1 post no");
      EXPECT_NE(message.find("cannot be combined with fix 2"), std::string::npos)
          << s.name << ": " << message;
      continue;
    }
    l.cmds({"compute t1 etd temp", "compute t2 rest temp",
            "fix average all ave/time 1 1 1 c_t1 c_t2 ave running", "run 1500 post no"});
    std::printf("diagonal on type 1, nve on type 2: kBT %.4f / %.4f\n", l.fix_vector("average", 0),
                l.fix_vector("average", 1));
    EXPECT_NEAR(l.fix_vector("average", 0), 1.0, 0.1);
    EXPECT_NEAR(l.fix_vector("average", 1), 1.0, 0.1);
  }
}

// A colloid held together by fix rigid/small in a fix etd solvent: the same rule
TEST_F(Combinations, RigidColloidInEtdSolvent)
{
  for (const Scheme &s : SCHEMES) {
    if (s.sphere) continue;    // (the same check as dpd/gen)
    Lammps l;
    l.cmds(system(s));
    l.cmds({"region ball sphere 3 3 3 1.0", "group colloid region ball",
            "group solvent subtract all colloid", "velocity all create 1.0 4 mom yes dist gaussian",
            "fix 1 solvent " + s.fix, "variable body atom 1",
            "fix 2 colloid rigid/small custom v_body"});
    if (!diagonal(s)) {
      const std::string message = l.error_of("run 1 post no");
      EXPECT_NE(message.find("cannot be combined with fix 2 (rigid/small)"), std::string::npos)
          << s.name << ": " << message;
      continue;
    }
    l.cmds({"compute t1 solvent temp", "fix average all ave/time 1 1 1 c_t1 ave running",
            "run 1000 post no"});
    EXPECT_NEAR(l.fix_scalar("average"), 1.0, 0.1);
  }
}

// Green-Kubo stress: fix ave/correlate of the pressure tensor every step. The implicit schemes'
// friction and noise are in the fix's virial (without it the stress holds only the
// conservative and kinetic parts): its share has a nonzero spread; the diagonal scheme's forces
// are the pair style's, and the fix adds no virial.
TEST_F(Combinations, GreenKuboStressIncludesTheFrictionAndNoise)
{
  for (const Scheme &s : SCHEMES) {
    Lammps l;
    l.cmds(system(s));
    l.cmds({"velocity all create 1.0 4 mom yes dist gaussian", "fix 1 all " + s.fix,
            "compute p all pressure thermo_temp", "compute pfix all pressure NULL fix",
            "run 0 post no"});
    // before any friction step the fix has no virial (it once read uninitialised memory here)
    for (int k = 0; k < 6; k++)
      EXPECT_EQ(l.compute_vector("pfix", k), 0.0) << s.name << " at set-up";
    l.cmds({"variable pxy equal c_p[4]", "variable fxy equal c_pfix[4]",
            "fix gk all ave/correlate 1 20 20 v_pxy type auto ave running",
            "variable fxy2 equal v_fxy^2", "fix spread all ave/time 1 1 1 v_fxy2 ave running",
            "run 100 post no"});
    const double fix_share = l.fix_scalar("spread");
    l.cmds({"variable acf0 equal f_gk[1][3]", "fix acf all ave/time 20 1 20 v_acf0",
            "run 20 post no"});
    const double acf0 = l.fix_scalar("acf");    // <Pxy(0)^2>
    EXPECT_TRUE(std::isfinite(acf0) && acf0 > 0.0) << s.name << ": " << acf0;
    if (diagonal(s))
      EXPECT_EQ(fix_share, 0.0) << s.name;
    else
      EXPECT_GT(fix_share, 0.0) << s.name;
  }
}

// compute stress/atom with the implicit schemes: the fix's per-atom virial adds up to its global
// virial (pairs that cross ranks are split between the ranks' atoms), on any number of ranks:
// sum_i S_i = -P V for the fix's share (compute pressure ... fix, stress/atom ... fix)
TEST_F(Combinations, StressPerAtomAddsUpToTheFixVirial)
{
  for (const Scheme &s : SCHEMES) {
    if (diagonal(s)) continue;    // (no fix virial: the pair style's forces)
    Lammps l;
    l.cmds(system(s));
    l.cmds(
        {"velocity all create 1.0 4 mom yes dist gaussian", "fix 1 all " + s.fix,
         "compute pfix all pressure NULL fix", "compute sfix all stress/atom NULL fix",
         "compute ssum all reduce sum c_sfix[1] c_sfix[2] c_sfix[3] c_sfix[4] c_sfix[5] c_sfix[6]",
         "variable check equal c_pfix[4]+c_ssum[4]/vol",
         "thermo_style custom step c_pfix[1] c_pfix[4] c_ssum[1] c_ssum[4]", "thermo 5",
         "run 5 post no"});
    for (int k = 0; k < 6; k++) {
      const double global = l.compute_vector("pfix", k),
                   summed = -l.compute_vector("ssum", k) / 216.0;
      EXPECT_NEAR(summed, global, 1e-9 * (1.0 + std::fabs(global))) << s.name << " component " << k;
      if (k == 0) EXPECT_NE(global, 0.0) << s.name;
    }
  }
}
