// compute dpd/tcurrent: analytic values for a sinusoidal velocity field, the direct sum over a
// random configuration, rank-count independence, use with fix ave/correlate, bad input.
#include "lammps_fixture.h"

#include "fix.h"
#include "input.h"
#include "lammps.h"
#include "modify.h"
#include "transverse_current.h"
#include "variable.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

using etdtest::Lammps;

namespace {

const double two_pi = 6.283185307179586;
const int K = 4;
const std::string DATA = etdtest::work_file("tcurrent_config.data");

bool contains(const std::string &text, const std::string &part)
{
  return text.find(part) != std::string::npos;
}

std::vector<double> current(Lammps &l, int nwave = K)
{
  std::vector<double> out(12 * nwave);
  for (int i = 0; i < 12 * nwave; i++) out[i] = l.compute_vector("J", i);
  return out;
}

// 12^3 simple-cubic lattice (spacing 0.5) in a box of side 6 starting at `lo`, with
// v_y = U cos(k_1 (x - lo)) and v_z = W sin(k_2 (x - lo)), k_j = 2 pi j / 6
void sinusoidal_field(Lammps &l, double lo)
{
  const std::string hi = std::to_string(lo + 6.0), los = std::to_string(lo);
  l.cmds({"units lj", "atom_modify map array", "lattice sc 8.0",    // spacing 0.5
          "region box block " + los + " " + hi + " " + los + " " + hi + " " + los + " " + hi +
              " units box",
          "create_box 1 box", "create_atoms 1 box", "mass 1 1.0",
          "variable vy atom 0.7*cos(2*PI*(x-" + los + ")/6)",
          "variable vz atom -0.3*sin(2*PI*2*(x-" + los + ")/6)", "velocity all set 0 v_vy v_vz",
          "compute J all dpd/tcurrent " + std::to_string(K), "thermo_style custom step c_J[1]",
          "run 0 post no"});
}

// the direct sum of the definition, J_t(k) = sum v_t exp(i k x), over gathered atoms
std::vector<double> direct_sum(Lammps &l, double lo, double L, const std::vector<int> &keep = {})
{
  const auto x = l.gather("x");
  const auto v = l.gather("v");
  std::vector<double> out(12 * K, 0.0);
  for (size_t i = 0; i < x.size() / 3; i++) {
    if (!keep.empty() && !keep[i]) continue;
    for (int axis = 0; axis < 3; axis++)
      for (int j = 1; j <= K; j++)
        for (int t = 0; t < 2; t++) {
          const double phase = two_pi * j * (x[3 * i + axis] - lo) / L;
          const double vt = v[3 * i + (axis + 1 + t) % 3];
          out[etd::transverse_current_index(K, axis, j, t, 0)] += vt * std::cos(phase);
          out[etd::transverse_current_index(K, axis, j, t, 1)] += vt * std::sin(phase);
        }
  }
  return out;
}

double max_abs_diff(const std::vector<double> &a, const std::vector<double> &b)
{
  double worst = 0.0;
  for (size_t i = 0; i < a.size(); i++) worst = std::max(worst, std::fabs(a[i] - b[i]));
  return worst;
}

}    // namespace

TEST(TCurrent, SinusoidalVelocityFieldGivesHalfNAtItsWaveNumberOnly)
{
  Lammps l;
  sinusoidal_field(l, 0.0);
  ASSERT_EQ(l.natoms(), 1728);
  const auto J = current(l);
  // along x: transverse y (t = 0) has Re J = N U / 2 at j = 1; transverse z (t = 1) has
  // Im J = N (-W) / 2 at j = 2; every other value is zero (the lattice has 12 points per axis,
  // so no aliasing for j <= 4)
  std::vector<double> expected(12 * K, 0.0);
  expected[etd::transverse_current_index(K, 0, 1, 0, 0)] = 1728 * 0.7 / 2;
  expected[etd::transverse_current_index(K, 0, 2, 1, 1)] = -1728 * 0.3 / 2;
  for (int i = 0; i < 12 * K; i++) EXPECT_NEAR(J[i], expected[i], 1e-9) << "index " << i;
  // the layout of the documentation: c_J[1] is Re J_y(k_1 x), c_J[4 + 4] is Im J_z(k_2 x)
  EXPECT_NEAR(l.lmp->input->variable->compute_equal("c_J[1]"), 1728 * 0.7 / 2, 1e-9);
  EXPECT_NEAR(l.lmp->input->variable->compute_equal("c_J[8]"), -1728 * 0.3 / 2, 1e-9);
}

TEST(TCurrent, BoxOriginDoesNotMatter)
{
  // (one LAMMPS instance at a time: the plugin registers its styles with the instance that
  // loads it)
  std::vector<double> at_zero, shifted;
  {
    Lammps a;
    sinusoidal_field(a, 0.0);
    at_zero = current(a);
  }
  {
    Lammps b;
    sinusoidal_field(b, -3.7);
    shifted = current(b);
  }
  EXPECT_LT(max_abs_diff(at_zero, shifted), 1e-9);
}

