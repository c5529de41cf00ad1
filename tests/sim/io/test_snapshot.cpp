// Output files: HDF5 snapshots (round trip, layout, errors, atomicity), the XDMF series index
// and summary.json.
#include <gtest/gtest.h>
#include <hdf5.h>
#include <unistd.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "core/atomic_file.hpp"
#include "sim/io/snapshot.hpp"
#include "sim/io/xdmf.hpp"
#include "sim/run/summary.hpp"

namespace fs = std::filesystem;
using namespace ejecta;

namespace {

// A fresh directory per test, removed afterwards.
class OutputFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("ejecta_test_snapshot_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ignored;
    fs::permissions(dir_, fs::perms::owner_all, fs::perm_options::add, ignored);
    fs::remove_all(dir_, ignored);
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::vector<std::string> directoryEntries() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_)) names.push_back(e.path().filename());
    return names;
  }

  fs::path dir_;
};

std::string readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Awkward doubles: subnormals, extremes, signed zero, non-finite values.
double awkwardDouble(std::mt19937_64& rng) {
  static constexpr double kSpecial[] = {
      4.9406564584124654e-324, 2.2250738585072009e-308, -1.0e-310, 1.7976931348623157e308,
      -1.0e300, -0.0, 0.0, std::numeric_limits<double>::infinity(),
      std::numeric_limits<double>::quiet_NaN(), 0.1};
  std::uniform_int_distribution<int> pick(0, 19);
  const int k = pick(rng);
  if (k < 10) return kSpecial[k];
  // Otherwise a random finite bit pattern anywhere in the exponent range.
  std::uint64_t bits = rng();
  if (((bits >> 52) & 0x7ff) == 0x7ff) bits &= ~(std::uint64_t{1} << 62);
  return std::bit_cast<double>(bits);
}

// What a snapshot may hold (sim/io/snapshot_checks.hpp): no NaN, finite science arrays,
// positive mass, density and h, lengths within 1e12 m. The awkward values are kept inside that.
enum class Stored { Any, Positive, Length, PositiveLength };

void fill(std::vector<double>& values, std::mt19937_64& rng, Stored kind = Stored::Any) {
  for (double& v : values) {
    v = awkwardDouble(rng);
    if (std::isnan(v)) v = 0.1;
    if (std::isinf(v)) v = std::copysign(1.7976931348623157e308, v);
    if (kind == Stored::Positive || kind == Stored::PositiveLength) v = v == 0.0 ? 4.9406564584124654e-324 : std::abs(v);
    if ((kind == Stored::Length || kind == Stored::PositiveLength) && std::abs(v) > 1e12) v = std::copysign(0.75e12, v);
  }
}

// n real particles (with `ghosts` ghost entries after them) full of awkward values. Position
// components beyond the geometry's dimension are 0, as the solver keeps them.
ParticleSet randomParticles(std::size_t n, std::size_t ghosts, Geometry geometry,
                            std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  ParticleSet p;
  p.resize(n + ghosts);
  for (int d = 0; d < 3; ++d) {
    fill(p.x[d], rng, Stored::Length);
    if (d >= spatialDimension(geometry)) std::fill(p.x[d].begin(), p.x[d].end(), 0.0);
    fill(p.v[d], rng);
    fill(p.a[d], rng);
  }
  for (auto* array : {&p.mass, &p.rho, &p.u, &p.h, &p.P, &p.cs, &p.du_dt, &p.drho_dt, &p.dh_dt,
                      &p.omega, &p.divv, &p.curlv, &p.areaDensity})
    fill(*array, rng, array == &p.h ? Stored::PositiveLength
                      : array == &p.mass || array == &p.rho ? Stored::Positive
                                                           : Stored::Any);
  for (auto& m : p.material) m = static_cast<int>(rng() >> 33);  // non-negative
  for (auto& id : p.id) id = static_cast<std::int64_t>(rng());
  p.numReal = n;
  p.ghostSource.assign(ghosts, 0);
  return p;
}

SnapshotInfo sampleInfo(Geometry geometry) {
  SnapshotInfo info;
  info.time = 1.2345678901234567e-3;
  info.step = 123456789012L;
  info.geometry = geometry;
  info.scene = "sedov \"blast\" <test> & ünïcode";
  info.dtNext = 3.0e-9;
  info.snapshotIndex = 42;
  info.nextOutputTime = 1.3e-3;
  info.initialEnergy = -4.9406564584124654e-324;
  info.initialMomentum = {1.0e-300, -2.5, 0.1};
  info.wallSeconds = 98.7654321;
  info.sceneSource = "[scene]\nname = \"sedov\"\n# a long-ish comment\n";
  info.materials = {{"granite", "tillotson (granite)", "collins", "grady_kipp"},
                    {"ünïcode & <air>", "ideal_gas", "none", "none"},
                    {"", "jwl (tnt)", "none", "none"}};
  return info;
}

