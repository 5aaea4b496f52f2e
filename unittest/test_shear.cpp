// fix etd under steady shear through fix deform ... remap v, the way LAMMPS users measure a
// viscosity, and under other box changes. The periodic image of an atom across the sheared
// boundary moves with its owner's velocity plus the box's rate (LAMMPS's ghost communication
// adds it); the implicit scheme must see the same relative velocities, and its own dissipative
// and random forces must enter the pressure (the pair style leaves them to the fix).
//  - eta = -Pxy / rate and the velocity profile's slope against stock velocity-Verlet at a
//    small step (dpd/ext with s = 1/2), in xy, xz and yz, inertial and overdamped;
//  - dpd/fpm: the particles spin with the flow's vorticity, -rate / 2;
//  - box scaling (remap x) and a tilted box at rest keep kBT and momentum;
//  - thermo_modify temp with temp/deform, and temp/profile, give the same kBT.
// Rank-count agreement under shear is in test_ranks.
#include "lammps_fixture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using etdtest::Lammps;

namespace {

// The papers' s = 1/2 fluid, n = 4, m = 0.01, in a triclinic box of side 8 (2,048 atoms)
const double RATE = 1.0;

struct ShearResult {
  double temperature, viscosity, slope, profile_temperature;    // temp/deform, temp/profile
};

// plane: xy, xz or yz (the flow along the first axis, its gradient along the second)
// integrator: stock | implicit | overdamped | diagonal; the production average runs
// 'production' time units after 'startup'.
ShearResult shear_run(const std::string &integrator, const std::string &plane, double dt,
                      double startup = 0.6, double production = 0.9)
{
  const std::string data = etdtest::work_file("shear_fluid.data");
  etdtest::write_random_data(data, 2048, 8.0, 2024, 1, 0.0);
  Lammps l;
  l.cmds({"units lj", "atom_modify map array", "comm_modify vel yes",
          "neigh_modify every 1 delay 0 check yes", "read_data " + data, "change_box all triclinic",
          "mass 1 0.01", "velocity all create 1.0 97 mom yes dist gaussian",
          "timestep " + std::to_string(dt)});
  if (integrator == "stock") {
    l.cmds({"pair_style dpd/ext 1.0 1.0 31", "pair_coeff 1 1 18.75 4.5 0.0 0.25 0.25",
            "fix 1 all nve"});
  } else {
    l.cmds({"pair_style dpd/gen 1.0 1.0 31", "pair_coeff 1 1 18.75 4.5 0.5"});
    if (integrator == "implicit")
      l.cmd("fix 1 all etd scheme implicit");
    else if (integrator == "overdamped")
      l.cmd("fix 1 all etd scheme implicit overdamped yes");
    else
      l.cmd("fix 1 all etd");
  }
  const char flow = plane[0], gradient = plane[1];
  const int stress_index = plane == "xy" ? 4 : (plane == "xz" ? 5 : 6);
  l.cmds({"fix 2 all deform 1 " + plane + " erate " + std::to_string(RATE) + " remap v",
          "compute tdef all temp/deform", "compute p all pressure tdef", "thermo_modify temp tdef",
          std::string("compute tprofile all temp/profile ") + (flow == 'x' ? "1 0 0 " : "0 1 0 ") +
              gradient + " 8",
          "variable stress equal c_p[" + std::to_string(stress_index) + "]",
          std::string("variable g atom ") + gradient, std::string("variable u atom v") + flow,
          "variable ug atom v_u*v_g", "variable gg atom v_g*v_g",
          "compute moments all reduce ave v_u v_g v_ug v_gg",
          "variable slope equal "
          "(c_moments[3]-c_moments[1]*c_moments[2])/(c_moments[4]-c_moments[2]^2)",
          "run " + std::to_string(static_cast<int>(std::lround(startup / dt))) + " post no",
          "fix average all ave/time 1 1 1 c_tdef v_stress v_slope c_tprofile ave running",
          "run " + std::to_string(static_cast<int>(std::lround(production / dt))) + " post no"});
  return {l.fix_vector("average", 0), -l.fix_vector("average", 1) / RATE,
          l.fix_vector("average", 2), l.fix_vector("average", 3)};
}

}    // namespace

