// `ejecta undex-reference SCENE [--zones N] [--out DIR] [--set KEY=VALUE ...]`: the converged 1D
// reference of a centred charge in an inert medium (docs/undex.md, "The converged 1D reference").
// The scene's geometry maps to the 1D symmetry (RZ and 3D: a sphere; 2D planar: a cylinder; 1D:
// a slab), its explosive body to the inner region (radius, density, energy, programmed burn from
// the detonation point), its one inert body to the outer region (out to its nearest face that is
// not a symmetry plane), and its gauges to their distances from the charge's centre. The 1D
// Lagrangian hydrocode (sim/exact/radial_lagrangian.hpp) runs to the scene's t_end with the outer
// node free at the medium's initial pressure, writes DIR/gauges_reference.csv (the layout of the
// SPH run's gauges.csv; default DIR runs/<scene name>, beside it) and prints the medium's share
// of the yield, each gauge's pulse (sim/sources/gauge_decay.hpp) and, for a sphere, Cole's similitude
// values.
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "apps/commands.hpp"
#include "core/atomic_file.hpp"
#include "sim/eos/jwl.hpp"
#include "sim/exact/radial_lagrangian.hpp"
#include "sim/setup/scene.hpp"
#include "sim/solid/materials.hpp"
#include "sim/sources/gauge_decay.hpp"
#include "sim/sources/gauges.hpp"
#include "sim/sources/programmed_burn.hpp"

namespace fs = std::filesystem;