template <typename T>
void expectBitsEqual(const std::vector<T>& expected, const std::vector<T>& actual,
                     std::size_t n, const char* name) {
  ASSERT_EQ(actual.size(), n) << name;
  for (std::size_t i = 0; i < n; ++i) {
    if constexpr (std::is_same_v<T, double>)
      ASSERT_EQ(std::bit_cast<std::uint64_t>(expected[i]), std::bit_cast<std::uint64_t>(actual[i]))
          << name << "[" << i << "]";
    else
      ASSERT_EQ(expected[i], actual[i]) << name << "[" << i << "]";
  }
}

void expectSameParticles(const ParticleSet& expected, const ParticleSet& actual) {
  const std::size_t n = expected.numReal;
  ASSERT_EQ(actual.numReal, n);
  ASSERT_EQ(actual.size(), n);
  EXPECT_EQ(actual.numGhosts(), 0u);
  EXPECT_TRUE(actual.ghostSource.empty());
  for (int d = 0; d < 3; ++d) {
    expectBitsEqual(expected.x[d], actual.x[d], n, "x");
    expectBitsEqual(expected.v[d], actual.v[d], n, "v");
    expectBitsEqual(expected.a[d], actual.a[d], n, "a");
  }
  expectBitsEqual(expected.mass, actual.mass, n, "mass");
  expectBitsEqual(expected.rho, actual.rho, n, "rho");
  expectBitsEqual(expected.u, actual.u, n, "u");
  expectBitsEqual(expected.h, actual.h, n, "h");
  expectBitsEqual(expected.P, actual.P, n, "P");
  expectBitsEqual(expected.cs, actual.cs, n, "cs");
  expectBitsEqual(expected.du_dt, actual.du_dt, n, "du_dt");
  expectBitsEqual(expected.drho_dt, actual.drho_dt, n, "drho_dt");
  expectBitsEqual(expected.dh_dt, actual.dh_dt, n, "dh_dt");
  expectBitsEqual(expected.material, actual.material, n, "material");
  expectBitsEqual(expected.id, actual.id, n, "id");
  // Not stored: recomputed by the density pass.
  EXPECT_EQ(actual.omega, std::vector<double>(n, 1.0));
  EXPECT_EQ(actual.divv, std::vector<double>(n, 0.0));
  EXPECT_EQ(actual.curlv, std::vector<double>(n, 0.0));
  EXPECT_EQ(actual.areaDensity, std::vector<double>(n, 0.0));
}

void expectSameInfo(const SnapshotInfo& expected, const SnapshotInfo& actual) {
  auto bits = [](double v) { return std::bit_cast<std::uint64_t>(v); };
  EXPECT_EQ(bits(actual.time), bits(expected.time));
  EXPECT_EQ(actual.step, expected.step);
  EXPECT_EQ(actual.geometry, expected.geometry);
  EXPECT_EQ(actual.scene, expected.scene);
  EXPECT_EQ(bits(actual.dtNext), bits(expected.dtNext));
  EXPECT_EQ(actual.snapshotIndex, expected.snapshotIndex);
  EXPECT_EQ(bits(actual.nextOutputTime), bits(expected.nextOutputTime));
  EXPECT_EQ(bits(actual.initialEnergy), bits(expected.initialEnergy));
  for (int d = 0; d < 3; ++d)
    EXPECT_EQ(bits(actual.initialMomentum[d]), bits(expected.initialMomentum[d]));
  EXPECT_EQ(bits(actual.wallSeconds), bits(expected.wallSeconds));
  EXPECT_EQ(actual.sceneSource, expected.sceneSource);
  EXPECT_EQ(actual.materials, expected.materials);
}

