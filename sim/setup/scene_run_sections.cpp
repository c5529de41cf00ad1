// The scene's [scene], [domain], [sph], [time] and [output] tables.
#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <string>

#include "sim/setup/scene_sections.hpp"

namespace ejecta::scene_detail {

namespace {

const EnumNames<BoundaryKind> kBoundaryNames{{"open", BoundaryKind::Open},
                                             {"periodic", BoundaryKind::Periodic},
                                             {"wall", BoundaryKind::Wall}};

}  // namespace

void readScene(const TableReader& root, Scene& scene) {
  const toml::table* t = root.optTable("scene");
  if (!t) root.fail("scene", "required table [scene] is missing");
  const TableReader r(root.context(), *t, "scene", "scene");
  scene.name = r.requireString("name");
  r.check(!scene.name.empty(), "name", "must not be empty");
  scene.description = r.optString("description").value_or("");
  const std::string dim = r.requireString("dimension");
  if (!parseGeometry(dim, scene.geometry))
    r.fail("dimension", "unknown value '" + dim + "'; allowed: '1d', '2d', 'rz', '3d'");
}

namespace {

void readAxis(const TableReader& domain, int axis, Geometry geometry, AxisBounds& out) {
  static constexpr std::string_view kAxisNames[3] = {"x", "y", "z"};
  const std::string_view name = kAxisNames[axis];
  const toml::table* t = domain.optTable(name);
  if (!t) return;  // unbounded and open
  const int dim = spatialDimension(geometry);
  if (axis >= dim)
    domain.fail(name, "axis not used in a " + std::string(geometryName(geometry)) +
                          " scene (allowed: " + (dim == 1 ? "x" : "x, y") + ")");
  const bool rAxis = (geometry == Geometry::Axisymmetric && axis == 0);
  const TableReader r(domain.context(), *t, domain.key(name), "domain." + std::string(name));

  out.min = r.requireQuantity("min", Dimension::Length);
  out.max = r.requireQuantity("max", Dimension::Length);
  r.check(out.min < out.max, "max",
          "max must exceed min (got min " + formatQuantity(out.min, Dimension::Length) + ", max " +
              formatQuantity(out.max, Dimension::Length) + ")");
  if (r.has("boundary") && (r.has("lower") || r.has("upper")))
    r.fail("boundary", "give either 'boundary' or 'lower'/'upper', not both");

  if (rAxis) {
    r.check(out.min == 0.0, "min", "must be 0 in an rz scene (r starts at the axis)");
    if (const auto lower = r.optString("lower"))
      r.check(*lower == "axis", "lower",
              "the lower r boundary is the axis; write 'axis' or omit it");
    const std::string_view side = r.has("boundary") ? "boundary" : "upper";
    out.upper = r.optEnum(side, kBoundaryNames).value_or(BoundaryKind::Open);
    r.check(out.upper != BoundaryKind::Periodic, side, "r cannot be periodic (r = 0 is the axis)");
    out.lower = BoundaryKind::Wall;  // the axis: mirror images, as at a wall
  } else {
    const auto both = r.optEnum("boundary", kBoundaryNames);
    out.lower = both ? *both : r.optEnum("lower", kBoundaryNames).value_or(BoundaryKind::Open);
    out.upper = both ? *both : r.optEnum("upper", kBoundaryNames).value_or(BoundaryKind::Open);
    if ((out.lower == BoundaryKind::Periodic) != (out.upper == BoundaryKind::Periodic))
      r.fail(r.has("upper") ? "upper" : "lower", "periodic must be on both sides");
  }
  out.bounded = true;
}

}  // namespace

void readDomain(const TableReader& root, Scene& scene) {
  const toml::table* t = root.optTable("domain");
  if (!t) return;
  const TableReader r(root.context(), *t, "domain", "domain");
  for (int axis = 0; axis < 3; ++axis) readAxis(r, axis, scene.geometry, scene.domain[axis]);
}

void readSph(const TableReader& root, SphOptions& sph) {
  const toml::table* t = root.optTable("sph");
  if (!t) return;
  const TableReader r(root.context(), *t, "sph", "sph");
  const Dimension one = Dimension::None;
  sph.kernel = r.optEnum<KernelKind>("kernel", {{"cubic_spline", KernelKind::CubicSpline},
                                                {"wendland_c2", KernelKind::WendlandC2},
                                                {"wendland_c4", KernelKind::WendlandC4}})
                   .value_or(sph.kernel);
  sph.density = r.optEnum<DensityMethod>("density", {{"summation", DensityMethod::Summation},
                                                     {"continuity", DensityMethod::Continuity}})
                    .value_or(sph.density);
  sph.smoothingLength = r.optEnum<SmoothingLengthMethod>(
                             "smoothing_length", {{"neighbours", SmoothingLengthMethod::Neighbours},
                                                  {"seed", SmoothingLengthMethod::Seed},
                                                  {"constant", SmoothingLengthMethod::Constant}})
                            .value_or(sph.smoothingLength);
  sph.eta = r.optQuantity("eta", one).value_or(sph.eta);
  // h = eta x spacing. Price (2012, J. Comput. Phys. 231, 759) recommends 1.2 for the cubic
  // spline; the wider Wendland kernels take up to ~2 (the shipped scenes use 1.2-2.0). Beyond
  // 0.5-3 the neighbour count (~ (2 eta)^d) is below a stencil or in the thousands: a typo.
  r.check(sph.eta >= 0.5 && sph.eta <= 3.0, "eta",
          "is " + formatQuantity(sph.eta, one) + "; must be between 0.5 and 3 (h = eta x spacing; "
          "1.2-2 is the kernels' range)");
  sph.relaxation = r.optQuantity("relaxation", one).value_or(sph.relaxation);
  r.check(sph.relaxation > 0.0 && sph.relaxation <= 1.0, "relaxation", "must be in (0, 1]");
  sph.courant = r.optQuantity("courant", one).value_or(sph.courant);
  r.check(sph.courant > 0.0 && sph.courant <= 1.0, "courant", "must be in (0, 1]");
  sph.forceFactor = r.optQuantity("force_factor", one).value_or(sph.forceFactor);
  r.check(sph.forceFactor > 0.0, "force_factor", positiveMessage(sph.forceFactor, one));
  sph.hMinFactor = r.optQuantity("h_min_factor", one).value_or(sph.hMinFactor);
  r.check(sph.hMinFactor >= 0.0 && sph.hMinFactor < 1.0, "h_min_factor", "must be in [0, 1)");
  sph.hMaxFactor = r.optQuantity("h_max_factor", one).value_or(sph.hMaxFactor);
  // Below 1 the cap would cut the initial h itself; beyond ~30 the neighbour check stops the run
  // before the cap is reached (30 x the kernel's expected neighbours).
  r.check(sph.hMaxFactor == 0.0 || (sph.hMaxFactor >= 1.0 && sph.hMaxFactor <= 30.0),
          "h_max_factor",
          "is " + formatQuantity(sph.hMaxFactor, one) + "; must be 0 (no cap) or in [1, 30]");

  if (const toml::table* vt = r.optTable("viscosity")) {
    const TableReader v(root.context(), *vt, "sph.viscosity", "sph.viscosity");
    sph.alpha = v.optQuantity("alpha", one).value_or(sph.alpha);
    v.check(sph.alpha >= 0.0, "alpha", nonNegativeMessage(sph.alpha, one));
    sph.beta = v.optQuantity("beta", one).value_or(sph.beta);
    v.check(sph.beta >= 0.0, "beta", nonNegativeMessage(sph.beta, one));
    sph.epsilon = v.optQuantity("epsilon", one).value_or(sph.epsilon);
    v.check(sph.epsilon > 0.0, "epsilon",
            positiveMessage(sph.epsilon, one) + "; it keeps the viscosity finite as r -> 0");
    sph.balsara = v.optBool("balsara").value_or(sph.balsara);
    sph.viscositySwitch = v.optEnum<ViscositySwitch>(
                               "switch", {{"none", ViscositySwitch::None},
                                          {"morris_monaghan", ViscositySwitch::MorrisMonaghan}})
                              .value_or(sph.viscositySwitch);
    sph.alphaMin = v.optQuantity("alpha_min", one).value_or(sph.alphaMin);
    v.check(sph.alphaMin >= 0.0, "alpha_min", nonNegativeMessage(sph.alphaMin, one));
    v.check(sph.viscositySwitch == ViscositySwitch::None || sph.alphaMin <= sph.alpha,
            "alpha_min", "must not exceed alpha (the switch keeps alpha_i between them)");
    sph.alphaDecay = v.optQuantity("decay", one).value_or(sph.alphaDecay);
    v.check(sph.alphaDecay > 0.0, "decay",
            positiveMessage(sph.alphaDecay, one) + "; alpha decays over h / (decay c)");
    sph.viscosityReconstruction =
        v.optEnum<ViscosityReconstruction>(
             "reconstruction", {{"none", ViscosityReconstruction::None},
                                {"van_leer", ViscosityReconstruction::VanLeer},
                                {"monotone", ViscosityReconstruction::Monotone}})
            .value_or(sph.viscosityReconstruction);
  }
  if (const toml::table* ct = r.optTable("conductivity")) {
    const TableReader c(root.context(), *ct, "sph.conductivity", "sph.conductivity");
    sph.conductivity = c.optQuantity("alpha", one).value_or(sph.conductivity);
    c.check(sph.conductivity >= 0.0, "alpha", nonNegativeMessage(sph.conductivity, one));
  }
  sph.form = r.optEnum<MomentumForm>("form", {{"lagrangian", MomentumForm::Lagrangian},
                                              {"interface", MomentumForm::Interface}})
                 .value_or(sph.form);
  sph.gradients = r.optEnum<GradientScheme>("gradients", {{"kernel", GradientScheme::Kernel},
                                                         {"iad", GradientScheme::IntegralApproach}})
                      .value_or(sph.gradients);
  if (sph.gradients == GradientScheme::IntegralApproach) {
    r.check(sph.form == MomentumForm::Lagrangian, "gradients",
            "\"iad\" takes the Lagrangian form (form = \"interface\" is not built for it)");
    r.check(sph.density == DensityMethod::Summation, "gradients",
            "\"iad\" takes summation density (continuity density's rate is not built for it)");
  }
  sph.volumeElements = r.optEnum<VolumeElements>("volume_elements",
                                                  {{"mass", VolumeElements::Mass},
                                                   {"generalised", VolumeElements::Generalised}})
                           .value_or(sph.volumeElements);
  sph.volumeExponent = r.optQuantity("volume_exponent", one).value_or(sph.volumeExponent);
  r.check(sph.volumeExponent >= 0.0 && sph.volumeExponent <= 1.0, "volume_exponent",
          "p of X = (m/rho)^p must lie in [0, 1] (0: X = 1, volumes 1/sum W; 1: the previous "
          "step's own volumes), got " + formatQuantity(sph.volumeExponent, one));
  if (sph.volumeElements == VolumeElements::Generalised) {
    r.check(sph.form == MomentumForm::Lagrangian, "volume_elements",
            "\"generalised\" takes the Lagrangian form (form = \"interface\" is not built for it)");
    r.check(sph.density == DensityMethod::Summation, "volume_elements",
            "\"generalised\" takes summation density (its volumes are kernel sums)");
    r.check(sph.gradients == GradientScheme::Kernel, "volume_elements",
            "\"generalised\" takes the kernel gradient: with gradients = \"iad\" it ran away "
            "(a particle at 1e12 m/s in a periodic 2D blast, docs/verification.md)");
  }
  sph.dissipation = r.optEnum<Dissipation>("dissipation", {{"viscosity", Dissipation::Viscosity},
                                                           {"riemann", Dissipation::Riemann}})
                        .value_or(sph.dissipation);
  if (sph.dissipation == Dissipation::Riemann) {
    const std::string why = "\"riemann\" (Godunov SPH) is built ";
    r.check(sph.form == MomentumForm::Lagrangian, "dissipation",
            why + "for the Lagrangian form (form = \"interface\" is not)");
    r.check(sph.density == DensityMethod::Summation, "dissipation",
            why + "with summation density (continuity density's rate is not)");
    r.check(sph.gradients == GradientScheme::Kernel, "dissipation",
            why + "with the kernel gradient (gradients = \"iad\" is not)");
    r.check(sph.volumeElements == VolumeElements::Mass, "dissipation",
            why + "with mass volumes (volume_elements = \"generalised\" is not)");
    // The pair's velocities are reconstructed to its midpoint as the viscosity's would be
    // (second order where the flow is smooth); "none" in [sph.viscosity] keeps the first order.
    // With individual steps too: the inactive partners' gradients are re-evaluated at each
    // sub-step (sim/sph/velocity_gradient_refresh.hpp; docs/time_steps.md).
    const toml::table* vt = r.optTable("viscosity");
    if (!vt || !vt->contains("reconstruction"))
      sph.viscosityReconstruction = ViscosityReconstruction::Monotone;
  }
  if (const toml::table* at = r.optTable("artificial_stress")) {
    const TableReader a(root.context(), *at, "sph.artificial_stress", "sph.artificial_stress");
    sph.artificialStress = a.optQuantity("epsilon", one).value_or(sph.artificialStress);
    a.check(sph.artificialStress >= 0.0, "epsilon",
            nonNegativeMessage(sph.artificialStress, one) + " (0 switches it off)");
    sph.artificialStressExponent = a.optQuantity("n", one).value_or(sph.artificialStressExponent);
    a.check(sph.artificialStressExponent > 0.0, "n",
            positiveMessage(sph.artificialStressExponent, one));
  }
}

void readTime(const TableReader& root, TimeOptions& time) {
  const toml::table* t = root.optTable("time");
  if (!t) root.fail("time", "required table [time] is missing (it must give t_end)");
  const TableReader r(root.context(), *t, "time", "time");
  const Dimension s = Dimension::Time;
  time.tEnd = r.requireQuantity("t_end");  // dimensions from the schema
  r.check(time.tEnd > 0.0, "t_end", positiveMessage(time.tEnd, s));
  time.dtMax = r.optQuantity("dt_max").value_or(time.dtMax);
  r.check(time.dtMax >= 0.0, "dt_max", nonNegativeMessage(time.dtMax, s) + "; 0 = unlimited");
  time.dtMin = r.optQuantity("dt_min").value_or(time.dtMin);
  r.check(time.dtMin >= 0.0, "dt_min", nonNegativeMessage(time.dtMin, s));
  if (time.dtMax > 0.0) r.check(time.dtMin < time.dtMax, "dt_min", "must be below dt_max");
  time.maxSteps = r.optInteger("max_steps").value_or(time.maxSteps);
  r.check(time.maxSteps >= 0, "max_steps", "must not be negative; 0 = unlimited");
  time.stepping = r.optEnum<Stepping>("stepping", {{"global", Stepping::Global},
                                                    {"individual", Stepping::Individual}})
                      .value_or(time.stepping);
  if (const auto factor = r.optInteger("limiter_factor")) {
    const long f = *factor;
    r.check(f == 0 || (f >= 2 && f <= 1024 && (f & (f - 1)) == 0), "limiter_factor",
            "must be a power of two from 2 to 1024, or 0 (no limiter), not " + std::to_string(f));
    time.limiterFactor = static_cast<int>(f);
  }
  time.closingSpeed = r.optBool("closing_speed").value_or(time.closingSpeed);
}

// The most snapshots a run may ask for: 100,000 (at 1e6 particles, ~100 MB each, 10 TB).
constexpr double kMaxSnapshots = 1e5;

void readOutput(const TableReader& root, OutputOptions& out, double tEnd) {
  const toml::table* t = root.optTable("output");
  if (!t) return;
  const TableReader r(root.context(), *t, "output", "output");
  out.snapshotInterval = r.optQuantity("snapshot_interval").value_or(0.0);
  r.check(out.snapshotInterval >= 0.0, "snapshot_interval",
          nonNegativeMessage(out.snapshotInterval, Dimension::Time) + "; 0 = first and last only");
  // Every step is cut to end on an output time: an interval far below the run's length would
  // write a snapshot per step (and steps of the interval's size) without ever tripping dt_min.
  if (out.snapshotInterval > 0.0)
    r.check(tEnd / out.snapshotInterval <= kMaxSnapshots, "snapshot_interval",
            "is " + formatQuantity(out.snapshotInterval, Dimension::Time) + ", which makes " +
                formatQuantity(tEnd / out.snapshotInterval, Dimension::None) + " snapshots to t_end = " +
                formatQuantity(tEnd, Dimension::Time) + "; at most 100000 (an interval of at least " +
                formatQuantity(tEnd / kMaxSnapshots, Dimension::Time) + ")");
  out.snapshots = r.optBool("snapshots").value_or(out.snapshots);
}


namespace {

// Why a fluid-only [sph] option refuses each case (nullptr: the option is built for it).
struct FluidOnlyReasons {
  const char* rz;      // RZ
  const char* steps;   // individual time steps
  const char* solids;  // a material with strength or fracture
};

// The refusals the fluid-only options of [sph] share, for the option `key` set to `value`.
void checkFluidOnlyOption(const TableReader& root, const Scene& scene, const std::string& key,
                          const std::string& value, const FluidOnlyReasons& why) {
  const TableReader sph(root.context(), *root.optTable("sph"), "sph", "sph");
  const std::string quoted = "\"" + value + "\"";
  if (why.rz)
    sph.check(scene.geometry != Geometry::Axisymmetric, key,
              quoted + " is built for 1D, 2D and 3D, not RZ (" + why.rz + ")");
  if (why.steps)
    sph.check(scene.time.stepping == Stepping::Global, key,
              quoted + " runs with global time steps (time.stepping = \"global\"): " + why.steps);
  for (const MaterialSpec& m : scene.materials)
    sph.check(!m.strength.present && !m.fracture.present, key,
              quoted + " is built for fluids; material '" + m.name +
                  "' has strength or fracture (" + why.solids + ")");
}

}  // namespace

void checkVolumeElements(const TableReader& root, const Scene& scene) {
  if (scene.sph.volumeElements != VolumeElements::Generalised) return;
  checkFluidOnlyOption(root, scene, "volume_elements", "generalised",
                       {"the ring masses' form is not",
                        "the weights of particles between their steps are not kept",
                        "the stress divergence keeps the mass volumes"});
}

void checkGradientScheme(const TableReader& root, const Scene& scene) {
  if (scene.sph.gradients != GradientScheme::IntegralApproach) return;
  checkFluidOnlyOption(root, scene, "gradients", "iad",
                       {"its ring-weighted matrices are not",
                        "the matrices of particles between their steps are not kept",
                        "the stress divergence keeps the kernel gradient"});
}

void checkDissipation(const TableReader& root, const Scene& scene) {
  if (scene.sph.dissipation != Dissipation::Riemann) return;
  checkFluidOnlyOption(root, scene, "dissipation", "riemann",
                       {nullptr, nullptr,
                        "the stress divergence keeps the artificial viscosity; a solid's Riemann "
                        "problem is not built"});
}

}  // namespace ejecta::scene_detail
