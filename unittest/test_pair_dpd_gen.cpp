// pair_style dpd/gen: equivalence with the stock styles, energy, cutoff split, noise statistics,
// restart, write_data, single(), hybrid use and every bad-input error.
#include "lammps_fixture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

using etdtest::Lammps;

namespace {

const std::string DATA = etdtest::work_file("dpd_gen_config.data");

// n = 3 fluid of 648 atoms in a 6^3 box, two types, random velocities
void setup_box(Lammps &l, const std::string &newton = "on")
{
  etdtest::write_random_data(DATA, 648, 6.0, 4711, 2, 1.5);
  l.cmds({"units lj", "atom_modify map array", "newton " + newton, "comm_modify vel yes",
          "neigh_modify every 1 delay 0 check yes", "read_data " + DATA, "mass * 1.0",
          "timestep 0.01", "thermo_modify norm no", "compute virial all pressure NULL virial"});
}

double max_rel_diff(const std::vector<double> &a, const std::vector<double> &b)
{
  double worst = 0.0, scale = 0.0;
  for (size_t i = 0; i < a.size(); i++) scale = std::max(scale, std::fabs(b[i]));
  for (size_t i = 0; i < a.size(); i++) worst = std::max(worst, std::fabs(a[i] - b[i]) / scale);
  return worst;
}

struct Snapshot {
  std::vector<double> f;
  std::vector<double> virial;
  double pe;
};

Snapshot snapshot(Lammps &l)
{
  l.cmd("run 0 post no");
  Snapshot s;
  s.f = l.gather("f");
  for (int k = 0; k < 6; k++) s.virial.push_back(l.compute_vector("virial", k));
  s.pe = l.thermo("pe");
  return s;
}

}    // namespace

TEST(PairDpdGen, EqualsStockDpdForS2AtZeroTemperature)
{
  Lammps l;
  setup_box(l);
  l.cmds({"pair_style dpd 0.0 1.0 123", "pair_coeff 1 1 25.0 4.5", "pair_coeff 1 2 30.0 6.0 0.9",
          "pair_coeff 2 2 18.75 3.0"});
  const Snapshot stock = snapshot(l);
  l.cmds({"pair_style dpd/gen 0.0 1.0 123", "pair_coeff 1 1 25.0 4.5 2.0",
          "pair_coeff 1 2 30.0 6.0 2.0 0.9", "pair_coeff 2 2 18.75 3.0 2.0"});
  const Snapshot ours = snapshot(l);
  EXPECT_LT(max_rel_diff(ours.f, stock.f), 1e-12);
  EXPECT_LT(max_rel_diff(ours.virial, stock.virial), 1e-12);
  EXPECT_NEAR(ours.pe, stock.pe, 1e-12 * std::fabs(stock.pe));
}

TEST(PairDpdGen, EqualsStockDpdExtForAnyS)
{
  for (double s : {0.5, 0.4244, 1.0, 3.0}) {
    Lammps l;
    setup_box(l);
    const std::string ws = std::to_string(s / 2), ss = std::to_string(s);
    l.cmds({"pair_style dpd/ext 0.0 1.0 123", "pair_coeff * * 25.0 4.5 0.0 " + ws + " " + ws,
            "pair_coeff 1 2 25.0 4.5 0.0 " + ws + " " + ws + " 1.2"});
    const Snapshot stock = snapshot(l);
    l.cmds({"pair_style dpd/gen 0.0 1.0 123", "pair_coeff * * 25.0 4.5 " + ss,
            "pair_coeff 1 2 25.0 4.5 " + ss + " 1.2"});
    const Snapshot ours = snapshot(l);
    EXPECT_LT(max_rel_diff(ours.f, stock.f), 1e-12) << "s=" << s;
    EXPECT_LT(max_rel_diff(ours.virial, stock.virial), 1e-12) << "s=" << s;
  }
}