// Runs f and returns the message of the std::runtime_error it must throw.
template <typename F>
std::string errorOf(F&& f) {
  try {
    f();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected std::runtime_error";
  return {};
}

// --- Direct HDF5 access for layout checks and for damaging files on purpose. ---

std::string stringAttribute(hid_t obj, const char* name) {
  const hid_t attr = H5Aopen(obj, name, H5P_DEFAULT);
  EXPECT_GE(attr, 0) << name;
  if (attr < 0) return {};
  const hid_t type = H5Aget_type(attr);
  EXPECT_EQ(H5Tget_class(type), H5T_STRING) << name;
  std::string value(H5Tget_size(type), '\0');
  EXPECT_GE(H5Aread(attr, type, value.data()), 0);
  H5Tclose(type);
  H5Aclose(attr);
  return value.substr(0, value.find('\0'));
}

template <typename T>
T numericAttribute(hid_t obj, const char* name, hid_t memType) {
  T value{};
  const hid_t attr = H5Aopen(obj, name, H5P_DEFAULT);
  EXPECT_GE(attr, 0) << name;
  if (attr < 0) return value;
  EXPECT_GE(H5Aread(attr, memType, &value), 0);
  H5Aclose(attr);
  return value;
}

void deleteLink(const std::string& file, const char* link) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  EXPECT_GE(H5Ldelete(f, link, H5P_DEFAULT), 0);
  H5Fclose(f);
}

void deleteAttribute(const std::string& file, const char* object, const char* name) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  EXPECT_GE(H5Adelete_by_name(f, object, name, H5P_DEFAULT), 0);
  H5Fclose(f);
}

constexpr Geometry kAllGeometries[] = {Geometry::Line, Geometry::Planar, Geometry::Axisymmetric,
                                       Geometry::Spatial};

}  // namespace

// --- Snapshots --------------------------------------------------------------------------------

TEST_F(OutputFiles, SnapshotRoundTripIsBitForBitInEveryGeometry) {
  std::uint64_t seed = 1;
  for (const Geometry g : kAllGeometries) {
    SCOPED_TRACE(std::string(geometryName(g)));
    const ParticleSet p = randomParticles(257, 13, g, seed++);
    const SnapshotInfo info = sampleInfo(g);
    const std::string file = path("snap.h5");
    writeSnapshot(file, p, info);
    SnapshotInfo back;
    const ParticleSet q = readSnapshot(file, back);
    expectSameParticles(p, q);
    expectSameInfo(info, back);
  }
}

TEST_F(OutputFiles, EmptySnapshotRoundTrips) {
  ParticleSet p;
  const SnapshotInfo info = sampleInfo(Geometry::Planar);
  writeSnapshot(path("empty.h5"), p, info);
  SnapshotInfo back;
  const ParticleSet q = readSnapshot(path("empty.h5"), back);
  EXPECT_EQ(q.size(), 0u);
  EXPECT_EQ(q.numReal, 0u);
  expectSameInfo(info, back);
}

TEST_F(OutputFiles, SnapshotWithoutAMaterialTableReadsAsNone) {
  // Snapshots written before /materials existed still read; a partial table is refused.
  const ParticleSet p = randomParticles(4, 0, Geometry::Planar, 5);
  writeSnapshot(path("old.h5"), p, sampleInfo(Geometry::Planar));
  deleteLink(path("old.h5"), "/materials");
  SnapshotInfo back;
  readSnapshot(path("old.h5"), back);
  EXPECT_TRUE(back.materials.empty());
  writeSnapshot(path("partial.h5"), p, sampleInfo(Geometry::Planar));
  deleteLink(path("partial.h5"), "/materials/eos");
  const std::string why = errorOf([&] { readSnapshot(path("partial.h5"), back); });
  EXPECT_NE(why.find("/materials/eos"), std::string::npos) << why;
  EXPECT_NE(why.find("partial.h5"), std::string::npos) << why;
}

TEST_F(OutputFiles, EmptyStringsRoundTrip) {
  const ParticleSet p = randomParticles(3, 0, Geometry::Spatial, 7);
  SnapshotInfo info = sampleInfo(Geometry::Spatial);
  info.scene.clear();
  info.sceneSource.clear();
  writeSnapshot(path("s.h5"), p, info);
  SnapshotInfo back;
  readSnapshot(path("s.h5"), back);
  EXPECT_EQ(back.scene, "");
  EXPECT_EQ(back.sceneSource, "");
}

