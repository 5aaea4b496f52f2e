// The KOKKOS styles (pair_style dpd/gen/kk) against the CPU styles in the same process, with
// LAMMPS run as `-k on t N -sf kk` (N from ETD_KOKKOS_THREADS, default 1; with ETD_KOKKOS_GPUS=G
// `-k on g G t N -sf kk -pk kokkos neigh half newton on`, for a CUDA Kokkos): forces, energy and
// virial; trajectories under fix nve and both schemes of fix etd; compute dpd/split; kBT and P
// beside LAMMPS's own dpd/kk; restart; bad input. Built and run only against a KOKKOS LAMMPS
// (tools/kokkos/test.sh), on 1 and 2 ranks with 1 and 2 threads, or with a CUDA Kokkos on 1 and 2
// ranks sharing one GPU (and 2 host threads where that Kokkos has OpenMP on the host).
#include "lammps_fixture.h"

#include <gtest/gtest.h>

#include "atom.h"
#include "atom_masks.h"
#include "domain.h"
#include "fix.h"
#include "force.h"
#include "lammps.h"
#include "library.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "pair.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <tuple>

using etdtest::Lammps;

namespace {

const std::string DATA = etdtest::work_file("kokkos_styles.data");

// how many GPUs the tests run on (ETD_KOKKOS_GPUS, a CUDA Kokkos: -k on g N), or null
const char *kokkos_gpus() { return std::getenv("ETD_KOKKOS_GPUS"); }

// the host threads per rank (ETD_KOKKOS_THREADS, default 1)
int kokkos_threads()
{
  const char *threads = std::getenv("ETD_KOKKOS_THREADS");
  return threads ? std::atoi(threads) : 1;
}

std::vector<std::string> kokkos_args()
{
  const char *gpus = kokkos_gpus();
  std::vector<std::string> args = {"-k", "on", "t", std::to_string(kokkos_threads()), "-sf", "kk"};
  if (!gpus) return args;
  // a GPU defaults to full lists and newton off; the tests compare with the CPU styles' default,
  // newton on (NewtonOffAndFullListSettingsFollowTheCpuStyle takes the GPU's defaults)
  args.insert(args.begin() + 2, {"g", gpus});
  args.insert(args.end(), {"-pk", "kokkos", "neigh", "half", "newton", "on"});
  return args;
}

// n = 3 fluid of 648 atoms in a 6^3 box, two types, random velocities; IDs come from the data
// file, so the noise (keyed on them) is the same on every rank count
void setup_box(Lammps &l, double mass = 1.0, double dt = 0.01)
{
  etdtest::write_random_data(DATA, 648, 6.0, 4711, 2, 1.5);
  l.cmds({"units lj", "atom_modify map array", "comm_modify vel yes",
          "neigh_modify every 1 delay 0 check yes", "read_data " + DATA,
          "mass * " + std::to_string(mass), "timestep " + std::to_string(dt),
          "thermo_modify norm no", "compute virial all pressure NULL virial"});
}

// 375 atoms of atom_style sphere (dpd/fpm's) at random in a 5^3 box, mass 1
const std::vector<std::string> SPHERE_BOX = {
    "units lj", "atom_style sphere", "atom_modify map array", "comm_modify vel yes",
    "region box block 0 5 0 5 0 5", "create_box 1 box", "create_atoms 1 random 375 4711 NULL",
    "set group all mass 1.0"};

const std::vector<std::string> GEN_S2 = {"pair_style dpd/gen 1.0 1.0 123",
                                         "pair_coeff * * 25.0 4.5 2.0"};
// s = 1/2, a separate dissipative cutoff and conservative exponent, a different cross pair
const std::vector<std::string> GEN_MIXED = {
    "pair_style dpd/gen 1.0 1.0 123", "pair_coeff 1 1 25.0 4.5 0.5 cut_d 0.9",
    "pair_coeff 1 2 30.0 6.0 0.5 1.1 exp_c 0.5", "pair_coeff 2 2 18.75 3.0 1.0 cut_d 1.2"};

double max_rel_diff(const std::vector<double> &a, const std::vector<double> &b)
{
  double worst = 0.0, scale = 0.0;
  for (double v : b) scale = std::max(scale, std::fabs(v));
  for (size_t i = 0; i < a.size(); i++) worst = std::max(worst, std::fabs(a[i] - b[i]) / scale);
  return worst;
}

struct Snapshot {
  std::vector<double> x, v, f, virial;
  double pe;
  double friction_temperature = 0.0;    // fix etd scheme implicit: its output 5
};

Snapshot snapshot(Lammps &l)
{
  Snapshot s;
  s.x = l.gather("x");
  s.v = l.gather("v");
  s.f = l.gather("f");
  for (int k = 0; k < 6; k++) s.virial.push_back(l.compute_vector("virial", k));
  s.pe = l.thermo("pe");
  return s;
}

// whether the pair style ran its Kokkos kernel (a Kokkos neighbor list) or the CPU loop on the host
bool pair_ran_kernel(Lammps &l)
{
  int kokkos_lists = 0;
  for (int n = 0; n < l.lmp->neighbor->nlist; n++)
    kokkos_lists += l.lmp->neighbor->lists[n]->kokkos;
  return kokkos_lists > 0;
}

// whether fix "integrate" ran its step in Kokkos kernels (fix etd/kk on the device; the host
// path reads every atom array)
bool fix_ran_kernel(Lammps &l)
{
  const LAMMPS_NS::Fix *fix = l.lmp->modify->get_fix_by_id("integrate");
  return fix && fix->kokkosable && fix->datamask_read != ALL_MASK;
}

// how many of fix "integrate"'s solves ("kernel_solves"), or pair assemblies with their
// right-hand sides ("kernel_assemblies"), of the last run ran in Kokkos kernels (fix etd/kk
// scheme implicit; 0 for any other fix)
double kernel_solves(Lammps &l, const char *what = "kernel_solves")
{
  LAMMPS_NS::Fix *fix = l.lmp->modify->get_fix_by_id("integrate");
  int dim = -1;
  const void *count = fix ? fix->extract(what, dim) : nullptr;
  return count ? *static_cast<const double *>(count) : 0.0;
}

// the pair style an instance really runs (the suffix applied or not)
std::string pair_style_of(Lammps &l)
{
  return l.lmp->force->pair_style;
}

// the same commands on the CPU styles and on the /kk styles
struct Pair {
  Snapshot cpu, kk;
  std::vector<double> start_v;    // the velocities read from the data file
  bool kernel = false;            // the /kk style ran its Kokkos kernel
  bool fix_kernel = false;        // fix "integrate" ran its step in Kokkos kernels
  double kernel_solves = 0.0;     // fix etd/kk scheme implicit: its solves in Kokkos kernels
  double kernel_assemblies = 0.0;    // and its pair assemblies
};
// package: more command-line words for the /kk instance (-pk kokkos ...); newton_off: the CPU
// instance runs with newton off too
Pair run_both(const std::vector<std::string> &pair, const std::vector<std::string> &run,
              double mass = 1.0, double dt = 0.01, const std::vector<std::string> &package = {},
              bool newton_off = false)
{
  Pair out;
  for (bool kokkos : {false, true}) {
    std::vector<std::string> args;
    if (kokkos) {
      args = kokkos_args();
      args.insert(args.end(), package.begin(), package.end());
    }
    Lammps l(MPI_COMM_WORLD, true, args);
    setup_box(l, mass, dt);
    if (newton_off && !kokkos) l.cmd("newton off on");    // (pair off; bond as set)
    l.cmds(pair);
    if (!kokkos) out.start_v = l.gather("v");
    l.cmds(run);
    EXPECT_EQ(pair_style_of(l), kokkos ? "dpd/gen/kk" : "dpd/gen");
    (kokkos ? out.kk : out.cpu) = snapshot(l);
    for (const std::string &command : run)
      if (command.find("scheme implicit") != std::string::npos)
        (kokkos ? out.kk : out.cpu).friction_temperature = l.fix_vector("integrate", 4);
    if (kokkos) out.kernel = pair_ran_kernel(l);
    if (kokkos) out.fix_kernel = fix_ran_kernel(l);
    if (kokkos) out.kernel_solves = kernel_solves(l);
    if (kokkos) out.kernel_assemblies = kernel_solves(l, "kernel_assemblies");
  }
  return out;
}

}    // namespace

