// Geometry of the radiation library: OBJ and STL readers (ASCII and binary files written here to
// a temporary folder) and their errors, primitives (areas, normals, closure), poses, emitter
// selection, the seed's baseline against a hand computation, Sobol' stratification, ray-casting
// modes, back faces and hot occluders, determinism across thread counts, and geometry files.
#include <gtest/gtest.h>
#include <omp.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "radiation/emitters.hpp"
#include "radiation/geometry_file.hpp"
#include "radiation/mesh_io.hpp"
#include "radiation/ray_scene.hpp"
#include "radiation/sampling.hpp"
#include "radiation/solid_angle_baseline.hpp"
#include "radiation/spacecraft.hpp"
#include "radiation/view_factors.hpp"

namespace ejecta::radiation {
namespace {

namespace fs = std::filesystem;
constexpr double kPi = std::numbers::pi;

class TempDir {
 public:
  TempDir() : path_(fs::temp_directory_path() / ("ejecta_radiation_" + std::to_string(::getpid()))) {
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  fs::path write(const std::string& name, const std::string& bytes) const {
    const fs::path p = path_ / name;
    std::ofstream(p, std::ios::binary) << bytes;
    return p;
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

// The message of the MeshError (or GeometryFileError) that f throws; fails the test otherwise.
template <typename Error, typename F>
std::string errorOf(F&& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an exception";
  return "";
}

double totalArea(const TriangleMesh& m) {
  double a = 0.0;
  for (std::size_t p = 0; p < m.patchCount(); ++p) a += m.patchArea(p);
  return a;
}

// Every edge of a closed, consistently oriented mesh appears once in each direction.
bool isClosedAndOriented(const TriangleMesh& m) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) ++edges[{t[k], t[(k + 1) % 3]}];
  for (const auto& [e, n] : edges) {
    if (n != 1) return false;
    const auto it = edges.find({e.second, e.first});
    if (it == edges.end() || it->second != 1) return false;
  }
  return true;
}

void expectVecNear(const Vec3& a, const Vec3& b, double tol) {
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[k], b[k], tol) << "component " << k;
}

// ----------------------------------------------------------------------------------- OBJ

TEST(ObjReader, GroupsBecomePatchesAndPolygonsAreSplit) {
  TempDir dir;
  const fs::path p = dir.write("craft.obj",
                               "# a unit square and a triangle\n"
                               "mtllib craft.mtl\n"
                               "o body\n"
                               "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                               "vt 0 0\nvn 0 0 1\n"
                               "g side0\n"
                               "usemtl grey\ns off\n"
                               "f 1/1/1 2/1/1 3//1 4\n"
                               "v 0 0 2\nv 2 0 2\nv 0 2 2\n"
                               "g side1\n"
                               "f -3 -2 -1   # the last three vertices\n"
                               "g side0\n"
                               "f 1 3 4\n");
  const TriangleMesh m = readObj(p);
  ASSERT_EQ(m.patchNames, (std::vector<std::string>{"side0", "side1"}));
  EXPECT_EQ(m.triangleCount(), 4u);
  EXPECT_EQ(m.vertices.size(), 7u);
  EXPECT_DOUBLE_EQ(m.patchArea(0), 1.5);  // the square plus half of it again
  EXPECT_DOUBLE_EQ(m.patchArea(1), 2.0);
  expectVecNear(m.patchNormal(1), {0, 0, 1}, 1e-15);
}

TEST(ObjReader, UngroupedFacesTakeTheFileStemOrTheGivenNameAndScale) {
  TempDir dir;
  const fs::path p = dir.write("panel.obj", "v 0 0 0\nv 1000 0 0\nv 0 1000 0\nf 1 2 3\n");
  EXPECT_EQ(readObj(p).patchNames, std::vector<std::string>{"panel"});
  const TriangleMesh m = readObj(p, {"solar array", 1e-3});
  EXPECT_EQ(m.patchNames, std::vector<std::string>{"solar array"});
  EXPECT_DOUBLE_EQ(m.patchArea(0), 0.5);
}

TEST(ObjReader, MalformedFilesNameTheFileLineAndReason) {
  TempDir dir;
  struct Case {
    const char* text;
    const char* expected;
  };
  const Case cases[] = {
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n", "bad.obj:4: face refers to vertex 9 but the file defines 3"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", "bad.obj:4: face vertex index 0"},
      {"v 0 0 0\nv 1 0 0\nf -3 1 2\n", "bad.obj:3: face vertex index -3 reaches before the first vertex"},
      {"v 0 0 0\nv 1 nan 0\n", "bad.obj:2: vertex is not finite"},
      {"v 0 0 0\nv 1 x 0\n", "bad.obj:2: vertex coordinate 'x' is not a number"},
      {"v 0 0\n", "bad.obj:1: a vertex needs 3 coordinates"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n", "bad.obj:4: a face needs at least 3 vertices"},
      {"v 0 0 0\ncurv 0 1 1 2\n", "bad.obj:2: unsupported OBJ statement 'curv'"},
      {"# only vertices\nv 0 0 0\n", "bad.obj: the mesh has no faces"},
  };
  for (const Case& c : cases) {
    const fs::path p = dir.write("bad.obj", c.text);
    const std::string msg = errorOf<MeshError>([&] { readObj(p); });
    EXPECT_NE(msg.find(c.expected), std::string::npos) << msg;
  }
  const std::string missing = errorOf<MeshError>([&] { readObj(dir.path() / "none.obj"); });
  EXPECT_NE(missing.find("none.obj: cannot open"), std::string::npos) << missing;
}

// ----------------------------------------------------------------------------------- STL

std::string binaryStl(const std::vector<std::array<float, 12>>& facets, const std::string& header = "binary") {
  std::string b(80, '\0');
  std::memcpy(b.data(), header.data(), std::min<std::size_t>(header.size(), 80));
  const auto n = static_cast<std::uint32_t>(facets.size());
  for (int k = 0; k < 4; ++k) b.push_back(static_cast<char>((n >> (8 * k)) & 0xff));
  for (const auto& f : facets) {
    for (float x : f) {
      std::uint32_t u;
      std::memcpy(&u, &x, 4);
      for (int k = 0; k < 4; ++k) b.push_back(static_cast<char>((u >> (8 * k)) & 0xff));
    }
    b.push_back('\0');
    b.push_back('\0');
  }
  return b;
}

TEST(StlReader, AsciiSolidsBecomePatchesAndStoredNormalsDecideTheOutside) {
  TempDir dir;
  const fs::path p = dir.write("two.stl",
                               "solid front\n"
                               "  facet normal 0 0 1\n    outer loop\n      vertex 0 0 0\n      vertex 1 0 0\n"
                               "      vertex 1 1 0\n    endloop\n  endfacet\n"
                               // Listed clockwise seen from +z, but its normal says +z: reversed.
                               "  facet normal 0 0 1\n    outer loop\n      vertex 0 0 0\n      vertex 0 1 0\n"
                               "      vertex 1 1 0\n    endloop\n  endfacet\n"
                               "endsolid front\n"
                               "solid back\n"
                               "  facet normal 0 0 0\n    outer loop\n      vertex 0 0 -1\n      vertex 0 1 -1\n"
                               "      vertex 1 0 -1\n    endloop\n  endfacet\n"
                               "endsolid back\n");
  const TriangleMesh m = readStl(p);
  ASSERT_EQ(m.patchNames, (std::vector<std::string>{"front", "back"}));
  EXPECT_EQ(m.triangleCount(), 3u);
  EXPECT_EQ(m.vertices.size(), 7u);  // 4 + 3: the two corners the first facets share are welded
  expectVecNear(m.triangleNormal(0), {0, 0, 1}, 1e-15);
  expectVecNear(m.triangleNormal(1), {0, 0, 1}, 1e-15);
  expectVecNear(m.triangleNormal(2), {0, 0, -1}, 1e-15);  // zero stored normal: winding kept
  EXPECT_DOUBLE_EQ(m.patchArea(0), 1.0);
}

TEST(StlReader, BinaryIsOnePatchNamedAfterTheFileOrTheOverride) {
  TempDir dir;
  // A header that starts with "solid", as some exporters write: still read as binary.
  const fs::path p = dir.write("hull.stl", binaryStl({{0, 0, 1, 0, 0, 0, 2, 0, 0, 0, 2, 0},
                                                     {0, 0, 1, 2, 0, 0, 2, 2, 0, 0, 2, 0}},
                                                    "solid exported by some CAD tool"));
  const TriangleMesh m = readStl(p);
  EXPECT_EQ(m.patchNames, std::vector<std::string>{"hull"});
  EXPECT_EQ(m.triangleCount(), 2u);
  EXPECT_EQ(m.vertices.size(), 4u);
  EXPECT_DOUBLE_EQ(m.patchArea(0), 4.0);
  EXPECT_EQ(readMesh(p, {"radiator", 1.0}).patchNames, std::vector<std::string>{"radiator"});
}

TEST(StlReader, MalformedFilesNameTheFileAndReason) {
  TempDir dir;
  const std::string good = binaryStl({{0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 0}});
  const fs::path truncated = dir.write("cut.stl", good.substr(0, good.size() - 7));
  std::string msg = errorOf<MeshError>([&] { readStl(truncated); });
  EXPECT_NE(msg.find("cut.stl: binary STL truncated: the header announces 2 triangles (184 bytes) but the file "
                     "has 177 bytes"),
            std::string::npos)
      << msg;
  const fs::path nan = dir.write("nan.stl", binaryStl({{0, 0, 1, 0, 0, 0, NAN, 0, 0, 0, 1, 0}}));
  msg = errorOf<MeshError>([&] { readStl(nan); });
  EXPECT_NE(msg.find("nan.stl: triangle 0 (byte 84): vertex 2 is not finite"), std::string::npos) << msg;
  const fs::path tiny = dir.write("tiny.stl", "abc");
  msg = errorOf<MeshError>([&] { readStl(tiny); });
  EXPECT_NE(msg.find("tiny.stl: 3 bytes: too short"), std::string::npos) << msg;
  const fs::path ascii = dir.write("typo.stl",
                                   "solid s\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertx 1 0 0\n");
  msg = errorOf<MeshError>([&] { readStl(ascii); });
  EXPECT_NE(msg.find("typo.stl:5: expected 'vertex', got 'vertx'"), std::string::npos) << msg;
  const fs::path cut = dir.write("eof.stl", "solid s\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n");
  msg = errorOf<MeshError>([&] { readStl(cut); });
  EXPECT_NE(msg.find("eof.stl:5: unexpected end of file"), std::string::npos) << msg;
  const fs::path empty = dir.write("empty.stl", "solid nothing\nendsolid nothing\n");
  msg = errorOf<MeshError>([&] { readStl(empty); });
  EXPECT_NE(msg.find("empty.stl: the STL has no facets"), std::string::npos) << msg;
  msg = errorOf<MeshError>([&] { readMesh(dir.write("craft.ply", "ply\n")); });
  EXPECT_NE(msg.find("unknown mesh format '.ply'"), std::string::npos) << msg;
}

// ---------------------------------------------------------------------------- primitives

TEST(Primitives, BoxFacesHaveTheirAreasNormalsAndNames) {
  const double d = 2.0, h = 1.0, w = 0.5;
  const TriangleMesh box = makeBox(d, h, w);
  const std::map<std::string, std::pair<double, Vec3>> expected = {
      {"side0", {h * w, {1, 0, 0}}},  {"aft", {h * w, {-1, 0, 0}}},  {"side1", {d * w, {0, 1, 0}}},
      {"side2", {d * w, {0, -1, 0}}}, {"side3", {d * h, {0, 0, 1}}}, {"side4", {d * h, {0, 0, -1}}}};
  ASSERT_EQ(box.patchCount(), 6u);
  for (const auto& [name, an] : expected) {
    const int p = box.findPatch(name);
    ASSERT_GE(p, 0) << name;
    EXPECT_DOUBLE_EQ(box.patchArea(static_cast<std::size_t>(p)), an.first) << name;
    expectVecNear(box.patchNormal(static_cast<std::size_t>(p)), an.second, 1e-15);
    // The face centre lies half the box's extent out along its normal.
    expectVecNear(box.patchCentroid(static_cast<std::size_t>(p)),
                  {0.5 * d * an.second[0], 0.5 * h * an.second[1], 0.5 * w * an.second[2]}, 1e-15);
  }
  EXPECT_TRUE(isClosedAndOriented(box));
  const TriangleMesh room = makeEnclosure({0, 0, 0}, {1, 2, 3});
  expectVecNear(room.patchNormal(static_cast<std::size_t>(room.findPatch("x-"))), {1, 0, 0}, 1e-15);
  expectVecNear(room.patchNormal(static_cast<std::size_t>(room.findPatch("z+"))), {0, 0, -1}, 1e-15);
  EXPECT_DOUBLE_EQ(totalArea(room), 2.0 * (2 + 3 + 6));
  EXPECT_THROW(makeBox(1.0, 0.0, 1.0), std::invalid_argument);
}

TEST(Primitives, CylinderDiscAndSphere) {
  const double r = 0.5, L = 2.0;
  const int n = 48;
  const TriangleMesh cyl = makeCylinder(r, L, n, 4);
  EXPECT_TRUE(isClosedAndOriented(cyl));
  // Caps keep the exact circle area; the mantle is within pi^2 / (6 n^2) of 2 pi r L.
  EXPECT_NEAR(cyl.patchArea(static_cast<std::size_t>(cyl.findPatch("front"))), kPi * r * r, 1e-14);
  double mantle = 0.0;
  for (int s = 0; s < 4; ++s) mantle += cyl.patchArea(static_cast<std::size_t>(cyl.findPatch("side" + std::to_string(s))));
  EXPECT_NEAR(mantle / (2 * kPi * r * L), 1.0, kPi * kPi / (6.0 * n * n) * 1.01);
  expectVecNear(cyl.patchNormal(static_cast<std::size_t>(cyl.findPatch("aft"))), {-1, 0, 0}, 1e-14);
  expectVecNear(cyl.patchNormal(static_cast<std::size_t>(cyl.findPatch("side0"))), {0, 1, 0}, 1e-14);  // +y
  expectVecNear(cyl.patchNormal(static_cast<std::size_t>(cyl.findPatch("side1"))), {0, 0, 1}, 1e-14);  // +z
  EXPECT_THROW(makeCylinder(r, L, 10, 4), std::invalid_argument);  // 4 does not divide 10

  const TriangleMesh disc = makeDisc("d", {1, 2, 3}, {0, 1, 1}, 2.0, 64);
  EXPECT_NEAR(disc.patchArea(0), kPi * 4.0, 1e-12);
  expectVecNear(disc.patchNormal(0), vec3::normalized({0, 1, 1}), 1e-14);

  const TriangleMesh ball = makeSphere("s", {1, 0, 0}, 3.0, 3);
  EXPECT_EQ(ball.triangleCount(), 20u * 64u);
  EXPECT_TRUE(isClosedAndOriented(ball));
  for (std::size_t t = 0; t < ball.triangleCount(); ++t) {
    const auto& tri = ball.triangles[t];
    const Vec3 c = vec3::scale(vec3::add(vec3::add(ball.vertices[tri[0]], ball.vertices[tri[1]]), ball.vertices[tri[2]]),
                               1.0 / 3.0);
    ASSERT_GT(vec3::dot(ball.triangleNormal(t), vec3::sub(c, {1, 0, 0})), 0.0) << "triangle " << t;
  }
  EXPECT_NEAR(totalArea(ball) / (4 * kPi * 9.0), 1.0, 0.01);  // inscribed: slightly less
}

// --------------------------------------------------------------------------------- poses

TEST(Pose, ForwardUpAxisAngleAndPlacement) {
  const Rotation r = Rotation::fromForwardUp({0, 2, 0}, {1, 0, 0.5});
  expectVecNear(r.axis(0), {0, 1, 0}, 1e-15);
  expectVecNear(r.axis(1), vec3::normalized({1, 0, 0.5}), 1e-15);
  expectVecNear(r.axis(2), vec3::cross(r.axis(0), r.axis(1)), 1e-15);
  // Orthonormal, right-handed.
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(vec3::dot(r.axis(i), r.axis(j)), i == j ? 1.0 : 0.0, 1e-15);

  const Rotation q = Rotation::fromAxisAngle({0, 0, 2}, kPi / 2);
  expectVecNear(q.apply({1, 0, 0}), {0, 1, 0}, 1e-15);
  expectVecNear(q.apply({0, 1, 0}), {-1, 0, 0}, 1e-15);
  expectVecNear(Rotation::fromAxisAngle({1, 1, 1}, 2 * kPi / 3).apply({1, 0, 0}), {0, 1, 0}, 1e-15);

  Pose pose;
  pose.position = {-10, 1, 2};
  pose.attitude = Rotation::fromForwardUp({0, 0, -1}, {0, 1, 0});  // flying along -z
  pose.velocity = {0, 0, -1e4};
  const TriangleMesh craft = placeMesh(makeBox(1, 1, 1), pose);
  const auto side0 = static_cast<std::size_t>(craft.findPatch("side0"));
  expectVecNear(craft.patchNormal(side0), {0, 0, -1}, 1e-15);
  expectVecNear(craft.patchCentroid(side0), {-10, 1, 1.5}, 1e-14);
  expectVecNear(pose.at(1e-3).position, {-10, 1, -8}, 1e-12);
  expectVecNear(pose.toWorld({1, 0, 0}), {-10, 1, 1}, 1e-15);

  EXPECT_THROW(Rotation::fromForwardUp({1, 0, 0}, {2, 0, 0}), std::invalid_argument);
  EXPECT_THROW(Rotation::fromForwardUp({0, 0, 0}, {0, 1, 0}), std::invalid_argument);
  EXPECT_THROW(Rotation::fromAxisAngle({0, 0, 0}, 1.0), std::invalid_argument);
}

// ------------------------------------------------------------------------------ emitters

TEST(Emitters, ThresholdMaterialsAndEmissivities) {
  const std::vector<double> x{0, 1, 2, 3, 4}, y(5, 0.0), z(5, 0.0), r(5, 0.1);
  const std::vector<double> t{1499.9, 1500.0, 2500.0, 300.0, 3000.0};
  const std::vector<int> mat{0, 0, 1, 1, 2};
  EmitterSelection sel;  // default: 1500 K, granite 0.45
  sel.emissivityByMaterial = {0.45, 0.9};
  sel.materialNames = {"granite", "iron"};
  const Emitters e = selectEmitters({x, y, z, r, t, mat}, sel);
  ASSERT_EQ(e.size(), 3u);  // 1499.9 K and 300 K are dropped; 1500 K is kept
  EXPECT_EQ(e.x, (std::vector<double>{1, 2, 4}));
  EXPECT_EQ(e.emissivity, (std::vector<double>{0.45, 0.9, 0.45}));  // material 2: the default
  EXPECT_EQ(e.groupNames, (std::vector<std::string>{"granite", "iron", "material2"}));
  EXPECT_EQ(e.group, (std::vector<std::uint32_t>{0, 1, 2}));
  EXPECT_DOUBLE_EQ(e.exitance(1), 0.9 * 5.670374419e-8 * std::pow(2500.0, 4));
  // Without materials everything is material 0 with the default emissivity.
  EXPECT_EQ(selectEmitters({x, y, z, r, t, {}}).emissivity, std::vector<double>(3, 0.45));
  EXPECT_NEAR(equalVolumeRadius(1.0), 0.6203504909, 1e-10);
  EXPECT_NEAR(opaqueLatticeRadius(2.0), std::sqrt(3.0), 1e-15);

  const std::vector<double> shortY(4, 0.0), badR{0.1, -1, 0.1, 0.1, 0.1};
  EXPECT_THROW(selectEmitters({x, shortY, z, r, t, {}}), std::invalid_argument);
  try {
    selectEmitters({x, y, z, badR, t, {}});
    ADD_FAILURE() << "a negative radius was accepted";
  } catch (const std::invalid_argument& err) {
    EXPECT_NE(std::string(err.what()).find("radius[1]"), std::string::npos) << err.what();
  }
}

// ------------------------------------------------------------------- the seed's baseline

TEST(SeedBaseline, MatchesAHandComputation) {
  // A 1 m x 1 m side at the origin facing +x; three particles: two in front, one behind.
  const TriangleMesh side = makeRectangle("side0", {0, -0.5, -0.5}, {0, 1, 0}, {0, 0, 1});
  Emitters e;
  e.add(10.0, 0.0, 0.0, 0.05, 2000.0, 0.45, "melt");  // r = 10
  e.add(3.0, 4.0, 0.0, 0.10, 1600.0, 0.45, "melt");   // r = 5
  e.add(-2.0, 0.0, 0.0, 0.05, 3000.0, 0.45, "melt");  // behind: not counted
  const double sigma = 5.670374419e-8;
  // Omega = l / r^2 with l = sqrt(1 m^2) = 1 m: 1/100 and 1/25.
  const double q = 0.01 * 0.45 * sigma * std::pow(2000.0, 4) + 0.04 * 0.45 * sigma * std::pow(1600.0, 4);
  const BaselineResult b = seedBaseline(e, side, 0);
  EXPECT_EQ(b.counted, 2u);
  EXPECT_NEAR(b.solidAngleSum, 0.05, 1e-15);
  EXPECT_NEAR(b.flux, q, 1e-12 * q);  // 4082.7 + 6689.0 = 10771.7 W/m^2
  // The other reading, l = the particle's diameter: 0.1/100 and 0.2/25.
  BaselineOptions o;
  o.length = BaselineLength::EmitterDiameter;
  EXPECT_NEAR(seedBaseline(e, side, 0, o).solidAngleSum, 0.001 + 0.008, 1e-15);
  o.frontOnly = false;
  EXPECT_EQ(seedBaseline(e, side, 0, o).counted, 3u);
  EXPECT_DOUBLE_EQ(seedSolidAngle(1.0, 2.0), 0.25);
}

TEST(SeedBaseline, GrowsWithTheParticleCountWhileTheViewFactorFluxDoesNot) {
  // The same hot slab (4 x 4 x 1 m at 2000 K, 10 m in front of a 1 m side) at two lattice
  // spacings. The ray-cast flux depends on the slab, not on how finely it is sampled; the seed's
  // sum gains a term per particle: 8x the particles, 8x the flux.
  const TriangleMesh side = makeRectangle("side0", {0, -0.5, -0.5}, {0, 1, 0}, {0, 0, 1});
  double flux[2], seed[2];
  std::size_t count[2];
  for (int level = 0; level < 2; ++level) {
    const double s = level == 0 ? 0.5 : 0.25;
    Emitters e;
    for (double x = 10.0 + 0.5 * s; x < 11.0; x += s)
      for (double y = -2.0 + 0.5 * s; y < 2.0; y += s)
        for (double z = -2.0 + 0.5 * s; z < 2.0; z += s) e.add(x, y, z, opaqueLatticeRadius(s), 2000.0, 0.45, "slab");
    const ViewFactorSolver solver(RadiationScene{side, e, {}});
    SamplingOptions o;
    o.rays = 1u << 16;
    flux[level] = solver.fromPatch(0, o).flux.value;
    seed[level] = seedBaseline(e, side, 0).flux;
    count[level] = e.size();
  }
  std::printf("  hot slab at 0.5 / 0.25 m spacing (%zu / %zu particles): ray-cast q %.1f / %.1f W/m^2, "
              "seed %.4g / %.4g W/m^2\n",
              count[0], count[1], flux[0], flux[1], seed[0], seed[1]);
  EXPECT_EQ(count[1], 8 * count[0]);
  EXPECT_NEAR(flux[1] / flux[0], 1.0, 0.05);  // the lattice surface moves by s/2 and its bumps shrink
  EXPECT_NEAR(seed[1] / seed[0], 8.0, 0.1);
  EXPECT_GT(seed[0], 10.0 * flux[0]);          // and it is far above the physical flux already
}

// ---------------------------------------------------------------------------- sampling

// Counts of the first 2^m points of a replicate in each of 2^a x 2^(m-a) boxes of dims (i, j).
bool isNet(const sampling::PointSet& set, int m, int i, int j) {
  const std::uint32_t n = 1u << m;
  for (int a = 0; a <= m; ++a) {
    std::vector<int> boxes(n, 0);
    for (std::uint32_t k = 0; k < n; ++k) {
      double u[4];
      set.point(k, u);
      const auto bi = static_cast<std::uint32_t>(u[i] * (1u << a));
      const auto bj = static_cast<std::uint32_t>(u[j] * (1u << (m - a)));
      if (++boxes[(bi << (m - a)) | bj] > 1) return false;
    }
  }
  return true;
}

TEST(Sampling, ScrambledSobolPointsKeepTheirStratification) {
  for (const std::uint64_t key : {0ull, 12345ull, 0xdeadbeefull}) {
    const sampling::PointSet set(sampling::Sampler::Sobol, key);
    // One point in each 1/2^m interval of every dimension, for 2^m points.
    for (int d = 0; d < sampling::kDimensions; ++d) {
      std::set<std::uint32_t> cells;
      for (std::uint32_t k = 0; k < 1024; ++k) {
        double u[4];
        set.point(k, u);
        ASSERT_GT(u[d], 0.0);
        ASSERT_LT(u[d], 1.0);
        cells.insert(static_cast<std::uint32_t>(u[d] * 1024));
      }
      EXPECT_EQ(cells.size(), 1024u) << "dimension " << d;
    }
    // Dimensions 1 and 2 form a (0, m, 2)-net: every elementary box of area 2^-m holds one point.
    EXPECT_TRUE(isNet(set, 10, 0, 1));
  }
  // Independent random points are no net.
  EXPECT_FALSE(isNet(sampling::PointSet(sampling::Sampler::Random, 1), 10, 0, 1));
  // Unscrambled values: the Joe-Kuo direction numbers give 0.5, 0.75, 0.25 ... in dimension 2.
  EXPECT_EQ(sampling::sobol(1, 1), 0x80000000u);
  EXPECT_EQ(sampling::sobol(2, 1), 0xc0000000u);
  EXPECT_EQ(sampling::sobol(3, 1), 0x40000000u);
}

// ------------------------------------------------------------------------- ray casting

TEST(RayScene, SinglePacketAndStreamTracingAgree) {
  RayScene scene;
  scene.addTriangles(makeSphere("s", {0, 0, 0}, 1.0, 2));
  const std::vector<double> xs{3.0, 0.0}, ys{0.0, 3.0}, zs{0.0, 0.0}, rs{0.5, 0.25};
  scene.addSpheres(xs, ys, zs, rs);
  scene.commit();
  RayBlock a, b, c;
  const sampling::PointSet set(sampling::Sampler::Random, 3);
  for (RayBlock* blk : {&a, &b, &c}) {
    blk->count = 200;  // not a multiple of 16: the last packet is partial
    for (int i = 0; i < blk->count; ++i) {
      double u[4];
      set.point(static_cast<std::uint32_t>(i), u);
      const auto d = sampling::squareToSphere(u[2], u[3]);
      blk->ox[i] = 1.5f;
      blk->oy[i] = 1.5f;
      blk->oz[i] = 0.0f;
      blk->dx[i] = static_cast<float>(d[0]);
      blk->dy[i] = static_cast<float>(d[1]);
      blk->dz[i] = static_cast<float>(d[2]);
    }
  }
  scene.trace(a, TraceMode::Single);
  scene.trace(b, TraceMode::Packet16);
  scene.trace(c, TraceMode::Stream);
  std::set<std::uint32_t> seen;
  for (int i = 0; i < a.count; ++i) {
    EXPECT_EQ(a.geometry[i], b.geometry[i]);
    EXPECT_EQ(a.geometry[i], c.geometry[i]);
    if (a.geometry[i] != RayScene::kMiss) {
      EXPECT_EQ(a.primitive[i], b.primitive[i]);
      EXPECT_EQ(a.primitive[i], c.primitive[i]);
      EXPECT_FLOAT_EQ(a.distance[i], b.distance[i]);
    }
    seen.insert(a.geometry[i]);
  }
  EXPECT_EQ(seen, (std::set<std::uint32_t>{0u, 1u, RayScene::kMiss}));  // all three outcomes occur
}

TEST(ViewFactors, BackFacesHotOccludersAndBadOptions) {
  // A plate whose front faces away from the receiver is struck on its back.
  const TriangleMesh plate = makeRectangle("plate", {-5, -5, 1}, {10, 0, 0}, {0, 10, 0});  // normal +z
  const ViewFactorSolver flipped(RadiationScene{plate, {}, {}});
  SamplingOptions o;
  o.rays = 1u << 14;
  const ReceiverResult r = flipped.fromPoint({0, 0, 0}, {0, 0, 1}, o);
  EXPECT_GT(r.toBackFace.value, 0.9);
  EXPECT_EQ(r.toPatch[0].value, 0.0);

  // A hot occluder sphere: element-to-sphere factor (R/d)^2 times eps sigma T^4.
  RadiationScene hot;
  hot.occluder.mesh = makeSphere("rock", {0, 0, 4}, 2.0, 5);
  hot.occluder.temperature = 1800.0;
  hot.occluder.emissivity = 0.5;
  const ViewFactorSolver solver(hot);
  o.rays = 1u << 16;
  const ReceiverResult h = solver.fromPoint({0, 0, 0}, {0, 0, 1}, o);
  const double f = 0.25, q = 0.5 * 5.670374419e-8 * std::pow(1800.0, 4) * f;
  EXPECT_NEAR(h.toOccluder.value, f, 0.01 * f);  // the 20480-triangle sphere is 0.2% small
  EXPECT_NEAR(h.flux.value, q, 0.01 * q);
  EXPECT_DOUBLE_EQ(h.fluxFromOccluder.value, h.flux.value);

  SamplingOptions bad;
  bad.replicates = 1;
  EXPECT_THROW(solver.fromPoint({0, 0, 0}, {0, 0, 1}, bad), std::invalid_argument);
  EXPECT_THROW(solver.fromPoint({0, 0, 0}, {0, 0, 0}, o), std::invalid_argument);
  EXPECT_THROW(flipped.fromPatch("nope", o), std::invalid_argument);
}

TEST(ViewFactors, IdenticalForAnyThreadCount) {
  // A box spacecraft before a lattice of hot spheres of two materials: counts are integers and
  // the flux is summed in a fixed order, so 1 and 2 threads give the same bits.
  RadiationScene scene;
  scene.surfaces = placeMesh(makeBox(1, 1, 1), Pose{{-5, 0, 0}, {}, {}});
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j)
      scene.emitters.add(0.0, -2.0 + 0.2 * i, -2.0 + 0.2 * j, 0.15, 1500.0 + 10.0 * (i + j), i < 10 ? 0.45 : 0.8,
                         i < 10 ? "granite" : "iron");
  const ViewFactorSolver solver(std::move(scene));
  SamplingOptions o;
  o.rays = 1u << 17;
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);
  const ReceiverResult one = solver.fromPatch("side0", o);
  omp_set_num_threads(2);
  const ReceiverResult two = solver.fromPatch("side0", o);
  omp_set_num_threads(saved);
  EXPECT_GT(one.flux.value, 0.0);
  EXPECT_EQ(one.flux.value, two.flux.value);
  EXPECT_EQ(one.flux.standardError, two.flux.standardError);
  for (std::size_t g = 0; g < 2; ++g) {
    EXPECT_EQ(one.toGroup[g].value, two.toGroup[g].value);
    EXPECT_EQ(one.fluxFromGroup[g].value, two.fluxFromGroup[g].value);
  }
  o.seed += 1;
  EXPECT_NE(solver.fromPatch("side0", o).flux.value, one.flux.value);  // the seed matters
}