TEST_F(OutputFiles, PositionComponentsBeyondTheDimensionAreWrittenAsZero) {
  ParticleSet p = randomParticles(5, 0, Geometry::Spatial, 3);
  writeSnapshot(path("line.h5"), p, sampleInfo(Geometry::Line));
  SnapshotInfo info;
  const ParticleSet q = readSnapshot(path("line.h5"), info);
  expectBitsEqual(p.x[0], q.x[0], 5, "x");
  EXPECT_EQ(q.x[1], std::vector<double>(5, 0.0));
  EXPECT_EQ(q.x[2], std::vector<double>(5, 0.0));
  expectBitsEqual(p.v[1], q.v[1], 5, "v");  // velocity keeps all components (RZ swirl)
}

TEST_F(OutputFiles, SnapshotLayoutHasUnitsDescriptionsAndRootAttributes) {
  const ParticleSet p = randomParticles(10, 0, Geometry::Axisymmetric, 11);
  const SnapshotInfo info = sampleInfo(Geometry::Axisymmetric);
  const std::string file = path("layout.h5");
  writeSnapshot(file, p, info);

  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  EXPECT_EQ(numericAttribute<double>(f, "time", H5T_NATIVE_DOUBLE), info.time);
  EXPECT_EQ(numericAttribute<int>(f, "dimension", H5T_NATIVE_INT), 2);
  EXPECT_EQ(stringAttribute(f, "geometry"), "rz");
  EXPECT_EQ(numericAttribute<std::int64_t>(f, "step", H5T_NATIVE_INT64), info.step);
  EXPECT_EQ(stringAttribute(f, "scene"), info.scene);
  EXPECT_EQ(stringAttribute(f, "ejecta_version"), "0.1.0");

  struct Expected { const char* path; const char* units; int rank; H5T_class_t cls; std::size_t size; };
  const Expected datasets[] = {
      {"/particles/position", "m", 2, H5T_FLOAT, 8},
      {"/particles/velocity", "m/s", 2, H5T_FLOAT, 8},
      {"/particles/density", "kg/m^3", 1, H5T_FLOAT, 8},
      {"/particles/pressure", "Pa", 1, H5T_FLOAT, 8},
      {"/particles/internal_energy", "J/kg", 1, H5T_FLOAT, 8},
      {"/particles/smoothing_length", "m", 1, H5T_FLOAT, 8},
      {"/particles/mass", "kg", 1, H5T_FLOAT, 8},
      {"/particles/material", "1", 1, H5T_INTEGER, 4},
      {"/particles/id", "1", 1, H5T_INTEGER, 8},
      {"/particles/sound_speed", "m/s", 1, H5T_FLOAT, 8},
      {"/restart/acceleration", "m/s^2", 2, H5T_FLOAT, 8},
      {"/restart/du_dt", "J/kg/s", 1, H5T_FLOAT, 8},
      {"/restart/drho_dt", "kg/m^3/s", 1, H5T_FLOAT, 8},
      {"/restart/dh_dt", "m/s", 1, H5T_FLOAT, 8},
  };
  for (const Expected& e : datasets) {
    SCOPED_TRACE(e.path);
    const hid_t d = H5Dopen2(f, e.path, H5P_DEFAULT);
    ASSERT_GE(d, 0);
    EXPECT_EQ(stringAttribute(d, "units"), e.units);
    EXPECT_FALSE(stringAttribute(d, "description").empty());
    const hid_t space = H5Dget_space(d);
    hsize_t dims[2] = {0, 0};
    EXPECT_EQ(H5Sget_simple_extent_dims(space, dims, nullptr), e.rank);
    EXPECT_EQ(dims[0], 10u);
    if (e.rank == 2) {
      EXPECT_EQ(dims[1], 3u);
    }
    const hid_t type = H5Dget_type(d);
    EXPECT_EQ(H5Tget_class(type), e.cls);
    EXPECT_EQ(H5Tget_size(type), e.size);
    H5Tclose(type);
    H5Sclose(space);
    H5Dclose(d);
  }
  const hid_t r = H5Gopen2(f, "/restart", H5P_DEFAULT);
  ASSERT_GE(r, 0);
  for (const char* name : {"dt_next", "snapshot_index", "next_output_time", "initial_energy",
                           "initial_momentum", "wall_seconds"})
    EXPECT_GT(H5Aexists(r, name), 0) << name;
  H5Gclose(r);
  H5Fclose(f);
}

