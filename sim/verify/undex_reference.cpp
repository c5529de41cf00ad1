#include "sim/verify/undex_reference.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <utility>

#include "sim/eos/jwl.hpp"
#include "sim/solid/materials.hpp"
#include "sim/sources/gauges.hpp"
#include "sim/sources/programmed_burn.hpp"

namespace ejecta::verify {

namespace {

using Point = std::array<double, 3>;

// Rows of gauges_reference.csv at most (plus the last step).
constexpr double kCsvRows = 20000.0;

[[noreturn]] void refuse(const Scene& scene, int line, const std::string& key,
                         const std::string& reason) {
  throw SceneError(scene.sourcePath + (line > 0 ? ":" + std::to_string(line) : "") + ": key '" +
                   key + "': " + reason);
}

std::string bodyKey(const BodySpec& b, std::size_t index) {
  return "bodies[" + std::to_string(b.entry >= 0 ? static_cast<std::size_t>(b.entry) : index) + "]";
}

// Lengths are compared to this fraction of the charge radius (scene values are decimal).
constexpr double kTolerance = 1e-9;

// The scene reduced to one dimension.
struct RadialScene {
  int j = 3;
  Point centre{};  // the detonation point
  int side = 0;    // 1D: +1 / -1 the charge and medium lie on that side only; 0 both
  std::size_t charge = 0, medium = 0;  // body indices
  double chargeRadius = 0.0, extent = 0.0;
  double ambient = 0.0;  // the medium's initial pressure [Pa]
};

double distance(const Point& a, const Point& b, int dim) {
  double s = 0.0;
  for (int d = 0; d < dim; ++d) s += (a[d] - b[d]) * (a[d] - b[d]);
  return std::sqrt(s);
}

double initialEnergy(const Scene& scene, const MaterialTable& materials, std::size_t index) {
  const BodySpec& b = scene.bodies[index];
  if (b.internalEnergy) return *b.internalEnergy;
  const EquationOfState& eos = *materials[static_cast<std::size_t>(b.material)].eos;
  if (!b.pressure) {
    if (const auto* jwl = dynamic_cast<const Jwl*>(&eos))
      return jwl->params().specificDetonationEnergy();
    refuse(scene, b.line, bodyKey(b, index) + ".pressure", "give 'pressure' or 'internal_energy'");
  }
  return eos.specificEnergy(b.density, *b.pressure);
}

// Checks that the scene is a centred charge in one inert medium and measures it.
RadialScene radialScene(const Scene& scene, const MaterialTable& materials) {
  RadialScene s;
  const int dim = spatialDimension(scene.geometry);
  s.j = scene.geometry == Geometry::Line ? 1 : (scene.geometry == Geometry::Planar ? 2 : 3);
  if (scene.detonations.size() != 1)
    refuse(scene, scene.detonations.empty() ? 0 : scene.detonations[1].line, "detonations",
           "the 1D reference needs exactly one detonation (got " +
               std::to_string(scene.detonations.size()) + ")");
  const DetonationSpec& det = scene.detonations[0];
  if (det.alongLine)
    refuse(scene, det.line, "detonations[0].line_to",
           "the 1D reference lights the charge at a point");
  s.centre = det.point;
  if (scene.geometry == Geometry::Axisymmetric && std::abs(det.point[0]) > 0.0)
    refuse(scene, det.line, "detonations[0].point",
           "in RZ the charge's centre must be on the axis (r = 0)");
  if (!scene.deposits.empty())
    refuse(scene, scene.deposits[0].line, "deposits", "the 1D reference has no energy deposits");
  if (!scene.voids.empty())
    refuse(scene, scene.voids[0].line, "bodies", "the 1D reference takes no voids");
  if (scene.bodies.size() != 2)
    refuse(scene, 0, "bodies",
           "the 1D reference takes one explosive body and one inert body (got " +
               std::to_string(scene.bodies.size()) + " bodies)");
  s.charge = scene.bodies[0].material == det.material ? 0 : 1;
  s.medium = 1 - s.charge;
  const BodySpec& charge = scene.bodies[s.charge];
  const BodySpec& medium = scene.bodies[s.medium];
  const std::string chargeKey = bodyKey(charge, s.charge), mediumKey = bodyKey(medium, s.medium);
  if (charge.material != det.material)
    refuse(scene, det.line, "detonations[0].material", "no body is of the detonated material");
  if (medium.material == det.material)
    refuse(scene, medium.line, mediumKey + ".material",
           "the medium must not be the detonated material");
  for (const std::size_t b : {s.charge, s.medium})
    for (double v : scene.bodies[b].velocity)
      if (v != 0.0)
        refuse(scene, scene.bodies[b].line, bodyKey(scene.bodies[b], b) + ".velocity",
               "the 1D reference starts at rest");

  // The charge: a sphere (disc, segment) centred on the detonation point, or in 1D a slab lit at
  // its middle or at an end that lies on a wall.
  if (charge.shape.kind == ShapeKind::Sphere) {
    if (distance(charge.shape.center, s.centre, dim) > kTolerance * charge.shape.radius)
      refuse(scene, charge.line, chargeKey + ".center",
             "the charge must be centred on the detonation point");
    s.chargeRadius = charge.shape.radius;
  } else if (charge.shape.kind == ShapeKind::Box && dim == 1) {
    const double a = charge.shape.min[0], b = charge.shape.max[0], p = s.centre[0],
                 tol = kTolerance * (b - a);
    if (std::abs(p - 0.5 * (a + b)) < tol) {
      s.chargeRadius = 0.5 * (b - a);
    } else if (std::abs(p - a) < tol || std::abs(p - b) < tol) {
      s.side = std::abs(p - a) < tol ? 1 : -1;
      const AxisBounds& x = scene.domain[0];
      const bool wall =
          s.side > 0 ? x.bounded && x.lower == BoundaryKind::Wall && std::abs(x.min - p) < tol
                     : x.bounded && x.upper == BoundaryKind::Wall && std::abs(x.max - p) < tol;
      if (!wall)
        refuse(scene, det.line, "detonations[0].point",
               "a slab lit at an end needs a wall at that end");
      s.chargeRadius = b - a;
    } else {
      refuse(scene, det.line, "detonations[0].point",
             "the slab must be lit at its middle or at an end");
    }
  } else {
    refuse(scene, charge.line, chargeKey + ".shape",
           "the charge must be a sphere (a disc in 2D, a segment in 1D)");
  }

  // The medium: out to its nearest face that is not a symmetry plane through the centre.
  const double tol = kTolerance * s.chargeRadius;
  if (medium.shape.kind == ShapeKind::Sphere) {
    if (distance(medium.shape.center, s.centre, dim) > tol)
      refuse(scene, medium.line, mediumKey + ".center", "the medium must be centred on the charge");
    s.extent = medium.shape.radius;
  } else if (medium.shape.kind == ShapeKind::Box) {
    s.extent = INFINITY;
    for (int d = 0; d < dim; ++d) {
      const double lo = medium.shape.min[d] - s.centre[d], hi = medium.shape.max[d] - s.centre[d];
      if (s.side != 0) {  // a slab on one side: the medium from the charge's far end on
        const double nearFace = s.side > 0 ? lo : -hi, farFace = s.side > 0 ? hi : -lo;
        if (std::abs(nearFace - s.chargeRadius) > tol)
          refuse(scene, medium.line, mediumKey, "the medium must start at the charge's far end");
        s.extent = farFace;
        continue;
      }
      if (lo > tol || hi < -tol)
        refuse(scene, medium.line, mediumKey, "the medium must surround the charge's centre");
      for (const auto& [face, isLower] : {std::pair{lo, true}, std::pair{hi, false}}) {
        if (std::abs(face) > tol) {
          s.extent = std::min(s.extent, std::abs(face));
          continue;
        }
        // A face through the centre is a symmetry plane: the RZ axis or a mirror wall there.
        const AxisBounds& axis = scene.domain[static_cast<std::size_t>(d)];
        const bool rzAxis = scene.geometry == Geometry::Axisymmetric && d == 0;
        const bool wall = axis.bounded &&
                          (isLower ? axis.lower : axis.upper) == BoundaryKind::Wall &&
                          std::abs((isLower ? axis.min : axis.max) - s.centre[d]) < tol;
        if (!rzAxis && !wall)
          refuse(scene, medium.line, mediumKey,
                 "a face through the charge's centre must be a mirror wall ('domain')");
      }
    }
  } else {
    refuse(scene, medium.line, mediumKey + ".shape", "the medium must be a box or a sphere");
  }
  if (!(s.extent > s.chargeRadius * (1.0 + kTolerance)))
    refuse(scene, medium.line, mediumKey, "the medium must extend beyond the charge");
  const EquationOfState& eos = *materials[static_cast<std::size_t>(medium.material)].eos;
  s.ambient = eos.pressure(medium.density, initialEnergy(scene, materials, s.medium));
  return s;
}

}  // namespace

UndexReference buildUndexReference(const Scene& scene, int zones) {
  const MaterialTable materials = MaterialTable::fromScene(scene);
  const BurnTable burn = burnTable(scene.detonations, materials);
  const RadialScene rs = radialScene(scene, materials);
  if (zones < 4)
    throw std::invalid_argument("--zones: at least 4 (got " + std::to_string(zones) + ")");
  const int dim = spatialDimension(scene.geometry);

  UndexReference ref;
  ref.symmetry = rs.j;
  ref.centre = rs.centre;
  ref.side = rs.side;
  ref.chargeRadius = rs.chargeRadius;
  ref.extent = rs.extent;
  ref.ambient = rs.ambient;
  const BodySpec& charge = scene.bodies[rs.charge];
  const BodySpec& medium = scene.bodies[rs.medium];
  const auto cm = static_cast<std::size_t>(charge.material),
             mm = static_cast<std::size_t>(medium.material);
  if (const auto* jwl = dynamic_cast<const Jwl*>(materials[cm].eos.get()))
    ref.chargeDetonationEnergy = jwl->params().specificDetonationEnergy();
  for (const GaugeSpec& g : scene.gauges) {
    const double r = distance(g.position, rs.centre, dim);
    Point direction{};
    for (int d = 0; d < dim; ++d) direction[d] = r > 0.0 ? (g.position[d] - rs.centre[d]) / r : 0.0;
    ref.gaugeRadius.push_back(r);
    ref.gaugeDirection.push_back(direction);
  }

  exact::RadialSetup& setup = ref.setup;
  setup.geometry = rs.j;
  setup.zoneWidth = rs.extent / zones;
  setup.outerPressure = rs.ambient;
  exact::RadialBurn chargeBurn{burn.velocity[cm], burn.rho0[cm], burn.cjRelativeVolume[cm],
                               scene.detonations[0].time};
  setup.regions.push_back({materials[cm].name, rs.chargeRadius, materials[cm].eos, charge.density,
                           initialEnergy(scene, materials, rs.charge), 0.0, chargeBurn});
  setup.regions.push_back({materials[mm].name,
                           rs.extent,
                           materials[mm].eos,
                           medium.density,
                           initialEnergy(scene, materials, rs.medium),
                           0.0,
                           {}});
  return ref;
}

std::string undexReferenceGaugeCsv(const Scene& scene, const UndexReference& reference,
                                   const std::vector<exact::RadialGauge>& gauges) {
  // The hydrocode steps every few ns (its thinnest zones are the water stretched around the
  // growing bubble), so rows are kept at least t_end / 20000 apart (36 ns for 0.72 ms: a crest
  // rising over ~1 us is still sampled to ~0.1%).
  const GaugeLayout layout = gaugeLayout(scene);
  std::string csv = gaugeHeader(layout) + "\n";
  std::vector<GaugeReading> readings(gauges.size());
  const std::size_t rows = gauges.empty() ? 0 : gauges[0].time.size();
  const double rowInterval = scene.time.tEnd / kCsvRows;
  double lastRow = -INFINITY;
  for (std::size_t row = 0; row < rows; ++row) {
    const double t = gauges[0].time[row];
    if (t - lastRow < rowInterval && row + 1 < rows) continue;
    lastRow = t;
    for (std::size_t g = 0; g < gauges.size(); ++g) {
      const double v = gauges[g].velocity[row];
      const Point& direction = reference.gaugeDirection[g];
      readings[g] = {gauges[g].pressure[row],
                     gauges[g].density[row],
                     {v * direction[0], v * direction[1], v * direction[2]}};
    }
    char head[64];
    std::snprintf(head, sizeof head, "%zu,%.10g", row, t);
    csv += head + gaugeRow(layout, readings) + "\n";
  }
  return csv;
}

}  // namespace ejecta::verify