TEST(KokkosStyles, ForcesEnergyAndVirialEqualTheCpuStyle)
{
  for (const auto &pair : {GEN_S2, GEN_MIXED}) {
    const Pair p = run_both(pair, {"run 0 post no"});
    EXPECT_LT(max_rel_diff(p.kk.f, p.cpu.f), 1e-12) << pair.back();
    EXPECT_LT(max_rel_diff(p.kk.virial, p.cpu.virial), 1e-12) << pair.back();
    EXPECT_NEAR(p.kk.pe, p.cpu.pe, 1e-12 * std::fabs(p.cpu.pe)) << pair.back();
  }
}

// Under newton off (with neigh full, a GPU's defaults) a pair with a ghost is computed on both
// sides, each for its own atom, and counts half in energy and virial: as the CPU style with
// newton off. Counting such a pair whole, or adding to the ghost, moves the energy and virial.
TEST(KokkosStyles, NewtonOffAndFullListSettingsFollowTheCpuStyle)
{
  for (const std::string neigh : {"full", "half"}) {
    const std::vector<std::string> package = {"-pk", "kokkos", "neigh", neigh, "newton", "off"};
    for (const auto &pair : {GEN_S2, GEN_MIXED}) {
      const Pair p = run_both(pair, {"run 0 post no"}, 1.0, 0.01, package, true);
      EXPECT_TRUE(p.kernel) << neigh;
      EXPECT_LT(max_rel_diff(p.kk.f, p.cpu.f), 1e-12) << neigh << ", " << pair.back();
      EXPECT_LT(max_rel_diff(p.kk.virial, p.cpu.virial), 1e-12) << neigh << ", " << pair.back();
      EXPECT_NEAR(p.kk.pe, p.cpu.pe, 1e-12 * std::fabs(p.cpu.pe)) << neigh << ", " << pair.back();
    }
    // the diagonal scheme (the kernel's friction sums) and the implicit one (its own search and
    // the host loop; 10 steps, as in TrajectoriesFollowTheCpuStyle)
    using Run = std::tuple<std::string, int, double>;
    for (const auto &[fix, steps, dt] : {Run{"fix integrate all etd scheme diagonal", 50, 0.002},
                                         Run{"fix integrate all etd scheme implicit", 10, 0.005}}) {
      const Pair p = run_both(GEN_MIXED, {fix, "run " + std::to_string(steps) + " post no"}, 0.01,
                              dt, package, true);
      EXPECT_LT(max_rel_diff(p.kk.x, p.cpu.x), 1e-8) << neigh << ", " << fix;
      EXPECT_LT(max_rel_diff(p.kk.v, p.cpu.v), 1e-8) << neigh << ", " << fix;
      EXPECT_LT(max_rel_diff(p.kk.virial, p.cpu.virial), 1e-6) << neigh << ", " << fix;
      EXPECT_GT(max_rel_diff(p.kk.v, p.start_v), 0.1) << neigh << ", " << fix;
    }
  }
}