TEST_F(OutputFiles, ReadingAFileWithoutADatasetNamesIt) {
  const ParticleSet p = randomParticles(4, 0, Geometry::Spatial, 5);
  const std::string file = path("damaged.h5");
  for (const char* link : {"/particles/density", "/particles/id", "/restart/du_dt"}) {
    writeSnapshot(file, p, sampleInfo(Geometry::Spatial));
    deleteLink(file, link);
    SnapshotInfo info;
    const std::string message = errorOf([&] { readSnapshot(file, info); });
    EXPECT_NE(message.find(link), std::string::npos) << message;
    EXPECT_NE(message.find(file), std::string::npos) << message;
  }
  writeSnapshot(file, p, sampleInfo(Geometry::Spatial));
  deleteLink(file, "/restart");
  SnapshotInfo info;
  std::string message = errorOf([&] { readSnapshot(file, info); });
  EXPECT_NE(message.find("/restart"), std::string::npos) << message;

  writeSnapshot(file, p, sampleInfo(Geometry::Spatial));
  deleteAttribute(file, "/", "time");
  message = errorOf([&] { readSnapshot(file, info); });
  EXPECT_NE(message.find("'time'"), std::string::npos) << message;
}

TEST_F(OutputFiles, ReadingAMissingOrNonHdf5FileFailsWithItsName) {
  SnapshotInfo info;
  std::string message = errorOf([&] { readSnapshot(path("absent.h5"), info); });
  EXPECT_NE(message.find(path("absent.h5")), std::string::npos) << message;

  writeFileAtomically(path("text.h5"), "not hdf5");
  message = errorOf([&] { readSnapshot(path("text.h5"), info); });
  EXPECT_NE(message.find(path("text.h5")), std::string::npos) << message;
}

TEST_F(OutputFiles, FailedSnapshotWriteLeavesTheEarlierFileIntact) {
  const std::string file = path("snap.h5");
  const ParticleSet good = randomParticles(20, 0, Geometry::Planar, 21);
  const SnapshotInfo info = sampleInfo(Geometry::Planar);
  writeSnapshot(file, good, info);

  // Simulated failure mid-write: the last particle dataset has too few entries, so the
  // temporary file is half written when the error is detected.
  ParticleSet bad = randomParticles(20, 0, Geometry::Planar, 22);
  bad.dh_dt.resize(5);
  const std::string message = errorOf([&] { writeSnapshot(file, bad, info); });
  EXPECT_NE(message.find(file), std::string::npos) << message;
  EXPECT_NE(message.find("dh_dt"), std::string::npos) << message;

  SnapshotInfo back;
  expectSameParticles(good, readSnapshot(file, back));
  EXPECT_EQ(directoryEntries(), std::vector<std::string>{"snap.h5"});  // no temporary left
}

TEST_F(OutputFiles, SnapshotIntoAMissingDirectoryFails) {
  const std::string file = path("no/such/dir/snap.h5");
  const std::string message = errorOf(
      [&] { writeSnapshot(file, randomParticles(2, 0, Geometry::Line, 1), sampleInfo(Geometry::Line)); });
  EXPECT_NE(message.find(file), std::string::npos) << message;
}

TEST_F(OutputFiles, SnapshotIntoAReadOnlyDirectoryKeepsTheEarlierFile) {
  if (::geteuid() == 0) GTEST_SKIP() << "permissions do not bind root";
  const std::string file = path("snap.h5");
  const ParticleSet good = randomParticles(8, 0, Geometry::Line, 31);
  writeSnapshot(file, good, sampleInfo(Geometry::Line));
  fs::permissions(dir_, fs::perms::owner_write | fs::perms::group_write | fs::perms::others_write,
                  fs::perm_options::remove);
  errorOf([&] { writeSnapshot(file, randomParticles(8, 0, Geometry::Line, 32), sampleInfo(Geometry::Line)); });
  fs::permissions(dir_, fs::perms::owner_write, fs::perm_options::add);
  SnapshotInfo back;
  expectSameParticles(good, readSnapshot(file, back));
}

TEST_F(OutputFiles, H5dumpReadsASnapshot) {
  if (std::system("command -v h5dump > /dev/null 2>&1") != 0) GTEST_SKIP() << "no h5dump";
  const std::string file = path("dump.h5");
  writeSnapshot(file, randomParticles(6, 0, Geometry::Spatial, 41), sampleInfo(Geometry::Spatial));
  const std::string out = path("dump.txt");
  ASSERT_EQ(std::system(("h5dump -H '" + file + "' > '" + out + "' 2>&1").c_str()), 0)
      << readText(out);
  const std::string header = readText(out);
  for (const char* expected : {"GROUP \"particles\"", "DATASET \"position\"", "DATASET \"id\"",
                               "ATTRIBUTE \"units\"", "GROUP \"restart\"", "ATTRIBUTE \"time\""})
    EXPECT_NE(header.find(expected), std::string::npos) << expected << "\n" << header;
}

