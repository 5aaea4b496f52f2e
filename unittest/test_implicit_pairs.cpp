// fix etd scheme implicit's own pair search against LAMMPS's neighbor lists (neighbors own /
// lammps): the same trajectories over 10 steps, the pair style reading the scheme's pairs during a run and
// building its own list outside one, and the set-ups the own search refuses. On 1 and 2 ranks.
#include "lammps.h"
#include "lammps_fixture.h"
#include "neigh_list.h"
#include "neighbor.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using etdtest::Lammps;

namespace {

const std::string DATA = etdtest::work_file("etd_implicit_pairs.data");

// 500 atoms of the n = 4, s = 1/2 fluid at m = 0.01 and dt = 0.005, the largest step the
// accuracy matrix gives the implicit scheme on it: the fastest atoms move about 0.1 in half a
// step, so the search's margin and its second search at the friction step are both exercised
void fluid(Lammps &l, const std::string &fix_options, bool triclinic = false)
{
  etdtest::write_random_data(DATA, 500, 5.0, 2468, 1, 1.0);
  l.cmds({"units lj", "atom_modify map array", "comm_modify vel yes", "neighbor 0.4 bin",
          "neigh_modify every 1 delay 0 check yes", "read_data " + DATA, "mass 1 0.01",
          "pair_style dpd/gen 1.0 1.0 555", "pair_coeff 1 1 18.75 4.5 0.5", "timestep 0.005"});
  if (triclinic)
    l.cmds({"change_box all triclinic", "fix shear all deform 1 xy erate 2.0 remap v"});
  l.cmd("fix 1 all etd scheme implicit " + fix_options);
}

double max_abs_diff(const std::vector<double> &a, const std::vector<double> &b)
{
  double worst = 0.0;
  for (size_t i = 0; i < a.size(); i++) worst = std::max(worst, std::fabs(a[i] - b[i]));
  return worst;
}

// positions compared under the minimum image of the 5^3 box (an atom may cross a boundary in
// one run and not the other; a sheared box's tilt stays below 1 in these runs)
double max_position_diff(const std::vector<double> &a, const std::vector<double> &b)
{
  double worst = 0.0;
  for (size_t i = 0; i < a.size(); i++) {
    const double d = a[i] - b[i];
    worst = std::max(worst, std::fabs(d - 5.0 * std::round(d / 5.0)));
  }
  return worst;
}

// whether LAMMPS builds a pairwise list at each reneighboring (any perpetual list)
bool lammps_builds_lists(Lammps &l)
{
  auto *neighbor = l.lmp->neighbor;
  for (int n = 0; n < neighbor->nlist; n++)
    if (!neighbor->lists[n]->occasional) return true;
  return false;
}

struct RunResult {
  std::vector<double> x, v;
  double press;
  bool perpetual_lists;
};

RunResult run_with(const std::string &fix_options, bool triclinic, int steps)
{
  Lammps l;
  fluid(l, fix_options, triclinic);
  l.cmd("run " + std::to_string(steps));
  return {l.gather("x"), l.gather("v"), l.thermo("press"), lammps_builds_lists(l)};
}

void expect_same_trajectory(const std::string &options, bool triclinic)
{
  // The two differ in the order pairs are summed. Conjugate gradients at tol 1e-12 keep that
  // difference at round-off (at the default 1e-6 a solve may stop an iteration earlier in one
  // of them), which this fluid at this step amplifies about tenfold per step (measured: 1e-14
  // in the pressure at step 5, 1e-10 at step 15, 1e-3 at step 50); a missing or extra pair
  // shows at once, well above 1e-8
  const std::string solve = options + " tol 1e-12 maxiter 1000";
  const RunResult own = run_with(solve + " neighbors own", triclinic, 10);
  const RunResult lists = run_with(solve + " neighbors lammps", triclinic, 10);
  EXPECT_FALSE(own.perpetual_lists);
  EXPECT_TRUE(lists.perpetual_lists);
  EXPECT_LT(max_position_diff(own.x, lists.x), 1e-8) << options;
  EXPECT_LT(max_abs_diff(own.v, lists.v), 1e-8) << options;
  EXPECT_NEAR(own.press, lists.press, 1e-8 * std::fabs(lists.press)) << options;
}

}    // namespace

TEST(ImplicitPairs, OwnSearchFollowsLammpsLists)
{
  expect_same_trajectory("", false);
}

TEST(ImplicitPairs, OwnSearchFollowsLammpsListsOverdamped)
{
  expect_same_trajectory("overdamped yes", false);
}

// moving periodic images under fix deform ... remap v: their velocity offsets come with the
// ghosts the own search lists
TEST(ImplicitPairs, OwnSearchFollowsLammpsListsInAShearedBox)
{
  expect_same_trajectory("", true);
}

// the default is the own search where the set-up allows it
TEST(ImplicitPairs, OwnSearchIsTheDefault)
{
  const RunResult automatic = run_with("", false, 20);
  const RunResult own = run_with("neighbors own", false, 20);
  EXPECT_FALSE(automatic.perpetual_lists);
  EXPECT_EQ(automatic.x, own.x);
}

// Outside a run (here a minimization, which moves the atoms) the scheme has no pairs for the
// step, and the pair style builds its own list: the energy is the one LAMMPS's lists give.
TEST(ImplicitPairs, PairStyleFindsItsPairsOutsideRuns)
{
  double energy[2];
  const std::string modes[2] = {"neighbors own", "neighbors lammps"};
  for (int m = 0; m < 2; m++) {
    Lammps l;
    fluid(l, modes[m]);
    l.cmds({"thermo_style custom step pe press", "run 20", "minimize 0 0 20 200"});
    energy[m] = l.thermo("pe");
  }
  EXPECT_NEAR(energy[0], energy[1], 1e-9 * std::fabs(energy[1]));
}

TEST(ImplicitPairs, NeighborsOwnRefusesWhatItCannotServe)
{
  etdtest::expect_errors(
      {
          {{"fix 1 all etd scheme implicit neighbors mine"}, "neighbors must be own or lammps"},
          {{"pair_style hybrid/overlay dpd/gen 1.0 1.0 555 soft 1.0",
            "pair_coeff 1 1 dpd/gen 18.75 4.5 0.5", "pair_coeff 1 1 soft 1.0",
            "fix 1 all etd scheme implicit neighbors own", "run 0"},
           "neighbors own is not supported with pair style hybrid"},
          {{"neigh_modify exclude type 1 1", "fix 1 all etd scheme implicit neighbors own",
            "run 0"},
           "neighbors own is not supported with neigh_modify exclude"},
      },
      [](Lammps &l) {
        etdtest::write_random_data(DATA, 500, 5.0, 2468, 1, 1.0);
        l.cmds({"units lj", "atom_modify map array", "comm_modify vel yes", "read_data " + DATA,
                "mass 1 0.01", "pair_style dpd/gen 1.0 1.0 555", "pair_coeff 1 1 18.75 4.5 0.5",
                "timestep 0.005"});
      });
}