// 50 steps: round-off from the summation order (a few 1e-16) grows by about 1e4 here
TEST(KokkosStyles, TrajectoriesFollowTheCpuStyle)
{
  struct Case {
    std::string fix;
    double mass, dt;
    bool kernel;        // the pair loop runs in the Kokkos kernel (else on the host)
    bool fix_kernel;    // the integrator's step runs in Kokkos kernels (nve/kk, etd/kk)
    int steps = 50;
    bool solve_kernel = false;    // the implicit scheme's solve runs in Kokkos kernels
  };
  for (const Case &c : {Case{"fix integrate all nve", 1.0, 0.01, true, true},
                        Case{"fix integrate all etd scheme diagonal", 0.01, 0.002, true, true},
                        // (order 2 is stable at this mass below dt = 0.0009: doc/fix_etd.rst)
                        Case{"fix integrate all etd scheme diagonal order 2 noise exact", 0.01,
                             0.0005, true, false},
                        // (the CPU style with LAMMPS's lists, whose pairs the /kk style's host
                        // loop also reads in their order. The solve's kernels sum in another
                        // order than the CPU solver, and this fluid amplifies round-off about
                        // tenfold a step: 10 steps)
                        Case{"fix integrate all etd scheme implicit neighbors lammps", 0.01, 0.005,
                             false, false, 10, true},
                        Case{"fix integrate all etd scheme implicit neighbors lammps tol 1e-10",
                             0.01, 0.005, false, false, 10, true},
                        // (the scheme's own pair search: the host loop reads its pairs, in the
                        // order the CPU style reads them)
                        Case{"fix integrate all etd scheme implicit neighbors own", 0.01, 0.005,
                             false, false, 10, true},
                        // (CG started from the old velocities, with G of them from the
                        // kernels' right-hand side)
                        Case{"fix integrate all etd scheme implicit tol 1e-10 start velocity",
                             0.01, 0.005, false, false, 10, true}}) {
    for (const auto &pair : {GEN_S2, GEN_MIXED}) {
      const Pair p = run_both(pair, {c.fix, "run " + std::to_string(c.steps) + " post no"},
                              c.mass, c.dt);
      EXPECT_EQ(p.kernel, c.kernel) << c.fix;
      EXPECT_EQ(p.fix_kernel, c.fix_kernel) << c.fix;
      EXPECT_EQ(p.kernel_solves > 0.0, c.solve_kernel) << c.fix;
      // (the pairs, their noise and the right-hand side too; at the last step, which tallies
      // the virial, the pairs are also copied back to the host, which sums it)
      EXPECT_EQ(p.kernel_assemblies > 0.0, c.solve_kernel) << c.fix;
      if (c.solve_kernel) {
        EXPECT_LT(max_rel_diff(p.kk.virial, p.cpu.virial), 1e-6) << c.fix << ", " << pair.back();
        // (the momentum correction's sums over the atoms, on the host's threads in ranges)
        EXPECT_GT(p.cpu.friction_temperature, 0.5) << c.fix;
        EXPECT_NEAR(p.kk.friction_temperature, p.cpu.friction_temperature,
                    1e-8 * p.cpu.friction_temperature)
            << c.fix << ", " << pair.back();
      }
      EXPECT_LT(max_rel_diff(p.kk.x, p.cpu.x), 1e-8) << c.fix << ", " << pair.back();
      EXPECT_LT(max_rel_diff(p.kk.v, p.cpu.v), 1e-8) << c.fix << ", " << pair.back();
      // the velocities moved far from their start (else the comparison would prove nothing)
      EXPECT_GT(max_rel_diff(p.kk.v, p.start_v), 0.1) << c.fix << ", " << pair.back();
    }
  }
}

// Atoms outside the fix's group (type 2 held at rest) are partners of the group's pairs: the
// kernels' assembly reports them (the momentum correction is then left out), as the host's
// does; with a compute dpd/split every step copies the pairs back to the host
TEST(KokkosStyles, ImplicitKernelsHoldAtomsOutsideTheGroup)
{
  for (const bool split : {false, true}) {
    const Pair p = run_both(
        GEN_S2,
        {"group mobile type 1", "velocity all set 0.0 0.0 0.0 sum no",
         "velocity mobile create 1.0 5 mom yes dist gaussian",
         "fix integrate mobile etd scheme implicit tol 1e-10",
         split ? "compute split all dpd/split" : "variable none equal 0", "run 10 post no"},
        0.01, 0.005);
    EXPECT_GT(p.kernel_assemblies, 0.0) << split;
    EXPECT_LT(max_rel_diff(p.kk.x, p.cpu.x), 1e-8) << split;
    EXPECT_LT(max_rel_diff(p.kk.v, p.cpu.v), 1e-8) << split;
  }
}