// ------------------------------------------------------------------------ geometry files

TEST(GeometryFile, ExampleFilesParseAndTheDiscExampleMatchesTheCatalog) {
  const fs::path dir = fs::path(EJECTA_SOURCE_DIR) / "scenes/geometry";
  const GeometryConfig seed = loadGeometryConfig(dir / "seed_follower.toml");
  ASSERT_TRUE(seed.spacecraft.has_value());
  EXPECT_EQ(seed.spacecraft->times.size(), 2u);
  const Emitters hot = buildEmitters(seed);
  EXPECT_EQ(hot.groupNames, std::vector<std::string>{"melt"});  // the 1200 K rim is below the cut
  const RadiationScene later = buildRadiationScene(seed, 5e-4);
  const auto side0 = static_cast<std::size_t>(later.surfaces.findPatch("side0"));
  expectVecNear(later.surfaces.patchCentroid(side0), {-4.5, 0, 0}, 1e-12);  // 5 m closer

  GeometryConfig discs = loadGeometryConfig(dir / "howell_coaxial_discs.toml");
  ViewFactorRunOptions run;
  run.rays = 1u << 18;
  const ViewFactorReport rep = computeViewFactors(discs, run);
  ASSERT_EQ(rep.receivers.size(), 3u);  // disc1, disc2 and the element
  const Estimate f12 = rep.receivers[0].result.toPatch[1];
  EXPECT_NEAR(f12.value, 0.468871, 4.0 * f12.standardError + 1e-5);
  EXPECT_NEAR(rep.receivers[2].result.toPatch[1].value, 0.5, 1e-3);
  // The JSON is valid and carries the numbers.
  const nlohmann::json j = nlohmann::json::parse(formatViewFactorJson(rep));
  EXPECT_EQ(j["receivers"][0]["name"], "disc1");
  EXPECT_NEAR(j["receivers"][0]["view_factors"]["patch:disc2"]["value"].get<double>(), f12.value,
              1e-9 * f12.value);  // 10 significant digits
  EXPECT_NE(formatViewFactorText(rep).find("F -> disc2"), std::string::npos);
}

