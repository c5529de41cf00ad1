// Fragmentation of a basalt sphere by an oblique impact (Nakamura & Fujiwara 1991; Benz & Asphaug
// 1994): scenes/nakamura_fujiwara.toml at reduced resolution, with the robust facts of the
// experiment's "core-type" break-up asserted. The comparison with the experiment, at the scene's
// own resolution, is in docs/fragmentation.md.
//
// The same analysis measures any run of that scene:
//   EJECTA_FRAGMENTATION_RUN=runs/nf build/tests/test_fragmentation
//       --gtest_filter=Fragmentation.ReportRunDirectory      (one command line)
// It prints the damaged mass against time and, for the last snapshot, the damage pattern and the
// intact fragments. Without the variable that test is skipped.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <numbers>
#include <numeric>
#include <regex>
#include <string>
#include <unordered_map>
#include <vector>

#include "sim/setup/bodies.hpp"
#include "sim/solid/materials.hpp"
#include "sim/run/run.hpp"
#include "sim/setup/scene.hpp"
#include "sim/io/snapshot.hpp"

namespace fs = std::filesystem;

namespace ejecta {
namespace {

using Vec = std::array<double, 3>;

double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec sub(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double norm(const Vec& a) { return std::sqrt(dot(a, a)); }

// Where the projectile first touches the target. bodies[0] is the target and bodies[1] the
// projectile, both spheres: the projectile's centre runs along its velocity until the two are
// R + r apart, and the axis is the unit vector from the target's centre to the contact point.
struct ImpactFrame {
  Vec centre{};        // target centre
  double radius = 0;   // target radius R
  Vec axis{};          // unit vector, target centre -> impact point
  double angle = 0;    // between the axis and the projectile's path reversed [rad]
  int material = 0;    // the target's material index
  double spacing = 0;  // the target's lattice spacing
};

ImpactFrame impactFrame(const Scene& scene) {
  const BodySpec& target = scene.bodies.at(0);
  const BodySpec& projectile = scene.bodies.at(1);
  ImpactFrame f;
  f.centre = target.shape.center;
  f.radius = target.shape.radius;
  f.material = target.material;
  f.spacing = target.spacing;
  const Vec d = sub(projectile.shape.center, f.centre);
  const double speed = norm(projectile.velocity);
  const Vec u = {projectile.velocity[0] / speed, projectile.velocity[1] / speed,
                 projectile.velocity[2] / speed};
  const double reach = f.radius + projectile.shape.radius;
  const double b = dot(d, u);
  const double t = -b - std::sqrt(std::max(b * b - dot(d, d) + reach * reach, 0.0));
  Vec contact = {d[0] + t * u[0], d[1] + t * u[1], d[2] + t * u[2]};
  const double length = norm(contact);
  for (double& c : contact) c /= length;
  f.axis = contact;
  f.angle = std::acos(std::clamp(-dot(contact, u), -1.0, 1.0));
  return f;
}

// Union-find over particle indices.
class DisjointSets {
 public:
  explicit DisjointSets(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
  std::size_t find(std::size_t i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
    return i;
  }
  void unite(std::size_t a, std::size_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::vector<std::size_t> parent_;
};

// Groups of the particles in `members` whose current positions lie closer than `link`, by cell
// hashing. Returns, per group, the member indices (into p).
std::vector<std::vector<std::size_t>> linkedGroups(const ParticleSet& p,
                                                   const std::vector<std::size_t>& members,
                                                   double link) {
  auto cellOf = [&](std::size_t i) {
    std::array<std::int64_t, 3> c{};
    for (int d = 0; d < 3; ++d) c[d] = static_cast<std::int64_t>(std::floor(p.x[d][i] / link));
    return c;
  };
  auto key = [](const std::array<std::int64_t, 3>& c) {
    return static_cast<std::uint64_t>((c[0] + (1 << 20)) * 2097152LL * 2097152LL +
                                      (c[1] + (1 << 20)) * 2097152LL + (c[2] + (1 << 20)));
  };
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> cells;
  for (std::size_t k = 0; k < members.size(); ++k) cells[key(cellOf(members[k]))].push_back(k);
  DisjointSets sets(members.size());
  const double link2 = link * link;
  for (std::size_t k = 0; k < members.size(); ++k) {
    const std::size_t i = members[k];
    const auto c = cellOf(i);
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const auto it = cells.find(key({c[0] + dx, c[1] + dy, c[2] + dz}));
          if (it == cells.end()) continue;
          for (const std::size_t l : it->second) {
            if (l <= k) continue;
            const std::size_t j = members[l];
            double r2 = 0.0;
            for (int d = 0; d < 3; ++d) r2 += (p.x[d][i] - p.x[d][j]) * (p.x[d][i] - p.x[d][j]);
            if (r2 < link2) sets.unite(k, l);
          }
        }
  }
  std::unordered_map<std::size_t, std::size_t> groupOfRoot;
  std::vector<std::vector<std::size_t>> groups;
  for (std::size_t k = 0; k < members.size(); ++k) {
    const std::size_t root = sets.find(k);
    auto [it, added] = groupOfRoot.emplace(root, groups.size());
    if (added) groups.emplace_back();
    groups[it->second].push_back(members[k]);
  }
  return groups;
}

// Damage and fragments of the target. Positions for the damage map are the initial ones (by
// particle id), so the pattern is that of the undeformed sphere: depth is measured from the
// impact point along the axis through the centre (0 at the impact point, 2R at the antipode),
// the polar angle at the centre from the impact point's direction.
struct FragmentationReport {
  double time = 0.0;
  double targetMass = 0.0;
  double damagedFraction = 0.0;   // mass with D > 0.99
  double meanDamage = 0.0;        // mass-weighted D
  Vec targetMomentum{};           // [kg m/s]
  Vec projectileVelocity{};       // mass-weighted velocity of everything but the target [m/s]
  double plasticFraction = 0.0;   // mass with plastic strain > 1e-3
  double plasticDepth = 0.0;      // the deepest such particle / R
  // Speeds of the damaged (D > 0.99) target mass: mass-weighted median, 90th percentile, largest.
  std::array<double, 3> damagedSpeeds{};
  // Damaged mass fraction (D > 0.99) in regions of the undeformed sphere:
  double impactCapDamaged = 0.0;  // depth < R/4 (the cap under the impact point)
  double antipodeCapDamaged = 0.0;  // depth > 7R/4 (the cap at the antipode)
  double coreDamaged = 0.0;       // r < R/2
  double shellDamaged = 0.0;      // r > 3R/4
  double nearOuterDamaged = 0.0;  // r > R/2, polar angle < 60 degrees (around the impact point)
  double farOuterDamaged = 0.0;   // r > R/2, polar angle > 120 degrees (around the antipode)
  // Along the axis (a cylinder of radius R/3 about it), in 8 bins of depth R/4.
  std::array<double, 8> axisDamaged{};
  // Polar angle (6 bins of 30 degrees) by radius (r/R in [0, 1/4, 1/2, 3/4, 9/10, 1]).
  std::array<std::array<double, 6>, 5> mapDamaged{};
  // Intact fragments: connected groups of target particles with D below a threshold, linked by
  // current distances below 1.5 target spacings. Fractions of the target mass, largest first.
  struct Group {
    double fraction = 0.0;     // of the target's mass
    Vec velocity{};            // mass-weighted [m/s]
    double centreDepth = 0.0;  // depth of its initial centre of mass / R
    double meanRadius = 0.0;   // mass-weighted mean initial distance from the centre / R
  };
  struct Fragments {
    double threshold = 1.0;
    std::vector<Group> largest;   // the five largest, largest first
    std::size_t groups = 0;       // all groups, single particles included
    double intactFraction = 0.0;  // all particles below the threshold
  };
  std::vector<Fragments> fragments;  // thresholds 1 (D < 1), 0.99, 0.5
  // The slice 0 < y < spacing of the undeformed sphere (x to the right, z up; the projectile
  // comes down from the upper right): 'O' the largest intact (D < 1) group, 'o' other intact,
  // '@' the second largest, '#' D > 0.99.
  std::vector<std::string> slice;
};

FragmentationReport analyse(const ParticleSet& initial, const ParticleSet& p,
                            const ImpactFrame& frame, double time) {
  FragmentationReport r;
  r.time = time;
  std::unordered_map<std::int64_t, std::size_t> initialOfId;
  for (std::size_t i = 0; i < initial.numReal; ++i) initialOfId[initial.id[i]] = i;
  const double R = frame.radius;
  struct Bin {
    double mass = 0.0, damaged = 0.0;
    double fraction() const { return mass > 0.0 ? damaged / mass : 0.0; }
  };
  Bin all, impactCap, antipodeCap, core, shell, nearOuter, farOuter;
  std::array<Bin, 8> axis{};
  std::array<std::array<Bin, 6>, 5> map{};
  const std::array<double, 5> radialEdges = {0.25, 0.5, 0.75, 0.9, 1.0};
  std::vector<std::size_t> target;
  double damageSum = 0.0, projectileMass = 0.0, plasticMass = 0.0;
  std::vector<std::pair<double, double>> damagedSpeed;  // (speed, mass)
  for (std::size_t i = 0; i < p.numReal; ++i) {
    if (p.material[i] != frame.material) {
      projectileMass += p.mass[i];
      for (int d = 0; d < 3; ++d) r.projectileVelocity[d] += p.mass[i] * p.v[d][i];
      continue;
    }
    for (int d = 0; d < 3; ++d) r.targetMomentum[d] += p.mass[i] * p.v[d][i];
    target.push_back(i);
    const std::size_t i0 = initialOfId.at(p.id[i]);
    const Vec rel = sub({initial.x[0][i0], initial.x[1][i0], initial.x[2][i0]}, frame.centre);
    const double along = dot(rel, frame.axis);
    const double depth = R - along;
    const double radius = norm(rel);
    const double offAxis = std::sqrt(std::max(radius * radius - along * along, 0.0));
    const double polar = std::acos(std::clamp(along / std::max(radius, 1e-300), -1.0, 1.0));
    const double m = p.mass[i];
    const double D = p.damage(i);
    const double broken = D > 0.99 ? m : 0.0;
    damageSum += m * D;
    if (!p.plasticStrain.empty() && p.plasticStrain[i] > 1e-3) {
      plasticMass += m;
      r.plasticDepth = std::max(r.plasticDepth, depth / R);
    }
    if (D > 0.99) damagedSpeed.emplace_back(norm({p.v[0][i], p.v[1][i], p.v[2][i]}), m);
    auto add = [&](Bin& b) {
      b.mass += m;
      b.damaged += broken;
    };
    add(all);
    if (depth < 0.25 * R) add(impactCap);
    if (depth > 1.75 * R) add(antipodeCap);
    if (radius < 0.5 * R) add(core);
    if (radius > 0.75 * R) add(shell);
    if (radius > 0.5 * R && polar < std::numbers::pi / 3.0) add(nearOuter);
    if (radius > 0.5 * R && polar > 2.0 * std::numbers::pi / 3.0) add(farOuter);
    if (offAxis < R / 3.0) add(axis[std::clamp(static_cast<int>(depth / (0.25 * R)), 0, 7)]);
    int ring = 0;
    while (ring < 4 && radius > radialEdges[ring] * R) ++ring;
    const int sector = std::clamp(static_cast<int>(polar / (std::numbers::pi / 6.0)), 0, 5);
    add(map[ring][sector]);
  }
  for (double& v : r.projectileVelocity) v /= projectileMass;
  r.targetMass = all.mass;
  r.plasticFraction = plasticMass / all.mass;
  std::sort(damagedSpeed.begin(), damagedSpeed.end());
  double damagedMass = 0.0, below = 0.0;
  for (const auto& [v, m] : damagedSpeed) damagedMass += m;
  for (const auto& [v, m] : damagedSpeed) {
    if (below < 0.5 * damagedMass && below + m >= 0.5 * damagedMass) r.damagedSpeeds[0] = v;
    if (below < 0.9 * damagedMass && below + m >= 0.9 * damagedMass) r.damagedSpeeds[1] = v;
    below += m;
  }
  if (!damagedSpeed.empty()) r.damagedSpeeds[2] = damagedSpeed.back().first;
  r.damagedFraction = all.fraction();
  r.meanDamage = damageSum / all.mass;
  r.impactCapDamaged = impactCap.fraction();
  r.antipodeCapDamaged = antipodeCap.fraction();
  r.coreDamaged = core.fraction();
  r.shellDamaged = shell.fraction();
  r.nearOuterDamaged = nearOuter.fraction();
  r.farOuterDamaged = farOuter.fraction();
  for (int b = 0; b < 8; ++b) r.axisDamaged[b] = axis[b].fraction();
  for (int ring = 0; ring < 5; ++ring)
    for (int s = 0; s < 6; ++s) r.mapDamaged[ring][s] = map[ring][s].fraction();

  for (const double threshold : {1.0, 0.99, 0.5}) {
    FragmentationReport::Fragments f;
    f.threshold = threshold;
    std::vector<std::size_t> intact;
    for (const std::size_t i : target)
      if (p.damage(i) < threshold) intact.push_back(i);
    auto groups = linkedGroups(p, intact, 1.5 * frame.spacing);
    auto massOf = [&](const std::vector<std::size_t>& g) {
      double m = 0.0;
      for (const std::size_t i : g) m += p.mass[i];
      return m;
    };
    std::sort(groups.begin(), groups.end(),
              [&](const auto& a, const auto& b) { return massOf(a) > massOf(b); });
    f.groups = groups.size();
    for (const std::size_t i : intact) f.intactFraction += p.mass[i] / all.mass;
    for (std::size_t g = 0; g < std::min<std::size_t>(5, groups.size()); ++g) {
      FragmentationReport::Group info;
      const double m = massOf(groups[g]);
      info.fraction = m / all.mass;
      Vec centre{};
      for (const std::size_t i : groups[g]) {
        const std::size_t i0 = initialOfId.at(p.id[i]);
        const Vec x0 = {initial.x[0][i0], initial.x[1][i0], initial.x[2][i0]};
        for (int d = 0; d < 3; ++d) {
          info.velocity[d] += p.mass[i] * p.v[d][i] / m;
          centre[d] += p.mass[i] * x0[d] / m;
        }
        info.meanRadius += p.mass[i] * norm(sub(x0, frame.centre)) / (m * R);
      }
      info.centreDepth = (R - dot(sub(centre, frame.centre), frame.axis)) / R;
      f.largest.push_back(info);
    }
    if (threshold == 1.0) {
      const double s = frame.spacing;
      const int n = static_cast<int>(std::ceil(2.0 * R / s));
      r.slice.assign(static_cast<std::size_t>(n), std::string(static_cast<std::size_t>(n), ' '));
      std::vector<char> rank(p.numReal, 0);
      for (std::size_t g = 0; g < std::min<std::size_t>(2, groups.size()); ++g)
        for (const std::size_t i : groups[g]) rank[i] = static_cast<char>(g + 1);
      for (const std::size_t i : target) {
        const std::size_t i0 = initialOfId.at(p.id[i]);
        const double y = initial.x[1][i0] - frame.centre[1];
        if (!(y > 0.0 && y < s)) continue;
        const int col = static_cast<int>(std::floor((initial.x[0][i0] - frame.centre[0] + R) / s));
        const int row = static_cast<int>(std::floor((initial.x[2][i0] - frame.centre[2] + R) / s));
        if (col < 0 || col >= n || row < 0 || row >= n) continue;
        const double D = p.damage(i);
        r.slice[static_cast<std::size_t>(n - 1 - row)][static_cast<std::size_t>(col)] =
            rank[i] == 1 ? 'O' : rank[i] == 2 ? '@' : D <= 0.99 ? 'o' : '#';
      }
    }
    r.fragments.push_back(f);
  }
  return r;
}

void print(const FragmentationReport& r) {
  std::printf("t = %.1f us: target %.4g kg, damaged (D > 0.99) %.3f of the mass, mean D %.3f\n",
              r.time * 1e6, r.targetMass, r.damagedFraction, r.meanDamage);
  std::printf("target momentum (%.4f, %.4f, %.4f) kg m/s; projectile at (%.0f, %.0f, %.0f) m/s\n",
              r.targetMomentum[0], r.targetMomentum[1], r.targetMomentum[2],
              r.projectileVelocity[0], r.projectileVelocity[1], r.projectileVelocity[2]);
  std::printf("plastic (strain > 1e-3): %.4f of the mass, down to depth %.3f R; damaged mass "
              "moves at %.1f (median), %.1f (90%%), %.1f (largest) m/s\n",
              r.plasticFraction, r.plasticDepth, r.damagedSpeeds[0], r.damagedSpeeds[1],
              r.damagedSpeeds[2]);
  std::printf("damaged fraction: impact cap %.3f, antipode cap %.3f, core (r < R/2) %.3f, "
              "shell (r > 3R/4) %.3f; r > R/2 within 60 deg of the impact point %.3f, of the antipode "
              "%.3f\n",
              r.impactCapDamaged, r.antipodeCapDamaged, r.coreDamaged, r.shellDamaged,
              r.nearOuterDamaged, r.farOuterDamaged);
  std::printf("along the axis (depth/R 0 -> 2, bins of 1/4):");
  for (const double a : r.axisDamaged) std::printf(" %.2f", a);
  std::printf("\npolar angle from the impact direction (deg):  0-30 30-60 60-90 90-120 120-150 "
              "150-180\n");
  const char* rings[] = {"r/R 0.00-0.25", "r/R 0.25-0.50", "r/R 0.50-0.75", "r/R 0.75-0.90",
                         "r/R 0.90-1.00"};
  for (int ring = 0; ring < 5; ++ring) {
    std::printf("  %s:                  ", rings[ring]);
    for (const double a : r.mapDamaged[ring]) std::printf(" %5.2f", a);
    std::printf("\n");
  }
  for (const auto& f : r.fragments) {
    std::printf("intact groups (D < %.2f): %.3f of the mass intact in %zu groups; largest",
                f.threshold, f.intactFraction, f.groups);
    for (const auto& g : f.largest) std::printf(" %.4f", g.fraction);
    std::printf("\n");
  }
  for (const auto& g : r.fragments.front().largest)
    std::printf("  group %.4f: centre at depth %.2f R, mean radius %.2f R, velocity (%.2f, %.2f, "
                "%.2f) m/s, speed %.2f m/s\n",
                g.fraction, g.centreDepth, g.meanRadius, g.velocity[0], g.velocity[1],
                g.velocity[2], norm(g.velocity));
  std::printf("slice 0 < y < spacing (x right, z up; O largest intact group, @ second, o other "
              "intact, # D > 0.99):\n");
  for (const std::string& line : r.slice) std::printf("  |%s|\n", line.c_str());
}

// The scene at reduced resolution: 2.5 mm spacing (7,208 target particles, 24 across the
// diameter) and an 8-particle projectile whose spacing keeps its mass at 0.2 g, to 20 us. By then
// the core and the outer spall shell have separated; to 60 us they change by a few % of the mass.
// At Courant 0.3, the default of every other scene: the crack growth limit on the time step
// (FractureModel::maxCrackIncrement) resolves the cracking, as Courant 0.1 did before it. Without
// that limit, at Courant 0.3 the core stays joined to the shell and this test fails (measured:
// one intact group of 0.32 of the mass, mean radius 0.81 R; docs/fragmentation.md).
TEST(Fragmentation, CoreTypeBreakUpOfABasaltSphere) {
  const std::string path = std::string(EJECTA_SOURCE_DIR) + "/scenes/nakamura_fujiwara.toml";
  const Scene scene = loadScene(path, {"bodies[0].spacing=2.5 mm", "bodies[1].spacing=2.76317 mm",
                                       "time.t_end=20 us", "sph.courant=0.3"});
  const ImpactFrame frame = impactFrame(scene);
  // First contact 30 degrees from the projectile's path, as in the experiment.
  EXPECT_NEAR(frame.angle * 180.0 / std::numbers::pi, 30.0, 0.01);

  ParticleSet initial, last;
  {
    const MaterialTable materials = MaterialTable::fromScene(scene);
    initial = buildParticles(scene, materials);
  }
  RunOptions options;
  options.onFinish = [&](const Simulation& sim, RunSummary&) { last = sim.particles(); };
  const RunOutcome outcome = runScene(scene, options);
  ASSERT_TRUE(outcome.ok) << outcome.error;
  EXPECT_LT(std::abs(outcome.summary.energy.relativeError), 1e-3);
  double projectileMass = 0.0;
  for (std::size_t i = 0; i < initial.numReal; ++i)
    if (initial.material[i] != frame.material) projectileMass += initial.mass[i];
  EXPECT_NEAR(projectileMass, 0.2e-3, 1e-7);

  const FragmentationReport r = analyse(initial, last, frame, outcome.summary.tEnd);
  print(r);
  // Measured: the impact cap 1.00 damaged, the outer half within 60 degrees of the impact point
  // 0.98 and of the antipode 0.38; 0.69 of the mass damaged; a core of 0.091 (mean radius
  // 0.44 R, centre at depth 1.21 R) at 0.73 m/s and a spall shell of 0.21 at 5.9 m/s (before the
  // fixes of the issue 3 review, at Courant 0.1: core 0.072 at 1.8 m/s, shell 0.22 at 5.5 m/s).
  // The bounds are wide because fragment masses move with resolution: the core holds 0.19 at
  // the scene's 1.5 mm at 20 us (docs/fragmentation.md).
  // The struck side is shattered, the far side much less.
  EXPECT_GT(r.impactCapDamaged, 0.9);
  EXPECT_GT(r.nearOuterDamaged, 0.9);
  EXPECT_LT(r.farOuterDamaged, 0.6);
  EXPECT_GT(r.damagedFraction, 0.5);
  EXPECT_LT(r.damagedFraction, 0.85);
  // Core type: an intact core (mean radius below R/2 + 10%) and, separated from it by a spall
  // layer, an intact outer shell on the far side (mean radius above 0.85 R). The core moves away
  // from the impact point, slower than the shell (the experiment's core: 1.35 m/s).
  const auto& groups = r.fragments.front().largest;  // D < 1
  const auto core = std::find_if(groups.begin(), groups.end(),
                                 [](const auto& g) { return g.meanRadius < 0.6; });
  const auto shell = std::find_if(groups.begin(), groups.end(),
                                  [](const auto& g) { return g.meanRadius > 0.85; });
  ASSERT_NE(core, groups.end());
  ASSERT_NE(shell, groups.end());
  EXPECT_GT(core->fraction, 0.03);
  EXPECT_GT(shell->fraction, 0.03);
  EXPECT_GT(core->centreDepth, 1.0);
  // Away from the impact point: within 60 degrees of the axis. Its speed is the least converged
  // number here (0.35 m/s with steps 10x shorter, docs/fragmentation.md), so only its direction
  // and an upper bound are asserted.
  EXPECT_GT(-dot(core->velocity, frame.axis), 0.5 * norm(core->velocity));
  EXPECT_LT(norm(core->velocity), 4.0);
  EXPECT_LT(norm(core->velocity), norm(shell->velocity));
}

// Measures a run of scenes/nakamura_fujiwara.toml (any resolution): EJECTA_FRAGMENTATION_RUN
// names its output directory.
TEST(Fragmentation, ReportRunDirectory) {
  const char* dir = std::getenv("EJECTA_FRAGMENTATION_RUN");
  if (dir == nullptr) GTEST_SKIP() << "set EJECTA_FRAGMENTATION_RUN to a run directory";
  std::vector<std::pair<long, fs::path>> files;
  const std::regex pattern(R"(snap_(\d{4,})\.h5)");
  for (const auto& e : fs::directory_iterator(fs::path(dir) / "snapshots")) {
    std::smatch m;
    const std::string name = e.path().filename().string();
    if (std::regex_match(name, m, pattern)) files.emplace_back(std::stol(m[1]), e.path());
  }
  ASSERT_FALSE(files.empty());
  std::sort(files.begin(), files.end());
  SnapshotInfo info0;
  const ParticleSet initial = readSnapshot(files.front().second.string(), info0);
  const ImpactFrame frame = impactFrame(storedScene(info0, files.front().second.string()));
  std::printf("impact axis (%.4f, %.4f, %.4f), %.2f deg from the projectile's path\n",
              frame.axis[0], frame.axis[1], frame.axis[2], frame.angle * 180.0 / std::numbers::pi);
  for (const auto& [index, file] : files) {
    SnapshotInfo info;
    const ParticleSet p = readSnapshot(file.string(), info);
    const FragmentationReport r = analyse(initial, p, frame, info.time);
    if (index == files.back().first) {
      std::printf("--- %s (step %ld, wall %.0f s)\n", file.string().c_str(), info.step,
                  info.wallSeconds);
      print(r);
    } else {
      const auto& f = r.fragments.front();
      std::printf("t = %5.1f us: damaged %.3f, mean D %.3f, largest intact (D < 1) %.3f moving at "
                  "%.2f m/s\n",
                  r.time * 1e6, r.damagedFraction, r.meanDamage,
                  f.largest.empty() ? 0.0 : f.largest[0].fraction,
                  f.largest.empty() ? 0.0 : norm(f.largest[0].velocity));
    }
  }
}

}  // namespace
}  // namespace ejecta

