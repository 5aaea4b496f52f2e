// fix wall/cylinder/bounce and fix wall/thermal/layer inside LAMMPS: a hand-built crossing,
// no escape in a driven run, the redrawn layer's statistics, bad input, rank independence.
#include "lammps.h"
#include "lammps_fixture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <utility>

using etdtest::Lammps;

namespace {

const std::string DATA = etdtest::work_file("walls_config.data");

double max_abs_diff(const std::vector<double> &a, const std::vector<double> &b)
{
  double worst = 0.0;
  for (size_t i = 0; i < a.size(); i++) worst = std::max(worst, std::fabs(a[i] - b[i]));
  return worst;
}

// An empty 10^3 box for hand-built atoms, no forces.
void empty_box(Lammps &l)
{
  l.cmds({"units lj", "atom_modify map array", "boundary p p p", "region box block 0 10 0 10 0 10",
          "create_box 1 box", "mass 1 1.0", "pair_style zero 1.0", "pair_coeff * *",
          "timestep 0.01"});
}

// A low-mass DPD fluid (n = 4, m = 0.01, s = 1/2) filling a cylinder along x.
void pipe_fluid(Lammps &l, double radius, const std::string &integrator)
{
  const std::string R = std::to_string(radius);
  l.cmds({"units lj", "atom_modify map array", "comm_modify vel yes",
          "neigh_modify every 1 delay 0 check yes", "boundary p p p",
          "region box block 0 6 -4 4 -4 4", "create_box 1 box",
          "region pipe cylinder x 0 0 " + R + " INF INF",
          "create_atoms 1 random " +
              std::to_string(static_cast<int>(4 * 6 * M_PI * radius * radius)) + " 8123 pipe",
          "mass 1 0.01", "velocity all create 1.0 4411 mom yes", "pair_style dpd/gen 1.0 1.0 2024",
          "pair_coeff 1 1 18.75 4.5 0.5", "timestep 0.001", integrator});
}

}    // namespace

TEST(WallCylinderBounce, HandBuiltCrossingIsReversedAndPutBack)
{
  Lammps l;
  empty_box(l);
  // axis z through (5, 5), R = 1: atom 1 crosses during the step, atom 2 stays inside
  l.cmds({"create_atoms 1 single 5.99 5.0 3.0 units box",
          "create_atoms 1 single 5.0 5.5 3.0 units box", "set atom 1 vx 3.0 vy 0.0 vz 1.0",
          "set atom 2 vx 1.0 vy 2.0 vz 0.0", "fix 1 all nve",
          "fix wall all wall/cylinder/bounce z 5.0 5.0 1.0", "run 1 post no"});
  const auto x = l.gather("x"), v = l.gather("v");
  // atom 1: wall reached at a third of the step, the other two thirds travelled back
  EXPECT_NEAR(x[0], 5.98, 1e-12);
  EXPECT_NEAR(x[1], 5.0, 1e-12);
  EXPECT_NEAR(x[2], 3.0 + 0.01 - 2.0 * (2.0 / 3.0) * 0.01, 1e-12);
  EXPECT_DOUBLE_EQ(v[0], -3.0);
  EXPECT_DOUBLE_EQ(v[1], 0.0);
  EXPECT_DOUBLE_EQ(v[2], -1.0);
  // atom 2: moved freely
  EXPECT_NEAR(x[3], 5.01, 1e-12);
  EXPECT_NEAR(x[4], 5.52, 1e-12);
  EXPECT_DOUBLE_EQ(v[3], 1.0);
  EXPECT_DOUBLE_EQ(v[4], 2.0);
  EXPECT_EQ(l.fix_vector("wall", 0), 1.0);
  EXPECT_EQ(l.fix_vector("wall", 1), 0.0);
}

TEST(WallCylinderBounce, NoAtomLeavesADrivenPipe)
{
  Lammps l;
  pipe_fluid(l, 3.0, "fix integrate all etd");
  l.cmds({"fix drive all addforce 2.0 0.0 0.0", "fix wall all wall/cylinder/bounce x 0.0 0.0 3.0",
          "variable r atom sqrt(y*y+z*z)", "compute rmax all reduce max v_r",
          "thermo_style custom step c_rmax", "thermo 50"});
  double worst = 0.0;
  for (int block = 0; block < 30; block++) {    // 1500 steps, checked every 50
    l.cmd("run 50 post no");
    worst = std::max(worst, l.compute_scalar("rmax"));
  }
  EXPECT_LE(worst, 3.0);
  EXPECT_GT(l.fix_vector("wall", 0), 100.0);    // the wall did work
  // the body force builds a flow along the pipe (the wall holds it back)
  l.cmds({"compute vcm all reduce ave vx", "run 0 post no"});
  EXPECT_GT(l.compute_scalar("vcm"), 0.5);
}