TEST(PairDpdGen, EnergyIsMinusIntegralOfConservativeForce)
{
  // gamma = 0 and T = 0: the force is purely conservative; rcC != rcD and p != 1
  Lammps l;
  setup_box(l);
  l.cmds({"pair_style dpd/gen 0.0 1.0 5", "pair_coeff 1 1 18.75 4.5 0.5 1.0 cut_d 1.4 exp_c 0.5",
          "pair_coeff 2 2 25 0.0 2.0", "pair_coeff 1 2 40 0.0 0.25 1.2 cut_d 0.8 exp_c 1.5",
          "pair_coeff 1 1 18.75 0.0 0.5 1.0 cut_d 1.4 exp_c 0.5"});
  const Snapshot base = snapshot(l);
  const double h = 1e-6;
  for (int tag : {1, 2, 77}) {
    for (int k = 0; k < 3; k++) {
      const char axis = "xyz"[k];
      auto energy_at = [&](double shift) {
        l.cmd("group moved id " + std::to_string(tag));
        l.cmd(std::string("displace_atoms moved move ") + (k == 0 ? std::to_string(shift) : "0") +
              " " + (k == 1 ? std::to_string(shift) : "0") + " " +
              (k == 2 ? std::to_string(shift) : "0") + " units box");
        l.cmd("run 0 post no");
        const double e = l.thermo("pe");
        l.cmd(std::string("displace_atoms moved move ") + (k == 0 ? std::to_string(-shift) : "0") +
              " " + (k == 1 ? std::to_string(-shift) : "0") + " " +
              (k == 2 ? std::to_string(-shift) : "0") + " units box");
        l.cmd("group moved delete");
        return e;
      };
      const double fd = -(energy_at(h) - energy_at(-h)) / (2 * h);
      EXPECT_NEAR(fd, base.f[3 * (tag - 1) + k], 1e-5 * (1 + std::fabs(fd)))
          << "atom " << tag << axis;
    }
  }
}

TEST(PairDpdGen, SeparateCutoffsActSeparately)
{
  // two atoms with relative velocity: at rcC < r < rcD only D and R act, at rcD < r < rcC only C
  for (int variant = 0; variant < 2; variant++) {
    Lammps l;
    l.cmds({"units lj", "atom_modify map array", "comm_modify vel yes",
            "neigh_modify every 1 delay 0 check yes", "region box block 0 10 0 10 0 10",
            "create_box 1 box", "create_atoms 1 single 5 5 5", "create_atoms 1 single 6.2 5 5",
            "mass 1 1.0", "velocity all set 0.3 0.2 0.1", "group first id 1",
            "velocity first set -0.5 0.0 0.0", "timestep 0.01",
            variant == 0 ? "pair_style dpd/gen 1.0 1.0 9" : "pair_style dpd/gen 1.0 1.5 9",
            variant == 0 ? "pair_coeff 1 1 25 4.5 0.5 1.0 cut_d 1.5"
                         : "pair_coeff 1 1 25 4.5 0.5 1.5 cut_d 1.0",
            "compute split all dpd/split", "thermo_style custom step c_split[1]", "run 0 post no"});
    auto split = l.gather_compute("split", 9);
    const double fc = split[0], fd = split[3], fr = split[6];
    if (variant == 0) {
      EXPECT_EQ(fc, 0.0);
      EXPECT_GT(std::fabs(fd), 1e-3);
      EXPECT_GT(std::fabs(fr), 0.0);
    } else {
      EXPECT_NEAR(fc, -25 * (1 - 1.2 / 1.5), 1e-12);
      EXPECT_EQ(fd, 0.0);
      EXPECT_EQ(fr, 0.0);
    }
    // the parts add up to the total force
    auto f = l.gather("f");
    for (int k = 0; k < 3; k++) EXPECT_NEAR(split[k] + split[3 + k] + split[6 + k], f[k], 1e-12);
  }
}

