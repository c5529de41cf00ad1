#pragma once
// Geometry files for `ejecta viewfactor GEOMETRY.toml [--rays N | --tol T] [--json]`: a
// spacecraft (primitive or mesh file, with its pose), extra plates, synthetic hot emitters, an
// optional occluding body, the receivers and the sampling. Parsed into plain structs with
// errors "FILE:LINE: key 'a.b': reason"; computeViewFactors runs it and the formatters print the
// report. Format and examples: docs/view_factors.md, scenes/geometry/*.toml. Lengths, times,
// temperatures and speeds are numbers in SI units (m, s, K, m/s) or quantity strings ("2 m",
// "1500 K"), read by core/units.hpp; rotation_angle is a number in degrees or a string ("90 deg").
#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/input_error.hpp"
#include "radiation/emitters.hpp"
#include "radiation/mesh.hpp"
#include "radiation/solid_angle_baseline.hpp"
#include "radiation/spacecraft.hpp"
#include "radiation/view_factors.hpp"

namespace ejecta::radiation {

// A bad geometry file (or a mesh or scene it names that cannot be built).
class GeometryFileError : public InputError {
 public:
  using InputError::InputError;
};

// A surface given by shape: the spacecraft body, a plate, the occluder.
struct SurfaceShape {
  enum class Kind { Box, Cylinder, Rectangle, Disc, Sphere, Mesh };
  Kind kind = Kind::Box;
  std::string name;                 // patch name (rectangle, disc, sphere); mesh: unnamed faces
  Vec3 size{1, 1, 1};               // box: depth (x), height (y), width (z) [m]
  double radius = 0.0;              // cylinder, disc, sphere [m]
  double length = 0.0;              // cylinder [m]
  int segments = 64;                // cylinder, disc
  int sectors = 1;                  // cylinder mantle patches
  int subdivisions = 4;             // sphere
  Vec3 corner{}, edge1{}, edge2{};  // rectangle [m]
  Vec3 center{}, normal{0, 0, 1};   // disc, sphere [m]
  std::filesystem::path mesh;       // mesh file (resolved against the geometry file's folder)
  double scale = 1.0;               // mesh file units to m
};

// The triangles of a shape, in its own frame (a spacecraft body: centred on the body origin).
// `source` names the file in messages (a mesh file that cannot be read).
TriangleMesh buildShape(const SurfaceShape& s, const std::string& source);

struct SpacecraftSpec {
  SurfaceShape body;
  Pose pose;
  std::vector<double> times{0.0};   // evaluate at pose.at(t) for each t [s]
};

// Hot material as a lattice of emitter spheres, or explicit points.
struct EmitterSpec {
  enum class Kind { Sphere, Box, Disc, Points };
  Kind kind = Kind::Sphere;
  std::string name;                 // the emitter group
  Vec3 center{}, normal{0, 0, 1};   // sphere, disc
  double radius = 0.0;              // sphere, disc: the region's radius [m]
  Vec3 min{}, max{};                // box [m]
  double spacing = 0.0;             // lattice spacing [m]
  double emitterRadius = 0.0;       // each sphere's radius; 0: opaque default (see the doc)
  std::vector<Vec3> points;         // points
  std::vector<double> radii;        // points: per point (else emitterRadius)
  std::vector<double> temperatures; // points: per point, or one value for all [K]
  double emissivity = kGraniteEmissivity;
};

struct OccluderSpec {
  SurfaceShape shape;
  double temperature = 0.0;         // [K]; > 0: it emits too
  double emissivity = kGraniteEmissivity;
};

struct PointReceiverSpec {
  std::string name;
  Vec3 position{}, normal{0, 0, 1};
};

// A view factor whose exact value is known ([[references]]): what `ejecta viewfactor
// --convergence` measures the error of. `to` is a surface patch or an emitter group.
struct ReferenceFactor {
  std::string from, to;
  double value = 0.0;
  std::string source;               // where the value comes from ("Howell C-41")
  int line = 0;                     // in the geometry file, for messages
};

struct GeometryConfig {
  std::string source;               // the file name, for messages and the report
  std::string name, description;
  std::optional<SpacecraftSpec> spacecraft;
  std::vector<SurfaceShape> surfaces;  // fixed plates (not moved with the spacecraft)
  std::vector<EmitterSpec> emitters;
  double minTemperature = kMoltenRockThreshold;
  std::optional<OccluderSpec> occluder;
  std::vector<std::string> receiverPatches;  // empty: every spacecraft patch (or every surface)
  std::vector<PointReceiverSpec> points;
  BaselineOptions baseline;
  SamplingOptions sampling;
  std::vector<ReferenceFactor> references;
};

// Parses TOML text; `baseDirectory` resolves relative mesh paths. Throws GeometryFileError.
GeometryConfig parseGeometryConfig(const std::string& tomlText, const std::string& sourceName,
                                   const std::filesystem::path& baseDirectory);
GeometryConfig loadGeometryConfig(const std::filesystem::path& path);

// The world at time t: spacecraft placed at pose.at(t), plates, emitters (hot enough), occluder.
// Throws GeometryFileError (naming the file) for a mesh file that cannot be read, duplicate
// patch names or an empty scene.
RadiationScene buildRadiationScene(const GeometryConfig& config, double time);
Emitters buildEmitters(const GeometryConfig& config);

// One receiver at one time.
struct ReceiverReport {
  std::string receiver;             // patch or point name
  bool point = false;
  double time = 0.0;                // [s]
  double area = 0.0;                // [m^2] (0 for points)
  ReceiverResult result;
  std::optional<BaselineResult> baseline;  // patches, when there are emitters
};

struct ViewFactorReport {
  std::string name, source;
  std::vector<std::string> patchNames, groupNames;
  std::size_t emitterCount = 0;
  bool occluder = false;
  SamplingOptions sampling;
  int threads = 1;
  double seconds = 0.0;             // wall time of the ray casting
  std::vector<ReceiverReport> receivers;
};

// Command-line overrides of the file's [sampling].
struct ViewFactorRunOptions {
  std::optional<std::uint64_t> rays;       // --rays N: fixed count
  std::optional<double> tolerance;         // --tol T: adaptive, absolute on view factors
};

ViewFactorReport computeViewFactors(const GeometryConfig& config, const ViewFactorRunOptions& run = {});

// Human-readable summary, and a JSON document (docs/view_factors.md lists its fields).
std::string formatViewFactorText(const ViewFactorReport& report);
std::string formatViewFactorJson(const ViewFactorReport& report);
// The incident flux of every receiving patch at every time, as the wall model reads it
// (radiation/radiative_balance.hpp, readFluxSeriesCsv): a header "time_s,<patch>,..." and rows
// "t, q_0, q_1, ..." [s, W/m^2]. Point receivers are left out.
std::string formatFluxSeriesCsv(const ViewFactorReport& report);

}  // namespace ejecta::radiation
