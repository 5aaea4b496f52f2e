// pair_style dpd/fpm: reduction to dpd/gen, momentum and angular momentum conservation,
// rank-count and newton independence, restart, write_data, single(), fix etd's angular update
// and every bad-input error.
#include "lammps_fixture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <sstream>

using etdtest::Lammps;

namespace {

const std::string DATA = etdtest::work_file("dpd_fpm_config.data");

// n = 3 fluid of 648 spheres (diameter 1, mass 1) in a 6^3 box, two types, random velocities
// and angular velocities
void setup_box(Lammps &l, const std::string &newton = "on", const std::string &boundary = "p p p")
{
  etdtest::write_random_sphere_data(DATA, 648, 6.0, 4711, 2, 1.5, 2.0, 1.0);
  l.cmds({"units lj", "atom_style sphere", "atom_modify map array", "boundary " + boundary,
          "newton " + newton, "comm_modify vel yes", "neigh_modify every 1 delay 0 check yes",
          "read_data " + DATA, "set group all mass 1.0", "timestep 0.01", "thermo_modify norm no",
          "compute virial all pressure NULL virial", "compute tq all property/atom tqx tqy tqz"});
}

double max_rel_diff(const std::vector<double> &a, const std::vector<double> &b)
{
  double worst = 0.0, scale = 0.0;
  for (size_t i = 0; i < a.size(); i++) scale = std::max(scale, std::fabs(b[i]));
  for (size_t i = 0; i < a.size(); i++) worst = std::max(worst, std::fabs(a[i] - b[i]) / scale);
  return worst;
}

double max_abs(const std::vector<double> &a)
{
  double m = 0.0;
  for (double x : a) m = std::max(m, std::fabs(x));
  return m;
}

struct Snapshot {
  std::vector<double> f, torque, virial;
  double pe;
};

Snapshot snapshot(Lammps &l, const std::string &run = "run 0 post no")
{
  l.cmd(run);
  Snapshot s;
  s.f = l.gather("f");
  s.torque = l.gather_compute("tq", 3);
  for (int k = 0; k < 6; k++) s.virial.push_back(l.compute_vector("virial", k));
  s.pe = l.thermo("pe");
  return s;
}

// total linear momentum and angular momentum (orbital m r x v plus spin I omega, I = 0.4 m r^2)
// of the gathered state; positions unwrapped with the image flags
void momenta(Lammps &l, double p[3], double angular[3], double &angular_scale)
{
  auto x = l.gather("x"), v = l.gather("v"), w = l.gather("omega");
  auto m = l.gather("rmass", 1), rad = l.gather("radius", 1);
  for (int k = 0; k < 3; k++) p[k] = angular[k] = 0.0;
  angular_scale = 0.0;
  for (size_t i = 0; i < m.size(); i++) {
    const double *xi = &x[3 * i], *vi = &v[3 * i], *wi = &w[3 * i];
    const double inertia = 0.4 * m[i] * rad[i] * rad[i];
    const double lx = m[i] * (xi[1] * vi[2] - xi[2] * vi[1]);
    const double ly = m[i] * (xi[2] * vi[0] - xi[0] * vi[2]);
    const double lz = m[i] * (xi[0] * vi[1] - xi[1] * vi[0]);
    angular[0] += lx + inertia * wi[0];
    angular[1] += ly + inertia * wi[1];
    angular[2] += lz + inertia * wi[2];
    angular_scale += std::fabs(lx) + std::fabs(ly) + std::fabs(lz);
    for (int k = 0; k < 3; k++) p[k] += m[i] * vi[k];
  }
}

}    // namespace