// A sheared box (triclinic, fix deform ... remap v): the ghosts' velocities carry the shear, in
// the Kokkos communication as in the CPU one; the implicit scheme's kernels give each pair with
// a moving image its velocity (the pairs' constant part of G in the right-hand side, and their
// offsets copied back for the virial), at a rate whose images move 2.5 per time unit
TEST(KokkosStyles, ShearedBoxFollowsTheCpuStyle)
{
  struct Case {
    std::string fix;
    double mass, dt;
    int steps = 50;
    bool implicit = false;
  };
  for (const Case &c :
       {Case{"fix integrate all nve", 1.0, 0.01}, Case{"fix integrate all etd", 0.01, 0.002},
        Case{"fix integrate all etd scheme implicit tol 1e-10", 0.01, 0.005, 10, true}}) {
    std::vector<double> v[2], x[2], virial[2];
    for (bool kokkos : {false, true}) {
      Lammps l(MPI_COMM_WORLD, true, kokkos ? kokkos_args() : std::vector<std::string>{});
      setup_box(l, c.mass, c.dt);
      l.cmds({"change_box all triclinic", "pair_style dpd/gen 1.0 1.0 123",
              "pair_coeff * * 25.0 4.5 2.0", c.fix, "fix shear all deform 1 xy erate 0.5 remap v",
              "compute p all pressure thermo_temp virial", "thermo_style custom step c_p[4]",
              "run " + std::to_string(c.steps) + " post no"});
      if (kokkos && !c.implicit) EXPECT_TRUE(pair_ran_kernel(l)) << c.fix;
      if (kokkos && c.implicit) EXPECT_GT(kernel_solves(l, "kernel_assemblies"), 0.0);
      v[kokkos] = l.gather("v");
      x[kokkos] = l.gather("x");
      virial[kokkos] = {l.compute_vector("p", 3)};
    }
    EXPECT_LT(max_rel_diff(v[1], v[0]), 1e-8) << c.fix;
    EXPECT_LT(max_rel_diff(x[1], x[0]), 1e-8) << c.fix;
    EXPECT_LT(max_rel_diff(virial[1], virial[0]), 1e-6) << c.fix;
  }
}

// dpd/gen/kk as a sub-style of hybrid/overlay (hybrid/overlay/kk) beside soft/kk
TEST(KokkosStyles, HybridOverlayFollowsTheCpuStyle)
{
  std::vector<double> v[2];
  for (bool kokkos : {false, true}) {
    Lammps l(MPI_COMM_WORLD, true, kokkos ? kokkos_args() : std::vector<std::string>{});
    setup_box(l);
    l.cmds({"pair_style hybrid/overlay dpd/gen 1.0 1.0 123 soft 1.0",
            "pair_coeff * * dpd/gen 25.0 4.5 0.5 cut_d 0.9", "pair_coeff * * soft 10.0",
            "fix integrate all nve", "run 50 post no"});
    EXPECT_EQ(pair_style_of(l), kokkos ? "hybrid/overlay/kk" : "hybrid/overlay");
    // the sub-style keeps its keyword; with -sf kk its class is the Kokkos one
    LAMMPS_NS::Pair *sub = l.lmp->force->pair_match("dpd/gen", 1);
    ASSERT_NE(sub, nullptr);
    EXPECT_EQ(sub->kokkosable, kokkos ? 1 : 0);
    v[kokkos] = l.gather("v");
  }
  EXPECT_LT(max_rel_diff(v[1], v[0]), 1e-8);
}

// the force split (and the diagonal friction the diagonal scheme asks for) summed in the kernel
TEST(KokkosStyles, ForceSplitEqualsTheCpuStyle)
{
  std::vector<double> split[2];
  for (bool kokkos : {false, true}) {
    Lammps l(MPI_COMM_WORLD, true, kokkos ? kokkos_args() : std::vector<std::string>{});
    setup_box(l, 0.01, 0.002);
    l.cmds(GEN_MIXED);
    l.cmds(
        {"fix integrate all etd scheme diagonal", "compute split all dpd/split", "run 10 post no"});
    split[kokkos] = l.gather_compute("split", 9);
    if (kokkos) EXPECT_TRUE(pair_ran_kernel(l));
  }
  EXPECT_LT(max_rel_diff(split[1], split[0]), 1e-10);
  EXPECT_GT(*std::max_element(split[0].begin(), split[0].end()), 1.0);
}