namespace ejecta::app {

namespace {

using Point = std::array<double, 3>;

[[noreturn]] void refuse(const Scene& scene, int line, const std::string& key,
                         const std::string& reason) {
  throw SceneError(scene.sourcePath + (line > 0 ? ":" + std::to_string(line) : "") + ": key '" +
                   key + "': " + reason);
}

std::string bodyKey(const BodySpec& b, std::size_t index) {
  return "bodies[" + std::to_string(b.entry >= 0 ? static_cast<std::size_t>(b.entry) : index) + "]";
}

// Rows of gauges_reference.csv at most (plus the last step).
constexpr double kCsvRows = 20000.0;

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

// Cole's similitude laws for TNT in SI (docs/undex.md: R. H. Cole, "Underwater Explosions", 1948,
// ch. 7, 21,600 psi and 58 us in lb and ft): peak [Pa] and theta [s], W in kg, R in m.
double colePeak(double w, double r) { return 52.39e6 * std::pow(std::cbrt(w) / r, 1.13); }
double coleTheta(double w, double r) {
  return 92.5e-6 * std::cbrt(w) * std::pow(std::cbrt(w) / r, -0.22);
}

}  // namespace

int undexReferenceCommand(const UndexReferenceArgs& args) {
  const Scene scene = loadScene(args.scene, args.overrides);
  const MaterialTable materials = MaterialTable::fromScene(scene);
  const BurnTable burn = burnTable(scene.detonations, materials);
  const RadialScene rs = radialScene(scene, materials);
  if (args.zones < 4)
    throw std::invalid_argument("--zones: at least 4 (got " + std::to_string(args.zones) + ")");
  const int dim = spatialDimension(scene.geometry);

  const BodySpec& charge = scene.bodies[rs.charge];
  const BodySpec& medium = scene.bodies[rs.medium];
  const auto cm = static_cast<std::size_t>(charge.material),
             mm = static_cast<std::size_t>(medium.material);
  exact::RadialSetup setup;
  setup.geometry = rs.j;
  setup.zoneWidth = rs.extent / args.zones;
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
  exact::RadialLagrangian run(setup);
  std::vector<double> radius;
  for (const GaugeSpec& g : scene.gauges) {
    radius.push_back(distance(g.position, rs.centre, dim));
    run.addGauge(g.name, radius.back());
  }
  const char* symmetry[] = {"", "planar", "cylindrical", "spherical"};
  const double chargeMass = run.regionMass(0);
  const char* perUnit[] = {"", " per m^2", " per m", ""};
  std::printf(
      "ejecta undex-reference: %s (%s): %s 1D Lagrangian reference, %zu zones of %.4g mm to %.4g "
      "m, "
      "charge %.4g m (%.4g kg%s), t_end %.4g ms\n",
      scene.name.c_str(), args.scene.c_str(), symmetry[rs.j], run.zoneCount(),
      setup.zoneWidth * 1e3, rs.extent, rs.chargeRadius, chargeMass, perUnit[rs.j],
      scene.time.tEnd * 1e3);
  std::fflush(stdout);
  const double energy0 = run.totalEnergy();
  const double mediumEnergy0 = run.regionInternalEnergy(1) + run.regionKineticEnergy(1);
  const auto start = std::chrono::steady_clock::now();
  run.advanceTo(scene.time.tEnd);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf(
      "  %ld steps in %.2f s wall (one core); energy error %.2g (with the outer pressure's work)\n",
      run.steps(), wall, (run.totalEnergy() - run.boundaryWork() - energy0) / energy0);
  // The charge's yield is its chemical energy, e0 x mass, as the energy ledger of `ejecta run`
  // counts it; the medium's share is what it gained (the outer pressure's work counted in).
  if (const auto* jwl = dynamic_cast<const Jwl*>(materials[cm].eos.get())) {
    const double yield = chargeMass * jwl->params().specificDetonationEnergy();
    const double gained = run.regionInternalEnergy(1) + run.regionKineticEnergy(1) - mediumEnergy0 -
                          run.boundaryWork();
    std::printf("  at t_end the %s holds %.1f%% of the charge's yield (%.4g J%s): %.1f%% kinetic\n",
                materials[mm].name.c_str(), 100.0 * gained / yield, yield, perUnit[rs.j],
                100.0 * run.regionKineticEnergy(1) / yield);
  }

  // gauges_reference.csv: the layout of the SPH run's gauges.csv, the velocity along each gauge's
  // direction from the centre. The hydrocode steps every few ns (its thinnest zones are the water
  // stretched around the growing bubble), so rows are kept at least t_end / 20000 apart (36 ns
  // for 0.72 ms: a crest rising over ~1 us is still sampled to ~0.1%); the printed pulses below
  // are measured on every step.
  std::string csv = gaugeHeader(gaugeLayout(scene)) + "\n";
  const std::vector<exact::RadialGauge>& gauges = run.gauges();
  std::vector<Point> direction(gauges.size());
  for (std::size_t g = 0; g < gauges.size(); ++g)
    for (int d = 0; d < dim; ++d)
      direction[g][d] =
          radius[g] > 0.0 ? (scene.gauges[g].position[d] - rs.centre[d]) / radius[g] : 0.0;
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
      readings[g] = {gauges[g].pressure[row],
                     gauges[g].density[row],
                     {v * direction[g][0], v * direction[g][1], v * direction[g][2]}};
    }
    char head[64];
    std::snprintf(head, sizeof head, "%zu,%.10g", row, t);
    csv += head + gaugeRow(gaugeLayout(scene), readings) + "\n";
  }
  const fs::path out = args.outDir.empty() ? fs::path("runs") / scene.name : fs::path(args.outDir);
  fs::create_directories(out);
  writeFileAtomically(out / "gauges_reference.csv", csv);

  const bool cole = rs.j == 3;
  std::printf("  %-10s %8s %11s %13s %11s %11s", "gauge", "R [m]", "peak [MPa]", "arrival [ms]",
              "θ 1/e [µs]", "θ fit [µs]");
  if (cole) std::printf(" %16s %6s %14s %6s", "Cole peak [MPa]", "ratio", "Cole θ [µs]", "ratio");
  std::printf("\n");
  for (std::size_t g = 0; g < gauges.size(); ++g) {
    std::printf("  %-10s %8.4g", gauges[g].name.c_str(), radius[g]);
    try {
      const ShockPulse pulse = measureShockPulse(gauges[g].time, gauges[g].pressure, rs.ambient);
      std::printf(" %11.4g %13.5g %11.4g %11.4g", pulse.peakPressure * 1e-6, pulse.arrival * 1e3,
                  pulse.eFoldTime * 1e6, pulse.fitTime * 1e6);
      if (cole) {
        const double p = colePeak(chargeMass, radius[g]), t = coleTheta(chargeMass, radius[g]);
        std::printf(" %16.4g %6.3f %14.4g %6.3f", p * 1e-6, pulse.peakPressure / p, t * 1e6,
                    pulse.eFoldTime / t);
      }
    } catch (const std::invalid_argument&) {
      std::printf(" %11s", "no pulse");
    }
    std::printf("\n");
  }
  if (cole)
    std::printf(
        "  Cole: 52.4 (W^(1/3)/R)^1.13 MPa, θ = 92.5 W^(1/3) (W^(1/3)/R)^(-0.22) µs "
        "(docs/undex.md); "
        "it applies beyond about 12 charge radii\n");
  std::printf("wrote %s\n", (out / "gauges_reference.csv").string().c_str());
  return 0;
}

}  // namespace ejecta::app