TEST(PairDpdFpm, ZeroShearFrictionEqualsDpdGen)
{
  // at T = 0 (deterministic) and at T = 1: the central noise is the number dpd/gen draws
  for (const char *T : {"0.0", "1.0"}) {
    Lammps l;
    setup_box(l);
    l.cmds({std::string("pair_style dpd/gen ") + T + " 1.0 123", "pair_coeff 1 1 25.0 4.5 0.5",
            "pair_coeff 1 2 30.0 6.0 0.5 0.9", "pair_coeff 2 2 18.75 3.0 2.0"});
    const Snapshot gen = snapshot(l);
    l.cmds({std::string("pair_style dpd/fpm ") + T + " 1.0 123", "pair_coeff 1 1 25.0 4.5 0.0 0.5",
            "pair_coeff 1 2 30.0 6.0 0.0 0.5 0.9", "pair_coeff 2 2 18.75 3.0 0.0 2.0"});
    const Snapshot fpm = snapshot(l);
    EXPECT_LT(max_rel_diff(fpm.f, gen.f), 1e-12) << "T = " << T;
    EXPECT_LT(max_rel_diff(fpm.virial, gen.virial), 1e-12) << "T = " << T;
    EXPECT_NEAR(fpm.pe, gen.pe, 1e-12 * std::fabs(gen.pe));
    EXPECT_EQ(max_abs(fpm.torque), 0.0);
  }
}

TEST(PairDpdFpm, ShearFrictionMakesTorques)
{
  // the test above must not pass because torques are never written
  Lammps l;
  setup_box(l);
  l.cmds({"pair_style dpd/fpm 0.0 1.0 123", "pair_coeff * * 25.0 4.5 4.5 0.5"});
  const Snapshot s = snapshot(l);
  EXPECT_GT(max_abs(s.torque), 1.0);
}

TEST(PairDpdFpm, ForceAndTorqueSumsVanishWithNoise)
{
  // sum F = 0 and sum (r_i x F_i + T_i) = 0 for every pair set, newton on and off; the
  // box is non-periodic so that r_i x F_i uses the positions the pairs see
  for (const std::string newton : {"on", "off"}) {
    Lammps l;
    setup_box(l, newton, "s s s");
    l.cmds({"pair_style dpd/fpm 1.0 1.0 31", "pair_coeff * * 25 4.5 4.5 0.5",
            "pair_coeff 1 2 25 3.5 5.5 0.5 1.2"});
    const Snapshot s = snapshot(l);
    auto x = l.gather("x");
    double total[3] = {0, 0, 0}, angular[3] = {0, 0, 0}, fscale = 0, lscale = 0;
    for (size_t a = 0; a < x.size() / 3; a++) {
      const double *r = &x[3 * a], *f = &s.f[3 * a], *t = &s.torque[3 * a];
      angular[0] += r[1] * f[2] - r[2] * f[1] + t[0];
      angular[1] += r[2] * f[0] - r[0] * f[2] + t[1];
      angular[2] += r[0] * f[1] - r[1] * f[0] + t[2];
      for (int k = 0; k < 3; k++) {
        total[k] += f[k];
        fscale += std::fabs(f[k]);
        lscale += std::fabs(r[k]) * std::fabs(f[(k + 1) % 3]);
      }
    }
    for (int k = 0; k < 3; k++) {
      EXPECT_LT(std::fabs(total[k]), 1e-13 * fscale) << "newton " << newton;
      EXPECT_LT(std::fabs(angular[k]), 1e-13 * lscale) << "newton " << newton;
    }
  }
}

TEST(PairDpdFpm, NveSphereConservesMomentumAndAngularMomentum)
{
  // velocity-Verlet kicks change sum m v and sum (m r x v + I omega) by dt/2 times the force
  // and torque sums (zero) and the drift leaves them unchanged: both hold to round-off per step
  for (const std::string newton : {"on", "off"}) {
    Lammps l;
    setup_box(l, newton, "s s s");
    l.cmds({"pair_style dpd/fpm 1.0 1.0 31", "pair_coeff * * 25 4.5 4.5 0.5",
            "pair_coeff 1 2 25 3.5 5.5 0.5", "fix 1 all nve/sphere", "run 0 post no"});
    double p0[3], l0[3], scale;
    momenta(l, p0, l0, scale);
    for (int step = 0; step < 5; step++) {
      l.cmd("run 2 post no");
      double p[3], am[3], s;
      momenta(l, p, am, s);
      for (int k = 0; k < 3; k++) {
        EXPECT_NEAR(p[k], p0[k], 1e-12 * 648) << "newton " << newton << " step " << step;
        EXPECT_NEAR(am[k], l0[k], 1e-13 * scale) << "newton " << newton << " step " << step;
      }
    }
  }
}