TEST(GeometryFile, SeedFollowerReportAndFluxSeries) {
  // The seed's example: side0 faces the melt, side1 and side2 are mirror images (equal fluxes
  // within their errors, as the seed's Table 4.2 has equal temperatures), the aft sees nothing,
  // and 5 m closer the flux is higher. The CSV is what the wall model reads.
  const GeometryConfig c = loadGeometryConfig(fs::path(EJECTA_SOURCE_DIR) / "scenes/geometry/seed_follower.toml");
  ViewFactorRunOptions run;
  run.rays = 1u << 14;
  const ViewFactorReport rep = computeViewFactors(c, run);
  ASSERT_EQ(rep.receivers.size(), 8u);  // 4 patches x 2 times
  std::map<std::pair<double, std::string>, Estimate> fluxes;
  for (const ReceiverReport& r : rep.receivers) fluxes[{r.time, r.receiver}] = r.result.flux;
  auto q = [&fluxes](double t, const char* patch) { return fluxes.at({t, patch}); };
  for (const double t : {0.0, 5e-4}) {
    const Estimate s0 = q(t, "side0"), s1 = q(t, "side1"), s2 = q(t, "side2");
    EXPECT_GT(s0.value, 5.0 * s1.value);
    EXPECT_NEAR(s1.value, s2.value, 5.0 * std::hypot(s1.standardError, s2.standardError));
    EXPECT_EQ(q(t, "aft").value, 0.0);
  }
  EXPECT_GT(q(5e-4, "side0").value, 2.0 * q(0.0, "side0").value);
  ASSERT_TRUE(rep.receivers[0].baseline.has_value());
  EXPECT_GT(rep.receivers[0].baseline->flux, 10.0 * rep.receivers[0].result.flux.value);
  const std::string csv = formatFluxSeriesCsv(rep);
  std::istringstream lines(csv);
  std::string header, row0, row1, extra;
  std::getline(lines, header);
  std::getline(lines, row0);
  std::getline(lines, row1);
  EXPECT_FALSE(std::getline(lines, extra));
  EXPECT_EQ(header, "time_s,side0,side1,side2,aft");
  EXPECT_EQ(row1.substr(0, row1.find(',')), "0.0005");
  const double side0 = std::stod(row0.substr(row0.find(',') + 1));
  EXPECT_NEAR(side0, q(0.0, "side0").value, 1e-9 * side0);
}