// Stock velocity-Verlet at dt = 0.0005 against the implicit scheme at dt = 0.003 in each plane.
// Before the images' velocity offsets entered the friction step the implicit scheme gave a flat
// profile and eta = 0.06 (the shear never entered the fluid); without the fix's virial eta was
// 0.02 with the right profile. One 0.9-unit average of this small box scatters by up to 10 %
// between seeds and planes (measured: stock 1.87-2.03, implicit 1.81-2.19), so the bounds are
// 25 % on eta and 10 % on the slope, which still fail by far on either defect; examples/shear
// compares longer runs.
TEST(Shear, ImplicitViscosityAndProfileMatchVelocityVerletInEveryPlane)
{
  if (etdtest::world_size() > 1) GTEST_SKIP() << "serial test";
  const ShearResult stock = shear_run("stock", "xy", 0.0005);
  std::printf("stock dpd/ext + nve, dt 0.0005, xy: kBT %.4f eta %.4f slope %.4f\n",
              stock.temperature, stock.viscosity, stock.slope);
  EXPECT_NEAR(stock.slope, RATE, 0.05 * RATE);
  for (const std::string plane : {"xy", "xz", "yz"}) {
    const ShearResult implicit = shear_run("implicit", plane, 0.003);
    std::printf("implicit, dt 0.003, %s: kBT %.4f (temp/profile %.4f) eta %.4f slope %.4f\n",
                plane.c_str(), implicit.temperature, implicit.profile_temperature,
                implicit.viscosity, implicit.slope);
    EXPECT_NEAR(implicit.viscosity, stock.viscosity, 0.25 * stock.viscosity) << plane;
    EXPECT_NEAR(implicit.slope, RATE, 0.10 * RATE) << plane;
    EXPECT_NEAR(implicit.temperature, stock.temperature, 0.02) << plane;
    // temp/profile subtracts each snapshot's measured profile (8 bins) instead of the imposed
    // one: measured 0.996-0.997, where temp/deform reads 1.046 here and 1.056 for stock
    EXPECT_NEAR(implicit.profile_temperature, 1.0, 0.02) << plane;
  }
}

// The diagonal scheme takes its friction from the pair style, whose ghosts carry LAMMPS's own
// velocity offsets; the zero-mass scheme solves with the fix's partners like the inertial one.
// The overdamped fluid has no kinetic stress (m -> 0), which at m = 0.01 is about 1 % of eta.
TEST(Shear, DiagonalAndOverdampedSchemesShearTheFluid)
{
  if (etdtest::world_size() > 1) GTEST_SKIP() << "serial test";
  const ShearResult implicit = shear_run("implicit", "xy", 0.003);
  const ShearResult diagonal = shear_run("diagonal", "xy", 0.0005);
  const ShearResult overdamped = shear_run("overdamped", "xy", 0.001, 0.3, 0.6);
  std::printf("implicit eta %.4f slope %.4f; diagonal eta %.4f slope %.4f; overdamped eta %.4f "
              "slope %.4f\n",
              implicit.viscosity, implicit.slope, diagonal.viscosity, diagonal.slope,
              overdamped.viscosity, overdamped.slope);
  EXPECT_NEAR(diagonal.viscosity, implicit.viscosity, 0.25 * implicit.viscosity);
  EXPECT_NEAR(diagonal.slope, RATE, 0.10 * RATE);
  EXPECT_NEAR(overdamped.viscosity, implicit.viscosity, 0.25 * implicit.viscosity);
  EXPECT_NEAR(overdamped.slope, RATE, 0.10 * RATE);
}

