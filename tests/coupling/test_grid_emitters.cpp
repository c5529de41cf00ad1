// coupling/grid_emitters: a grid file's hot voxels as emitters, refused where the file holds the
// fraction grids of only some of the run's materials (the others' voxels would be dropped).
#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "coupling/grid_emitters.hpp"
#include "fields/grid_set.hpp"
#include "fields/vdb_grids.hpp"
#include "support/temp_dir_test.hpp"

namespace ejecta::coupling {
namespace {

namespace fs = std::filesystem;

// A 4^3 block of voxels at 2,000 K, each holding rock (fraction 0.75) and iron (0.25), written
// with `runMaterials` as the run's material list and the fraction grids of `written` only.
std::string writeHotBlock(const fs::path& file, const std::vector<std::string>& runMaterials,
                          const std::vector<std::string>& written) {
  fields::GridSet set;
  set.lattice = fields::SparseLattice(3, 0.5, 1 + 1 + static_cast<int>(written.size()));
  const std::size_t block = set.lattice.addBlock({0, 0, 0});
  set.source = Geometry::Axisymmetric;
  set.materials = runMaterials;
  set.grids.push_back({"temperature", "K", 1, false});
  for (std::size_t m = 0; m < written.size(); ++m)
    set.grids.push_back({"fraction_" + written[m], "1", static_cast<int>(m) + 2, false, true});
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k) {
        const int voxel = set.lattice.localIndex(i, j, k);
        set.lattice.data(block, 0)[voxel] = 1.0f;
        set.lattice.data(block, 1)[voxel] = 2000.0f;
        for (std::size_t m = 0; m < written.size(); ++m)
          set.lattice.data(block, static_cast<int>(m) + 2)[voxel] = written[m] == "rock" ? 0.75f : 0.25f;
      }
  fields::GridFileMeta meta;
  meta.scene = "hot block";
  meta.levelSet = false;
  fields::writeGridFile(file.string(), set, meta);
  return file.string();
}

class GridEmitters : public test::TempDirTest {};

TEST_F(GridEmitters, EveryMaterialsFractionGivesFullVoxels) {
  const std::string file = writeHotBlock(dir_ / "all.vdb", {"rock", "iron"}, {"rock", "iron"});
  GridEmitterStats stats;
  const radiation::Emitters e = emittersFromGridFile(file, {}, &stats);
  ASSERT_EQ(e.size(), 64u);
  EXPECT_TRUE(stats.fillWeighted);
  EXPECT_NEAR(stats.hotVolume, 64 * 0.125, 1e-9);  // fractions 0.75 + 0.25: every voxel full
}

TEST_F(GridEmitters, FractionsOfSomeMaterialsAreRefused) {
  // Iron's fraction not written: each voxel would count 0.75 full, and iron-only voxels none.
  const std::string file = writeHotBlock(dir_ / "some.vdb", {"rock", "iron"}, {"rock"});
  try {
    emittersFromGridFile(file);
    FAIL() << "a file without iron's fraction grid was read as emitters";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(file), std::string::npos) << what;
    EXPECT_NE(what.find("fraction grids of rock but not of iron"), std::string::npos) << what;
    EXPECT_NE(what.find("--emitters particles"), std::string::npos) << what;
  }
  // A file from before the material list (none stored) is read as it was.
  const std::string old = writeHotBlock(dir_ / "old.vdb", {}, {"rock"});
  EXPECT_EQ(emittersFromGridFile(old).size(), 64u);
}

}  // namespace
}  // namespace ejecta::coupling