TEST(GeometryFile, MeshPathsAreRelativeToTheFile) {
  TempDir dir;
  fs::create_directories(dir.path() / "meshes");
  dir.write("meshes/panel.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\ng panel\nf 1 2 3 4\n");
  const fs::path toml = dir.write("g.toml",
                                  "[spacecraft]\nshape = \"mesh\"\nmesh = \"meshes/panel.obj\"\nposition = [0, 0, -2]\n"
                                  "[[emitters]]\nname = \"spot\"\nshape = \"points\"\npoints = [[0.5, 0.5, 3.0]]\n"
                                  "emitter_radius = 0.5\ntemperature = 2000.0\n");
  const GeometryConfig c = loadGeometryConfig(toml);
  const RadiationScene s = buildRadiationScene(c, 0.0);
  EXPECT_EQ(s.surfaces.patchNames, std::vector<std::string>{"panel"});
  EXPECT_EQ(s.emitters.size(), 1u);
  EXPECT_EQ(s.emitters.emissivity[0], kGraniteEmissivity);
  fs::remove(dir.path() / "meshes/panel.obj");
  const std::string msg = errorOf<GeometryFileError>([&] { buildRadiationScene(c, 0.0); });
  EXPECT_NE(msg.find("meshes/panel.obj: cannot open the mesh file"), std::string::npos) << msg;
}

