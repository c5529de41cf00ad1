#include "coupling/thermal_picture.hpp"

#include <algorithm>
#include <cmath>

#include "coupling/particle_images.hpp"
#include "radiation/geometry_file.hpp"
#include "render/color_scale.hpp"
#include "render/png_io.hpp"

namespace ejecta::coupling {

namespace {

namespace v3 = radiation::vec3;

// The point where the plane z = 0 cuts the edge a-b (a[2] and b[2] of opposite signs).
radiation::Vec3 crossing(const radiation::Vec3& a, const radiation::Vec3& b) {
  const double s = a[2] / (a[2] - b[2]);
  return {a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1]), 0.0};
}

// The pose of the pass where the spacecraft sees the most flux on any face.
double peakFluxTime(const radiation::ThermalResult& result) {
  double best = -1.0, time = result.times.empty() ? 0.0 : result.times.back();
  for (const radiation::PatchThermal& p : result.patches)
    if (p.peakFlux > best) {
      best = p.peakFlux;
      time = p.peakTime;
    }
  return time;
}

}  // namespace

SectionBands sectionBands(const radiation::TriangleMesh& mesh, const std::vector<double>& patchValues,
                          double band) {
  SectionBands out;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    std::vector<radiation::Vec3> cut;
    for (int e = 0; e < 3; ++e) {
      const radiation::Vec3& a = mesh.vertices[mesh.triangles[t][e]];
      const radiation::Vec3& b = mesh.vertices[mesh.triangles[t][(e + 1) % 3]];
      if ((a[2] < 0.0) != (b[2] < 0.0)) cut.push_back(crossing(a, b));
    }
    if (cut.size() != 2) continue;
    const radiation::Vec3 along = v3::sub(cut[1], cut[0]);
    const double length = v3::norm(along);
    if (!(length > 0.0)) continue;
    // Across the cut, in the plane, so that the band straddles the face's trace.
    const radiation::Vec3 across = v3::scale({-along[1], along[0], 0.0}, 0.5 * band / length);
    const auto base = static_cast<std::uint32_t>(out.vertices.size());
    out.vertices.push_back(v3::sub(cut[0], across));
    out.vertices.push_back(v3::sub(cut[1], across));
    out.vertices.push_back(v3::add(cut[1], across));
    out.vertices.push_back(v3::add(cut[0], across));
    out.triangles.push_back({base, base + 1, base + 2});
    out.triangles.push_back({base, base + 2, base + 3});
    const double value = patchValues.at(mesh.patchOf[t]);
    out.values.insert(out.values.end(), {value, value});
  }
  return out;
}

void writeThermalPicture(render::Renderer& renderer, const ParticleSet& particles, Geometry geometry,
                         double time, const radiation::ThermalStudy& study,
                         const radiation::ThermalResult& result, const std::string& title,
                         const std::filesystem::path& out, std::optional<double> poseTime) {
  // The spacecraft where it sees the most, its faces at their steady temperatures.
  radiation::GeometryConfig craft;
  craft.source = study.source;
  craft.spacecraft = study.spacecraft;
  const double when = poseTime.value_or(peakFluxTime(result));
  const radiation::TriangleMesh mesh = radiation::buildRadiationScene(craft, when).surfaces;
  std::vector<double> faceTemperature(mesh.patchCount(), 0.0);
  for (std::size_t p = 0; p < mesh.patchCount(); ++p)
    for (const radiation::PatchThermal& pt : result.patches)
      if (pt.patch == mesh.patchNames[p]) faceTemperature[p] = pt.steadyTemperature;

  ParticleLayerArrays arrays;
  render::ParticleLayer hot =
      particleLayer(particles, geometry, {.field = "temperature", .log = true, .cut = "z", .cutAt = 0.0, .camera = std::nullopt, .title = "", .axes = false, .center = std::nullopt}, arrays);
  const std::vector<double>& temperature = arrays.values;
  // One scale for the rock and the faces, so their colours compare.
  const double faceMax = *std::max_element(faceTemperature.begin(), faceTemperature.end());
  // The rock's robust range on a log scale (render's own percentiles), widened to the faces.
  render::ColorScaleSpec robust;
  robust.kind = render::ScaleKind::Log;
  robust.highPercentile = 99.5;
  const render::ColorScale rock = render::resolveScale(robust, temperature);
  hot.scale.min = rock.min();
  hot.scale.max = std::max({rock.max(), faceMax, rock.min() * 10.0});
  hot.scale.map = render::ColorMapName::Inferno;

  const double size = std::max(mesh.boundingRadius(), 1e-3);
  const bool planar = spatialDimension(geometry) == 2;
  const SectionBands bands = sectionBands(mesh, faceTemperature, 0.12 * size);
  render::MeshLayer body;
  if (planar) {
    body.vertices = bands.vertices;
    body.triangles = bands.triangles;
    body.triangleValues = bands.values;
  } else {
    body.vertices = mesh.vertices;
    body.triangles = mesh.triangles;
  }
  std::vector<double> perTriangle;
  if (!planar) {
    for (std::uint32_t p : mesh.patchOf) perTriangle.push_back(faceTemperature[p]);
    body.triangleValues = perTriangle;
  }
  // The faces on a scale of their own (on the rock's they were one colour: they span a few
  // hundred kelvin of the rock's thousands), with their own colour bar.
  body.scale = render::ColorScaleSpec{};
  body.scale.map = render::ColorMapName::Viridis;
  const auto [coolest, hottest] = std::minmax_element(faceTemperature.begin(), faceTemperature.end());
  body.scale.min = *coolest;
  body.scale.max = *hottest > *coolest ? *hottest : *coolest + 1.0;
  body.shaded = !planar;
  body.field = "faces, eq. 4.8";
  body.units = "K";
  body.colorBar = true;

  render::Picture scene;
  scene.meshes.push_back(body);
  scene.particles.push_back(hot);
  scene.annotations.title = title;
  scene.annotations.time = time;
  render::View view = particleView(geometry, "z");
  if (planar) {
    // Frame the crater point and the spacecraft, with room for the crater below the point.
    const radiation::Vec3 centre = mesh.boundingCenter();
    const radiation::Vec3& target = study.approach.target;
    const double gap = v3::norm(v3::sub(centre, target));
    const double width = std::max(20.0 * size, 2.5 * (gap + size));
    // Below the midpoint: the crater opens below the target point, the sky above the craft is
    // empty.
    const radiation::Vec3 down = v3::normalized(v3::sub(target, centre));
    view.center = std::array<double, 2>{0.5 * (centre[0] + target[0]) + 0.15 * width * down[0],
                                        0.5 * (centre[1] + target[1]) + 0.15 * width * down[1]};
    view.width = width;
  }
  render::writePng(out, renderer.render(scene, view).image);
}

}  // namespace ejecta::coupling
