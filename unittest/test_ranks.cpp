// Rank-count independence: one program under mpirun -np 4 runs the same system on 1, 2 and 4
// ranks (sub-communicators) and with newton on and off, and compares per-atom results by ID.
#include "lammps.h"
#include "lammps_fixture.h"
#include "neigh_list.h"
#include "neighbor.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

using etdtest::Lammps;

namespace {

const std::string DATA = etdtest::work_file("ranks_config.data");

double max_abs_diff(const std::vector<double> &a, const std::vector<double> &b)
{
  double worst = 0.0;
  for (size_t i = 0; i < a.size(); i++) worst = std::max(worst, std::fabs(a[i] - b[i]));
  return worst;
}

std::vector<std::string> fluid(const std::string &newton, const std::string &data = DATA)
{
  return {"units lj",
          "atom_modify map array",
          "newton " + newton,
          "comm_modify vel yes",
          "neigh_modify every 1 delay 0 check yes",
          "read_data " + data,
          "mass 1 0.01",
          "mass 2 1.0",
          "timestep 0.001",
          "pair_style dpd/gen 1.0 1.0 2718",
          "pair_coeff 1 1 18.75 4.5 0.5",
          "pair_coeff 2 2 25 4.5 2.0",
          "pair_coeff 1 2 1750 20.48 0.25 1.0 cut_d 1.5 exp_c 0.5"};
}

// all velocities, then all positions, by atom ID
std::vector<double> velocities_and_positions(Lammps &l)
{
  auto v = l.gather("v");
  auto x = l.gather("x");
  v.insert(v.end(), x.begin(), x.end());
  return v;
}

// results[first + 1 ... first + count - 1] agree with results[first] to 'relative' of its
// largest magnitude
void expect_agreement(const std::vector<std::vector<double>> &results, int first, int count,
                      double relative, const std::string &what)
{
  double scale = 0.0;
  for (double v : results[first]) scale = std::max(scale, std::fabs(v));
  for (int k = 1; k < count; k++) {
    const double diff = max_abs_diff(results[first + k], results[first]);
    EXPECT_LT(diff, relative * scale) << what << " variant " << k << " diff " << diff;
  }
}

// Atoms whose half of the box (the 2 x 2 x 1 decomposition of 4 ranks splits x and y at
// the middle of the 7.2 box) changed between two snapshots, counting periodic wrap-arounds.
double crossings(const std::vector<double> &before, const std::vector<double> &after)
{
  auto half = [](double c) {
    return static_cast<int>(std::floor(c / 3.6)) & 1;
  };
  double count = 0.0;
  for (size_t a = 0; a < before.size() / 3; a++)
    if (half(before[3 * a]) != half(after[3 * a]) ||
        half(before[3 * a + 1]) != half(after[3 * a + 1]))
      count += 1.0;
  return count;
}

}    // namespace

class Ranks : public ::testing::Test {
 protected:
  void SetUp() override
  {
    if (etdtest::world_size() < 4) GTEST_SKIP() << "needs mpirun -np 4";
    etdtest::write_random_data(DATA, 1500, 7.2, 99, 2, 1.0);
  }
};

TEST_F(Ranks, ForcesAgreeAcrossRankCountsAndNewton)
{
  std::vector<std::vector<double>> results;
  for (const std::string newton : {"on", "off"})
    for (int ranks : {1, 2, 4})
      results.push_back(etdtest::on_ranks(ranks, [&](Lammps &l) {
        l.cmds(fluid(newton));
        l.cmds({"compute split all dpd/split", "run 0 post no"});
        auto f = l.gather("f");
        auto split = l.gather_compute("split", 9);
        f.insert(f.end(), split.begin(), split.end());
        return f;
      }));
  if (etdtest::world_rank() != 0) return;
  double scale = 0.0;
  for (double v : results[0]) scale = std::max(scale, std::fabs(v));
  for (size_t k = 1; k < results.size(); k++)
    EXPECT_LT(max_abs_diff(results[k], results[0]), 1e-10 * scale) << "variant " << k;
}

TEST_F(Ranks, EtdTrajectoryAgreesAcrossRankCounts)
{
  std::vector<std::vector<double>> results;
  for (const std::string order : {"1", "2"})
    for (int ranks : {1, 2, 4})
      results.push_back(etdtest::on_ranks(ranks, [&](Lammps &l) {
        l.cmds(fluid("on"));
        // re-neighbor (and so migrate) every step: an atom that crosses a sub-domain boundary
        // changes rank at the next step and must carry its order-2 state with it
        l.cmds({"neigh_modify every 1 delay 0 check no", "fix 1 all etd order " + order});
        const auto x0 = l.gather("x");
        l.cmd("run 20 post no");
        auto x = l.gather("x");
        auto v = l.gather("v");
        x.insert(x.end(), v.begin(), v.end());
        x.push_back(crossings(x0, x));
        return x;
      }));
  if (etdtest::world_rank() != 0) return;
  EXPECT_GT(results.front().back(), 10.0) << "too few atoms changed sub-domain to test migration";
  // summation order differs between decompositions; round-off grows over the 20 steps of this
  // stiff fluid (velocities up to about 40), so compare relative to the largest value
  for (int o = 0; o < 2; o++) {
    double scale = 0.0;
    for (double v : results[3 * o]) scale = std::max(scale, std::fabs(v));
    for (int k = 1; k < 3; k++) {
      const double diff = max_abs_diff(results[3 * o + k], results[3 * o]);
      EXPECT_LT(diff, 1e-10 * scale) << "order " << o + 1 << " variant " << k << " diff " << diff;
    }
  }
}