// Geometry files read their quantities with core's parser, the scenes' one: a value with a unit
// gives what the same value in SI gives, and a unit of the wrong dimension names the key.
TEST(GeometryFile, AcceptsQuantitiesWithUnits) {
  const std::string withUnits =
      "[spacecraft]\nshape = \"cylinder\"\nradius = \"50 cm\"\nlength = \"2 m\"\n"
      "position = [\"1 km\", 0, \"-20 mm\"]\nvelocity = [\"10 km/s\", 0, 0]\n"
      "rotation_axis = [0, 0, 1]\nrotation_angle = \"0.5 rad\"\ntimes = [0, \"0.5 ms\"]\n"
      "[[emitters]]\nname = \"melt\"\nshape = \"sphere\"\ncenter = [0, 0, 0]\nradius = \"1 m\"\n"
      "spacing = \"25 cm\"\ntemperature = \"2.2e3 K\"\n"
      "[hot_material]\nmin_temperature = \"1500 K\"\n"
      "[receivers]\nbaseline_length = \"100 cm\"\n";
  const GeometryConfig c = parseGeometryConfig(withUnits, "units.toml", ".");
  ASSERT_TRUE(c.spacecraft.has_value());
  EXPECT_DOUBLE_EQ(c.spacecraft->body.radius, 0.5);
  EXPECT_DOUBLE_EQ(c.spacecraft->body.length, 2.0);
  EXPECT_DOUBLE_EQ(c.spacecraft->pose.position[0], 1000.0);
  EXPECT_DOUBLE_EQ(c.spacecraft->pose.position[2], -0.02);
  EXPECT_DOUBLE_EQ(c.spacecraft->pose.velocity[0], 1e4);
  ASSERT_EQ(c.spacecraft->times.size(), 2u);
  EXPECT_DOUBLE_EQ(c.spacecraft->times[1], 5e-4);
  ASSERT_EQ(c.emitters.size(), 1u);
  EXPECT_DOUBLE_EQ(c.emitters[0].spacing, 0.25);
  EXPECT_DOUBLE_EQ(c.emitters[0].temperatures[0], 2200.0);
  EXPECT_DOUBLE_EQ(c.minTemperature, 1500.0);
  EXPECT_DOUBLE_EQ(c.baseline.receiverSide, 1.0);
  // A plain number of degrees (the key's old form) and "0.5 rad" agree on the attitude.
  std::string degrees = withUnits;
  degrees.replace(degrees.find("\"0.5 rad\""), 9, std::to_string(0.5 * 180.0 / std::numbers::pi));
  const Vec3 x = c.spacecraft->pose.attitude.apply({1, 0, 0});
  const Vec3 y = parseGeometryConfig(degrees, "deg.toml", ".").spacecraft->pose.attitude.apply({1, 0, 0});
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(x[k], y[k], 1e-6);

  const std::string wrong = errorOf<GeometryFileError>([] {
    parseGeometryConfig("[spacecraft]\nshape = \"box\"\nsize = [1, \"1 K\", 1]\n", "g.toml", ".");
  });
  EXPECT_NE(wrong.find("g.toml:3: key 'spacecraft.size[1]': expected a length (m), got a temperature (K)"),
            std::string::npos) << wrong;
}