TEST(WallCylinderBounce, NoAtomEntersAnObstacle)
{
  Lammps l;
  l.cmds({"units lj", "atom_modify map array", "comm_modify vel yes",
          "neigh_modify every 1 delay 0 check yes", "region box block 0 6 0 6 0 4",
          "create_box 1 box", "region rod cylinder z 3 3 1.0 INF INF side out",
          "create_atoms 1 random 540 771 rod", "mass 1 0.01", "velocity all create 1.0 99 mom yes",
          "pair_style dpd/gen 1.0 1.0 5", "pair_coeff 1 1 18.75 4.5 0.5", "timestep 0.001",
          "fix integrate all etd", "fix drive all addforce 3.0 0.0 0.0",
          "fix rod all wall/cylinder/bounce z 3.0 3.0 1.0 side out",
          "variable r atom sqrt((x-3)^2+(y-3)^2)", "compute rmin all reduce min v_r"});
  double closest = 10.0;
  for (int block = 0; block < 20; block++) {
    l.cmd("run 50 post no");
    closest = std::min(closest, l.compute_scalar("rmin"));
  }
  EXPECT_GE(closest, 1.0);
  EXPECT_GT(l.fix_vector("rod", 0), 10.0);
}

// A small Couette cell: fluid (n = 4, m = 0.01, kBT = 1) in |z| < 3 between frozen fcc walls
// in 3 < |z| < 4.5 moving at -+3 along x, a 0.2 thermal layer at each wall; fix etd with the
// given scheme (the walls' reflecting planes are left to the caller).
// Diffusive reflection at the cell's wall planes, at the walls' speed and kBT = 1.
const std::string STOCHASTIC_WALLS = "fix reflect fluid wall/reflect/stochastic diffusive 77 zlo -3 "
                                     "1.0 -3 0 0 zhi 3 1.0 3 0 0 units box";

// Whether the stock fix wall/reflect/stochastic crashes in this LAMMPS (from 4 Jul 2026 on; fix
// etd then refuses it: src/lammps_compat.h)
bool stock_stochastic_walls_crash()
{
  return Lammps().lmp->num_ver >= 20260704;
}

void couette_cell_setup(Lammps &l, const std::string &scheme)
{
  l.cmds({"units lj",
          "atom_modify map array",
          "comm_modify vel yes",
          "neigh_modify every 1 delay 0 check yes",
          "boundary p p f",
          "region box block 0 4 0 4 -6 6 units box",
          "create_box 3 box",
          "lattice fcc 4.0 origin 0 0 0.25",
          "region fluid block INF INF INF INF -3 3 units box",
          "region lo block INF INF INF INF -4.5 -3 units box",
          "region hi block INF INF INF INF 3 4.5 units box",
          "create_atoms 1 region fluid",
          "create_atoms 2 region lo",
          "create_atoms 3 region hi",
          "group fluid type 1",
          "group walls type 2 3",
          "group lo type 2",
          "group hi type 3",
          "mass * 0.01",
          "pair_style dpd/gen 1.0 1.0 4711",
          "pair_coeff * * 18.75 4.5 0.5",
          "pair_coeff 2*3 2*3 0.0 0.0 0.5",
          "neigh_modify exclude type 2 2 exclude type 3 3 exclude type 2 3",
          "velocity fluid create 1.0 8231 mom yes",
          "velocity lo set -3 0 0",
          "velocity hi set 3 0 0",
          "timestep 0.001",
          "fix integrate fluid etd scheme " + scheme,
          "fix move_lo lo move linear -3 0 0",
          "fix move_hi hi move linear 3 0 0",
          "fix layer fluid wall/thermal/layer 99 zlo -3 0.2 1.0 -3 0 0 zhi 3 0.2 1.0 3 0 0",
          "thermo_modify lost ignore",
          "variable absz atom abs(z)",
          "compute zmax fluid reduce max v_absz",
          "fix zmax_series all vector 1 c_zmax"});
}