// Mean temp and press of dpd/gen/kk + nve beside LAMMPS's own dpd/kk (same fluid, same step:
// velocity-Verlet at dt = 0.01 runs about 0.7 % hot here). 3,000 atoms, means every 10 steps
// over 1,500 steps after 300. Neither run repeats itself with threads (the order of the sums
// changes, and dpd/kk's random streams with it): over five runs on 2 ranks x 2 threads the
// temp means spread over 1.0049-1.0097 (dpd/gen/kk) and 1.0008-1.0126 (dpd/kk), press over
// 0.2 %. Hence 2 % on the ratio of temps and 1.5 % on temp itself.
TEST(KokkosStyles, HoldsTemperatureAndPressureBesideLammpsDpdKokkos)
{
  const std::string data = etdtest::work_file("kokkos_fluid.data");
  double temp[2], press[2];
  for (int stock : {0, 1}) {
    etdtest::write_random_data(data, 3000, 10.0, 2718, 1, 0.0);
    Lammps l(MPI_COMM_WORLD, true, kokkos_args());
    l.cmds({"units lj", "atom_modify map array", "comm_modify vel yes",
            "neigh_modify every 1 delay 0 check yes", "read_data " + data, "mass 1 1.0",
            "velocity all create 1.0 8731 mom yes dist gaussian", "timestep 0.01",
            stock ? "pair_style dpd 1.0 1.0 4242" : "pair_style dpd/gen 1.0 1.0 4242",
            stock ? "pair_coeff * * 25.0 4.5" : "pair_coeff * * 25.0 4.5 2.0",
            "fix integrate all nve", "run 300 post no", "reset_timestep 0",
            "fix average all ave/time 10 150 1500 c_thermo_temp c_thermo_press",
            "run 1500 post no"});
    EXPECT_EQ(pair_style_of(l), stock ? "dpd/kk" : "dpd/gen/kk");
    temp[stock] = l.fix_vector("average", 0);
    press[stock] = l.fix_vector("average", 1);
  }
  if (etdtest::world_rank() == 0)
    std::printf("dpd/gen/kk temp %.4f press %.3f; dpd/kk temp %.4f press %.3f\n", temp[0], press[0],
                temp[1], press[1]);
  EXPECT_NEAR(temp[0], 1.0, 0.015);
  EXPECT_NEAR(temp[0] / temp[1], 1.0, 0.02);
  EXPECT_NEAR(press[0] / press[1], 1.0, 0.01);
}

// fix etd/kk (the diagonal scheme's default step in kernels) beside the CPU fix etd: mean temp and
// press of 3,000 atoms at m = 0.01, dt = 0.002, every 10 steps over 1,500 steps after 300
// (standard errors about 0.15 % and 0.1 %; both runs carry the scheme's own bias alike)
TEST(KokkosStyles, DiagonalSchemeMatchesTheCpuFixInTemperatureAndPressure)
{
  const std::string data = etdtest::work_file("kokkos_fluid_etd.data");
  double temp[2], press[2];
  for (int kokkos : {0, 1}) {
    etdtest::write_random_data(data, 3000, 10.0, 2718, 1, 0.0);
    Lammps l(MPI_COMM_WORLD, true, kokkos ? kokkos_args() : std::vector<std::string>{});
    l.cmds({"units lj", "atom_modify map array", "comm_modify vel yes",
            "neigh_modify every 1 delay 0 check yes", "read_data " + data, "mass 1 0.01",
            "velocity all create 1.0 8731 mom yes dist gaussian", "timestep 0.002",
            "pair_style dpd/gen 1.0 1.0 4242", "pair_coeff * * 25.0 4.5 2.0",
            "fix integrate all etd", "run 300 post no", "reset_timestep 0",
            "fix average all ave/time 10 150 1500 c_thermo_temp c_thermo_press",
            "run 1500 post no"});
    if (kokkos) EXPECT_TRUE(fix_ran_kernel(l));
    temp[kokkos] = l.fix_vector("average", 0);
    press[kokkos] = l.fix_vector("average", 1);
  }
  if (etdtest::world_rank() == 0)
    std::printf("fix etd/kk temp %.4f press %.3f; fix etd temp %.4f press %.3f\n", temp[1],
                press[1], temp[0], press[0]);
  EXPECT_NEAR(temp[1] / temp[0], 1.0, 0.01);
  EXPECT_NEAR(press[1] / press[0], 1.0, 0.01);
  EXPECT_NEAR(temp[1], 1.0, 0.05);
}

// LAMMPS's memory line (and `info memory`) counts what fix etd/kk scheme implicit holds in its
// kernels' views (the step's pairs, the solve's vectors), as it counts the CPU fix's arrays
TEST(KokkosStyles, ImplicitFixCountsTheKernelsMemory)
{
  double bytes[2] = {0.0, 0.0};
  for (bool kokkos : {false, true}) {
    Lammps l(MPI_COMM_WORLD, true, kokkos ? kokkos_args() : std::vector<std::string>{});
    setup_box(l, 0.01, 0.005);
    l.cmds(GEN_S2);
    // (no pressure at the last step: the kernels' pairs are then not copied to the host, where
    // the CPU fix's own arrays would count them)
    l.cmds({"thermo_style custom step temp", "fix integrate all etd scheme implicit",
            "run 5 post no"});
    if (kokkos) ASSERT_GT(kernel_solves(l), 0.0);
    bytes[kokkos] = l.lmp->modify->get_fix_by_id("integrate")->memory_usage();
  }
  // both hold LAMMPS's per-atom arrays of the fix; the CPU fix its pairs (FrictionPair) and
  // vectors, the kernels the same pairs twice (packed, and staged at their candidates' slots)
  // and their vectors; without the views the kk fix counted less than the CPU fix
  std::printf("fix etd scheme implicit: %.0f bytes, fix etd/kk: %.0f bytes\n", bytes[0], bytes[1]);
  EXPECT_GT(bytes[1], bytes[0]);
  EXPECT_LT(bytes[1], 4.0 * bytes[0]);
}