// dpd/fpm particles in simple shear u_x = rate y spin with half the vorticity, Omega_z =
// -rate / 2, through the pairs' shear friction: the rotational unknowns of the implicit step
// see the sheared images too. The velocity profile is linear as for dpd/gen.
TEST(Shear, FpmParticlesSpinWithTheVorticity)
{
  if (etdtest::world_size() > 1) GTEST_SKIP() << "serial test";
  const std::string data = etdtest::work_file("shear_fpm.data");
  etdtest::write_random_sphere_data(data, 1536, 8.0, 97531, 1, 0.0, 0.0, 1.0);
  // the implicit scheme at its step, the diagonal one (friction from the pair style, ghosts
  // moved by LAMMPS) at a small one
  for (const std::string scheme : {"implicit", "diagonal"}) {
    const bool implicit = scheme == "implicit";
    Lammps l;
    l.cmds({"units lj",
            "atom_style sphere",
            "atom_modify map array",
            "comm_modify vel yes",
            "neigh_modify every 1 delay 0 check yes",
            "read_data " + data,
            "change_box all triclinic",
            "set group all mass 0.01",
            "velocity all create 1.0 5 mom yes dist gaussian",
            "pair_style dpd/fpm 1.0 1.0 8642",
            "pair_coeff 1 1 25 4.5 4.5 0.5",
            implicit ? "timestep 0.003" : "timestep 0.0005",
            implicit ? "fix 1 all etd scheme implicit" : "fix 1 all etd",
            "fix 2 all deform 1 xy erate 1.0 remap v",
            "variable uy atom vx*y",
            "variable yy atom y*y",
            "compute spin all property/atom omegaz",
            "compute moments all reduce ave vx y v_uy v_yy c_spin",
            "variable slope equal "
            "(c_moments[3]-c_moments[1]*c_moments[2])/(c_moments[4]-c_moments[2]^2)",
            implicit ? "run 200 post no" : "run 600 post no",
            "fix average all ave/time 1 1 1 v_slope c_moments[5] ave running",
            implicit ? "run 300 post no" : "run 1200 post no"});
    const double slope = l.fix_vector("average", 0), spin = l.fix_vector("average", 1);
    std::printf("dpd/fpm + %s under xy shear at rate 1: slope %.4f, mean Omega_z %.4f\n",
                scheme.c_str(), slope, spin);
    EXPECT_NEAR(slope, 1.0, 0.05) << scheme;
    // one rotational degree of freedom's thermal spread is sqrt(kBT/I) = 20: the mean over 1,536
    // particles and 300 steps is known to about 0.02
    EXPECT_NEAR(spin, -0.5, 0.05) << scheme;
  }
}

// Box changes without moving images: fix deform x scale (remap x) and a tilted box at rest.
// Momentum stays at round-off, kBT at 1 within 2 % (600 steps, 2,048 atoms).
TEST(Shear, ScaledAndTiltedBoxesKeepTemperatureAndMomentum)
{
  if (etdtest::world_size() > 1) GTEST_SKIP() << "serial test";
  const std::string data = etdtest::work_file("shear_box.data");
  etdtest::write_random_data(data, 2048, 8.0, 1234, 1, 0.0);
  for (const std::string box : {"fix 2 all deform 1 x scale 1.1 remap x",
                                "change_box all xy final 2.0 xz final -1.0 remap"}) {
    Lammps l;
    l.cmds({"units lj", "atom_modify map array", "comm_modify vel yes",
            "neigh_modify every 1 delay 0 check yes", "read_data " + data,
            "change_box all triclinic", "mass 1 0.01",
            "velocity all create 1.0 11 mom yes dist gaussian", "pair_style dpd/gen 1.0 1.0 3",
            "pair_coeff 1 1 18.75 4.5 0.5", "timestep 0.003", "fix 1 all etd scheme implicit", box,
            "run 200 post no", "fix average all ave/time 1 1 1 c_thermo_temp ave running",
            "run 400 post no"});
    const auto v = l.gather("v");
    double p[3] = {0.0, 0.0, 0.0};
    for (size_t a = 0; a < v.size() / 3; a++)
      for (int k = 0; k < 3; k++) p[k] += 0.01 * v[3 * a + k];
    std::printf("%s: kBT %.4f, momentum %.2e %.2e %.2e\n", box.c_str(), l.fix_scalar("average"),
                p[0], p[1], p[2]);
    EXPECT_NEAR(l.fix_scalar("average"), 1.0, 0.02) << box;
    for (double pk : p) EXPECT_LT(std::fabs(pk), 1e-12) << box;
  }
}