// The cell run for a number of steps with fix wall/reflect at z = -+3 (with_reflect), or with
// fix wall/reflect/stochastic there (stochastic: diffusive, at the walls' speed and kBT = 1).
// Returns the largest |z| of a fluid atom over every step of the run and the number of fluid
// atoms at its end (lost atoms are dropped, not an error).
std::pair<double, long> couette_cell(bool with_reflect, int steps, double *redrawn = nullptr,
                                     const std::string &scheme = "diagonal",
                                     bool stochastic = false)
{
  Lammps l;
  couette_cell_setup(l, scheme);
  if (with_reflect) l.cmd("fix reflect fluid wall/reflect zlo -3 zhi 3 units box");
  if (stochastic) l.cmd(STOCHASTIC_WALLS);
  l.cmd("run " + std::to_string(steps) + " post no");
  if (redrawn) *redrawn = l.fix_vector("layer", 1);    // kinetic energy the redraws added
  l.cmds({"variable zmax_run equal max(f_zmax_series)", "variable nfluid equal count(fluid)",
          "fix result all ave/time 1 1 1 v_zmax_run v_nfluid", "run 0 post no"});
  return {l.fix_vector("result", 0), std::lround(l.fix_vector("result", 1))};
}

TEST(WallThermalLayer, NoFluidAtomCrossesPlaneWallsInALongCouetteRun)
{
  // 384 fluid atoms; 5000 steps = 5 time units, about 30 wall-normal crossings of the cell by
  // a thermal atom (sqrt(kBT/m) = 10), every step checked
  double redrawn = 0.0;
  const auto kept = couette_cell(true, 5000, &redrawn);
  EXPECT_LE(kept.first, 3.0);
  EXPECT_EQ(kept.second, 384);
  EXPECT_NE(redrawn, 0.0);    // the layers were populated and exchanged heat
  // the same cell without the reflecting planes: the check sees fluid entering the walls
  const auto open = couette_cell(false, 500);
  EXPECT_GT(open.first, 3.0);
  // the implicit scheme (friction between the two half drifts) with the same walls
  const auto implicit = couette_cell(true, 2000, &redrawn, "implicit");
  EXPECT_LE(implicit.first, 3.0);
  EXPECT_EQ(implicit.second, 384);
}

// fix wall/reflect/stochastic moves a crossing atom back along its velocity after the drift:
// right for the diagonal scheme, whose drift uses that velocity; the implicit scheme's atoms
// travel with the mean of the velocities before and after its friction step, so the
// combination is refused (it left atoms beyond the wall and lost one in the sphere-in-Couette
// example).
TEST(WallReflectStochastic, DiagonalSchemeKeepsTheFluidInside)
{
  if (stock_stochastic_walls_crash()) {
    // there the stock fix crashes at its first step; fix etd stops before it
    etdtest::expect_errors({{{STOCHASTIC_WALLS, "run 0"},
                             "crashes at its first step in this LAMMPS version"}},
                           [](Lammps &l) { couette_cell_setup(l, "diagonal"); });
    GTEST_SKIP() << "fix wall/reflect/stochastic crashes in this LAMMPS version (refused)";
  }
  const auto kept = couette_cell(false, 2000, nullptr, "diagonal", true);
  EXPECT_LE(kept.first, 3.0);
  EXPECT_EQ(kept.second, 384);
}

TEST(WallReflectStochastic, ImplicitSchemeIsRefused)
{
  // (where the stock fix crashes, fix etd's preamble refuses it first)
  const bool stock_fix_crashes = stock_stochastic_walls_crash();
  etdtest::expect_errors({{{STOCHASTIC_WALLS, "run 0"},
                           stock_fix_crashes
                               ? "crashes at its first step in this LAMMPS version"
                               : "cannot be combined with fix wall/reflect/stochastic (reflect)"}},
                         [](Lammps &l) { couette_cell_setup(l, "implicit"); });
  // the overdamped drift uses the velocity it leaves behind: allowed (where the stock fix works)
  if (stock_fix_crashes) return;
  Lammps l;
  couette_cell_setup(l, "implicit overdamped yes");
  l.cmd(STOCHASTIC_WALLS);
  EXPECT_NO_THROW(l.cmd("run 0 post no"));
}

