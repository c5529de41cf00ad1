// The hostile-input corpus (issue 24, docs/robustness.md): every case in tests/hostile/cases.toml
// gives `ejecta` a bad input (a scene, a snapshot, a grid file, a mesh, a geometry, thermal or
// shield file, a restart directory, a command-line option) and asserts the exit status and that
// the message names the file and the key. Each case is its own CTest test; the snapshots, grid
// files and run directories they damage are copies of one small run that the fixture
// `hostile_base` makes first (tests/CMakeLists.txt). A hang is cut by `timeout` and fails.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <toml++/toml.h>
#include <vector>

#include "support/command_line.hpp"

namespace fs = std::filesystem;

namespace ejecta::test {
namespace {

const fs::path kSource = EJECTA_SOURCE_DIR;
const fs::path kCorpus = kSource / "tests" / "hostile";
const fs::path kBase = fs::path(EJECTA_BINARY_DIR) / "hostile_base";  // the fixture's run

// One case of cases.toml.
struct Case {
  std::string name;
  const toml::table* table = nullptr;
};

// gtest prints a failing case by its name, not its bytes.
void PrintTo(const Case& c, std::ostream* out) { *out << c.name; }

std::vector<Case> loadCases() {
  static const toml::table doc = toml::parse_file((kCorpus / "cases.toml").string());
  std::vector<Case> cases;
  if (const toml::array* list = doc["case"].as_array())
    for (const toml::node& n : *list)
      if (const toml::table* t = n.as_table()) cases.push_back({(*t)["name"].value_or(std::string()), t});
  return cases;
}

std::string readBytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void writeBytes(const fs::path& p, const std::string& bytes) {
  fs::create_directories(p.parent_path());
  std::ofstream out(p, std::ios::binary);
  out << bytes;
}

std::string replaceAll(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

double parseValue(const std::string& v) {
  if (v == "nan") return std::numeric_limits<double>::quiet_NaN();
  if (v == "inf") return std::numeric_limits<double>::infinity();
  if (v == "-inf") return -std::numeric_limits<double>::infinity();
  return std::stod(v);
}

// Writes `value` into row `row`, column `column` of dataset `path` (converted to its type), or
// every row when row < 0: a hand-edited file whose checksums HDF5 recomputes, so only ejecta's
// own checks can refuse it.
void setDatasetValue(const fs::path& file, const std::string& path, long row, int column, double value) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(f, 0) << file;
  const hid_t d = H5Dopen2(f, path.c_str(), H5P_DEFAULT);
  ASSERT_GE(d, 0) << path;
  const hid_t space = H5Dget_space(d);
  const int rank = H5Sget_simple_extent_ndims(space);
  hsize_t dims[2] = {0, 1};
  H5Sget_simple_extent_dims(space, dims, nullptr);
  const hsize_t first = row < 0 ? 0 : static_cast<hsize_t>(row);
  const hsize_t count[2] = {row < 0 ? dims[0] : 1, 1};
  const hsize_t start[2] = {first, static_cast<hsize_t>(column)};
  H5Sselect_hyperslab(space, H5S_SELECT_SET, start, nullptr, count, nullptr);
  const std::vector<double> values(count[0], value);
  const hid_t memory = H5Screate_simple(1, count, nullptr);
  (void)rank;
  EXPECT_GE(H5Dwrite(d, H5T_NATIVE_DOUBLE, memory, space, H5P_DEFAULT, values.data()), 0);
  H5Sclose(memory);
  H5Sclose(space);
  H5Dclose(d);
  H5Fclose(f);
}

void setAttributeValue(const fs::path& file, const std::string& object, const std::string& name, double value) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(f, 0) << file;
  const hid_t o = H5Oopen(f, object.c_str(), H5P_DEFAULT);
  const hid_t a = H5Aopen(o, name.c_str(), H5P_DEFAULT);
  ASSERT_GE(a, 0) << object << " " << name;
  EXPECT_GE(H5Awrite(a, H5T_NATIVE_DOUBLE, &value), 0);
  H5Aclose(a);
  H5Oclose(o);
  H5Fclose(f);
}

void deleteLink(const fs::path& file, const std::string& path) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(f, 0) << file;
  EXPECT_GE(H5Ldelete(f, path.c_str(), H5P_DEFAULT), 0) << path;
  H5Fclose(f);
}

