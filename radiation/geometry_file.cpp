// Geometry files → the radiation scene: shapes, emitter lattices and the occluder built from a
// GeometryConfig (read by geometry_file_reader.cpp), then the view factors cast at every time
// (computeViewFactors). The report is printed by geometry_file_report.cpp.
#include "radiation/geometry_file.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "radiation/mesh_io.hpp"

namespace ejecta::radiation {

TriangleMesh buildShape(const SurfaceShape& s, const std::string& source) {
  using K = SurfaceShape::Kind;
  switch (s.kind) {
    case K::Box: return makeBox(s.size[0], s.size[1], s.size[2]);
    case K::Cylinder: return makeCylinder(s.radius, s.length, s.segments, s.sectors);
    case K::Rectangle: return makeRectangle(s.name, s.corner, s.edge1, s.edge2);
    case K::Disc: return makeDisc(s.name, s.center, s.normal, s.radius, s.segments);
    case K::Sphere: return makeSphere(s.name, s.center, s.radius, s.subdivisions);
    case K::Mesh:
      try {
        return readMesh(s.mesh, {s.name, s.scale});
      } catch (const MeshError& e) {
        throw GeometryFileError(source + ": " + e.what());
      }
  }
  return {};
}

namespace {

// Lattice points of an emitter region (spacing s, centred on the region).
std::vector<Vec3> latticePoints(const EmitterSpec& e) {
  std::vector<Vec3> pts;
  using K = EmitterSpec::Kind;
  const double s = e.spacing;
  if (e.kind == K::Box) {
    int n[3];
    for (int k = 0; k < 3; ++k) n[k] = std::max(1, static_cast<int>(std::lround((e.max[k] - e.min[k]) / s)));
    for (int i = 0; i < n[0]; ++i)
      for (int j = 0; j < n[1]; ++j)
        for (int k = 0; k < n[2]; ++k)
          pts.push_back({e.min[0] + (i + 0.5) * (e.max[0] - e.min[0]) / n[0],
                         e.min[1] + (j + 0.5) * (e.max[1] - e.min[1]) / n[1],
                         e.min[2] + (k + 0.5) * (e.max[2] - e.min[2]) / n[2]});
  } else if (e.kind == K::Sphere) {
    const int m = static_cast<int>(std::floor(e.radius / s));
    for (int i = -m; i <= m; ++i)
      for (int j = -m; j <= m; ++j)
        for (int k = -m; k <= m; ++k) {
          const Vec3 d{i * s, j * s, k * s};
          if (vec3::norm(d) <= e.radius) pts.push_back(vec3::add(e.center, d));
        }
  } else if (e.kind == K::Disc) {
    const Vec3 n = vec3::normalized(e.normal);
    const Vec3 helper = std::abs(n[0]) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    const Vec3 u = vec3::normalized(vec3::cross(helper, n)), v = vec3::cross(n, u);
    const int m = static_cast<int>(std::floor(e.radius / s));
    for (int i = -m; i <= m; ++i)
      for (int j = -m; j <= m; ++j)
        if (std::hypot(i * s, j * s) <= e.radius)
          pts.push_back(vec3::add(e.center, vec3::add(vec3::scale(u, i * s), vec3::scale(v, j * s))));
  } else {
    pts = e.points;
  }
  return pts;
}


}  // namespace

Emitters buildEmitters(const GeometryConfig& config) {
  Emitters all;
  for (const EmitterSpec& e : config.emitters) {
    const std::vector<Vec3> pts = latticePoints(e);
    // Default sphere size of a lattice: just opaque (every point of a 3D region, or of a disc's
    // plane, inside some sphere: sqrt(3)/2 or sqrt(2)/2 spacings).
    double defaultRadius = e.emitterRadius;
    if (defaultRadius == 0.0 && e.kind != EmitterSpec::Kind::Points)
      defaultRadius = e.kind == EmitterSpec::Kind::Disc ? 0.5 * std::sqrt(2.0) * e.spacing
                                                        : opaqueLatticeRadius(e.spacing);
    std::vector<double> x, y, z, r, t;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      x.push_back(pts[i][0]);
      y.push_back(pts[i][1]);
      z.push_back(pts[i][2]);
      r.push_back(e.radii.empty() ? defaultRadius : e.radii[i]);
      t.push_back(e.temperatures.size() == 1 ? e.temperatures[0] : e.temperatures[i]);
    }
    EmitterSource src{x, y, z, r, t, {}};
    EmitterSelection sel;
    sel.minTemperature = config.minTemperature;
    sel.emissivityByMaterial = {e.emissivity};
    sel.materialNames = {e.name};
    try {
      all.append(selectEmitters(src, sel));
    } catch (const std::invalid_argument& err) {
      throw GeometryFileError(config.source + ": emitters '" + e.name + "': " + err.what());
    }
  }
  return all;
}