// LAMMPS's memory line counts the copies of the forces that dpd/gen/kk keeps for its threads,
// one per thread where they share a half list (on one thread, or a GPU, there are none)
TEST(KokkosStyles, PairCountsTheThreadsCopies)
{
  double bytes[2] = {0.0, 0.0};
  double copies = 0.0;
  for (bool kokkos : {false, true}) {
    Lammps l(MPI_COMM_WORLD, true, kokkos ? kokkos_args() : std::vector<std::string>{});
    setup_box(l);
    l.cmds(GEN_S2);
    l.cmds({"fix integrate all nve", "run 5 post no"});
    bytes[kokkos] = l.lmp->force->pair->memory_usage();
    if (kokkos) {
      ASSERT_TRUE(pair_ran_kernel(l));
      if (!kokkos_gpus() && kokkos_threads() > 1)
        copies = kokkos_threads() * 3.0 * sizeof(double) * l.lmp->atom->nmax;
    }
  }
  std::printf("pair dpd/gen: %.0f bytes, dpd/gen/kk: %.0f bytes\n", bytes[0], bytes[1]);
  EXPECT_DOUBLE_EQ(bytes[1] - bytes[0], copies);
}

// write_restart after 25 steps and a new instance from the file: the same state after 50 steps
// as one run straight through (the noise is keyed on IDs and the timestep, not on a stream)
TEST(KokkosStyles, RestartContinuesTheRun)
{
  struct Case {
    std::string fix;
    double mass, dt;
    double tolerance = 1e-10;
    bool implicit = false;
  };
  // (the implicit scheme's kernels: the restart reorders the atoms, so its sums run in another
  // order, which 25 steps of this fluid amplify from round-off; its tolerance is tight in CG)
  for (const Case &c : {Case{"fix integrate all nve", 1.0, 0.01},
                        Case{"fix integrate all etd scheme diagonal", 0.01, 0.002},
                        Case{"fix integrate all etd scheme implicit tol 1e-12", 0.01, 0.005, 1e-6,
                             true}}) {
    const std::string restart = etdtest::work_file("kokkos_styles.restart");
    std::vector<double> straight, resumed;
    {
      Lammps l(MPI_COMM_WORLD, true, kokkos_args());
      setup_box(l, c.mass, c.dt);
      l.cmds(GEN_MIXED);
      l.cmds({c.fix, "run 25 post no", "write_restart " + restart, "run 25 post no"});
      straight = l.gather("v");
    }
    {
      Lammps l(MPI_COMM_WORLD, true, kokkos_args());
      l.cmds({"read_restart " + restart, "comm_modify vel yes",
              "neigh_modify every 1 delay 0 check yes", c.fix, "run 25 post no"});
      EXPECT_EQ(pair_style_of(l), "dpd/gen/kk");
      if (c.implicit)
        EXPECT_GT(kernel_solves(l), 0.0) << c.fix;
      else
        EXPECT_TRUE(fix_ran_kernel(l)) << c.fix;
      resumed = l.gather("v");
    }
    EXPECT_LT(max_rel_diff(resumed, straight), c.tolerance) << c.fix;
  }
}

// Of the pairs within the cutoff among this rank's atoms, the fraction whose two atoms lie in
// different halves of the atoms' index order (the threads' shares of the kernels)
double pairs_across_index_halves(Lammps &l)
{
  const int nlocal = l.lmp->atom->nlocal;
  double **x = l.lmp->atom->x;
  const double *lo = l.lmp->domain->boxlo, *hi = l.lmp->domain->boxhi;
  long pairs = 0, across = 0;
  for (int i = 0; i < nlocal; i++)
    for (int j = i + 1; j < nlocal; j++) {
      double rsq = 0.0;
      for (int k = 0; k < 3; k++) {
        const double side = hi[k] - lo[k];
        double d = x[i][k] - x[j][k];
        d -= side * std::round(d / side);
        rsq += d * d;
      }
      if (rsq >= 1.0) continue;
      pairs++;
      if ((i < nlocal / 2) != (j < nlocal / 2)) across++;
    }
  return pairs > 0 ? double(across) / double(pairs) : 0.0;
}