// --- Atomic file helpers ----------------------------------------------------------------------

TEST_F(OutputFiles, WriteFileAtomicallyReplacesContents) {
  writeFileAtomically(path("a.txt"), "first");
  writeFileAtomically(path("a.txt"), "second, longer");
  EXPECT_EQ(readText(path("a.txt")), "second, longer");
  writeFileAtomically(path("a.txt"), "");
  EXPECT_EQ(readText(path("a.txt")), "");
  EXPECT_EQ(directoryEntries(), std::vector<std::string>{"a.txt"});
}

TEST_F(OutputFiles, UncommittedTargetLeavesNoTraceAndKeepsTheOldFile) {
  writeFileAtomically(path("a.txt"), "old");
  fs::path temp;
  {
    AtomicFileTarget target(path("a.txt"));
    temp = target.tempPath();
    EXPECT_EQ(temp.parent_path(), dir_);
    std::ofstream(temp) << "new but abandoned";
  }
  EXPECT_FALSE(fs::exists(temp));
  EXPECT_EQ(readText(path("a.txt")), "old");

  AtomicFileTarget target(path("a.txt"));
  std::ofstream(target.tempPath()) << "new";
  target.commit();
  EXPECT_TRUE(target.committed());
  EXPECT_EQ(readText(path("a.txt")), "new");
  EXPECT_EQ(directoryEntries(), std::vector<std::string>{"a.txt"});
}

TEST_F(OutputFiles, WriteFileAtomicallyIntoAMissingDirectoryFails) {
  const std::string message = errorOf([&] { writeFileAtomically(path("x/a.txt"), "text"); });
  EXPECT_NE(message.find(path("x/a.txt")), std::string::npos) << message;
}

// --- XDMF -------------------------------------------------------------------------------------

namespace {

std::size_t countOf(const std::string& text, const std::string& what) {
  std::size_t count = 0;
  for (auto pos = text.find(what); pos != std::string::npos; pos = text.find(what, pos + 1)) ++count;
  return count;
}

// Minimal well-formedness check: every element is closed in order (no attributes contain '>').
bool tagsBalance(const std::string& xml) {
  std::vector<std::string> open;
  for (std::size_t pos = xml.find('<'); pos != std::string::npos; pos = xml.find('<', pos + 1)) {
    const std::size_t end = xml.find('>', pos);
    if (end == std::string::npos) return false;
    const std::string tag = xml.substr(pos + 1, end - pos - 1);
    if (tag.empty() || tag[0] == '?' || tag[0] == '!') continue;
    if (tag[0] == '/') {
      if (open.empty() || open.back() != tag.substr(1)) return false;
      open.pop_back();
    } else if (tag.back() != '/') {
      open.push_back(tag.substr(0, tag.find_first_of(" \n\t")));
    }
  }
  return open.empty();
}

}  // namespace