// The implicit scheme's virial holds the kinetic stress of the step's drifts beyond m v v of the
// velocities it leaves, m (c h + h c + 2 h h) per atom with h = (dt/2) F/m. Three atoms out of
// each other's reach under a body force (no pairs, so this is all of the fix's virial): the
// fix's share of the pressure, times the volume, against that sum from their v and f.
TEST(Shear, ImplicitVirialHoldsTheDriftsKineticStress)
{
  if (etdtest::world_size() > 1) GTEST_SKIP() << "serial test";
  const double mass = 0.5, dt = 0.01, volume = 1000.0;
  Lammps l;
  l.cmds({"units lj", "atom_modify map array", "comm_modify vel yes",
          "neigh_modify every 1 delay 0 check yes", "region box block 0 10 0 10 0 10",
          "create_box 1 box", "create_atoms 1 single 1 1 1", "create_atoms 1 single 5 5 5",
          "create_atoms 1 single 8 2 6", "mass 1 0.5", "pair_style dpd/gen 1.0 1.0 5",
          "pair_coeff 1 1 25 4.5 2", "velocity all create 1.0 8 dist gaussian",
          "timestep 0.01", "fix 1 all etd scheme implicit", "fix 2 all addforce 1.0 -2.0 0.5",
          "compute pfix all pressure NULL fix",
          "thermo_style custom step c_pfix[1] c_pfix[2] c_pfix[3] c_pfix[4] c_pfix[5] c_pfix[6]",
          "thermo 5", "run 5 post no"});
  const auto v = l.gather("v"), f = l.gather("f");
  const int a[6] = {0, 1, 2, 0, 0, 1}, b[6] = {0, 1, 2, 1, 2, 2};
  for (int k = 0; k < 6; k++) {
    double expected = 0.0;
    for (int atom = 0; atom < 3; atom++) {
      const double *c = &v[3 * atom], *force = &f[3 * atom];
      const double ha = 0.5 * dt * force[a[k]] / mass, hb = 0.5 * dt * force[b[k]] / mass;
      expected += mass * (c[a[k]] * hb + ha * c[b[k]] + 2.0 * ha * hb);
    }
    const double tallied = l.compute_vector("pfix", k) * volume;
    EXPECT_NEAR(tallied, expected, 1e-12 * (1.0 + std::fabs(expected))) << "component " << k;
    EXPECT_NE(expected, 0.0) << "component " << k;
  }
}

// Under shear the drifts' kinetic stress is several per cent of the Groot-Warren fluid's
// viscosity at m = 1 and the matrix's large steps: at dt = 0.04, rate 0.5, eta from LAMMPS's
// pressure (with it) reads 5.5-6.2 % below eta from m v v of v alone (8 seeds, 20 time units;
// the reference lies between them, bench/accuracy/results/viscosity_shear.md). Here one seed,
// 8 time units: the gap must be there, with its sign.
TEST(Shear, ImplicitPressureReadsTheDriftsMomentumFlux)
{
  if (etdtest::world_size() > 1) GTEST_SKIP() << "serial test";
  const std::string data = etdtest::work_file("shear_gw.data");
  etdtest::write_random_data(data, 3000, 10.0, 77, 1, 0.0);
  Lammps l;
  l.cmds({"units lj", "atom_modify map array", "comm_modify vel yes",
          "neigh_modify every 1 delay 0 check yes", "neighbor 1.0 bin", "read_data " + data,
          "change_box all triclinic", "mass 1 1.0",
          "velocity all create 1.0 5 mom yes dist gaussian",
          "velocity all ramp vx 0 5 y 0 10 sum yes units box", "pair_style dpd/gen 1.0 1.0 9",
          "pair_coeff 1 1 25 4.5 2", "timestep 0.04", "fix 1 all etd scheme implicit",
          "fix 2 all deform 1 xy erate 0.5 remap v", "compute tdef all temp/deform",
          "compute p all pressure tdef", "variable pxy equal c_p[4]",
          // m v_end v_end + m h h of the peculiar end-of-step velocities, minus m v v
          "fix vend all ave/atom 1 1 1 f_1[1] f_1[2]", "variable stream atom 0.5*(y-ylo)",
          "variable kend atom mass*(f_vend[1]-v_stream)*f_vend[2]+0.25*dt*dt*fx*fy/mass",
          "compute kend all reduce sum v_kend",
          "variable pxyv equal v_pxy-(c_kend-c_tdef[4])/vol", "run 50 post no",
          "fix average all ave/time 1 1 1 v_pxy v_pxyv ave running", "run 200 post no"});
  const double eta = -l.fix_vector("average", 0) / 0.5, eta_v = -l.fix_vector("average", 1) / 0.5;
  std::printf("GW m = 1, dt 0.04, rate 0.5: eta %.4f from the pressure, %.4f from m v v of v\n",
              eta, eta_v);
  EXPECT_GT(eta_v - eta, 0.03 * eta);
  EXPECT_LT(eta_v - eta, 0.09 * eta);
}