// While the /kk kernels run (fix etd/kk's implicit scheme, the diagonal scheme with the pair
// style's kernel, and the pair style's kernel under fix nve), LAMMPS sorts the atoms at a
// reneighboring at least every 20 steps (atom_modify sort is every 1000 by default): at these
// masses and steps the atoms otherwise leave the sorted order within tens to hundreds of steps
// (as under the CPU styles, which LAMMPS sorts at the run's start only), and the threads' halves
// of the atoms then share many pairs. With atom_modify sort 0 nothing sorts (the data file's
// random order stays).
TEST(KokkosStyles, KernelsKeepTheAtomsSorted)
{
  // bound: the share kept sorted stays below it (a random order gives about 0.5); measured
  // 0.14-0.17 under the implicit scheme, 0.17-0.26 under the diagonal one, whose atoms move
  // further between sorts, and 0.14-0.17 under fix nve (0.49 where the pair style left LAMMPS's
  // period), on 1 and 2 ranks. On a GPU the pair style's kernel (fix nve, scheme diagonal) leaves
  // LAMMPS's period, as dpd/kk does: its share is then the CPU style's; the implicit scheme,
  // whose pair loop and search stay on the host's threads, keeps the atoms sorted there too.
  struct Scheme {
    const char *fix;
    double mass, dt;
    int steps;
    double bound;
  };
  const bool gpu = kokkos_gpus() != nullptr;
  struct Case {
    bool kokkos;
    const char *sort;
  };
  for (const Scheme &scheme : {Scheme{"etd scheme implicit", 0.01, 0.005, 100, 0.2},
                               Scheme{"etd scheme diagonal", 0.01, 0.002, 250, 0.3},
                               Scheme{"nve", 1.0, 0.01, 500, 0.3}}) {
    std::vector<double> across;
    for (const Case &c : {Case{true, "1000"}, Case{false, "1000"}, Case{true, "0"}}) {
      Lammps l(MPI_COMM_WORLD, true, c.kokkos ? kokkos_args() : std::vector<std::string>{});
      setup_box(l, scheme.mass, scheme.dt);
      l.cmds(GEN_S2);
      l.cmds({std::string("atom_modify sort ") + c.sort + " 0.0",
              std::string("fix integrate all ") + scheme.fix,
              "run " + std::to_string(scheme.steps) + " post no"});
      if (std::string(scheme.fix).find("implicit") != std::string::npos)
        EXPECT_EQ(kernel_solves(l) > 0.0, c.kokkos);
      across.push_back(pairs_across_index_halves(l));
    }
    const bool sorts = !gpu || std::string(scheme.fix).find("implicit") != std::string::npos;
    if (sorts) {
      EXPECT_LT(across[0], scheme.bound) << scheme.fix;
      EXPECT_GT(across[1], 1.5 * across[0]) << scheme.fix << ": the CPU fix";
      EXPECT_GT(across[2], 1.5 * across[0]) << scheme.fix << ": atom_modify sort 0";
    } else {
      EXPECT_GT(across[0], scheme.bound) << scheme.fix << ": LAMMPS's period on a GPU";
      EXPECT_GT(across[0], 0.75 * across[1]) << scheme.fix << ": as the CPU style";
    }
    std::printf("%s: pairs across the index halves: %.3f (kk), %.3f (CPU), %.3f (kk, sort 0)\n",
                scheme.fix, across[0], across[1], across[2]);
  }
}

// The zero-mass limit runs in the kernels: both assemblies and solves of a step (predictor and
// midpoint) count, the solve deflated where all atoms move, and with atoms held at rest (type 2
// outside the group, whose friction on the group the kernels sum) without deflation; the
// trajectory follows the CPU fix. With a compute dpd/split every step copies the pairs back to
// the host, which sums the impulse and the split there. (A
// perturbed fcc lattice at n = 3, each atom with twelve partners: in the random configuration
// some atom has almost none in some direction, and one overdamped step throws it out of the skin.)
TEST(KokkosStyles, OverdampedSolvesInTheKernels)
{
  struct Case {
    bool held, split, sheared;
  };
  for (const auto &[held, split, sheared] :
       {Case{false, false, false}, Case{true, false, false}, Case{true, true, false},
        Case{false, false, true}}) {
    Snapshot result[2];
    double solves = 0.0, assemblies = 0.0;
    for (const bool kokkos : {false, true}) {
      Lammps l(MPI_COMM_WORLD, true, kokkos ? kokkos_args() : std::vector<std::string>{});
      l.cmds({"units lj", "atom_modify map array", "comm_modify vel yes",
              "neigh_modify every 1 delay 0 check yes", "lattice fcc 3.0",
              "region box block 0 4 0 4 0 4", "create_box 2 box", "create_atoms 1 box",
              "set type 1 type/fraction 2 0.2 99", "displace_atoms all random 0.1 0.1 0.1 77",
              "mass * 1.0", "timestep 0.001", "thermo_modify norm no",
              "compute virial all pressure NULL virial", "pair_style dpd/gen 1.0 1.0 123",
              "pair_coeff * * 25.0 4.5 2.0", "group mobile type 1",
              "velocity all create 1.0 5 loop geom",    // (atoms outside the group keep theirs)
              std::string("fix integrate ") + (held ? "mobile" : "all") +
                  " etd scheme implicit overdamped yes tol 1e-10",
              split ? "compute split all dpd/split" : "variable none equal 0"});
      // (a sheared box: the images' velocities, whose friction the kernels sum)
      if (sheared)
        l.cmds({"change_box all triclinic", "fix shear all deform 1 xy erate 0.5 remap v"});
      l.cmd("run 10 post no");
      result[kokkos] = snapshot(l);
      if (kokkos) solves = kernel_solves(l);
      if (kokkos) assemblies = kernel_solves(l, "kernel_assemblies");
    }
    const std::string name = std::string(held ? "held" : "all") + (split ? ", split" : "") +
        (sheared ? ", sheared" : "");
    EXPECT_EQ(solves, 20.0) << name;
    EXPECT_EQ(assemblies, 20.0) << name;
    EXPECT_LT(max_rel_diff(result[1].x, result[0].x), 1e-8) << name;
    EXPECT_LT(max_rel_diff(result[1].v, result[0].v), 1e-8) << name;
    EXPECT_LT(max_rel_diff(result[1].virial, result[0].virial), 1e-6) << name;
    double speed = 0.0;    // (the atoms moved: else the comparison would prove nothing)
    for (const double v : result[0].v) speed = std::max(speed, std::fabs(v));
    EXPECT_GT(speed, 0.1) << name;
  }
}

