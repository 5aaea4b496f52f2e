// The plugin loads, registers every style it claims, and rejects misuse with clear errors.
#include "lammps_fixture.h"

#include "lammps.h"
#include "library.h"

#include <gtest/gtest.h>

using etdtest::Lammps;

TEST(Plugin, RegistersEveryStyle)
{
  Lammps l;
  EXPECT_TRUE(lammps_has_style(l.lmp, "pair", "dpd/gen"));
  EXPECT_TRUE(lammps_has_style(l.lmp, "fix", "etd"));
  EXPECT_TRUE(lammps_has_style(l.lmp, "compute", "dpd/split"));
  // and the stock styles we compare against are in this LAMMPS
  EXPECT_TRUE(lammps_has_style(l.lmp, "pair", "dpd"));
  EXPECT_TRUE(lammps_has_style(l.lmp, "pair", "dpd/ext"));
}

TEST(Plugin, LoadingTwiceIsHarmless)
{
  Lammps l;
  l.cmd(std::string("plugin load ") + ETD_PLUGIN_PATH);
  EXPECT_TRUE(lammps_has_style(l.lmp, "pair", "dpd/gen"));
}

TEST(Plugin, StyleUsedWithoutItsPairStyleGivesClearError)
{
  Lammps l;
  l.cmds({"units lj", "atom_modify map array", "region box block 0 4 0 4 0 4",
          "create_box 1 box", "create_atoms 1 random 40 1 NULL", "mass 1 1.0",
          "pair_style zero 1.0", "pair_coeff * *", "fix 1 all etd"});
  const std::string message = l.error_of("run 1");
  EXPECT_NE(message.find("Fix etd requires pair style dpd/gen"), std::string::npos) << message;
}