TEST(PairDpdFpm, ForceSplitAndFrictionAreConsistent)
{
  // compute dpd/split: the C, D and R parts add up to the force; with gamma = 0 (T = 0) there
  // is no D; the D part includes the rotational drag (zero linear velocities, spinning atoms)
  Lammps l;
  setup_box(l);
  l.cmds({"pair_style dpd/fpm 1.0 1.0 5", "pair_coeff * * 25 4.5 4.5 0.5",
          "compute split all dpd/split", "thermo_style custom step c_split[1]", "run 0 post no"});
  auto split = l.gather_compute("split", 9);
  auto f = l.gather("f");
  for (size_t a = 0; a < f.size() / 3; a++)
    for (int k = 0; k < 3; k++)
      EXPECT_NEAR(split[9 * a + k] + split[9 * a + 3 + k] + split[9 * a + 6 + k], f[3 * a + k],
                  1e-11 * (1 + std::fabs(f[3 * a + k])));
  l.cmds({"velocity all set 0 0 0", "run 0 post no"});
  split = l.gather_compute("split", 9);
  double dissipative = 0.0;
  for (size_t a = 0; a < f.size() / 3; a++)
    for (int k = 0; k < 3; k++)
      dissipative = std::max(dissipative, std::fabs(split[9 * a + 3 + k]));
  EXPECT_GT(dissipative, 0.1);
}

// Under fix etd scheme implicit the pair style computes only the conservative force, and
// compute dpd/split's C columns are that force (D and R come from the scheme).
TEST(PairDpdFpm, ForceSplitUnderTheImplicitSchemeHasTheConservativeForce)
{
  Lammps l;
  setup_box(l);
  l.cmds({"pair_style dpd/fpm 1.0 1.0 5", "pair_coeff * * 25 4.5 4.5 0.5",
          "fix 1 all etd scheme implicit", "compute split all dpd/split",
          "thermo_style custom step c_split[1]", "run 0 post no"});
  const auto split = l.gather_compute("split", 9);
  const auto f = l.gather("f");
  double largest = 0.0;
  for (size_t a = 0; a < f.size() / 3; a++)
    for (int k = 0; k < 3; k++) {
      EXPECT_NEAR(split[9 * a + k], f[3 * a + k], 1e-11 * (1 + std::fabs(f[3 * a + k])));
      largest = std::max(largest, std::fabs(split[9 * a + k]));
    }
  EXPECT_GT(largest, 1.0);
}