TEST(PairDpdGen, RandomForcesSumToZeroAndHaveTheRightVariance)
{
  // 400 isolated pairs at r = 0.4 with zero relative velocity: F = sigma w_R theta / sqrt(dt)
  Lammps l;
  l.cmds({"units lj", "atom_modify map array", "comm_modify vel yes",
          "neigh_modify every 1 delay 0 check yes", "region box block 0 40 0 40 0 20",
          "create_box 1 box", "mass 1 1.0", "timestep 0.004"});
  for (int i = 0; i < 20; i++)
    for (int j = 0; j < 20; j++) {
      const double x = 1 + 2 * i, y = 1 + 2 * j, z = 1 + (i + j) % 9 * 2;
      l.cmd("create_atoms 1 single " + std::to_string(x) + " " + std::to_string(y) + " " +
            std::to_string(z));
      l.cmd("create_atoms 1 single " + std::to_string(x + 0.4) + " " + std::to_string(y) + " " +
            std::to_string(z));
    }
  const double T = 1.3, gamma = 4.5, s = 0.5, dt = 0.004;
  l.cmds({"pair_style dpd/gen 1.3 1.0 77", "pair_coeff 1 1 0.0 4.5 0.5"});
  const double expected_var = 2 * gamma * T * std::pow(1 - 0.4, s) / dt;
  double sum = 0, sumsq = 0;
  long count = 0;
  for (int step = 0; step < 25; step++) {
    l.cmd("reset_timestep " + std::to_string(1000 + step));
    l.cmd("run 0 post no");
    auto f = l.gather("f");
    double total[3] = {0, 0, 0}, scale = 0;
    for (size_t a = 0; a < f.size() / 3; a++)
      for (int k = 0; k < 3; k++) {
        total[k] += f[3 * a + k];
        scale = std::max(scale, std::fabs(f[3 * a + k]));
      }
    for (int k = 0; k < 3; k++) EXPECT_LT(std::fabs(total[k]), 1e-12 * scale * f.size());
    for (size_t a = 0; a < f.size() / 3; a += 2) {
      sum += f[3 * a];
      sumsq += f[3 * a] * f[3 * a];
      count++;
    }
  }
  // 10,000 samples: the variance's relative standard error is sqrt(2/N) = 1.4 %; allow 5 of them
  const double var = sumsq / count - (sum / count) * (sum / count);
  EXPECT_NEAR(var / expected_var, 1.0, 5 * std::sqrt(2.0 / count));
  EXPECT_NEAR(sum / count / std::sqrt(expected_var), 0.0, 5 / std::sqrt(double(count)));
}

TEST(PairDpdGen, NewtonOffConservesMomentumExactly)
{
  for (const std::string newton : {"on", "off"}) {
    Lammps l;
    setup_box(l, newton);
    l.cmds({"pair_style dpd/gen 1.0 1.0 31", "pair_coeff * * 25 4.5 0.5", "run 0 post no"});
    auto f = l.gather("f");
    double total[3] = {0, 0, 0}, scale = 0;
    for (size_t a = 0; a < f.size() / 3; a++)
      for (int k = 0; k < 3; k++) {
        total[k] += f[3 * a + k];
        scale = std::max(scale, std::fabs(f[3 * a + k]));
      }
    for (int k = 0; k < 3; k++)
      EXPECT_LT(std::fabs(total[k]), 1e-11 * scale) << "newton " << newton;
  }
}