TEST(TCurrent, GroupSelectsAtoms)
{
  Lammps l;
  etdtest::write_random_data(DATA, 500, 5.0, 17, 2, 1.0);
  l.cmds({"units lj", "atom_modify map array", "read_data " + DATA, "mass * 1.0",
          "region left block 0 2.5 INF INF INF INF units box", "group left region left",
          "compute J left dpd/tcurrent " + std::to_string(K), "run 0 post no"});
  const auto x = l.gather("x");
  std::vector<int> keep(x.size() / 3);
  for (size_t i = 0; i < keep.size(); i++) keep[i] = x[3 * i] < 2.5;
  const auto expected = direct_sum(l, 0.0, 5.0, keep);
  EXPECT_LT(max_abs_diff(current(l), expected), 1e-10);
  // and the group matters: the whole fluid gives other values
  EXPECT_GT(max_abs_diff(direct_sum(l, 0.0, 5.0), expected), 1e-3);
}

// A DPD fluid run for a few steps (atoms cross the periodic boundaries and change ranks): the
// compute equals the direct sum and does not depend on the number of ranks.
TEST(TCurrent, MatchesDirectSumOnAnyRankCount)
{
  etdtest::write_random_data(DATA, 800, 6.0, 23, 1, 1.5);
  std::vector<std::vector<double>> results;
  for (int ranks : {1, 2, 4}) {
    if (ranks > etdtest::world_size()) break;
    results.push_back(etdtest::on_ranks(ranks, [&](Lammps &l) {
      l.cmds({"units lj", "atom_modify map array", "comm_modify vel yes",
              "neigh_modify every 1 delay 0 check yes", "read_data " + DATA, "mass * 1.0",
              "pair_style dpd/gen 1.0 1.0 77", "pair_coeff 1 1 25 4.5 0.5", "fix 1 all nve",
              "timestep 0.01", "compute J all dpd/tcurrent " + std::to_string(K),
              "thermo_style custom step c_J[1]", "run 50 post no"});
      auto J = current(l);
      const auto expected = direct_sum(l, 0.0, 6.0);
      EXPECT_LT(max_abs_diff(J, expected), 1e-10) << ranks << " ranks";
      return J;
    }));
  }
  if (etdtest::world_rank() != 0) return;
  double scale = 0.0;
  for (double v : results[0]) scale = std::max(scale, std::fabs(v));
  EXPECT_GT(scale, 1.0);
  for (size_t k = 1; k < results.size(); k++)
    EXPECT_LT(max_abs_diff(results[k], results[0]), 1e-10 * scale) << "variant " << k;
}

// Stock fix ave/correlate takes every value with c_J[*]; for a frozen sinusoidal field the
// autocorrelation of Re J_y(k_1 x) is (N U / 2)^2 at every lag. (LAMMPS 29Sep2021 rejects
// optional keywords after a wildcard in ave/correlate; the defaults are type auto, ave one.)
TEST(TCurrent, FeedsFixAveCorrelate)
{
  Lammps l;
  sinusoidal_field(l, 0.0);
  l.cmds({"fix corr all ave/correlate 2 4 8 c_J[*]", "run 8 post no"});
  LAMMPS_NS::Fix *fix = l.lmp->modify->fix[l.lmp->modify->find_fix("corr")];
  const double amplitude = 1728 * 0.7 / 2;
  const int re_y = etd::transverse_current_index(K, 0, 1, 0, 0);
  const int im_z = etd::transverse_current_index(K, 0, 2, 1, 1);
  for (int lag = 0; lag < 4; lag++) {
    // columns: lag, count, then one correlation per value
    EXPECT_NEAR(fix->compute_array(lag, 2 + re_y), amplitude * amplitude, 1e-6);
    EXPECT_NEAR(fix->compute_array(lag, 2 + im_z), 1728 * 1728 * 0.0225, 1e-6);
    EXPECT_NEAR(fix->compute_array(lag, 2 + im_z + 1), 0.0, 1e-6);
  }
}

TEST(TCurrent, BadInputErrors)
{
  const std::vector<std::string> periodic = {"units lj", "region box block 0 5 0 5 0 5",
                                             "create_box 1 box", "create_atoms 1 random 50 3 NULL",
                                             "mass 1 1.0"};
  etdtest::expect_errors(
      {
          {{"compute J all dpd/tcurrent"},
           "Illegal compute dpd/tcurrent command: expected 'compute ID group dpd/tcurrent K'"},
          {{"compute J all dpd/tcurrent 4 5"}, "Illegal compute dpd/tcurrent"},
          {{"compute J all dpd/tcurrent four"}, "must be a positive integer, got 'four'"},
          {{"compute J all dpd/tcurrent 2.5"}, "must be a positive integer"},
          {{"compute J all dpd/tcurrent 0"}, "must be between 1 and 100000, got 0"},
          {{"compute J all dpd/tcurrent -3"}, "must be between 1 and 100000"},
      },
      [&](Lammps &l) {
        l.cmds(periodic);
      });
  // boxes the transverse current is not defined for: a wall, a tilted box, two dimensions
  const std::vector<std::string> run = {"create_atoms 1 random 50 3 NULL", "mass 1 1.0",
                                        "compute J all dpd/tcurrent 2",
                                        "thermo_style custom step c_J[1]", "run 0"};
  auto box = [&](std::vector<std::string> head) {
    head.insert(head.end(), run.begin(), run.end());
    return head;
  };
  etdtest::expect_errors(
      {
          {box({"units lj", "boundary p p f", "region box block 0 5 0 5 0 5", "create_box 1 box"}),
           "requires a box periodic in x, y and z"},
          {box({"units lj", "region box prism 0 5 0 5 0 5 1 0 0", "create_box 1 box"}),
           "requires an orthogonal box"},
          {box({"units lj", "dimension 2", "region box block 0 5 0 5 -0.5 0.5",
                "create_box 1 box"}),
           "requires a 3d system"},
      },
      [](Lammps &) {
      });
}