TEST(PairDpdFpm, TorqueSplitAddsUpToTheTorque)
{
  // compute dpd/split torque yes: the torque's dissipative and random parts (columns 10-15) add
  // up to each atom's torque; at T = 0 the random part is zero and the dissipative part is the
  // whole torque; with a spin and no noise the dissipative torque opposes the spin
  // (-gamma_S w (r^2/4)(1 - e e) Omega summed over pairs: its z component is negative for a
  // positive Omega_z). The first nine columns stay those of the force.
  Lammps l;
  setup_box(l);
  l.cmds({"pair_style dpd/fpm 1.0 1.0 5", "pair_coeff * * 25 4.5 6.0 0.5",
          "compute split all dpd/split torque yes", "compute force_only all dpd/split torque no",
          "thermo_style custom step c_split[10] c_force_only[1]", "run 0 post no"});
  auto split = l.gather_compute("split", 15);
  auto force_only = l.gather_compute("force_only", 9);
  auto f = l.gather("f");
  auto tq = l.gather_compute("tq", 3);
  const size_t natoms = f.size() / 3;
  double random_torque = 0.0;
  for (size_t a = 0; a < natoms; a++)
    for (int k = 0; k < 3; k++) {
      EXPECT_NEAR(split[15 * a + 9 + k] + split[15 * a + 12 + k], tq[3 * a + k],
                  1e-11 * (1 + std::fabs(tq[3 * a + k])));
      EXPECT_EQ(split[15 * a + 3 + k], force_only[9 * a + 3 + k]);
      random_torque = std::max(random_torque, std::fabs(split[15 * a + 12 + k]));
    }
  EXPECT_GT(random_torque, 1.0);    // the noise makes torques: the check above is not empty

  l.cmds({"pair_style dpd/fpm 0.0 1.0 5", "pair_coeff * * 25 4.5 6.0 0.5", "velocity all set 0 0 0",
          "set group all omega 0 0 2.0", "run 0 post no"});
  split = l.gather_compute("split", 15);
  tq = l.gather_compute("tq", 3);
  for (size_t a = 0; a < natoms; a++) {
    for (int k = 0; k < 3; k++) {
      EXPECT_EQ(split[15 * a + 12 + k], 0.0);
      EXPECT_NEAR(split[15 * a + 9 + k], tq[3 * a + k], 1e-12 * (1 + std::fabs(tq[3 * a + k])));
    }
    // a lone atom (no partner inside the cutoff) has no torque at all
    if (std::fabs(tq[3 * a + 2]) > 0.0) EXPECT_LT(split[15 * a + 11], 0.0);
  }
}

TEST(PairDpdFpm, FixEtdUsesTheRotationalFrictionDiagonal)
{
  // two atoms 0.6 apart along x, a = gamma_C = 0, T = 0; atom 1 spins about z, atom 2 does not.
  // The pair's rotational friction is G = gamma_S w r^2/4 on z for both; the torque on each is
  // -G (w1 + w2). The ETD update then gives w1' = e^z w1 and w2' = -(1 - e^z) w1 with
  // z = -G dt / I: an explicit update would give 1 - G dt/I instead of e^z.
  Lammps l;
  l.cmds({"units lj", "atom_style sphere", "atom_modify map array", "comm_modify vel yes",
          "neigh_modify every 1 delay 0 check yes", "region box block 0 10 0 10 0 10",
          "create_box 1 box", "create_atoms 1 single 5 5 5", "create_atoms 1 single 5.6 5 5",
          "set group all diameter 0.5", "set group all mass 2.0", "group first id 1",
          "set group first omega 0 0 3.0", "timestep 0.2", "pair_style dpd/fpm 0.0 1.0 7",
          "pair_coeff 1 1 0.0 0.0 8.0 0.5", "fix 1 all etd", "run 1 post no"});
  auto w = l.gather("omega");
  const double G = 8.0 * std::sqrt(0.4) * 0.09, inertia = 0.4 * 2.0 * 0.0625;
  const double decay = std::exp(-G * 0.2 / inertia);
  EXPECT_LT(decay, 0.5);    // stiff: the explicit update would differ a lot
  EXPECT_NEAR(w[2], decay * 3.0, 1e-12);
  EXPECT_NEAR(w[5], -(1 - decay) * 3.0, 1e-12);
  EXPECT_NEAR(w[0], 0.0, 1e-14);
  EXPECT_NEAR(w[1], 0.0, 1e-14);
}

