// Verification problems of solid mechanics: elastic and elastic-plastic waves in 1D, colliding
// rubber rings (tensile instability) in 2D, and the Taylor bar in RZ.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "sim/solid/materials.hpp"
#include "sim/eos/mie_gruneisen.hpp"
#include "sim/verify/runner.hpp"

namespace ejecta::verify::detail {

namespace {

// Bulk sound speed C0 and density of a Mie-Grueneisen material of the scene (library entry or
// its parameters).
struct ElasticConstants {
  double rho0, c0, G;
  double longitudinalSpeed() const { return std::sqrt(c0 * c0 + 4.0 * G / (3.0 * rho0)); }
  double bulkModulus() const { return rho0 * c0 * c0; }
};

ElasticConstants elasticConstants(const Scene& scene) {
  const MaterialSpec& m = scene.materials.at(0);
  ElasticConstants e{};
  if (!m.library.empty()) {
    const ShockMaterial& s = shockMaterial(m.library);
    e.rho0 = s.rho0;
    e.c0 = s.c0;
  }
  for (const auto& [k, v] : m.parameters) {
    if (k == "rho0") e.rho0 = v;
    if (k == "c0") e.c0 = v;
  }
  e.G = *m.strength.find("shear_modulus");
  return e;
}

// Mean of sigma_xx = -P + S_xx and of v over the target particles in [x0, x1].
void meanState(const ParticleSet& p, double x0, double x1, double& sigma, double& v) {
  double s = 0.0, vs = 0.0;
  int n = 0;
  for (std::size_t i = 0; i < p.numReal; ++i)
    if (p.x[0][i] > x0 && p.x[0][i] < x1) {
      s += -p.P[i] + p.stress[0][i];
      vs += p.v[0][i];
      ++n;
    }
  if (n == 0) throw std::runtime_error("no particles in the sampled interval");
  sigma = s / n;
  v = vs / n;
}

Report elasticWave(const Options& options) {
  const std::string name = "elastic_wave_1d";
  const Scene scene = problemScene(name, options);
  const ElasticConstants e = elasticConstants(scene);
  const double cL = e.longitudinalSpeed();
  const double up = 0.5 * scene.bodies[0].velocity[0];
  const double tFirst = 0.5 * scene.time.tEnd;
  double xFirst = 0.0, tAtFirst = 0.0;
  Finished f = runAt(scene, 1.0, options, [&](const Simulation& sim) {
    if (tAtFirst == 0.0 && sim.time() >= tFirst) {
      tAtFirst = sim.time();
      xFirst = waveFront(sim.particles(), 0.5 * up);
    }
  });
  const double xFront = waveFront(f.particles, 0.5 * up);
  const double speed = (xFront - xFirst) / (f.time - tAtFirst);
  double sigma, v;
  meanState(f.particles, 0.25 * xFront, 0.75 * xFront, sigma, v);
  const double sigmaExact = -e.rho0 * cL * up;
  f.run.metrics = {
      {"wave_speed", speed, "m/s"},
      {"wave_speed_exact", cL, "m/s"},
      {"wave_speed_error", (speed - cL) / cL, "1"},
      {"particle_velocity", v, "m/s"},
      {"stress", sigma, "Pa"},
      {"stress_error", (sigma - sigmaExact) / sigmaExact, "1"},
  };
  return singleRunReport(name, scene,
                         "c_L = sqrt((K + 4G/3)/rho), sigma = -rho c_L u_p (linear elasticity)",
                         std::move(f.run));
}

Report elasticPlastic(const Options& options) {
  const std::string name = "elastic_plastic_1d";
  const Scene scene = problemScene(name, options);
  const ElasticConstants e = elasticConstants(scene);
  const double Y = *scene.materials[0].strength.find("yield_stress");
  const double cL = e.longitudinalSpeed();
  // HEL with the material's own (nonlinear) pressure: yield is reached at the logarithmic
  // strain Y/(2G) (S_xx = (4G/3) eps = 2Y/3), i.e. at rho0 exp(Y/(2G)), with the small elastic
  // work e = sigma eps / (2 rho0) in the energy. The linear estimate (K + 4G/3) Y/(2G) is
  // ~1% lower for Al-2024.
  const double epsYield = Y / (2.0 * e.G);
  const MieGruneisen eos(shockMaterial(scene.materials[0].library));
  double hel = (e.bulkModulus() + 4.0 * e.G / 3.0) * Y / (2.0 * e.G);
  for (int it = 0; it < 5; ++it)
    hel = eos.pressure(e.rho0 * std::exp(epsYield), 0.5 * hel * epsYield / e.rho0) + 2.0 * Y / 3.0;
  const double upHel = hel / (e.rho0 * cL);
  const double tFirst = 0.5 * scene.time.tEnd;
  double xFirst = 0.0, tAtFirst = 0.0;
  Finished f = runAt(scene, 1.0, options, [&](const Simulation& sim) {
    if (tAtFirst == 0.0 && sim.time() >= tFirst) {
      tAtFirst = sim.time();
      xFirst = waveFront(sim.particles(), 0.5 * upHel);
    }
  });
  const ParticleSet& p = f.particles;
  const double xPrecursor = waveFront(p, 0.5 * upHel);
  const double speed = (xPrecursor - xFirst) / (f.time - tAtFirst);
  // The plastic wave front: where v crosses halfway between the precursor and the final state.
  const double upFinal = 0.5 * scene.bodies[0].velocity[0];
  const double xPlastic = waveFront(p, 0.5 * (upHel + upFinal));
  // Precursor plateau: between the two fronts, away from both smeared edges.
  double sigmaHel, vHel;
  const double gap = xPrecursor - xPlastic;
  meanState(p, xPlastic + 0.3 * gap, xPrecursor - 0.3 * gap, sigmaHel, vHel);
  // Deviatoric stress behind the plastic wave, on the yield surface.
  double sxx = 0.0;
  int n = 0;
  for (std::size_t i = 0; i < p.numReal; ++i)
    if (p.x[0][i] > 0.25 * xPlastic && p.x[0][i] < 0.75 * xPlastic) {
      sxx += p.stress[0][i];
      ++n;
    }
  sxx /= std::max(n, 1);
  f.run.metrics = {
      {"precursor_speed", speed, "m/s"},
      {"precursor_speed_error", (speed - cL) / cL, "1"},
      {"hel", -sigmaHel, "Pa"},
      {"hel_exact", hel, "Pa"},
      {"hel_error", (-sigmaHel - hel) / hel, "1"},
      {"deviatoric_stress_error", (sxx + 2.0 * Y / 3.0) / (2.0 * Y / 3.0), "1"},
  };
  return singleRunReport(name, scene,
                         "sigma_HEL = (K + 4G/3) Y/(2G); precursor at c_L; S_xx = -2Y/3 behind",
                         std::move(f.run));
}

// Number of particles in the largest group of a body connected by gaps below `link`.
std::size_t largestCluster(const ParticleSet& p, const std::vector<std::size_t>& members,
                           double link) {
  const std::size_t n = members.size();
  std::vector<std::size_t> parent(n);
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  auto find = [&](std::size_t a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  };
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b) {
      const std::size_t i = members[a], j = members[b];
      const double dx = p.x[0][i] - p.x[0][j], dy = p.x[1][i] - p.x[1][j];
      if (dx * dx + dy * dy < link * link) parent[find(a)] = find(b);
    }
  std::vector<std::size_t> size(n, 0);
  for (std::size_t a = 0; a < n; ++a) ++size[find(a)];
  return *std::max_element(size.begin(), size.end());
}

Report rubberRings(const Options& options) {
  const std::string name = "rubber_rings";
  const Scene scene = problemScene(name, options);
  const double v0 = scene.bodies[0].velocity[0];
  Finished f = runAt(scene, 1.0, options);
  const ParticleSet& p = f.particles;
  std::vector<std::size_t> left, right;
  double momentumLeft = 0.0, massLeft = 0.0;
  // Ids follow the bodies: the first ring's particles come first, and the rings are mirror
  // images, so each holds half of them.
  const std::size_t perRing = p.numReal / 2;
  for (std::size_t i = 0; i < p.numReal; ++i) {
    if (static_cast<std::size_t>(p.id[i]) < perRing) {
      left.push_back(i);
      momentumLeft += p.mass[i] * p.v[0][i];
      massLeft += p.mass[i];
    } else {
      right.push_back(i);
    }
  }
  const double spacing = scene.bodies[0].spacing;
  const double link = 2.0 * spacing;  // a crack opens gaps wider than two spacings
  const double intactLeft = static_cast<double>(largestCluster(p, left, link)) / left.size();
  const double intactRight = static_cast<double>(largestCluster(p, right, link)) / right.size();
  f.run.metrics = {
      {"rebound_velocity_ratio", -(momentumLeft / massLeft) / v0, "1"},
      {"intact_fraction_left", intactLeft, "1"},
      {"intact_fraction_right", intactRight, "1"},
  };
  return singleRunReport(name, scene,
                         "Gray, Monaghan & Swift (2001): elastic rings bounce apart without fracture",
                         std::move(f.run));
}

Report taylorBar(const Options& options) {
  const std::string name = "taylor_bar";
  const Scene scene = problemScene(name, options);
  Finished f = runAt(scene, 1.0, options);
  const ParticleSet& p = f.particles;
  const double s = f.run.spacing;
  // Particles are the centres of cells of size s: the surface lies s/2 beyond the outermost.
  double zMax = 0.0, rFoot = 0.0, epsMax = 0.0;
  for (std::size_t i = 0; i < p.numReal; ++i) {
    zMax = std::max(zMax, p.x[1][i]);
    if (p.x[1][i] < s) rFoot = std::max(rFoot, p.x[0][i]);
    epsMax = std::max(epsMax, p.plasticStrain[i]);
  }
  const double length = zMax + 0.5 * s, diameter = 2.0 * (rFoot + 0.5 * s);
  // DynELA v4 documentation, Samples-Impacts (DynELA / Abaqus, axisymmetric): the mean of the two.
  const double lengthRef = 0.5 * (26.52e-3 + 26.56e-3), diameterRef = 0.5 * (11.15e-3 + 11.16e-3);
  f.run.metrics = {
      {"final_length", length, "m"},
      {"final_length_error", (length - lengthRef) / lengthRef, "1"},
      {"footprint_diameter", diameter, "m"},
      {"footprint_diameter_error", (diameter - diameterRef) / diameterRef, "1"},
      {"max_plastic_strain", epsMax, "1"},
  };
  return singleRunReport(name, scene,
                         "DynELA v4 / Abaqus Taylor benchmark: L = 26.54 mm, D = 11.155 mm at 80 us",
                         std::move(f.run));
}

}  // namespace

std::vector<Problem> strengthProblems() {
  return {
      {"elastic_wave_1d", "Elastic wave in Al-2024, 1D: longitudinal speed and stress", 1, elasticWave},
      {"elastic_plastic_1d", "Al-2024 at 200 m/s, 1D: elastic precursor (HEL) and plastic wave", 1,
       elasticPlastic},
      {"rubber_rings", "Colliding elastic rings (Gray et al. 2001), 2D: bounce without fracture", 1,
       rubberRings},
      {"taylor_bar", "Taylor bar, 42CrMo4 at 287 m/s, RZ, Johnson-Cook: length and footprint", 1,
       taylorBar},
  };
}

}  // namespace ejecta::verify::detail
