// Equilibrium temperature: dpd/gen with fix nve (m = 1) and fix etd (m = 0.01).
// These runs take about 30 s together; they are part of the default suite (label physics).
#include "lammps_fixture.h"

#include <gtest/gtest.h>

#include <cmath>

using etdtest::Lammps;

namespace {

// means over the production run, sampled every 10 steps, of kBT and of the given extra quantities
std::vector<double> mean_values(const std::string &pair_coeff, double mass, double dt, int natoms,
                                double L, int equilibrate, int production,
                                const std::string &integrator,
                                const std::vector<std::string> &extra)
{
  std::string joined;
  for (const std::string &quantity : extra) joined += " " + quantity;
  const std::string data = etdtest::work_file("equilibrium_" + std::to_string(natoms) + ".data");
  etdtest::write_random_data(data, natoms, L, 31337, 1, 0.0);
  Lammps l;
  l.cmds({"units lj", "atom_modify map array", "comm_modify vel yes",
          "neigh_modify every 1 delay 0 check yes", "read_data " + data,
          "mass 1 " + std::to_string(mass), "velocity all create 1.0 8731 mom yes dist gaussian",
          "pair_style dpd/gen 1.0 1.0 4242", pair_coeff, "timestep " + std::to_string(dt),
          "fix integrate all " + integrator, "run " + std::to_string(equilibrate) + " post no",
          "reset_timestep 0",
          "fix average all ave/time 10 " + std::to_string(production / 10) + " " +
              std::to_string(production) + " c_thermo_temp" + joined,
          "run " + std::to_string(production) + " post no"});
  if (extra.empty()) return {l.fix_scalar("average")};
  std::vector<double> means;
  for (size_t k = 0; k <= extra.size(); k++)
    means.push_back(l.fix_vector("average", static_cast<int>(k)));
  return means;
}

double mean_temperature(const std::string &pair_coeff, double mass, double dt, int natoms, double L,
                        int equilibrate, int production, const std::string &integrator)
{
  return mean_values(pair_coeff, mass, dt, natoms, L, equilibrate, production, integrator, {})[0];
}

}    // namespace

// velocity-Verlet at dt = 0.01 runs about 0.7 % hot here (stock pair dpd too: 1.0056-1.0098 over
// 10,000 steps for three seeds), so the 1 % tolerance needs a well-converged mean: 3,000 atoms
// over 16,000 steps scatter by about 0.15 % between seeds.
TEST(Equilibrium, VelocityVerletHoldsTemperatureForS2AndHalf)
{
  for (const char *s : {"2.0", "0.5"}) {
    const double kT = mean_temperature(std::string("pair_coeff 1 1 25.0 4.5 ") + s, 1.0, 0.01, 3000,
                                       10.0, 500, 16000, "nve");
    std::printf("fix nve, m = 1, dt = 0.01, s = %s: kBT = %.4f\n", s, kT);
    EXPECT_NEAR(kT, 1.0, 0.01) << "s = " << s;
  }
}

// Seed 000's fluid at m = 0.01, dt = 0.001 (velocity-Verlet overheats by 10 % here). 4,000 atoms
// over 3,000 steps: standard error of the mean about 0.1 %; tolerance 2 %.
TEST(Equilibrium, EtdHoldsTemperatureAtLowMass)
{
  // order 2 is not asserted here: at this stiffness it overheats (doc/fix_etd.rst)
  for (const char *order : {"1"}) {
    const double kT = mean_temperature("pair_coeff 1 1 18.75 4.5 0.5", 0.01, 0.001, 4000, 10.0, 500,
                                       3000, std::string("etd order ") + order);
    std::printf("fix etd order %s, m = 0.01, dt = 0.001, s = 1/2: kBT = %.4f\n", order, kT);
    EXPECT_NEAR(kT, 1.0, 0.02) << "order " << order;
  }
}

// The implicit scheme at steps where velocity-Verlet fails (m = 0.01: it overheats 10 % at
// dt = 0.001 and fails beyond 0.0009; m = 0.001: fails beyond 0.0002). 4,000 atoms, 1,500
// steps each after 300: standard error about 0.1 %.
TEST(Equilibrium, ImplicitHoldsTemperatureAtLargeSteps)
{
  struct Case {
    double mass, dt;
  };
  for (const Case c : {Case{0.01, 0.003}, Case{0.001, 0.001}}) {
    const double kT = mean_temperature("pair_coeff 1 1 18.75 4.5 0.5", c.mass, c.dt, 4000, 10.0,
                                       300, 1500, "etd scheme implicit");
    std::printf("fix etd scheme implicit, m = %g, dt = %g: kBT = %.4f\n", c.mass, c.dt, kT);
    EXPECT_NEAR(kT, 1.0, 0.01) << "m = " << c.mass << ", dt = " << c.dt;
  }
}