TEST(WallThermalLayer, LayerGetsTheWallMaxwellianAndTheRestIsUntouched)
{
  Lammps l;
  l.cmds({"units lj", "atom_modify map array", "region box block 0 10 0 10 0 10",
          "create_box 1 box", "create_atoms 1 random 40000 17 NULL", "mass 1 0.25",
          "velocity all set 1.0 -2.0 0.5", "pair_style zero 1.0", "pair_coeff * *",
          "timestep 0.001",
          "fix layer all wall/thermal/layer 4321 zlo 1.0 2.0 0.5 3.0 -1.0 0.0 zhi 9.0 1.0 2.0 0.0 "
          "0.0 0.0",
          "run 1 post no"});
  const auto x = l.gather("x"), v = l.gather("v");
  double sum[2][3] = {{0}}, sum2[2][3] = {{0}};
  int n[2] = {0, 0};
  for (size_t i = 0; i < x.size() / 3; i++) {
    const double z = x[3 * i + 2];
    const int face = (z >= 1.0 && z < 3.0) ? 0 : (z > 8.0 && z <= 9.0) ? 1 : -1;
    if (face < 0) {    // outside both layers: as set
      EXPECT_EQ(v[3 * i], 1.0);
      EXPECT_EQ(v[3 * i + 1], -2.0);
      EXPECT_EQ(v[3 * i + 2], 0.5);
      continue;
    }
    n[face]++;
    for (int k = 0; k < 3; k++) {
      sum[face][k] += v[3 * i + k];
      sum2[face][k] += v[3 * i + k] * v[3 * i + k];
    }
  }
  ASSERT_GT(n[0], 7000);
  ASSERT_GT(n[1], 3500);
  const double wall_v[2][3] = {{3.0, -1.0, 0.0}, {0.0, 0.0, 0.0}};
  const double kT_over_m[2] = {0.5 / 0.25, 2.0 / 0.25};
  EXPECT_EQ(l.fix_vector("layer", 0), n[0] + n[1]);
  for (int f = 0; f < 2; f++)
    for (int k = 0; k < 3; k++) {
      const double mean = sum[f][k] / n[f];
      const double var = sum2[f][k] / n[f] - mean * mean;
      // 5 standard errors
      EXPECT_NEAR(mean, wall_v[f][k], 5.0 * std::sqrt(kT_over_m[f] / n[f]))
          << "face " << f << " k " << k;
      EXPECT_NEAR(var / kT_over_m[f], 1.0, 5.0 * std::sqrt(2.0 / n[f]))
          << "face " << f << " k " << k;
    }
}

TEST(WallThermalLayer, DrawsDependOnSeedAndStep)
{
  auto layer_velocities = [](const std::string &seed, int steps) {
    Lammps l;
    l.cmds({"units lj", "atom_modify map array", "region box block 0 4 0 4 0 4", "create_box 1 box",
            "create_atoms 1 random 200 5 NULL", "mass 1 1.0", "pair_style zero 1.0",
            "pair_coeff * *",
            "fix layer all wall/thermal/layer " + seed + " zlo 0.0 4.0 1.0 0.0 0.0 0.0",
            "run " + std::to_string(steps) + " post no"});
    return l.gather("v");
  };
  const auto a = layer_velocities("11", 1), b = layer_velocities("11", 1);
  const auto c = layer_velocities("12", 1), d = layer_velocities("11", 2);
  EXPECT_EQ(max_abs_diff(a, b), 0.0);
  EXPECT_GT(max_abs_diff(a, c), 0.1);
  EXPECT_GT(max_abs_diff(a, d), 0.1);
}