TEST_F(OutputFiles, XdmfSeriesHasOneGridPerSnapshot) {
  const std::vector<XdmfEntry> entries = {
      {"snapshots/snap_0000.h5", 0.0, 100, Geometry::Axisymmetric, xdmfAttributes(ParticleSet{}),
       {"granite", "rubble"}, true},
      {"snapshots/snap_0001.h5", 1.25e-6, 100, Geometry::Axisymmetric, xdmfAttributes(ParticleSet{}),
       {"granite", "rubble"}, true},
      {"snapshots/a&b.h5", 0.1, 98, Geometry::Axisymmetric, xdmfAttributes(ParticleSet{}), {"a<b"}, false},
  };
  const std::string file = path("run.xdmf");
  writeXdmfSeries(file, entries);
  const std::string xml = readText(file);

  EXPECT_TRUE(tagsBalance(xml)) << xml;
  EXPECT_EQ(countOf(xml, "CollectionType=\"Temporal\""), 1u);
  EXPECT_EQ(countOf(xml, "GridType=\"Uniform\""), entries.size());
  EXPECT_EQ(countOf(xml, "TopologyType=\"Polyvertex\""), entries.size());
  EXPECT_EQ(countOf(xml, "<Time "), entries.size());
  EXPECT_NE(xml.find("<Time Value=\"0\"/>"), std::string::npos);
  EXPECT_NE(xml.find("<Time Value=\"1.25e-06\"/>"), std::string::npos);
  EXPECT_NE(xml.find("<Time Value=\"0.1\"/>"), std::string::npos);
  EXPECT_EQ(countOf(xml, "snapshots/snap_0001.h5:/particles/position"), 1u);
  // Every /particles dataset of a plain particle set: geometry + 10 attributes.
  EXPECT_EQ(countOf(xml, "snapshots/snap_0001.h5:/particles/"), 11u);
  EXPECT_NE(xml.find("snapshots/a&amp;b.h5:/particles/velocity"), std::string::npos);
  EXPECT_NE(xml.find("Dimensions=\"98 3\""), std::string::npos);
  for (const char* name : {"density", "pressure", "internal_energy", "smoothing_length", "mass",
                           "material", "id"})
    EXPECT_EQ(countOf(xml, "<Attribute Name=\"" + std::string(name) +
                               "\" AttributeType=\"Scalar\""),
              entries.size())
        << name;
  EXPECT_EQ(countOf(xml, "<Attribute Name=\"velocity\" AttributeType=\"Vector\""),
            entries.size());
  // Units on every attribute, material names by id on every grid (escaped).
  EXPECT_EQ(countOf(xml, "<Information Name=\"units\""), 10 * entries.size());
  EXPECT_NE(xml.find("<Information Name=\"units\" Value=\"kg/m^3\"/>"), std::string::npos);
  EXPECT_EQ(countOf(xml, "<Information Name=\"materials\" Value=\"0: granite, 1: rubble\"/>"), 2u);
  EXPECT_EQ(countOf(xml, "<Information Name=\"materials\" Value=\"0: a&lt;b\"/>"), 1u);
  // The connectivity where the snapshot has it; an older snapshot's grid goes without.
  EXPECT_EQ(countOf(xml, ":/xdmf/vertices</DataItem>"), 2u);
  EXPECT_EQ(countOf(xml, "NumberOfElements=\"98\" NodesPerElement=\"1\"/>"), 1u);
}

