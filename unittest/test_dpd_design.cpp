// Command dpd/design: the variables it sets, their use in pair_coeff, and every bad-input error.
#include "lammps_fixture.h"

#include "input.h"
#include "kinetic_theory.h"
#include "lammps.h"
#include "variable.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using etdtest::Lammps;

namespace {

const std::string FLUID = " density 4 mass 1 temp 1 cutoff 1.5";

double variable(Lammps &l, const std::string &name)
{
  return l.lmp->input->variable->compute_equal("v_" + name);
}

bool contains(const std::string &text, const std::string &part)
{
  return text.find(part) != std::string::npos;
}

}    // namespace

TEST(DpdDesign, SetsVariablesOfThePaperCase)
{
  Lammps l;
  l.cmd("dpd/design fluid eta 30 sc 500" + FLUID);
  // Table 1 of the TCAF paper (4 decimals) and the derived quantities
  EXPECT_NEAR(variable(l, "fluid_s"), 0.4244, 5e-5);
  EXPECT_NEAR(variable(l, "fluid_gamma"), 6.9710, 5e-5);
  EXPECT_NEAR(variable(l, "fluid_sigma"), std::sqrt(2.0 * variable(l, "fluid_gamma")), 1e-12);
  EXPECT_NEAR(variable(l, "fluid_E"), 24.0, 1e-12);
  EXPECT_NEAR(variable(l, "fluid_D"), 30.0 / (4.0 * 500.0), 1e-12);
  // kinetic theory of the whole fluid: the kinetic part (0.03) adds to the imposed 30
  EXPECT_NEAR(variable(l, "fluid_eta"), 30.0300, 5e-4);
  EXPECT_GT(variable(l, "fluid_eta"), 30.0);
  EXPECT_NEAR(variable(l, "fluid_Sc"), variable(l, "fluid_eta") / (4.0 * variable(l, "fluid_D")),
              1e-9);
  EXPECT_NEAR(variable(l, "fluid_tauP"), 0.93, 5e-3);
}

TEST(DpdDesign, OtherTableRowsAndTheTauPForm)
{
  Lammps l;
  l.cmd("dpd/design a eta 24 sc 500" + FLUID);
  EXPECT_NEAR(variable(l, "a_s"), 1.6441, 5e-5);
  EXPECT_NEAR(variable(l, "a_gamma"), 32.9714, 5e-5);
  l.cmd("dpd/design b eta 30 sc 800" + FLUID);
  EXPECT_NEAR(variable(l, "b_s"), 1.7169, 5e-5);
  EXPECT_NEAR(variable(l, "b_gamma"), 44.9254, 5e-5);
  // the same fluid through its particle diffusion time gives the same parameters
  char text[64];
  std::snprintf(text, sizeof(text), "%.17g", variable(l, "b_tauP"));
  l.cmd(std::string("dpd/design c eta 30 taup ") + text + FLUID);
  EXPECT_NEAR(variable(l, "c_s"), variable(l, "b_s"), 1e-12);
  EXPECT_NEAR(variable(l, "c_gamma"), variable(l, "b_gamma"), 1e-10);
  EXPECT_NEAR(variable(l, "c_E"), variable(l, "b_E"), 1e-12);
}

TEST(DpdDesign, RepeatingANameReplacesItsValues)
{
  Lammps l;
  l.cmd("dpd/design fluid eta 30 sc 500" + FLUID);
  l.cmd("dpd/design fluid eta 30 sc 600" + FLUID);
  EXPECT_NEAR(variable(l, "fluid_s"), 0.8898, 5e-5);
  EXPECT_NEAR(variable(l, "fluid_gamma"), 15.0263, 5e-5);
}

TEST(DpdDesign, KeywordOrderDoesNotMatter)
{
  Lammps l;
  l.cmd("dpd/design x cutoff 1.5 temp 1 mass 1 density 4 sc 700 eta 30");
  EXPECT_NEAR(variable(l, "x_s"), 1.3181, 5e-5);
  EXPECT_NEAR(variable(l, "x_gamma"), 27.4087, 5e-5);
}

// The designed s and gamma, substituted into pair_coeff, act in the force: two atoms at zero
// temperature approaching each other feel a + dissipative force with the designed weight.
TEST(DpdDesign, VariablesWorkInPairCoeff)
{
  Lammps l;
  l.cmds({"dpd/design fluid eta 30 sc 500" + FLUID, "units lj", "atom_modify map array",
          "comm_modify vel yes", "neigh_modify every 1 delay 0 check yes",
          "region box block 0 6 0 6 0 6", "create_box 1 box", "create_atoms 1 single 2.0 3.0 3.0",
          "create_atoms 1 single 2.6 3.0 3.0", "mass 1 1.0", "velocity all set 0.5 0 0",
          "group right id 2", "velocity right set -0.5 0 0", "pair_style dpd/gen 0.0 1.5 1234",
          "pair_coeff 1 1 3.5328 ${fluid_gamma} ${fluid_s}", "run 0 post no"});
  const std::vector<double> f = l.gather("f");
  const double s = variable(l, "fluid_s"), gamma = variable(l, "fluid_gamma");
  const double r = 0.6, rc = 1.5;
  // atom 1 is at smaller x: e = r_12/r = -x, v_12 = (1, 0, 0), e.v_12 = -1
  const double expected = -(3.5328 * (1.0 - r / rc)) - gamma * std::pow(1.0 - r / rc, s);
  EXPECT_NEAR(f[0], expected, 1e-9 * std::fabs(expected));
  EXPECT_NEAR(f[3], -expected, 1e-9 * std::fabs(expected));
  // the force differs from the one with the unrounded Table 1 numbers only by their rounding
  EXPECT_NEAR(f[0], -(3.5328 * 0.6) - 6.9710 * std::pow(0.6, 0.4244), 2e-4);
}