TEST(PairDpdGen, RestartContinuesExactly)
{
  // LAMMPS re-evaluates forces at the start of every run, so the reference is a run split at the
  // same step: run 20; run 20 against run 20; write_restart; (new instance) read_restart; run 20
  const std::string restart = etdtest::work_file("dpd_gen.restart");
  std::vector<double> x_ref, v_ref;
  {
    Lammps l;
    setup_box(l);
    l.cmds({"pair_style dpd/gen 1.0 1.0 31", "pair_coeff * * 25 4.5 0.5",
            "pair_coeff 1 2 30 5 2 1.1 cut_d 0.9 exp_c 0.5", "fix 1 all nve", "run 20",
            "write_restart " + restart, "run 20"});
    x_ref = l.gather("x");
    v_ref = l.gather("v");
  }
  Lammps l;
  l.cmds({"read_restart " + restart, "comm_modify vel yes",
          "neigh_modify every 1 delay 0 check yes", "timestep 0.01", "fix 1 all nve", "run 20"});
  EXPECT_LT(max_rel_diff(l.gather("x"), x_ref), 1e-13);
  EXPECT_LT(max_rel_diff(l.gather("v"), v_ref), 1e-13);
}

TEST(PairDpdGen, WriteDataRoundTripsPerPairSettings)
{
  const std::string data = etdtest::work_file("dpd_gen_roundtrip.data");
  std::vector<double> f_ref;
  {
    Lammps l;
    setup_box(l);
    l.cmds({"pair_style dpd/gen 1.0 1.0 31", "pair_coeff 1 1 25 4.5 0.5 cut_d 1.3",
            "pair_coeff 2 2 18 3 2", "pair_coeff 1 2 1750 20.48 0.25 1.0 cut_d 1.5 exp_c 0.5",
            "run 0 post no", "write_data " + data + " pair ij"});
    f_ref = l.gather("f");
  }
  Lammps l;
  l.cmds({"units lj", "atom_modify map array", "comm_modify vel yes",
          "neigh_modify every 1 delay 0 check yes", "pair_style dpd/gen 1.0 1.0 31",
          "read_data " + data, "timestep 0.01", "run 0 post no"});
  EXPECT_LT(max_rel_diff(l.gather("f"), f_ref), 1e-13);
}

TEST(PairDpdGen, SingleGivesTheConservativeForceToPairWrite)
{
  const std::string table = etdtest::work_file("dpd_gen_table.txt");
  if (etdtest::world_rank() == 0) std::remove(table.c_str());    // pair_write appends
  Lammps l;
  setup_box(l);
  l.cmds({"pair_style dpd/gen 1.0 1.0 31", "pair_coeff * * 1750 20.48 0.25 1.0 cut_d 1.5 exp_c 0.5",
          "pair_write 1 2 10 r 0.1 0.99 " + table + " DPDGEN"});
  if (etdtest::world_rank() != 0) return;
  std::ifstream in(table);
  std::string line;
  int rows = 0;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    int index;
    double r, e, f;
    if (!(fields >> index >> r >> e >> f)) continue;
    EXPECT_NEAR(f, 1750 * std::sqrt(1 - r), 1e-8 * 1750) << line;
    EXPECT_NEAR(e, 1750 / 1.5 * std::pow(1 - r, 1.5), 1e-8 * 1750) << line;
    rows++;
  }
  EXPECT_EQ(rows, 10);
}

TEST(PairDpdGen, WorksInsideHybridOverlay)
{
  Lammps l;
  setup_box(l);
  l.cmds({"pair_style dpd/gen 0.0 1.0 1", "pair_coeff * * 25 4.5 0.5",
          "pair_coeff 1 2 25 4.5 0.5 1.2"});
  const Snapshot alone = snapshot(l);
  l.cmds({"pair_style hybrid/overlay dpd/gen 0.0 1.0 1 zero 1.2",
          "pair_coeff * * dpd/gen 25 4.5 0.5", "pair_coeff 1 2 dpd/gen 25 4.5 0.5 1.2",
          "pair_coeff * * zero", "compute split all dpd/split", "variable fc equal c_split[1]",
          "thermo_style custom step v_fc"});
  const Snapshot overlay = snapshot(l);
  EXPECT_LT(max_rel_diff(overlay.f, alone.f), 1e-14);
  EXPECT_LT(max_rel_diff(overlay.virial, alone.virial), 1e-13);
}