namespace {

// The parts of a scene that do not move, and the spacecraft in its body frame.
struct SceneParts {
  TriangleMesh body;      // body frame (empty without a spacecraft)
  TriangleMesh plates;
  Emitters emitters;
  Occluder occluder;
};

SceneParts buildParts(const GeometryConfig& config) {
  SceneParts parts;
  try {
    if (config.spacecraft) parts.body = buildShape(config.spacecraft->body, config.source);
    for (const SurfaceShape& s : config.surfaces) {
      const TriangleMesh plate = buildShape(s, config.source);
      for (const std::string& name : plate.patchNames)
        if (parts.body.findPatch(name) >= 0 || parts.plates.findPatch(name) >= 0)
          throw GeometryFileError(config.source + ": surface patch '" + name +
                                  "' has the name of a patch that already exists");
      parts.plates.append(plate);
    }
    parts.emitters = buildEmitters(config);
    if (config.occluder) {
      parts.occluder.mesh = buildShape(config.occluder->shape, config.source);
      parts.occluder.temperature = config.occluder->temperature;
      parts.occluder.emissivity = config.occluder->emissivity;
    }
  } catch (const std::invalid_argument& e) {
    throw GeometryFileError(config.source + ": " + e.what());
  }
  return parts;
}

RadiationScene assemble(const GeometryConfig& config, const SceneParts& parts, double time) {
  RadiationScene scene;
  if (config.spacecraft) scene.surfaces = placeMesh(parts.body, config.spacecraft->pose.at(time));
  scene.surfaces.append(parts.plates);
  scene.emitters = parts.emitters;
  scene.occluder = parts.occluder;
  return scene;
}

}  // namespace

RadiationScene buildRadiationScene(const GeometryConfig& config, double time) {
  return assemble(config, buildParts(config), time);
}

ViewFactorReport computeViewFactors(const GeometryConfig& config, const ViewFactorRunOptions& run) {
  ViewFactorReport report;
  report.name = config.name;
  report.source = config.source;
  report.sampling = config.sampling;
  if (run.rays) {
    report.sampling.rays = *run.rays;
  } else if (run.tolerance) {
    report.sampling.rays = 0;
    report.sampling.absoluteTolerance = *run.tolerance;
  }
  report.threads = omp_get_max_threads();
  const SceneParts parts = buildParts(config);
  // The receivers: the listed patches, else the spacecraft's, else every plate.
  std::vector<std::string> patches = config.receiverPatches;
  if (patches.empty()) patches = config.spacecraft ? parts.body.patchNames : parts.plates.patchNames;
  for (const std::string& p : patches)
    if (parts.body.findPatch(p) < 0 && parts.plates.findPatch(p) < 0)
      throw GeometryFileError(config.source + ": receiver patch '" + p + "' does not exist");
  const std::vector<double> times = config.spacecraft ? config.spacecraft->times : std::vector<double>{0.0};
  const auto start = std::chrono::steady_clock::now();
  for (const double time : times) {
    ViewFactorSolver solver(assemble(config, parts, time));
    const RadiationScene& s = solver.scene();
    report.patchNames = s.surfaces.patchNames;
    report.groupNames = s.emitters.groupNames;
    report.emitterCount = s.emitters.size();
    report.occluder = !s.occluder.mesh.triangles.empty();
    for (const std::string& p : patches) {
      const auto idx = static_cast<std::size_t>(s.surfaces.findPatch(p));
      ReceiverReport r;
      r.receiver = p;
      r.time = time;
      r.area = s.surfaces.patchArea(idx);
      r.result = solver.fromPatch(idx, report.sampling);
      if (!s.emitters.empty()) r.baseline = seedBaseline(s.emitters, s.surfaces, idx, config.baseline);
      report.receivers.push_back(std::move(r));
    }
    for (const PointReceiverSpec& pt : config.points) {
      ReceiverReport r;
      r.receiver = pt.name;
      r.point = true;
      r.time = time;
      r.result = solver.fromPoint(pt.position, pt.normal, report.sampling);
      report.receivers.push_back(std::move(r));
    }
  }
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace ejecta::radiation
