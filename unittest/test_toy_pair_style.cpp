// A third pair style added as README's "Adding a pair style" says: a law, its coefficient
// description and one registration line, here inside the test. Its forces against the analytic
// ones, its pair_coeff errors, and fix etd's implicit scheme on it (which takes its friction
// from the law: the same trajectory as dpd/gen's where the conservative forces vanish).
#include "lammps_fixture.h"
#include "pair_dpd_style.h"

#include <gtest/gtest.h>

#include "force.h"
#include "lammps.h"
#include "library.h"
#include "version.h"

#include <cmath>

using etdtest::Lammps;

namespace {

// the law: DPD with conservative force a (1 - r^2/rc^2) along e, whose energy is
// a rc [(1 - x) - (1 - x^3)/3] at x = r/rc
struct QuadraticConservative {
  static double force(const etd::PairCoefficients &c, double rsq, double r, double special)
  {
    if (rsq >= c.rcsq_c) return 0.0;
    return special * c.a * (1.0 - rsq / c.rcsq_c);
  }
  static double energy(const etd::PairCoefficients &c, double rsq, double r, double special)
  {
    if (rsq >= c.rcsq_c) return 0.0;
    const double x = r * c.inv_rc_c;
    return special * c.a * c.rc_c * ((1.0 - x) - (1.0 - x * x * x) / 3.0);
  }
};

// its coefficients: pair_coeff I J a gamma [cutoff], friction weight (1 - r/rc)^2
struct ToyStyle {
  static constexpr const char *name = "dpd/toy";
  static constexpr const char *info = "ETD-DPD test: DPD with a quadratic conservative weight";
  using Law = etd::CentralDpdLaw<QuadraticConservative>;

  enum { A, GAMMA, CUTOFF };
  static constexpr etd::CoeffParam params[] = {
      {"a", "a", etd::CoeffArg::Required, etd::CoeffBound::Any, etd::DEFAULT_VALUE, 0.0, false,
       nullptr, "a0"},
      {"gamma", "gamma", etd::CoeffArg::Required, etd::CoeffBound::NonNegative, etd::DEFAULT_VALUE,
       0.0, false, nullptr, "gamma"},
      {"cutoff", "cutoff", etd::CoeffArg::Optional, etd::CoeffBound::Positive, etd::DEFAULT_CUTOFF,
       0.0, true, nullptr, nullptr},
  };

  static etd::PairCoefficients coefficients(const double *v, double kT)
  {
    etd::PairCoefficients c;
    c.set(v[A], v[GAMMA], 2.0, 1.0, v[CUTOFF], v[CUTOFF], kT);
    return c;
  }
};

// what LAMMPS's plugin_register does with a pair style, for this instance alone (its list of
// loaded plugins is global to the process)
void add_pair_style(lammpsplugin_t *plugin, void *lmp)
{
  auto *instance = static_cast<LAMMPS_NS::LAMMPS *>(lmp);
  (*instance->force->pair_map)[plugin->name] = (LAMMPS_NS::Force::PairCreator) plugin->creator.v1;
}

void register_toy(Lammps &l)
{
  lammpsplugin_t plugin = {};
  plugin.version = LAMMPS_VERSION;
  plugin.author = "ETD-DPD tests";
  LAMMPS_NS::register_pair_style<ToyStyle>(plugin, &add_pair_style, l.lmp);
}

// two atoms 0.6 apart along x, atom 1 moving towards atom 2
void two_atoms(Lammps &l, const std::string &style, const std::string &coeff)
{
  register_toy(l);
  l.cmds({"units lj", "atom_modify map array", "comm_modify vel yes",
          "region box block 0 10 0 10 0 10", "create_box 1 box", "create_atoms 1 single 5 5 5",
          "create_atoms 1 single 5.6 5 5", "mass 1 1.0", "group first id 1",
          "velocity first set 0.5 0 0", "timestep 0.01", "thermo_modify norm no",
          "pair_style " + style, "pair_coeff " + coeff, "run 0 post no"});
}

}    // namespace