TEST(PairDpdGen, BadInputGivesClearErrors)
{
  etdtest::expect_errors(
      {
          {{"pair_style dpd/gen 1.0 1.0"}, "expected 3 arguments"},
          {{"pair_style dpd/gen -1.0 1.0 5"}, "temperature must be >= 0"},
          {{"pair_style dpd/gen 1.0 0.0 5"}, "cutoff must be > 0"},
          {{"pair_style dpd/gen 1.0 1.0 -3"}, "seed must be a positive integer"},
          {{"pair_style dpd/gen 1.0 1.0 abc"},
           "'abc'"},    // LAMMPS parses the number: its wording is not ours; the argument is named
          {{"pair_style dpd/gen 1.0 1.0 5", "pair_coeff 1 1 25 4.5"}, "expected I J a gamma s"},
          {{"pair_style dpd/gen 1.0 1.0 5", "pair_coeff 1 1 25 -4.5 0.5"}, "gamma must be >= 0"},
          {{"pair_style dpd/gen 1.0 1.0 5", "pair_coeff 1 1 25 4.5 0"}, "exponent s must be > 0"},
          {{"pair_style dpd/gen 1.0 1.0 5", "pair_coeff 1 1 25 4.5 -1"}, "exponent s must be > 0"},
          {{"pair_style dpd/gen 1.0 1.0 5", "pair_coeff 1 1 25 4.5 0.5 -1.0"},
           "cutoff must be > 0"},
          {{"pair_style dpd/gen 1.0 1.0 5", "pair_coeff 1 1 25 4.5 0.5 cut_d 0"},
           "cut_d must be > 0"},
          {{"pair_style dpd/gen 1.0 1.0 5", "pair_coeff 1 1 25 4.5 0.5 cut_d"},
           "cut_d needs a value"},
          {{"pair_style dpd/gen 1.0 1.0 5", "pair_coeff 1 1 25 4.5 0.5 exp_c 0"},
           "exp_c must be > 0"},
          {{"pair_style dpd/gen 1.0 1.0 5", "pair_coeff 1 1 25 4.5 0.5 1.0 bogus 3"},
           "unknown keyword or extra argument 'bogus'"},
          {{"pair_style dpd/gen 1.0 1.0 5", "pair_coeff 1 1 25 4.5 0.5 1.0 2.0"},
           "unknown keyword or extra argument '2.0'"},
          {{"pair_style dpd/gen 1.0 1.0 5", "pair_coeff 1 1 25 4.5 0.5", "run 0"},
           ""},    // LAMMPS's own check: only that it stops
          {{"comm_modify vel no", "pair_style dpd/gen 1.0 1.0 5", "pair_coeff * * 25 4.5 0.5",
            "run 0"},
           "comm_modify vel yes"},
          {{"pair_style hybrid dpd/gen 1.0 1.0 5 zero 1.0", "pair_coeff * * dpd/gen 25 4.5"},
           "expected I J a gamma s"},
          {{"pair_style hybrid dpd/gen 1.0 1.0 5 zero 1.0", "pair_coeff * * dpd/gen 25 4.5 0.5",
            "pair_coeff 1 2 zero", "comm_modify vel no", "run 0"},
           "comm_modify vel yes"},
          {{"pair_style dpd/gen 1.0 1.0 5", "pair_coeff * * 25 4.5 0.5",
            "compute s all dpd/split extra"},
           "compute dpd/split"},
          {{"pair_style zero 1.0", "pair_coeff * *", "compute s all dpd/split", "run 0"},
           "Compute dpd/split requires pair style dpd/gen"},
          {{"pair_style dpd/gen 1.0 1.0 5", "pair_coeff * * 25 4.5 0.5",
            "compute s all dpd/split torque yes", "run 0"},
           "torque yes requires pair style dpd/fpm"},
      },
      [](Lammps &l) {
        setup_box(l);
      });
}