TEST(PairDpdFpm, FixEtdKeepsStiffRotationNearEquilibrium)
{
  // diameter 0.3 (I = 0.009 m): Gamma_rot dt / I is about 2.3 at dt = 0.01, where fix
  // nve/sphere diverges (measured kBT_rot 26 after 800 steps); fix etd stays near kBT = 1
  // (measured 0.84: the diagonal scheme's under-estimate of the noise at large |z|)
  Lammps l;
  setup_box(l);
  l.cmds({"set group all diameter 0.3", "pair_style dpd/fpm 1.0 1.0 5",
          "pair_coeff * * 25 4.5 4.5 0.5", "velocity all create 1.0 77 dist gaussian",
          "compute rot all erotate/sphere", "variable trot equal c_rot/(1.5*atoms)",
          "fix 1 all etd", "run 200 post no", "reset_timestep 0",
          "fix avg all ave/time 10 30 300 v_trot c_thermo_temp", "run 300 post no"});
  const double rotational_kT = l.fix_vector("avg", 0), kT = l.fix_vector("avg", 1);
  std::printf("fix etd, diameter 0.3: kBT = %.4f, rotational kBT = %.4f\n", kT, rotational_kT);
  EXPECT_GT(rotational_kT, 0.6);
  EXPECT_LT(rotational_kT, 1.2);
  EXPECT_NEAR(kT, 1.0, 0.1);
}

TEST(PairDpdFpm, RestartContinuesExactly)
{
  const std::string restart = etdtest::work_file("dpd_fpm.restart");
  for (const std::string integrator : {"nve/sphere", "etd"}) {
    std::vector<double> x_ref, v_ref, w_ref;
    {
      Lammps l;
      setup_box(l);
      l.cmds({"pair_style dpd/fpm 1.0 1.0 31", "pair_coeff * * 25 4.5 4.5 0.5",
              "pair_coeff 1 2 30 3.5 5.5 1.0 1.1", "fix 1 all " + integrator, "run 20",
              "write_restart " + restart, "run 20"});
      x_ref = l.gather("x");
      v_ref = l.gather("v");
      w_ref = l.gather("omega");
    }
    Lammps l;
    l.cmds({"read_restart " + restart, "comm_modify vel yes",
            "neigh_modify every 1 delay 0 check yes", "timestep 0.01", "fix 1 all " + integrator,
            "run 20"});
    EXPECT_LT(max_rel_diff(l.gather("x"), x_ref), 1e-13) << integrator;
    EXPECT_LT(max_rel_diff(l.gather("v"), v_ref), 1e-13) << integrator;
    EXPECT_LT(max_rel_diff(l.gather("omega"), w_ref), 1e-13) << integrator;
  }
}

TEST(PairDpdFpm, WriteDataRoundTripsPerPairSettings)
{
  const std::string data = etdtest::work_file("dpd_fpm_roundtrip.data");
  Snapshot ref;
  {
    Lammps l;
    setup_box(l);
    l.cmds({"pair_style dpd/fpm 1.0 1.0 31", "pair_coeff 1 1 25 4.5 4.5 0.5",
            "pair_coeff 2 2 18 3 1 2", "pair_coeff 1 2 40 3.5 5.5 0.25 1.3"});
    ref = snapshot(l);
    l.cmd("write_data " + data + " pair ij");
  }
  Lammps l;
  l.cmds({"units lj", "atom_style sphere", "atom_modify map array", "comm_modify vel yes",
          "neigh_modify every 1 delay 0 check yes", "pair_style dpd/fpm 1.0 1.0 31",
          "read_data " + data, "timestep 0.01", "compute virial all pressure NULL virial",
          "compute tq all property/atom tqx tqy tqz"});
  const Snapshot back = snapshot(l);
  EXPECT_LT(max_rel_diff(back.f, ref.f), 1e-13);
  EXPECT_LT(max_rel_diff(back.torque, ref.torque), 1e-13);
}