TEST_F(OutputFiles, XdmfGivesTensorsAsMatricesWithNamedColumns) {
  // The deviatoric stress (xx, yy, zz, xy; RZ rr, zz, theta-theta, rz) is no XDMF Tensor6 in
  // either order or size: a Matrix of the (N, 4) dataset, its columns named.
  ParticleSet p;
  p.append({0, 0, 0}, {0, 0, 0}, 1.0, 1.0, 0.0, 0.1, 0);
  p.enableStrength(4);
  const std::vector<XdmfAttribute> attributes = xdmfAttributes(p);
  const auto stress = std::find_if(attributes.begin(), attributes.end(),
                                   [](const XdmfAttribute& a) { return a.name == "stress"; });
  ASSERT_NE(stress, attributes.end());
  EXPECT_TRUE(stress->tensor);
  EXPECT_EQ(xdmfComponentNames(*stress, Geometry::Axisymmetric),
            (std::vector<std::string>{"rr", "zz", "tt", "rz"}));
  EXPECT_EQ(xdmfComponentNames(*stress, Geometry::Planar),
            (std::vector<std::string>{"xx", "yy", "zz", "xy"}));
  writeXdmfSeries(path("stress.xdmf"), {{"s.h5", 0.0, 7, Geometry::Axisymmetric, attributes, {}, true}});
  const std::string xml = readText(path("stress.xdmf"));
  EXPECT_TRUE(tagsBalance(xml)) << xml;
  EXPECT_NE(xml.find("<Attribute Name=\"stress\" AttributeType=\"Matrix\""), std::string::npos) << xml;
  EXPECT_NE(xml.find("<Information Name=\"components\" Value=\"rr, zz, tt, rz\"/>"), std::string::npos);
  EXPECT_NE(xml.find("Dimensions=\"7 4\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">s.h5:/particles/stress<"),
            std::string::npos);
  EXPECT_NE(xml.find("<Attribute Name=\"plastic_strain\" AttributeType=\"Scalar\""), std::string::npos);
  // The connectivity the Xdmf3 readers need, from the snapshot's vertex index.
  EXPECT_NE(xml.find("<DataItem Dimensions=\"7\" NumberType=\"Int\" Precision=\"4\" Format=\"HDF\">s.h5:/xdmf/vertices</DataItem>"),
            std::string::npos);
}

TEST_F(OutputFiles, SnapshotsHoldTheXdmfVertexIndex) {
  const ParticleSet p = randomParticles(9, 0, Geometry::Spatial, 3);
  writeSnapshot(path("v.h5"), p, sampleInfo(Geometry::Spatial));
  const hid_t f = H5Fopen(path("v.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  const hid_t d = H5Dopen2(f, "/xdmf/vertices", H5P_DEFAULT);
  ASSERT_GE(d, 0);
  std::vector<int> index(9, -1);
  EXPECT_GE(H5Dread(d, H5T_NATIVE_INT, H5S_ALL, H5S_ALL, H5P_DEFAULT, index.data()), 0);
  for (int i = 0; i < 9; ++i) EXPECT_EQ(index[i], i);
  H5Dclose(d);
  H5Fclose(f);
  const SnapshotLayout layout = readSnapshotLayout(path("v.h5"));
  EXPECT_TRUE(layout.xdmfVertices);
  EXPECT_NE(std::find(layout.particleDatasets.begin(), layout.particleDatasets.end(), "density"),
            layout.particleDatasets.end());
  deleteLink(path("v.h5"), "/xdmf/vertices");
  EXPECT_FALSE(readSnapshotLayout(path("v.h5")).xdmfVertices);
  EXPECT_EQ(xdmfVertexPrecision(9), 4);
  EXPECT_EQ(xdmfVertexPrecision(std::size_t{1} << 31), 8);
}

TEST_F(OutputFiles, EmptyXdmfSeriesIsWellFormed) {
  writeXdmfSeries(path("empty.xdmf"), {});
  const std::string xml = readText(path("empty.xdmf"));
  EXPECT_TRUE(tagsBalance(xml)) << xml;
  EXPECT_EQ(countOf(xml, "GridType=\"Uniform\""), 0u);
}

// --- summary.json -----------------------------------------------------------------------------

TEST_F(OutputFiles, SummaryJsonParsesBack) {
  RunSummary s;
  s.scene = "sedov";
  s.particles = 40000;
  s.steps = 1234;
  s.tEnd = 0.05;
  s.wallSeconds = 12.5;
  s.threads = 8;
  s.energy = {1.0, 1.0000001, 1.0e-7};
  s.momentum.initial = {0.0, 1.5, -2.0};
  s.momentum.final = {1e-15, 1.5, -2.0};
  s.status = RunSummary::Status::Failed;
  s.message = "time step collapsed";
  s.extras = {{"courant", 0.3}, {"kernel", "wendland_c2"}, {"neighbours", std::int64_t{58}},
              {"rz", true}, {"bad", std::nan("")}};
  writeSummaryJson(path("summary.json"), s);

  const auto j = nlohmann::json::parse(readText(path("summary.json")));
  EXPECT_EQ(j.at("scene"), "sedov");
  EXPECT_EQ(j.at("particles"), 40000);
  EXPECT_EQ(j.at("steps"), 1234);
  EXPECT_EQ(j.at("t_end"), 0.05);
  EXPECT_EQ(j.at("wall_seconds"), 12.5);
  EXPECT_EQ(j.at("threads"), 8);
  EXPECT_EQ(j.at("energy").at("initial"), 1.0);
  EXPECT_EQ(j.at("energy").at("final"), 1.0000001);
  EXPECT_EQ(j.at("energy").at("relative_error"), 1.0e-7);
  EXPECT_EQ(j.at("momentum").at("initial"), nlohmann::json({0.0, 1.5, -2.0}));
  EXPECT_EQ(j.at("momentum").at("final")[0], 1e-15);
  EXPECT_EQ(j.at("status"), "failed");
  EXPECT_EQ(j.at("message"), "time step collapsed");
  EXPECT_EQ(j.at("ejecta_version"), "0.1.0");
  const auto& extras = j.at("extras");
  EXPECT_EQ(extras.at("courant"), 0.3);
  EXPECT_EQ(extras.at("kernel"), "wendland_c2");  // a literal must not decay to bool
  EXPECT_EQ(extras.at("neighbours"), 58);
  EXPECT_EQ(extras.at("rz"), true);
  EXPECT_TRUE(extras.at("bad").is_null());
}

TEST_F(OutputFiles, CompletedSummaryStatus) {
  RunSummary s;
  writeSummaryJson(path("summary.json"), s);
  const auto j = nlohmann::json::parse(readText(path("summary.json")));
  EXPECT_EQ(j.at("status"), "completed");
  EXPECT_TRUE(j.at("extras").is_object());
}