TEST(DpdDesign, ImpossibleFluidStopsWithTheBound)
{
  Lammps l;
  // Sc_min = 50 eta^2 / (3 kBT m n^2 rc^2) = 416.667 for eta = 30
  std::string message = l.error_of("dpd/design fluid eta 30 sc 400" + FLUID);
  EXPECT_TRUE(contains(message, "no exponent s > 0")) << message;
  EXPECT_TRUE(contains(message, "E = 19.2, needs E > 20")) << message;
  EXPECT_TRUE(contains(message, "Sc must exceed 416.667")) << message;
  EXPECT_TRUE(contains(message, "eta must be below 29.3939")) << message;
  // and no variables were set
  EXPECT_EQ(l.lmp->input->variable->find("fluid_s"), -1);

  const etd::kinetic::FluidState paper{4.0, 1.0, 1.0, 1.5};
  message = l.error_of("dpd/design fluid eta 30 taup 0.5" + FLUID);
  EXPECT_TRUE(contains(message, "tau_P must exceed")) << message;
  char bound[32];
  std::snprintf(bound, sizeof(bound), "%.6g", etd::kinetic::min_particle_diffusion_time(paper, 30));
  EXPECT_TRUE(contains(message, bound)) << message << " (expected " << bound << ")";
  std::snprintf(bound, sizeof(bound), "%.6g",
                etd::kinetic::max_viscosity_for_particle_diffusion_time(paper, 0.5));
  EXPECT_TRUE(contains(message, std::string("eta must be below ") + bound)) << message;
  // exactly at the bound (E = 20, s = 0) is impossible too
  message = l.error_of("dpd/design fluid eta 30 sc 416.66666666666669" + FLUID);
  EXPECT_TRUE(contains(message, "no exponent s > 0")) << message;
}

TEST(DpdDesign, BadInputErrors)
{
  etdtest::expect_errors(
      {
          {{"dpd/design"}, "Illegal dpd/design command: expected 'dpd/design name"},
          {{"dpd/design my-fluid eta 30 sc 500" + FLUID}, "name 'my-fluid' must contain only"},
          {{"dpd/design 30 sc 500" + FLUID}, "the first argument is the name"},
          {{"dpd/design f eta 30 schmidt 500" + FLUID}, "unknown keyword 'schmidt'"},
          {{"dpd/design f eta 30 eta 31 sc 500" + FLUID}, "keyword 'eta' given twice"},
          {{"dpd/design f sc 500" + FLUID + " eta"}, "keyword 'eta' needs a value"},
          {{"dpd/design f eta thirty sc 500" + FLUID},
           "eta (viscosity) must be a number, got 'thirty'"},
          {{"dpd/design f eta 0 sc 500" + FLUID},
           "eta (viscosity) must be a finite number > 0, got 0"},
          {{"dpd/design f eta -30 sc 500" + FLUID}, "eta (viscosity) must be a finite number > 0"},
          {{"dpd/design f eta 1e400 sc 500" + FLUID},
           "eta (viscosity) must be a finite number > 0"},
          {{"dpd/design f eta 30 sc -5" + FLUID},
           "sc (Schmidt number) must be a finite number > 0"},
          {{"dpd/design f eta 30 taup 0" + FLUID},
           "taup (particle diffusion time) must be a finite"},
          {{"dpd/design f eta 30 sc 500 density 0 mass 1 temp 1 cutoff 1.5"},
           "density (number density) must be a finite number > 0"},
          {{"dpd/design f eta 30 sc 500 density 4 mass x temp 1 cutoff 1.5"},
           "mass (particle mass) must be a number"},
          {{"dpd/design f eta 30 sc 500 density 4 mass 1 temp -1 cutoff 1.5"},
           "temp (temperature kBT) must be a finite number > 0"},
          {{"dpd/design f eta 30 sc 500 density 4 mass 1 temp 1 cutoff 0"},
           "cutoff (cutoff) must be a finite number > 0"},
          {{"dpd/design f eta 30 sc 500 taup 1" + FLUID}, "give either sc or taup, not both"},
          {{"dpd/design f eta 30" + FLUID}, "missing keyword sc or taup"},
          {{"dpd/design f sc 500" + FLUID}, "missing keyword eta (viscosity)"},
          {{"dpd/design f eta 30 sc 500 mass 1 temp 1 cutoff 1.5"}, "missing keyword density"},
          {{"dpd/design f eta 30 sc 500 density 4 temp 1 cutoff 1.5"}, "missing keyword mass"},
          {{"dpd/design f eta 30 sc 500 density 4 mass 1 cutoff 1.5"}, "missing keyword temp"},
          {{"dpd/design f eta 30 sc 500 density 4 mass 1 temp 1"}, "missing keyword cutoff"},
      },
      [](Lammps &) {
      });
  // a variable of another style under the same name is refused by LAMMPS itself (in its own
  // words, which differ between versions: only the refusal is checked)
  Lammps l;
  l.cmd("variable g_s string abc");
  EXPECT_FALSE(l.error_of("dpd/design g eta 30 sc 500" + FLUID).empty());
}