// The implicit scheme solves a global linear system: different decompositions sum the CG dot
// products in different orders, so trajectories agree to the solver tolerance (tol 1e-10
// here), not to round-off. Newton off is included. Inertial and overdamped.
TEST_F(Ranks, ImplicitTrajectoryAgreesAcrossRankCountsToSolverTolerance)
{
  std::vector<std::vector<double>> results;
  for (const std::string variant : {"", " overdamped yes"})
    for (const std::string newton : {"on", "off"})
      for (int ranks : {1, 2, 4})
        results.push_back(etdtest::on_ranks(ranks, [&](Lammps &l) {
          l.cmds(fluid(newton));
          l.cmds({"fix 1 all etd scheme implicit tol 1e-10" + variant, "run 5 post no"});
          return velocities_and_positions(l);
        }));
  if (etdtest::world_rank() != 0) return;
  expect_agreement(results, 0, 6, 1e-7, "inertial");
  expect_agreement(results, 6, 6, 1e-7, "overdamped");
}

// The scheme needs a newton-off list on several ranks. With newton on, the pair style makes
// its own list newton off for the run, and the fix gets a copy of it: one list built per
// reneighboring, not two (the second doubled a 2-rank step's neighbor time). The pair style's
// forces then stay on owned atoms and its virial is summed pair by pair (LAMMPS's f dot r sum
// needs the ghost forces): the pressure, the energy and the trajectory must not notice.
TEST_F(Ranks, ImplicitBuildsOneNeighborListAndKeepsThePressure)
{
  std::vector<std::vector<double>> results;
  for (const std::string newton : {"on", "off"})
    for (int ranks : {1, 2, 4})
      results.push_back(etdtest::on_ranks(ranks, [&](Lammps &l) {
        l.cmds(fluid(newton));
        l.cmds({"fix 1 all etd scheme implicit tol 1e-10",
                "compute pair_press all pressure NULL pair",
                "thermo_style custom step press c_pair_press pe", "run 3 post no"});
        int built = 0;
        const LAMMPS_NS::Neighbor *neighbor = l.lmp->neighbor;
        for (int i = 0; i < neighbor->nlist; i++)
          if (!neighbor->lists[i]->copy) built++;
        auto values = velocities_and_positions(l);
        values.insert(values.begin(), {l.thermo("press"), l.thermo("c_pair_press"),
                                       l.thermo("pe"), static_cast<double>(built)});
        return values;
      }));
  if (etdtest::world_rank() != 0) return;
  for (size_t k = 0; k < results.size(); k++) {
    EXPECT_EQ(results[k][3], 1.0) << "neighbor lists built, variant " << k;
    for (int q = 0; q < 3; q++)
      EXPECT_NEAR(results[k][q], results[0][q], 1e-7 * std::fabs(results[0][q]))
          << "quantity " << q << " (press, pair pressure, pe), variant " << k;
  }
  expect_agreement(results, 0, 6, 1e-7, "trajectory");
}

// Slabs thinner than twice the neighbor cutoff (1.5 + skin 0.3 for the colloid-solvent pairs):
// on 2 ranks in x (slabs 3 wide in a box of 6) an atom of the other rank can be a partner
// through both of its periodic images; on 4 ranks (slabs 1.5) ghosts come from ranks two
// away. The fix asks each owner once per atom (partner_exchange.h); the trajectory must not
// notice.
TEST_F(Ranks, ImplicitTrajectoryAgreesWithSlabsThinnerThanTwoCutoffs)
{
  const std::string thin = etdtest::work_file("ranks_thin.data");
  etdtest::write_random_data(thin, 864, 6.0, 7, 2, 1.0);
  std::vector<std::vector<double>> results;
  for (int ranks : {1, 2, 4})
    results.push_back(etdtest::on_ranks(ranks, [&](Lammps &l) {
      l.cmds({"processors " + std::to_string(ranks) + " 1 1"});
      l.cmds(fluid("on", thin));
      l.cmds({"fix 1 all etd scheme implicit tol 1e-10", "run 5 post no"});
      return velocities_and_positions(l);
    }));
  if (etdtest::world_rank() != 0) return;
  expect_agreement(results, 0, 3, 1e-7, "thin slabs");
}

// Steady shear through fix deform ... remap v in a triclinic box: the images across the sheared
// boundary move with their owners' velocities plus the box's rate, whether the owner is on this
// rank or another (the fix's partner exchange). Inertial and overdamped, 1, 2 and 4 ranks.
TEST_F(Ranks, ImplicitTrajectoryUnderShearAgreesAcrossRankCounts)
{
  std::vector<std::vector<double>> results;
  for (const std::string variant : {"", " overdamped yes"})
    for (int ranks : {1, 2, 4})
      results.push_back(etdtest::on_ranks(ranks, [&](Lammps &l) {
        l.cmds(fluid("on"));
        l.cmds({"change_box all triclinic", "fix 1 all etd scheme implicit tol 1e-10" + variant,
                "fix 2 all deform 1 xy erate 2.0 xz erate 1.0 yz erate -1.0 remap v",
                "run 10 post no"});
        return velocities_and_positions(l);
      }));
  if (etdtest::world_rank() != 0) return;
  expect_agreement(results, 0, 3, 1e-7, "inertial under shear");
  expect_agreement(results, 3, 3, 1e-7, "overdamped under shear");
}