TEST(Walls, BadInputIsAnError)
{
  etdtest::expect_errors(
      {
          {{"fix w all wall/cylinder/bounce z 5 5"}, "expected dim c1 c2 radius"},
          {{"fix w all wall/cylinder/bounce q 5 5 1"}, "dim must be x, y or z, got q"},
          {{"fix w all wall/cylinder/bounce z 5 5 0"}, "radius must be > 0"},
          {{"fix w all wall/cylinder/bounce z 5 5 -1"}, "radius must be > 0"},
          {{"fix w all wall/cylinder/bounce z 5 5 1 side across"},
           "side must be in or out, got across"},
          {{"fix w all wall/cylinder/bounce z 5 5 1 side"}, "side needs in or out"},
          {{"fix w all wall/cylinder/bounce z 5 5 1 speed 2"}, "unknown keyword speed"},
          {{"fix w all wall/cylinder/bounce z 5 5 6", "run 0"}, "does not fit in the periodic box"},
          {{"fix w all wall/cylinder/bounce z 5 5 1", "run_style respa 2 2", "run 0"}, "respa"},
          {{"fix w all wall/thermal/layer 5 zlo 0 1 1 0 0"}, "expected seed and at least one face"},
          {{"fix w all wall/thermal/layer 0 zlo 0 1 1 0 0 0"}, "seed must be > 0"},
          {{"fix w all wall/thermal/layer 5 zmid 0 1 1 0 0 0"}, "unknown face zmid"},
          {{"fix w all wall/thermal/layer 5 zlo 0 0 1 0 0 0"}, "thickness of face zlo must be > 0"},
          {{"fix w all wall/thermal/layer 5 zhi 0 1 -1 0 0 0"}, "kT of face zhi must be >= 0"},
          {{"fix w all wall/thermal/layer 5 zlo 0 1 1 0 0 2"},
           "velocity of face zlo must lie in the wall plane"},
          {{"fix w all wall/thermal/layer 5 xlo 0 1 1 0 1 0 xlo 2 1 1 0 0 0"},
           "face xlo given twice"},
          {{"fix w all wall/thermal/layer 5 xlo 0 1 1 0 1 0 yhi 2 1 1"},
           "face yhi needs position thickness"},
      },
      [](Lammps &l) {
        empty_box(l);
      });
}

TEST(Walls, ThermalLayerNeedsAtomIds)
{
  Lammps l;
  l.cmds({"units lj", "atom_modify id no", "region box block 0 4 0 4 0 4", "create_box 1 box",
          "create_atoms 1 single 1 1 1", "mass 1 1.0", "pair_style zero 1.0", "pair_coeff * *",
          "fix w all wall/thermal/layer 5 zlo 0 1 1 0 0 0"});
  EXPECT_NE(l.error_of("run 0").find("requires atom IDs"), std::string::npos);
}

TEST(Walls, TrajectoriesAgreeAcrossRankCounts)
{
  if (etdtest::world_size() < 4) GTEST_SKIP() << "needs mpirun -np 4";
  etdtest::write_random_data(DATA, 1500, 7.2, 4242, 1, 1.0);
  std::vector<std::vector<double>> results;
  for (int ranks : {1, 2, 4})
    results.push_back(etdtest::on_ranks(ranks, [&](Lammps &l) {
      l.cmds({"units lj", "atom_modify map array", "comm_modify vel yes",
              "neigh_modify every 1 delay 0 check yes", "read_data " + DATA, "mass 1 0.01",
              "timestep 0.001", "pair_style dpd/gen 1.0 1.0 2718", "pair_coeff 1 1 18.75 4.5 0.5",
              "fix 1 all etd",
              "fix layer all wall/thermal/layer 77 zlo 1.0 0.8 1.0 2.0 0.0 0.0 zhi 6.2 0.8 1.0 "
              "-2.0 0.0 0.0",
              "fix rod all wall/cylinder/bounce x 3.6 3.6 1.0 side out", "run 20 post no"});
      auto x = l.gather("x");
      auto v = l.gather("v");
      x.insert(x.end(), v.begin(), v.end());
      x.push_back(l.fix_vector("rod", 0));
      x.push_back(l.fix_vector("layer", 0));
      return x;
    }));
  if (etdtest::world_rank() != 0) return;
  double scale = 0.0;
  for (double v : results[0]) scale = std::max(scale, std::fabs(v));
  for (int k = 1; k < 3; k++) {
    const double diff = max_abs_diff(results[k], results[0]);
    EXPECT_LT(diff, 1e-10 * scale) << "variant " << k << " diff " << diff;
  }
  EXPECT_GT(results[0][results[0].size() - 1], 0.0);    // the layer was active
  EXPECT_GT(results[0][results[0].size() - 2], 0.0);    // atoms were bounced off the rod
}
