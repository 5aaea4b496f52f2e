// The peer in the same binary: LAMMPS's fix shardlow with pair_style dpd/fdt (package DPD-REACT)
// beside fix etd scheme implicit with dpd/gen, on the standard fluid (Groot-Warren: n = 3,
// a = 25, gamma = 4.5, s = 2) at a mass and step where velocity-Verlet fails. Both are judged
// as a user reads them: LAMMPS's temp of the velocities at the end of the step, and the
// pressure. The accuracy matrix (bench/accuracy) does the same at scale.
#include "lammps_fixture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using etdtest::Lammps;

namespace {

const std::string DATA = etdtest::work_file("shardlow_peer.data");
constexpr double kMass = 0.01, kStep = 0.005;

struct Means {
  double temp, press;
};

// GW fluid of 3,000 atoms from a random start; `style` sets the pair style and integrator.
// Means of temp and press sampled every 10 steps over 1,500 steps after 300 (at m = 0.01 the
// velocities decorrelate within about one step here: standard error of temp about 0.15 %).
Means run_fluid(const std::vector<std::string> &style)
{
  etdtest::write_random_data(DATA, 3000, 10.0, 2718, 1, 0.0);
  Lammps l;
  l.cmds({"units lj", "atom_modify map array", "comm_modify vel yes",
          "neigh_modify every 1 delay 0 check yes", "read_data " + DATA,
          "mass 1 " + std::to_string(kMass), "velocity all create 1.0 8731 mom yes dist gaussian",
          "timestep " + std::to_string(kStep)});
  l.cmds(style);
  l.cmds({"run 300 post no", "reset_timestep 0",
          "fix average all ave/time 10 150 1500 c_thermo_temp c_thermo_press",
          "run 1500 post no"});
  return {l.fix_vector("average", 0), l.fix_vector("average", 1)};
}

}    // namespace

// Measured (1 rank): shardlow 1.0004 / 23.67, implicit 0.9998 / 23.66. The implicit scheme's
// end-of-step velocities are its friction step's output (doc/fix_etd.rst); BAOAB's end-of-step
// velocities would read 2.9 % low here and fail.
TEST(ShardlowPeer, BothHoldTemperatureAndAgreeOnPressure)
{
  const Means peer = run_fluid({"pair_style dpd/fdt 1.0 1.0 4242", "pair_coeff * * 25.0 3.0",
                                "fix ssa all shardlow", "fix integrate all nve"});
  const Means ours = run_fluid({"pair_style dpd/gen 1.0 1.0 4242", "pair_coeff * * 25.0 4.5 2.0",
                                "fix integrate all etd scheme implicit"});
  std::printf("m = %g, dt = %g: shardlow temp %.4f press %.3f; implicit temp %.4f press %.3f\n",
              kMass, kStep, peer.temp, peer.press, ours.temp, ours.press);
  EXPECT_NEAR(peer.temp, 1.0, 0.01);
  EXPECT_NEAR(ours.temp, 1.0, 0.01);
  EXPECT_NEAR(ours.press / peer.press, 1.0, 0.01);
}

// Each integrator refuses the other's pair style. (LAMMPS's refusal of fix shardlow in a
// triclinic box is shown by bench/shardlow, not here: in 29Sep2021 the instance crashes in its
// destructor after that ERROR.)
TEST(ShardlowPeer, EachRefusesTheOthersPairStyle)
{
  const auto setup = [](Lammps &l) {
    etdtest::write_random_data(DATA, 200, 4.0, 2718, 1, 0.0);
    l.cmds({"units lj", "atom_modify map array", "comm_modify vel yes",
            "neigh_modify every 1 delay 0 check yes", "read_data " + DATA, "mass 1 0.01"});
  };
  etdtest::expect_errors(
      {{{"pair_style dpd/fdt 1.0 1.0 4242", "pair_coeff * * 25.0 3.0",
         "fix integrate all etd scheme implicit", "run 1"},
        "Fix etd requires pair style dpd/gen or dpd/fpm"},
       {{"pair_style dpd/fdt 1.0 1.0 4242", "pair_coeff * * 25.0 3.0", "fix integrate all etd",
         "run 1"},
        "Fix etd requires pair style dpd/gen or dpd/fpm"},
       {{"pair_style dpd/gen 1.0 1.0 4242", "pair_coeff * * 25.0 4.5 2.0",
         "fix ssa all shardlow"},
        ""}},
      setup);
}