// At m = 0.001, dt = 0.0015, BAOAB's end-of-step velocities would run cool by the splitting's
// dt^2 <F_x^2> / (4 m kBT) = 1.75 % (<F_x^2> = 31.1 for this fluid, doc/fix_etd.rst). The
// scheme leaves the friction step's output in v instead (the half-step form), so LAMMPS's temp
// is the friction-step temperature (the fix's output 5, counted over 3N rather than 3N - 3
// degrees of freedom) and holds kBT. 4,000 atoms, 1,500 steps: standard error about 0.1 %.
TEST(Equilibrium, ImplicitEndOfStepVelocitiesHoldTemperature)
{
  const auto means = mean_values("pair_coeff 1 1 18.75 4.5 0.5", 0.001, 0.0015, 4000, 10.0, 300,
                                 1500, "etd scheme implicit", {"f_integrate[5]"});
  std::printf("m = 0.001, dt = 0.0015: kBT end of step %.4f, after the friction step %.4f\n",
              means[0], means[1]);
  EXPECT_NEAR(means[0], 1.0, 0.006);
  EXPECT_NEAR(means[0] / means[1], 1.0, 1e-3);
}

// Two species driven apart by opposite body forces (+f and -f along x) drift at a steady
// relative velocity that the displacements give exactly. The fix's per-atom output, BAOAB's
// end-of-step velocity v + dt/2 F/m, carries that drift; v itself, the friction step's output,
// lags it by dt/2 <F>/m per species (measured at m = 0.01, dt = 0.005, f = 3 on the s = 1/2
// fluid: displacements 0.820, the output 0.821, v -0.51). doc/fix_etd.rst, "Which velocities
// a step leaves".
TEST(Equilibrium, ImplicitEndVelocityCarriesTheStreamingVelocity)
{
  const std::string data = etdtest::work_file("equilibrium_drift.data");
  etdtest::write_random_data(data, 2048, 8.0, 2024, 2, 0.0);
  const double dt = 0.005;
  const int steps = 1000;
  Lammps l;
  l.cmds({"units lj", "atom_modify map array", "comm_modify vel yes",
          "neigh_modify every 1 delay 0 check yes", "read_data " + data, "mass * 0.01",
          "velocity all create 1.0 8731 mom yes dist gaussian", "pair_style dpd/gen 1.0 1.0 4242",
          "pair_coeff * * 18.75 4.5 0.5", "group A type 1", "group B type 2",
          "fix integrate all etd scheme implicit", "fix pushA A addforce 3.0 0 0",
          "fix pushB B addforce -3.0 0 0", "timestep " + std::to_string(dt), "run 200 post no",
          "reset_timestep 0", "compute comA A com", "compute comB B com", "compute vA A reduce ave vx",
          "compute vB B reduce ave vx", "compute eA A reduce ave f_integrate[1]",
          "compute eB B reduce ave f_integrate[1]",
          "thermo_style custom step c_comA[1] c_comB[1]", "run 0 post no"});
  const double start = l.compute_vector("comA", 0) - l.compute_vector("comB", 0);
  l.cmds({"fix average all ave/time 1 " + std::to_string(steps) + " " + std::to_string(steps) +
              " c_vA c_vB c_eA c_eB",
          "run " + std::to_string(steps) + " post no"});
  const double streaming =
      (l.compute_vector("comA", 0) - l.compute_vector("comB", 0) - start) / (steps * dt);
  const double from_output = l.fix_vector("average", 2) - l.fix_vector("average", 3);
  const double from_v = l.fix_vector("average", 0) - l.fix_vector("average", 1);
  std::printf("relative drift: displacements %.4f, f_integrate[1] %.4f, v %.4f\n", streaming,
              from_output, from_v);
  EXPECT_GT(streaming, 0.5);
  EXPECT_NEAR(from_output / streaming, 1.0, 0.01);
  EXPECT_LT(from_v, 0.5 * streaming);
}