TEST(PairDpdFpm, SingleGivesTheConservativeForceToPairWrite)
{
  const std::string table = etdtest::work_file("dpd_fpm_table.txt");
  if (etdtest::world_rank() == 0) std::remove(table.c_str());    // pair_write appends
  Lammps l;
  setup_box(l);
  l.cmds({"pair_style dpd/fpm 1.0 1.0 31", "pair_coeff * * 25 3.5 5.5 0.5 1.2",
          "pair_write 1 2 10 r 0.1 1.19 " + table + " DPDFPM"});
  if (etdtest::world_rank() != 0) return;
  std::ifstream in(table);
  std::string line;
  int rows = 0;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    int index;
    double r, e, f;
    if (!(fields >> index >> r >> e >> f)) continue;
    EXPECT_NEAR(f, 25 * (1 - r / 1.2), 1e-10) << line;
    EXPECT_NEAR(e, 0.5 * 25 * 1.2 * (1 - r / 1.2) * (1 - r / 1.2), 1e-10) << line;
    rows++;
  }
  EXPECT_EQ(rows, 10);
}

TEST(PairDpdFpm, ForcesAndTorquesAgreeAcrossRankCountsAndNewton)
{
  // one program, sub-communicators of 1, 2 and 4 ranks (as many as this run has), newton on and
  // off; 1,500 spheres read from a data file, compared after 5 steps of fix nve/sphere
  const std::string data = etdtest::work_file("dpd_fpm_ranks.data");
  etdtest::write_random_sphere_data(data, 1500, 8.0, 99, 2, 1.0, 1.0, 1.0);
  std::vector<std::vector<double>> results;
  for (const std::string newton : {"on", "off"})
    for (int ranks : {1, 2, 4}) {
      if (ranks > etdtest::world_size()) continue;
      results.push_back(etdtest::on_ranks(ranks, [&](Lammps &l) {
        l.cmds({"units lj", "atom_style sphere", "atom_modify map array", "newton " + newton,
                "comm_modify vel yes", "neigh_modify every 1 delay 0 check yes",
                "read_data " + data, "set group all mass 1.0", "timestep 0.005",
                "pair_style dpd/fpm 1.0 1.0 2718", "pair_coeff * * 25 4.5 4.5 0.5",
                "pair_coeff 1 2 25 3.5 5.5 0.5", "compute tq all property/atom tqx tqy tqz",
                "fix 1 all nve/sphere", "run 5 post no"});
        auto out = l.gather("f");
        auto tq = l.gather_compute("tq", 3);
        auto w = l.gather("omega");
        out.insert(out.end(), tq.begin(), tq.end());
        out.insert(out.end(), w.begin(), w.end());
        return out;
      }));
    }
  if (etdtest::world_rank() != 0) return;
  ASSERT_GE(results.size(), 2u);
  const double scale = max_abs(results[0]);
  for (size_t k = 1; k < results.size(); k++) {
    double worst = 0.0;
    for (size_t i = 0; i < results[0].size(); i++)
      worst = std::max(worst, std::fabs(results[k][i] - results[0][i]));
    EXPECT_LT(worst, 1e-10 * scale) << "variant " << k;
  }
}