// fix etd/kk scheme implicit solves on the host where its kernels do not apply (dpd/fpm's
// rotation), and says so; not with dpd/gen, inertial or overdamped
TEST(KokkosStyles, ImplicitSolveOnTheHostIsNamed)
{
  struct Case {
    std::string name;
    std::vector<std::string> setup;
    std::string fix;
    bool warns;
  };
  std::vector<std::string> spheres = SPHERE_BOX;
  spheres.insert(spheres.end(), {"pair_style dpd/fpm 1.0 1.0 8642", "pair_coeff 1 1 25 4.5 4.5 0.5",
                                 "timestep 0.003"});
  for (const Case &c : {Case{"dpd/gen", {}, "", false},
                        Case{"dpd/gen overdamped", {}, " overdamped yes", false},
                        Case{"dpd/fpm", spheres, "", true}}) {
    const std::string log = etdtest::work_file("kokkos_implicit_np" +
                                               std::to_string(etdtest::world_size()) + ".log");
    {
      Lammps l(MPI_COMM_WORLD, true, kokkos_args());
      if (c.setup.empty()) {
        setup_box(l, 0.01, 0.0005);
        l.cmds(GEN_S2);
      } else {
        l.cmds(c.setup);
      }
      l.cmds({"log " + log, "fix integrate all etd scheme implicit" + c.fix, "run 0 post no",
              "log none"});
    }
    if (etdtest::world_rank() != 0) continue;    // (rank 0 writes the log)
    const std::string text = etdtest::read_file(log);
    const bool warned =
        text.find("the friction solve runs on the host with dpd/fpm pairs") != std::string::npos;
    EXPECT_EQ(warned, c.warns) << c.name << ": " << text;
  }
}

TEST(KokkosStyles, BadInputStopsWithAnError)
{
  const auto setup = [](Lammps &l) {
    setup_box(l);
  };
  // the CPU style's own checks, through the /kk style
  etdtest::expect_errors(
      {{{"pair_style dpd/gen 1.0 1.0 123", "pair_coeff * * 25.0 -4.5 2.0"},
        "pair_coeff dpd/gen: gamma must be >= 0, got -4.5"},
       {{"pair_style dpd/gen 1.0 1.0 123", "pair_coeff * * 25.0 4.5"}, "expected I J a gamma s"},
       {{"pair_style dpd/gen 1.0 1.0 123", "pair_coeff 1 1 25.0 4.5 2.0", "run 0"},
        "are not set"},    // (LAMMPS's own check or the style's, by version)
       {{"comm_modify vel no", "pair_style dpd/gen 1.0 1.0 123", "pair_coeff * * 25.0 4.5 2.0",
         "run 0"},
        "comm_modify vel yes"},
       // fix etd/kk: the CPU fix's keyword errors and neighbor-list guards
       {{"pair_style dpd/gen 1.0 1.0 123", "pair_coeff * * 25.0 4.5 2.0",
         "fix integrate all etd order 3"},
        "order must be 1 or 2, got 3"},
       {{"pair_style dpd/gen 1.0 1.0 123", "pair_coeff * * 25.0 4.5 2.0",
         "neigh_modify every 1 delay 10 check yes", "fix integrate all etd", "run 2 post no"},
        "lets atoms outrun the neighbor skin"}},
      setup, kokkos_args());
  // neighbor multi: LAMMPS's KOKKOS build stops for a /kk style's list and crashed binning a
  // host style's (dpd/fpm has no /kk variant); both pair styles stop with the same ERROR
  const std::string multi = "cannot use 'neighbor ... multi'";
  etdtest::expect_errors({{{"pair_style dpd/gen 1.0 1.0 123", "pair_coeff * * 25.0 4.5 2.0",
                            "neighbor 0.3 multi", "run 0 post no"},
                           multi}},
                         setup, kokkos_args());
  const auto spheres = [](Lammps &l) {
    l.cmds(SPHERE_BOX);
    l.cmd("timestep 0.01");
  };
  etdtest::expect_errors({{{"pair_style dpd/fpm 1.0 1.0 8642", "pair_coeff 1 1 25 4.5 4.5 0.5",
                            "neighbor 0.3 multi", "fix integrate all nve/sphere",
                            "run 0 post no"},
                           multi}},
                         spheres, kokkos_args());
}

// LAMMPS finalises Kokkos once, after the last instance and before MPI
class KokkosFinalize : public ::testing::Environment {
 public:
  void TearDown() override { lammps_kokkos_finalize(); }
};
const auto *const kokkos_finalize = ::testing::AddGlobalTestEnvironment(new KokkosFinalize);