// Byte-level damage: `count` bit flips at offsets past `skip` (seeded), then truncation to the
// fraction `keep` of the file.
void damageBytes(const fs::path& file, const toml::table& t) {
  std::string bytes = readBytes(file);
  const auto flips = t["flips"].value_or<std::int64_t>(0);
  std::mt19937_64 random(static_cast<std::uint64_t>(t["seed"].value_or<std::int64_t>(1)));
  const auto skip = static_cast<std::size_t>(t["skip"].value_or<std::int64_t>(0));
  for (std::int64_t k = 0; k < flips && bytes.size() > skip; ++k) {
    const std::size_t at = skip + random() % (bytes.size() - skip);
    bytes[at] = static_cast<char>(bytes[at] ^ (1 << (random() % 8)));
  }
  if (const auto keep = t["keep"].value<double>())
    bytes.resize(static_cast<std::size_t>(*keep * static_cast<double>(bytes.size())));
  writeBytes(file, bytes);
}

class HostileInput : public ::testing::TestWithParam<Case> {};

TEST_P(HostileInput, IsRefusedWithTheFileAndKeyNamed) {
  const toml::table& t = *GetParam().table;
  ASSERT_TRUE(fs::exists(kBase / "snapshots" / "snap_0003.h5"))
      << "the fixture hostile_base has not run (ctest runs it first)";
  const fs::path dir = fs::path(EJECTA_BINARY_DIR) / "hostile" / GetParam().name;
  fs::remove_all(dir);
  fs::create_directories(dir);

  // The input: a copy of a base artefact or a file of the case's own, then damaged.
  const std::string kind = t["kind"].value_or(std::string("none"));
  fs::path input;
  if (kind == "scene") {
    std::string text = readBytes(kCorpus / "base_scene.toml");
    if (const toml::array* edits = t["replace"].as_array())
      for (const toml::node& e : *edits) {
        const toml::array& pair = *e.as_array();
        const std::string from = pair[0].value_or(std::string()), to = pair[1].value_or(std::string());
        ASSERT_NE(text.find(from), std::string::npos) << "the base scene has no '" << from << "'";
        text.replace(text.find(from), from.size(), to);
      }
    text += t["append"].value_or(std::string());
    input = dir / "scene.toml";
    writeBytes(input, text);
  } else if (kind == "text") {
    input = dir / ("input" + t["ext"].value_or(std::string(".toml")));
    writeBytes(input, t["text"].value_or(std::string()));
  } else if (kind == "snapshot" || kind == "grid") {
    const std::string from = t["from"].value_or(std::string(kind == "snapshot" ? "snapshots/snap_0003.h5"
                                                                                : "fields/fields_0003.vdb"));
    input = dir / fs::path(from).filename();
    fs::copy_file(kBase / from, input);
  } else if (kind == "rundir") {
    input = dir / "run";
    fs::copy(kBase, input, fs::copy_options::recursive);
  } else {
    ASSERT_EQ(kind, "none") << "unknown kind";
  }
  const fs::path target = kind == "rundir" ? input / t["target"].value_or(std::string("snapshots/snap_0003.h5")) : input;
  if (const toml::table* set = t["set_dataset"].as_table())
    setDatasetValue(target, (*set)["path"].value_or(std::string()), (*set)["row"].value_or<std::int64_t>(0),
                    static_cast<int>((*set)["column"].value_or<std::int64_t>(0)),
                    parseValue((*set)["value"].value_or(std::string("0"))));
  if (const toml::table* set = t["set_attribute"].as_table())
    setAttributeValue(target, (*set)["object"].value_or(std::string("/")), (*set)["name"].value_or(std::string()),
                      parseValue((*set)["value"].value_or(std::string("0"))));
  if (const auto link = t["delete"].value<std::string>()) deleteLink(target, *link);
  if (const toml::table* bytes = t["damage"].as_table()) damageBytes(target, *bytes);
  if (const toml::array* removes = t["remove"].as_array())
    for (const toml::node& r : *removes) fs::remove_all(input / r.value_or(std::string()));

  // Other files the case writes beside the input (meshes a geometry file names, ...).
  if (const toml::table* files = t["files"].as_table())
    for (auto&& [name, content] : *files) writeBytes(dir / std::string(name.str()), content.value_or(std::string()));

  auto expand = [&](std::string s) {
    s = replaceAll(s, "{input}", input.string());
    s = replaceAll(s, "{dir}", dir.string());
    s = replaceAll(s, "{base}", kBase.string());
    s = replaceAll(s, "{src}", kSource.string());
    return s;
  };
  auto commandOf = [&](const toml::array& args) {
    std::string command = "cd " + dir.string() + " && timeout 120 " + kEjecta;
    for (const toml::node& a : args) command += " '" + expand(a.value_or(std::string())) + "'";
    return command;
  };
  std::string output;
  // Commands that prepare the case (another run to mix in), then copies between their outputs.
  if (const toml::array* before = t["before"].as_array())
    for (const toml::node& b : *before) {
      const std::string command = commandOf(*b.as_array());
      ASSERT_EQ(runCommand(command, output), 0) << command << "\n" << output;
    }
  if (const toml::array* copies = t["copy"].as_array())
    for (const toml::node& c : *copies) {
      const toml::array& pair = *c.as_array();
      fs::copy_file(expand(pair[0].value_or(std::string())), expand(pair[1].value_or(std::string())),
                    fs::copy_options::overwrite_existing);
    }
  const std::string command = commandOf(t["args"].as_array() ? *t["args"].as_array() : toml::array{});
  const int status = runCommand(command, output);

  const auto expected = t["exit"].value_or<std::int64_t>(1);
  EXPECT_EQ(status, expected) << command << "\n" << output;
  if (const toml::array* expect = t["expect"].as_array())
    for (const toml::node& e : *expect) {
      const std::string want = expand(e.value_or(std::string()));
      EXPECT_NE(output.find(want), std::string::npos) << "the message lacks '" << want << "':\n" << output;
    }
  // What must survive a refusal (an earlier run's outputs) or be gone after it (stale files).
  if (const toml::array* keeps = t["keeps"].as_array()) {
    for (const toml::node& k : *keeps) {
      const std::string path = expand(k.value_or(std::string()));
      EXPECT_TRUE(fs::exists(path)) << path << " is gone";
    }
  }
  if (const toml::array* gone = t["gone"].as_array()) {
    for (const toml::node& g : *gone) {
      const std::string path = expand(g.value_or(std::string()));
      EXPECT_FALSE(fs::exists(path)) << path << " is still there";
    }
  }
  EXPECT_EQ(output.find("terminate called"), std::string::npos) << output;
}

std::string caseName(const ::testing::TestParamInfo<Case>& info) { return info.param.name; }

INSTANTIATE_TEST_SUITE_P(Corpus, HostileInput, ::testing::ValuesIn(loadCases()), caseName);

// The corpus is what the issue asks for: at least 150 cases, each with a unique name.
TEST(HostileCorpus, HoldsAtLeast150UniquelyNamedCases) {
  const std::vector<Case> cases = loadCases();
  EXPECT_GE(cases.size(), 150u);
  std::vector<std::string> names;
  for (const Case& c : cases) {
    EXPECT_FALSE(c.name.empty());
    EXPECT_TRUE(std::all_of(c.name.begin(), c.name.end(), [](char ch) { return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_'; }))
        << c.name;
    names.push_back(c.name);
  }
  std::sort(names.begin(), names.end());
  EXPECT_EQ(std::adjacent_find(names.begin(), names.end()), names.end());
}

}  // namespace
}  // namespace ejecta::test