TEST(PairDpdFpm, BadInputGivesClearErrors)
{
  etdtest::expect_errors(
      {
          {{"pair_style dpd/fpm 1.0 1.0"}, "expected 3 arguments"},
          {{"pair_style dpd/fpm -1.0 1.0 5"}, "temperature must be >= 0"},
          {{"pair_style dpd/fpm 1.0 0.0 5"}, "cutoff must be > 0"},
          {{"pair_style dpd/fpm 1.0 1.0 -3"}, "seed must be a positive integer"},
          {{"pair_style dpd/fpm 1.0 1.0 abc"},
           "'abc'"},    // LAMMPS parses the number: its wording is not ours; the argument is named
          {{"pair_style dpd/fpm 1.0 1.0 5", "pair_coeff 1 1 25 4.5 4.5"},
           "expected I J a gamma_C gamma_S s"},
          {{"pair_style dpd/fpm 1.0 1.0 5", "pair_coeff 1 1 25 4.5 4.5 0.5 1.0 2.0"},
           "expected I J a gamma_C gamma_S s"},
          {{"pair_style dpd/fpm 1.0 1.0 5", "pair_coeff 1 1 25 -4.5 4.5 0.5"},
           "gamma_C must be >= 0"},
          {{"pair_style dpd/fpm 1.0 1.0 5", "pair_coeff 1 1 25 4.5 -4.5 0.5"},
           "gamma_S must be >= 0"},
          {{"pair_style dpd/fpm 1.0 1.0 5", "pair_coeff 1 1 25 4.5 4.5 0"},
           "exponent s must be > 0"},
          {{"pair_style dpd/fpm 1.0 1.0 5", "pair_coeff 1 1 25 4.5 4.5 0.5 -1"},
           "cutoff must be > 0"},
          {{"pair_style dpd/fpm 1.0 1.0 5", "pair_coeff 1 1 25 4.5 4.5 0.5", "run 0"},
           ""},    // LAMMPS's own check: only that it stops
          {{"pair_style dpd/fpm 1.0 1.0 5", "pair_coeff 1 1 25 4.5 4.5 0.5",
            "pair_coeff 2 2 25 4.5 4.5 0.5", "run 0"},
           "types 1 2 are not set (no mixing)"},
          {{"comm_modify vel no", "pair_style dpd/fpm 1.0 1.0 5", "pair_coeff * * 25 4.5 4.5 0.5",
            "run 0"},
           "comm_modify vel yes"},
          {{"pair_style hybrid dpd/fpm 1.0 1.0 5 zero 1.0", "pair_coeff * * dpd/fpm 25 4.5 4.5"},
           "expected I J a gamma_C gamma_S s"},
          {{"pair_style dpd/fpm 1.0 1.0 5", "pair_coeff * * 25 4.5 4.5 0.5",
            "set atom 3 diameter 0.0", "fix 1 all etd", "run 1"},
           "atom 3 has zero moment of inertia"},
          {{"pair_style dpd/fpm 1.0 1.0 5", "pair_coeff * * 25 4.5 4.5 0.5",
            "compute s all dpd/split torque maybe"},
           "torque must be yes or no, got maybe"},
          {{"pair_style dpd/fpm 1.0 1.0 5", "pair_coeff * * 25 4.5 4.5 0.5",
            "compute s all dpd/split torque"},
           "keyword torque needs yes or no"},
          {{"pair_style dpd/fpm 1.0 1.0 5", "pair_coeff * * 25 4.5 4.5 0.5",
            "compute s all dpd/split torque yes", "fix 1 all etd scheme implicit", "run 0"},
           "torque yes is not supported with fix etd scheme implicit"},
      },
      [](Lammps &l) {
        setup_box(l);
      });
  // atom styles without angular velocity, and without atom IDs
  {
    Lammps l;
    etdtest::write_random_data(etdtest::work_file("dpd_fpm_atomic.data"), 100, 4.0, 3, 1, 1.0);
    l.cmds({"units lj", "atom_style atomic", "comm_modify vel yes",
            "neigh_modify every 1 delay 0 check yes",
            "read_data " + etdtest::work_file("dpd_fpm_atomic.data")});
    const std::string message =
        l.error_of({"pair_style dpd/fpm 1.0 1.0 5", "pair_coeff * * 25 4.5 4.5 0.5", "run 0"});
    EXPECT_NE(message.find("requires atoms with angular velocity and torque"), std::string::npos)
        << message;
  }
  {
    Lammps l;
    const std::string message =
        l.error_of({"units lj", "atom_style sphere", "atom_modify id no", "comm_modify vel yes",
                    "neigh_modify every 1 delay 0 check yes", "region box block 0 4 0 4 0 4",
                    "create_box 1 box", "create_atoms 1 random 50 3 box",
                    "pair_style dpd/fpm 1.0 1.0 5", "pair_coeff * * 25 4.5 4.5 0.5", "run 0"});
    EXPECT_NE(message.find("requires atom IDs"), std::string::npos) << message;
  }
}