TEST(GeometryFile, ErrorsNameTheFileLineAndKey) {
  struct Case {
    const char* text;
    const char* expected;
  };
  const Case cases[] = {
      {"[spacecraft]\nshape = \"box\"\nsise = [1, 1, 1]\n", "g.toml:3: key 'spacecraft.sise': unknown key"},
      {"[spacecraft]\nshape = \"box\"\nsize = [1, 1]\n", "g.toml:3: key 'spacecraft.size': expected an array of 3"},
      {"[spacecraft]\nshape = \"ball\"\n", "g.toml:2: key 'spacecraft.shape': unknown value 'ball'"},
      {"[spacecraft]\nshape = \"box\"\n", "key 'spacecraft.size': required key is missing"},
      {"[spacecraft]\nshape = \"box\"\nsize = [1, 1, 1]\nforward = [1, 0, 0]\nup = [2, 0, 0]\n",
       "g.toml:5: key 'spacecraft.up': up must not be zero or parallel to forward"},
      {"[spacecraft]\nshape = \"box\"\nsize = [1, 1, 1]\nradius = 2.0\n",
       "g.toml:4: key 'spacecraft.radius': not used by shape 'box'"},
      {"[[points]]\nname = \"p\"\nposition = [0, 0, 0]\n[sampling]\nrays = 1000\ntolerance = 1e-3\n",
       "key 'sampling.rays': give a fixed ray count or tolerances, not both"},
      {"[[points]]\nname = \"p\"\nposition = [0, 0, 0]\n[[emitters]]\nname = \"e\"\nshape = \"sphere\"\n"
       "center = [0, 0, 0]\nradius = 1.0\nspacing = 0.1\ntemperature = 2000\nemissivity = 1.5\n",
       "g.toml:11: key 'emitters[0].emissivity': must be in (0, 1]"},
      {"[geometry]\nname = \"nothing\"\n", "g.toml:1: nothing to receive radiation"},
      {"[spacecraft\n", "g.toml:1: TOML syntax error"},
  };
  for (const Case& c : cases) {
    const std::string msg = errorOf<GeometryFileError>([&] { parseGeometryConfig(c.text, "g.toml", "."); });
    EXPECT_NE(msg.find(c.expected), std::string::npos) << "got: " << msg << "\nexpected: " << c.expected;
  }
}

}  // namespace
}  // namespace ejecta::radiation
