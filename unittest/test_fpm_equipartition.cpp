// Equipartition with pair_style dpd/fpm: translational and rotational kBT of the fluid of Pan,
// Pivkin and Karniadakis (rho = 3, a = 25, gamma_C = gamma_S = 4.5, s = 0.5, m = 1,
// diameter 1) with 10 % of the atoms of a second type using the colloid-fluid drag
// (gamma_C = 3.5, gamma_S = 5.5). 1,536 atoms, dt = 0.01, 300 steps of equilibration and
// 2,000 of production (about 5 s per integrator on one core). Label physics.
#include "lammps_fixture.h"

#include <gtest/gtest.h>

#include <cmath>

using etdtest::Lammps;

namespace {

struct Temperatures {
  double translational, rotational;
};

Temperatures measure(const std::string &integrator)
{
  const std::string data = etdtest::work_file("fpm_equipartition.data");
  etdtest::write_random_sphere_data(data, 1536, 8.0, 2468, 10, 0.0, 0.0, 1.0);
  Lammps l;
  l.cmds({"units lj",
          "atom_style sphere",
          "atom_modify map array",
          "comm_modify vel yes",
          "neigh_modify every 1 delay 0 check yes",
          "read_data " + data,
          "set group all mass 1.0",
          "set type 3*10 type 1",
          "velocity all create 1.0 1357 mom yes dist gaussian",
          "pair_style dpd/fpm 1.0 1.0 8642",
          "pair_coeff * * 25 4.5 4.5 0.5",
          "pair_coeff 1 2 25 3.5 5.5 0.5",
          "timestep 0.01",
          "fix integrate all " + integrator,
          "compute rot all erotate/sphere",
          "variable trot equal c_rot/(1.5*atoms)",
          "run 300 post no",
          "reset_timestep 0",
          "fix average all ave/time 10 200 2000 c_thermo_temp v_trot",
          "run 2000 post no"});
  return {l.fix_vector("average", 0), l.fix_vector("average", 1)};
}

}    // namespace

// One sample of either kBT has relative spread sqrt(2/(3N)) = 2.1 %; the 200 samples (every
// 0.1 time units, relaxation times about 0.05) give a standard error near 0.2 %, so the 2 %
// tolerance is about 10 standard errors wide and what it detects is a bias.
TEST(FpmEquipartition, NveSphere)
{
  const Temperatures t = measure("nve/sphere");
  std::printf("fix nve/sphere, dt = 0.01: kBT = %.4f, rotational kBT = %.4f\n", t.translational,
              t.rotational);
  EXPECT_NEAR(t.translational, 1.0, 0.02);
  EXPECT_NEAR(t.rotational, 1.0, 0.02);
}

TEST(FpmEquipartition, FixEtd)
{
  const Temperatures t = measure("etd");
  std::printf("fix etd, dt = 0.01: kBT = %.4f, rotational kBT = %.4f\n", t.translational,
              t.rotational);
  EXPECT_NEAR(t.translational, 1.0, 0.02);
  EXPECT_NEAR(t.rotational, 1.0, 0.02);
}
