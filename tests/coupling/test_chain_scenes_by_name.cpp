// The shipped scenes from the command line (apps/cmd_scenes.cpp, sim/setup/scene_catalog.hpp):
// `ejecta scenes` lists every file with the command that takes it, `ejecta scenes show` prints
// one byte for byte, `ejecta run NAME` runs a shipped scene from a directory that has no scenes/,
// and a mistyped name is refused with exit status 1 and a pointer to the list; the studies
// (`ejecta whipple`, `ejecta viewfactor`, `ejecta thermal`) are taken by name as the list says.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "support/command_line.hpp"

namespace fs = std::filesystem;

namespace {

using ejecta::test::kEjecta;
using ejecta::test::readTextFile;
using ejecta::test::runCommand;

TEST(ScenesByName, TheListNamesEveryShippedFileAndItsCommand) {
  std::string out;
  ASSERT_EQ(runCommand(kEjecta + " scenes", out), 0) << out;
  for (const auto& e : fs::recursive_directory_iterator(fs::path(EJECTA_SOURCE_DIR) / "scenes")) {
    if (e.path().extension() != ".toml") continue;
    const std::string name =
        fs::relative(e.path(), fs::path(EJECTA_SOURCE_DIR) / "scenes").replace_extension().string();
    EXPECT_NE(out.find(name + " "), std::string::npos) << name << "\n" << out;
  }
  EXPECT_NE(out.find("ejecta viewfactor"), std::string::npos);
  EXPECT_NE(out.find("Aluminium impactor on a granite-core"), std::string::npos);  // impact_rz
  ASSERT_EQ(runCommand(kEjecta + " scenes --kind geometry", out), 0) << out;
  EXPECT_EQ(out.find("impact_rz"), std::string::npos) << out;
  EXPECT_NE(out.find("geometry/seed_follower"), std::string::npos) << out;
  EXPECT_EQ(runCommand(kEjecta + " scenes --kind scenes", out), 1) << out;
}

TEST(ScenesByName, ShowPrintsTheFileByteForByte) {
  std::string out;
  ASSERT_EQ(runCommand(kEjecta + " scenes show verification/sod_1d 2>/dev/null", out), 0);
  EXPECT_EQ(out, readTextFile(fs::path(EJECTA_SOURCE_DIR) / "scenes/verification/sod_1d.toml"));
  EXPECT_EQ(runCommand(kEjecta + " scenes show no_such_scene", out), 1);
  EXPECT_NE(out.find("no_such_scene"), std::string::npos) << out;
}

TEST(ScenesByName, RunTakesAShippedNameFromAnyDirectory) {
  const fs::path dir = fs::temp_directory_path() / ("ejecta_by_name_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::string out;
  const std::string cd = "cd " + dir.string() + " && ";
  ASSERT_EQ(runCommand(cd + kEjecta + " run sod_1d --set 'time.t_end=0.01 s' --quiet --no-charts "
                       "--threads 1 --out run",
                       out),
            0)
      << out;
  EXPECT_NE(out.find("shipped scene 'verification/sod_1d'"), std::string::npos) << out;
  EXPECT_TRUE(fs::exists(dir / "run" / "summary.json"));
  // The run stores the shipped text, so it restarts without the name resolving again.
  EXPECT_NE(readTextFile(dir / "run" / "summary.json").find("\"completed\""), std::string::npos);
  EXPECT_EQ(runCommand(cd + kEjecta + " run sod_1e --quiet", out), 1) << out;
  EXPECT_NE(out.find("sod_1e: cannot open: no such file, and no shipped scene of that name"), std::string::npos) << out;
  EXPECT_NE(out.find("ejecta scenes"), std::string::npos) << out;
  fs::remove_all(dir);
}

TEST(ScenesByName, StudiesAreTakenByNameAsTheListSays) {
  const fs::path dir = fs::temp_directory_path() / ("ejecta_studies_by_name_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string cd = "cd " + dir.string() + " && ";
  std::string byName, byFile;
  // The same answer from the name as from the file (the seed's 3.2 mm wall: d_c = 4.43 mm at 10 km/s).
  ASSERT_EQ(runCommand(cd + kEjecta + " whipple whipple/haiv --out w", byName), 0) << byName;
  ASSERT_EQ(runCommand(cd + kEjecta + " whipple " + EJECTA_SOURCE_DIR + "/scenes/whipple/haiv.toml --out f", byFile), 0)
      << byFile;
  EXPECT_NE(byName.find("shipped scene 'whipple/haiv'"), std::string::npos) << byName;
  EXPECT_EQ(readTextFile(dir / "w" / "ble.csv"), readTextFile(dir / "f" / "ble.csv"));
  EXPECT_FALSE(readTextFile(dir / "w" / "ble.csv").empty());
  ASSERT_EQ(runCommand(cd + kEjecta + " viewfactor geometry/howell_coaxial_discs --rays 4096", byName), 0) << byName;
  EXPECT_NE(byName.find("F -> disc2"), std::string::npos) << byName;
  // A thermal study by name gets as far as its hot material (none given here).
  EXPECT_EQ(runCommand(cd + kEjecta + " thermal thermal/follower", byName), 1) << byName;
  EXPECT_NE(byName.find("no hot material"), std::string::npos) << byName;
  EXPECT_EQ(runCommand(cd + kEjecta + " thermal thermal/folower --from x", byName), 1) << byName;
  EXPECT_NE(byName.find("thermal/folower: cannot open: no such file, and no shipped scene"), std::string::npos)
      << byName;
  fs::remove_all(dir);
}

}  // namespace
