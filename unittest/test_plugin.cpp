// The plugin loads, registers every style it claims, and rejects misuse with clear errors.
#include "lammps_fixture.h"

#include "lammps.h"
#include "library.h"
#include "plugin.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <utility>

using etdtest::Lammps;

// The styles the doc pages describe: each page of doc/ opens with LAMMPS's ".. index:: pair_style
// NAME" (fix NAME, compute NAME, or the bare NAME of a command).
// Every `.. index::` line of the doc pages: "pair_style NAME", "fix NAME", ... or a command.
// A KOKKOS variant NAME/kk is registered with NAME/kk/device and NAME/kk/host, in a plugin built
// with the KOKKOS styles only (ETD_DPD_KOKKOS).
static std::set<std::pair<std::string, std::string>> documented_styles()
{
  std::set<std::pair<std::string, std::string>> styles;
  for (const auto &page : std::filesystem::directory_iterator(ETD_DOC_DIR)) {
    if (page.path().extension() != ".rst") continue;
    std::ifstream in(page.path());
    std::string line;
    while (std::getline(in, line) && line.rfind(".. index::", 0) == 0) {
      std::istringstream words(line.substr(10));
      std::string first, second;
      words >> first >> second;
      if (second.empty()) {
        styles.insert({"command", first});
        continue;
      }
      const std::string category = first == "pair_style" ? "pair" : first;
      const bool kokkos = second.size() > 3 && second.compare(second.size() - 3, 3, "/kk") == 0;
#ifdef ETD_DPD_KOKKOS
      if (kokkos)
        for (const char *variant : {"/device", "/host"})
          styles.insert({category, second + variant});
#else
      if (kokkos) continue;
#endif
      styles.insert({category, second});
    }
  }
  return styles;
}

// Every style the package documents is registered, usable by LAMMPS under its name, and
// nothing else is: the plugin's own registration list is exactly the styles with a doc page
// (eight: dpd/gen, dpd/fpm, etd, wall/thermal/layer, wall/cylinder/bounce, dpd/split,
// dpd/tcurrent, dpd/design; with the KOKKOS styles also dpd/gen/kk and etd/kk).
TEST(Plugin, RegistersEveryStyle)
{
  Lammps l;
  const std::set<std::pair<std::string, std::string>> documented = documented_styles();
  ASSERT_EQ(documented.count({"pair", "dpd/gen"}), 1u) << "doc pages not read from " << ETD_DOC_DIR;
  ASSERT_EQ(documented.count({"command", "dpd/design"}), 1u);
  std::set<std::pair<std::string, std::string>> registered;
  for (int i = 0; i < LAMMPS_NS::plugin_get_num_plugins(); i++) {
    const lammpsplugin_t *info = LAMMPS_NS::plugin_get_info(i);
    registered.insert({info->style, info->name});
  }
  EXPECT_EQ(registered, documented);
  for (const auto &[category, name] : documented)
    EXPECT_TRUE(lammps_has_style(l.lmp, category.c_str(), name.c_str())) << category << " " << name;
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
  l.cmds({"units lj", "atom_modify map array", "region box block 0 4 0 4 0 4", "create_box 1 box",
          "create_atoms 1 random 40 1 NULL", "mass 1 1.0", "pair_style zero 1.0", "pair_coeff * *",
          "fix 1 all etd"});
  const std::string message = l.error_of("run 1");
  EXPECT_NE(message.find("Fix etd requires pair style dpd/gen"), std::string::npos) << message;
}
