// Thermal study files → ThermalStudy, read with core's table reader: every key checked against
// its table's allowed keys, messages "FILE:LINE: key 'a.b': reason" (ThermalStudyError), every
// dimensional value a number (SI) or a quantity string read by core/units.hpp ("1 km/s",
// "0.2 mm"): the units a scene accepts. The spacecraft's shape is a geometry file's
// (geometry_file_reader.hpp).
#include <cmath>
#include <limits>

#include "radiation/geometry_file_reader.hpp"
#include "radiation/study_input.hpp"
#include "radiation/thermal_study.hpp"

namespace ejecta::radiation {

namespace fs = std::filesystem;

namespace {

using config::TableReader;
using namespace input;

const config::SchemaTables& studySchema() {
  static const config::SchemaTables keys = {
      {"", {"study", "spacecraft", "approach", "emitters", "walls", "wall", "limit", "sizing", "sampling",
            "baseline"}},
      {"study", {"name", "description"}},
      {"spacecraft", {"shape", "size", "radius", "length", "segments", "sectors", "mesh", "patch", "scale",
                      "forward", "up"}},
      {"approach", {"target", "start", "distance", "direction", "velocity", "speed", "duration", "samples"}},
      {"emitters", {"min_temperature", "default_emissivity", "emissivity"}},
      {"emitters.emissivity", {"*"}},  // by material name
      {"walls[]", {"patch", "patches", "layers", "absorptivity", "emissivity", "cold_emissivity"}},
      {"layers[]", {"material", "thickness", "cells"}},
      {"wall", {"initial_temperature", "time_step"}},
      {"limit", {"kind", "value"}},
      {"sizing", {"coatings", "patches", "max_thickness", "tolerance", "coating_cells"}},
      {"sampling", {"rays", "tolerance", "relative_tolerance", "max_rays", "replicates", "seed"}},
      {"baseline", {"length"}},
  };
  return keys;
}

constexpr auto kRaise = &config::raiseInputError<ThermalStudyError>;

void readSpacecraft(const TableReader& t, ThermalStudy& s, const fs::path& base, const Vec3& flight) {
  s.spacecraft.body = readShape(t, ShapeRole::StudyBody, base);
  // side0 (body +x) leads: by default it points along the flight, towards the crater.
  const Vec3 forward = vec3::normalized(direction(t, "forward", flight));
  const Vec3 up = vec3::normalized(direction(t, "up", std::abs(forward[1]) < 0.99 ? Vec3{0, 1, 0} : Vec3{1, 0, 0}));
  try {
    s.spacecraft.pose.attitude = Rotation::fromForwardUp(forward, up);
  } catch (const std::invalid_argument& e) {
    t.fail(t.has("up") ? "up" : "forward", e.what());
  }
}

void readApproach(const TableReader& t, ApproachSpec& a) {
  a.target = optVec3(t, "target", Dimension::Length).value_or(Vec3{});
  if (t.has("start") == t.has("distance")) {
    if (t.has("start")) t.fail("distance", "give either start or distance (with direction), not both");
    t.require("start");
  }
  if (t.has("direction") && !t.has("distance")) t.fail("direction", "only used with distance");
  if (t.has("start")) {
    a.start = requireVec3(t, "start", Dimension::Length);
  } else {
    const double d = requirePositive(t, "distance", Dimension::Length);
    a.start = vec3::add(a.target, vec3::scale(vec3::normalized(direction(t, "direction", {0, 1, 0})), d));
  }
  const Vec3 towards = vec3::sub(a.target, a.start);
  if (t.has("velocity") == t.has("speed")) {
    if (t.has("velocity")) t.fail("speed", "give either velocity [m/s] or speed (towards the target), not both");
    t.require("speed");
  }
  if (t.has("velocity")) {
    a.velocity = requireVec3(t, "velocity", Dimension::Velocity);
  } else {
    const double v = requirePositive(t, "speed", Dimension::Velocity);
    if (vec3::norm(towards) == 0.0) t.fail("speed", "the start is the target: no direction to fly in");
    a.velocity = vec3::scale(towards, v / vec3::norm(towards));
  }
  a.duration = requirePositive(t, "duration", Dimension::Time);
  a.samples = static_cast<int>(integerIn(t, "samples", 11, 2, 100000));
}

void readEmitters(const TableReader& t, EmitterChoice& e) {
  e.minTemperature = t.optQuantity("min_temperature", Dimension::Temperature).value_or(e.minTemperature);
  if (!(e.minTemperature >= 0.0)) t.fail("min_temperature", "must be >= 0 K");
  e.defaultEmissivity = numberIn(t, "default_emissivity", kGraniteEmissivity, 1e-300, 1.0, "(0, 1]");
  if (const toml::table* m = t.optTable("emissivity")) {
    const TableReader byMaterial(t.context(), *m, t.key("emissivity"), "emitters.emissivity");
    for (auto&& [k, v] : *m)
      e.emissivityByMaterial[std::string(k.str())] = numberIn(byMaterial, k.str(), 1.0, 1e-300, 1.0, "(0, 1]");
  }
}

WallSpec readWall(const TableReader& t) {
  WallSpec w;
  w.line = config::lineOf(t.table());
  if (t.has("patch") && t.has("patches")) t.fail("patches", "give patch or patches, not both");
  if (t.has("patch")) w.patches = {t.requireString("patch")};
  else w.patches = stringList(t, "patches");
  const auto layers = t.tableArray("layers");
  if (layers.empty()) t.fail("layers", "required: layers from the hot face to the cold one, e.g. "
                                       "[{material = \"tungsten\", thickness = \"0.2 mm\"}, ...]");
  for (std::size_t i = 0; i < layers.size(); ++i) {
    const TableReader l(t.context(), *layers[i], t.key("layers") + "[" + std::to_string(i) + "]", "layers[]");
    const std::string material = l.requireString("material");
    const double thickness = requirePositive(l, "thickness", Dimension::Length);
    const int cells = static_cast<int>(integerIn(l, "cells", 20, 1, 100000));
    try {
      w.layers.push_back(wallLayer(material, thickness, cells));
    } catch (const std::invalid_argument& e) {
      l.fail("material", e.what());
    }
  }
  if (t.has("absorptivity")) w.absorptivity = numberIn(t, "absorptivity", 0, 0.0, 1.0, "[0, 1]");
  if (t.has("emissivity")) w.emissivity = numberIn(t, "emissivity", 0, 0.0, 1.0, "[0, 1]");
  w.coldEmissivity = numberIn(t, "cold_emissivity", 0.0, 0.0, 1.0, "[0, 1]");
  return w;
}

void readLimit(const TableReader& t, ShieldLimit& limit) {
  using K = ShieldLimit::Kind;
  limit.kind = t.optEnum<K>("kind", {{"melting", K::MeltingPoint},
                                     {"margin", K::MarginBelowMelting},
                                     {"temperature", K::Temperature}})
                   .value_or(K::MeltingPoint);
  if (limit.kind == K::MeltingPoint) {
    if (t.has("value")) t.fail("value", "not used by kind 'melting'");
  } else {
    limit.value = t.requireQuantity("value", Dimension::Temperature);
    if (limit.kind == K::MarginBelowMelting && !(limit.value >= 0.0)) t.fail("value", "the margin must be >= 0 K");
    if (limit.kind == K::Temperature && !(limit.value > 0.0)) t.fail("value", "must be > 0 K");
  }
}

void readSizing(const TableReader& t, SizingSpec& s) {
  s.coatings = stringList(t, "coatings");
  for (const std::string& c : s.coatings) {
    try {
      wallMaterial(c);
    } catch (const std::invalid_argument& e) {
      t.fail("coatings", e.what());
    }
  }
  s.patches = stringList(t, "patches");
  s.maxThickness = optPositive(t, "max_thickness", Dimension::Length, s.maxThickness);
  s.tolerance = numberIn(t, "tolerance", s.tolerance, 1e-9, 0.5, "[1e-9, 0.5]");
  s.coatingCells = static_cast<int>(integerIn(t, "coating_cells", s.coatingCells, 1, 100000));
}

void readSampling(const TableReader& t, SamplingOptions& s) {
  s.absoluteTolerance = 1e-3;
  s.relativeTolerance = 0.0;
  // A relative target applies to every patch, and a face that sees little needs many rays to
  // reach it: a lower cap than the solver's 2^24 bounds that cost (docs/thermal.md).
  s.maxRays = 1u << 22;
  if (t.has("rays")) s.rays = static_cast<std::uint64_t>(integerIn(t, "rays", 0, 256, 1LL << 34));
  s.absoluteTolerance = numberIn(t, "tolerance", s.absoluteTolerance, 1e-7, 0.5, "[1e-7, 0.5]");
  s.relativeTolerance = numberIn(t, "relative_tolerance", s.relativeTolerance, 0.0, 1.0, "[0, 1]");
  s.maxRays = static_cast<std::uint64_t>(integerIn(t, "max_rays", static_cast<long long>(s.maxRays), 4096, 1LL << 34));
  s.replicates = static_cast<int>(integerIn(t, "replicates", s.replicates, 2, 1024));
  s.seed = static_cast<std::uint64_t>(integerIn(t, "seed", static_cast<long long>(s.seed), 0,
                                                std::numeric_limits<long long>::max()));
}

}  // namespace

std::vector<double> ApproachSpec::times() const {
  std::vector<double> t(static_cast<std::size_t>(samples));
  for (int i = 0; i < samples; ++i) t[i] = duration * i / (samples - 1);
  return t;
}

ThermalStudy parseThermalStudy(const std::string& tomlText, const std::string& sourceName,
                               const fs::path& baseDirectory) {
  const InputDocument doc(tomlText, sourceName, studySchema(), kRaise);
  const TableReader top = doc.top();
  ThermalStudy s;
  s.source = sourceName;
  readStudyTitle(top, s.name, s.description);
  if (!top.has("approach")) top.fail("approach", "required: the spacecraft's pass ([approach])");
  readApproach(subTable(top, "approach"), s.approach);
  const Vec3 flight = vec3::norm(s.approach.velocity) > 0.0 ? vec3::normalized(s.approach.velocity) : Vec3{1, 0, 0};
  readSpacecraft(subTable(top, "spacecraft"), s, baseDirectory, flight);
  s.spacecraft.pose.position = s.approach.start;
  s.spacecraft.pose.velocity = s.approach.velocity;
  s.spacecraft.times = s.approach.times();
  readEmitters(subTable(top, "emitters"), s.emitters);
  const auto walls = top.tableArray("walls");
  for (std::size_t i = 0; i < walls.size(); ++i)
    s.walls.push_back(readWall(TableReader(doc.context(), *walls[i], "walls[" + std::to_string(i) + "]", "walls[]")));
  const TableReader wall = subTable(top, "wall");
  s.initialTemperature = optPositive(wall, "initial_temperature", Dimension::Temperature, s.initialTemperature);
  s.timeStep = optPositive(wall, "time_step", Dimension::Time, 0.0);
  // The wall solvers step the whole pass: 1e7 steps is hours per face; a step far below the
  // pass's length is a unit slip ("1e-15 s"), not a resolution.
  constexpr double kMaxWallSteps = 1e7;
  if (s.timeStep > 0.0 && s.approach.duration / s.timeStep > kMaxWallSteps)
    wall.fail("time_step", "is " + formatQuantity(s.timeStep, Dimension::Time) + ": " +
                               formatQuantity(s.approach.duration / s.timeStep, Dimension::None) +
                               " steps over the " + formatQuantity(s.approach.duration, Dimension::Time) +
                               " pass; at most 1e7 (absent: the pass / 2000)");
  readLimit(subTable(top, "limit"), s.limit);
  const TableReader sizing = subTable(top, "sizing");
  readSizing(sizing, s.sizing);
  if (!s.sizing.coatings.empty() && s.walls.empty())
    sizing.fail("coatings", "sizing needs a structure: give [[walls]] (its last layer is the structure)");
  readSampling(subTable(top, "sampling"), s.sampling);
  s.baseline.receiverSide = optPositive(subTable(top, "baseline"), "length", Dimension::Length, 0.0);
  return s;
}

ThermalStudy loadThermalStudy(const fs::path& path) {
  return parseThermalStudy(readInputFile(path, "thermal study file", kRaise), path.string(), path.parent_path());
}

}  // namespace ejecta::radiation