TEST(ToyPairStyle, ForceEnergyAndSingleAsTheLaw)
{
  Lammps l;
  two_atoms(l, "dpd/toy 0.0 1.2 5", "1 1 25.0 4.5");
  const double r = 0.6, rc = 1.2, a = 25.0, gamma = 4.5;
  const double conservative = a * (1.0 - r * r / (rc * rc));
  const double dissipative = -gamma * (1.0 - r / rc) * (1.0 - r / rc) * (-0.5);    // e = -x
  const auto f = l.gather("f");
  EXPECT_NEAR(f[0], -(conservative + dissipative), 1e-12);    // on atom 1, along e = -x
  EXPECT_NEAR(f[3], conservative + dissipative, 1e-12);
  const double x = r / rc;
  EXPECT_NEAR(l.thermo("pe"), a * rc * ((1.0 - x) - (1.0 - x * x * x) / 3.0), 1e-12);

  // single(), through compute pair/local: the conservative part (the pair's row on one rank)
  l.cmds({"compute pairs all pair/local dist eng force", "run 0 post no"});
  const int rows =
      *static_cast<int *>(lammps_extract_compute(l.lmp, "pairs", LMP_STYLE_LOCAL, LMP_SIZE_ROWS));
  auto **local = static_cast<double **>(
      lammps_extract_compute(l.lmp, "pairs", LMP_STYLE_LOCAL, LMP_TYPE_ARRAY));
  double mine[2] = {0.0, 0.0}, all[2];    // force, energy
  for (int row = 0; row < rows; row++) {
    mine[0] += local[row][2];
    mine[1] += local[row][1];
  }
  MPI_Allreduce(mine, all, 2, MPI_DOUBLE, MPI_SUM, l.comm);
  EXPECT_NEAR(all[0], conservative, 1e-12);
  EXPECT_NEAR(all[1], a * rc * ((1.0 - x) - (1.0 - x * x * x) / 3.0), 1e-12);
}

TEST(ToyPairStyle, CoefficientErrorsFromItsDescription)
{
  etdtest::expect_errors(
      {
          {{"pair_style dpd/toy 1.0 1.0 5", "pair_coeff 1 1 25"}, "expected I J a gamma [cutoff]"},
          {{"pair_style dpd/toy 1.0 1.0 5", "pair_coeff 1 1 25 -1"}, "gamma must be >= 0"},
          {{"pair_style dpd/toy 1.0 1.0 5", "pair_coeff 1 1 25 1 0"}, "cutoff must be > 0"},
          {{"pair_style dpd/toy 1.0 1.0 5", "pair_coeff 1 1 25 1 1 1"},
           "expected I J a gamma [cutoff], got 6 arguments"},
      },
      [](Lammps &l) {
        register_toy(l);
        l.cmds({"region box block 0 4 0 4 0 4", "create_box 1 box"});
      });
}

// fix etd scheme implicit applies the law's friction and noise itself: with a = 0 the toy
// style and dpd/gen (s = 2, the same friction) give the same trajectory to the bit
TEST(ToyPairStyle, ImplicitSchemeTakesItsFriction)
{
  const std::string data = etdtest::work_file("toy_config.data");
  etdtest::write_random_data(data, 300, 5.0, 31, 1, 1.0);
  auto run = [&](const std::string &style, const std::string &coeff) {
    Lammps l;
    register_toy(l);
    l.cmds({"units lj", "atom_modify map array", "comm_modify vel yes",
            "neigh_modify every 1 delay 0 check yes", "read_data " + data, "mass 1 0.05",
            "timestep 0.01", "pair_style " + style + " 1.0 1.0 77", "pair_coeff " + coeff,
            "fix 1 all etd scheme implicit", "run 50 post no"});
    return l.gather("v");
  };
  const auto toy = run("dpd/toy", "* * 0.0 4.5");
  const auto gen = run("dpd/gen", "* * 0.0 4.5 2.0");
  ASSERT_EQ(toy.size(), gen.size());
  for (size_t k = 0; k < toy.size(); k++) ASSERT_EQ(toy[k], gen[k]) << k;

  // with a != 0 it runs under both schemes (the diagonal one takes the friction diagonal
  // from the pair loop) and stays near the set temperature
  for (const std::string scheme : {"implicit", "diagonal"}) {
    Lammps l;
    register_toy(l);
    l.cmds({"units lj", "atom_modify map array", "comm_modify vel yes",
            "neigh_modify every 1 delay 0 check yes", "read_data " + data, "mass 1 0.05",
            "timestep 0.01", "pair_style dpd/toy 1.0 1.0 77", "pair_coeff * * 25.0 4.5",
            "fix 1 all etd scheme " + scheme, "run 200 post no"});
    EXPECT_NEAR(l.thermo("temp"), 1.0, 0.3) << scheme;
  }
}
