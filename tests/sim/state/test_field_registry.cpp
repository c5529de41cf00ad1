// The field registry (sim/state/field_spec.hpp, docs/design.md "Fields declared once"): a field
// declared once, by a test-only package, is integrated by the leapfrog, reordered with its
// particle, written to snapshots, listed in the XDMF and carried through a restart, with no other
// change to the code. And the built-in declarations drive what the snapshot and grids carry.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <memory>

#include "sim/io/snapshot.hpp"
#include "sim/io/xdmf.hpp"
#include "sim/run/physics_package.hpp"
#include "sim/run/run.hpp"
#include "sim/run/simulation.hpp"
#include "sim/setup/bodies.hpp"
#include "sim/setup/scene.hpp"
#include "sim/solid/materials.hpp"
#include "sim/sph/boundaries.hpp"
#include "sim/state/builtin_fields.hpp"
#include "sim/state/particle_fields.hpp"
#include "support/command_line.hpp"
#include "support/periodic_blast.hpp"

namespace fs = std::filesystem;
using namespace ejecta;

namespace {

// A clock of each particle's own pace: d(tracer)/dt = c_i = 1 + (id mod 7) s/s, so tracer = c_i t,
// which the leapfrog integrates exactly (up to rounding) and which tells whether the value stayed
// with its particle when the run reordered them.
double pace(std::int64_t id) { return 1.0 + static_cast<double>(id % 7); }

class PacedClock : public PhysicsPackage {
 public:
  std::string name() const override { return "paced_clock"; }
  void registerFields(ParticleSet& p) override {
    FieldSpec tracer;
    tracer.name = "tracer";
    tracer.units = "s";
    tracer.description = "the particle's own clock (test package)";
    tracer.output = FieldOutput::Particles;
    tracer.evolution = Evolution::Kicked;
    tracer.rate = "dtracer_dt";
    p.declare(tracer);
    FieldSpec rate;
    rate.name = "dtracer_dt";
    rate.units = "1";
    rate.description = "rate of the tracer (test package)";
    rate.output = FieldOutput::Restart;
    p.declare(rate);
  }
  void evaluateDerivatives(ParticleSet& p, const PackageContext&) override {
    std::vector<double>& rate = p.column(*p.field("dtracer_dt"), 0);
    for (std::size_t i = 0; i < p.numReal; ++i) rate[i] = pace(p.id[i]);
  }
  // A package's vote on the step: at least 64 steps to the blast's 0.02 s, so the run reorders
  // its particles (every 16 steps) several times.
  double timestep(const ParticleSet&, const PackageContext&) const override { return 0.02 / 64; }
};

fs::path tempDir(const std::string& tag) {
  return fs::temp_directory_path() / ("ejecta_registry_" + tag + "_" + std::to_string(::getpid()));
}

std::map<std::int64_t, std::size_t> indexById(const ParticleSet& p) {
  std::map<std::int64_t, std::size_t> index;
  for (std::size_t i = 0; i < p.numReal; ++i) index[p.id[i]] = i;
  return index;
}

}  // namespace

TEST(FieldRegistry, APackageFieldIsIntegratedWrittenListedAndRestarted) {
  const fs::path full = tempDir("full"), cut = tempDir("cut");
  const std::vector<std::shared_ptr<PhysicsPackage>> packages{std::make_shared<PacedClock>()};
  ejecta::test::runAndResumeFromSnapshot2(ejecta::test::periodicBlastScene(), full, cut, 2, packages);

  SnapshotInfo infoA, infoB;
  const ParticleSet a = readSnapshot((full / "snapshots" / "snap_0004.h5").string(), infoA);
  const ParticleSet b = readSnapshot((cut / "snapshots" / "snap_0004.h5").string(), infoB);

  // Written, with its declaration's units, and read back as a field of the set.
  const Field* tracer = a.field("tracer");
  ASSERT_NE(tracer, nullptr);
  EXPECT_EQ(tracer->spec.units, "s");
  EXPECT_EQ(tracer->spec.output, FieldOutput::Particles);
  ASSERT_NE(a.field("dtracer_dt"), nullptr);
  EXPECT_EQ(a.field("dtracer_dt")->spec.output, FieldOutput::Restart);

  // Integrated, and reordered with its particle (the run sorts every 16 steps): each clock reads
  // its own pace times the time. Constant rates make the leapfrog exact; what is left is the
  // rounding of ~100 half kicks, ~1e-14 relative, so 1e-12 is a hundred times that while a clock
  // that changed particle is off by at least 1/7.
  const std::vector<double>& t = a.column(*tracer, 0);
  ASSERT_NEAR(infoA.time, 0.02, 1e-15);
  for (std::size_t i = 0; i < a.numReal; ++i)
    EXPECT_NEAR(t[i], pace(a.id[i]) * infoA.time, 1e-12 * pace(a.id[i]) * infoA.time) << "id " << a.id[i];
  EXPECT_GE(infoA.step, 64) << "the package's time-step vote was not taken";

  // Restarted: resuming halfway gives the uninterrupted run's tracer to the bit.
  const std::map<std::int64_t, std::size_t> inB = indexById(b);
  const std::vector<double>& tb = b.column(*b.field("tracer"), 0);
  for (std::size_t i = 0; i < a.numReal; ++i) EXPECT_EQ(t[i], tb[inB.at(a.id[i])]) << "id " << a.id[i];

  // Listed in the XDMF, in every grid of both series (the restart rebuilt its own).
  for (const fs::path& dir : {full, cut}) {
    const std::string xml = ejecta::test::readTextFile(dir / "snapshots.xdmf");
    std::size_t grids = 0, listed = 0;
    for (std::size_t at = 0; (at = xml.find("GridType=\"Uniform\"", at)) != std::string::npos; ++at) ++grids;
    for (std::size_t at = 0; (at = xml.find("<Attribute Name=\"tracer\" AttributeType=\"Scalar\"", at)) !=
                             std::string::npos;
         ++at)
      ++listed;
    EXPECT_EQ(grids, 5u) << dir;
    EXPECT_EQ(listed, grids) << dir;
  }
  fs::remove_all(full);
  fs::remove_all(cut);
}

TEST(FieldRegistry, DeclaringTwiceKeepsTheValuesAndAMismatchIsRefused) {
  ParticleSet p;
  p.append({0, 0, 0}, {0, 0, 0}, 1.0, 1.0, 0.0, 0.1, 0);
  FieldSpec s;
  s.name = "extra";
  s.fill = 2.5;
  p.declare(s);
  EXPECT_EQ(p.column(*p.field("extra"), 0)[0], 2.5);
  p.column(*p.field("extra"), 0)[0] = 7.0;
  s.units = "m";
  p.declare(s);  // a package re-declaring a field read back from a snapshot
  EXPECT_EQ(p.column(*p.field("extra"), 0)[0], 7.0);
  EXPECT_EQ(p.field("extra")->spec.units, "m");
  s.components = 3;
  EXPECT_THROW(p.declare(s), std::invalid_argument);
  // Resizing and reordering carry the package's column with the built-in ones.
  p.append({1, 0, 0}, {0, 0, 0}, 1.0, 1.0, 0.0, 0.1, 0);
  EXPECT_EQ(p.column(*p.field("extra"), 0)[1], 2.5);
  p.permute({1, 0});
  EXPECT_EQ(p.column(*p.field("extra"), 0)[0], 2.5);
  EXPECT_EQ(p.column(*p.field("extra"), 0)[1], 7.0);
  EXPECT_EQ(p.id[1], 0);
}

TEST(FieldRegistry, GroupsJoinInRegistryOrderWhateverOrderTheyAreEnabled) {
  ParticleSet p;
  p.enableViscositySwitch(0.1);
  p.enableStrength(4);
  p.enableFracture();
  // Fracture before Strength: the crack's cap must see the stress before its kick.
  auto rank = [&](const std::string& name) {
    for (std::size_t k = 0; k < p.fields().size(); ++k)
      if (p.fields()[k].spec.name == name) return static_cast<long>(k);
    return -1L;
  };
  EXPECT_LT(rank("density"), rank("crack"));
  EXPECT_LT(rank("crack"), rank("stress"));
  EXPECT_LT(rank("stress"), rank("viscosity_alpha"));
  EXPECT_EQ(p.field("stress")->spec.components, 4);
  p.enableFracture();  // once only
  std::size_t cracks = 0;
  for (const Field& f : p.fields()) cracks += f.spec.name == "crack";
  EXPECT_EQ(cracks, 1u);
}

TEST(FieldRegistry, GridsAndTheXdmfComeFromTheDeclarations) {
  // Every gridded built-in field is a named particle field, with the declaration's units.
  for (const Field& f : allBuiltinFields()) {
    const ParticleFieldInfo* info = findParticleScalarField(f.spec.name);
    EXPECT_EQ(info != nullptr, f.spec.grid) << f.spec.name;
    if (info) {
      EXPECT_EQ(info->units, f.spec.units);
    }
  }
  // A field the run does not carry reads as its declared absent value.
  ParticleSet p;
  p.append({0, 0, 0}, {3, 4, 0}, 1.0, 1.0, 0.0, 0.1, 0);
  EXPECT_EQ(particleScalarField(p, "burn_fraction")[0], 1.0);
  EXPECT_EQ(particleScalarField(p, "damage")[0], 0.0);
  EXPECT_EQ(particleScalarField(p, "speed")[0], 5.0);
  p.enableFracture();
  p.crack[0] = 0.5;
  EXPECT_EQ(particleScalarField(p, "damage")[0], 0.125);
  // The XDMF lists the declared scalars first, then the vectors.
  const std::vector<XdmfAttribute> attributes = xdmfAttributes(p);
  ASSERT_FALSE(attributes.empty());
  EXPECT_EQ(attributes.front().name, "density");
  EXPECT_EQ(attributes.back().name, "velocity");
  EXPECT_EQ(attributes.back().components, 3);
}

TEST(FieldRegistry, GhostsCarryHaloFieldsThroughTheirMirrorParity) {
  // A package's vector and tensor fields reach the ghosts as the built-in ones do: at the x = 0
  // wall a vector's x component and a tensor's xy component change sign, the rest are copied.
  DomainBounds domain{};
  domain[0] = {0.0, 1.0, BoundaryKind::Wall, BoundaryKind::Wall, true};
  domain[1] = {0.0, 1.0, BoundaryKind::Periodic, BoundaryKind::Periodic, true};
  ParticleSet p;
  p.append({0.02, 0.5, 0}, {0, 0, 0}, 1, 1, 1, 0.02, 0);
  FieldSpec vec;
  vec.name = "package_vector";
  vec.components = 3;
  vec.halo = true;
  vec.parity = MirrorParity::Vector;
  p.declare(vec);
  FieldSpec tensor;
  tensor.name = "package_tensor";
  tensor.components = 4;  // xx, yy, zz, xy
  tensor.halo = true;
  tensor.parity = MirrorParity::SymmetricTensor;
  p.declare(tensor);
  FieldSpec local;
  local.name = "package_local";  // not read from neighbours: ghosts do not carry it
  local.fill = 0.0;
  p.declare(local);
  for (int c = 0; c < 3; ++c) p.column(*p.field("package_vector"), c)[0] = 1.0 + c;
  for (int c = 0; c < 4; ++c) p.column(*p.field("package_tensor"), c)[0] = 10.0 + c;
  p.column(*p.field("package_local"), 0)[0] = 5.0;
  Boundaries b(Geometry::Planar, domain);
  b.makeGhosts(p, 2.0);
  ASSERT_EQ(p.numGhosts(), 1u);
  const std::size_t g = p.numReal;
  EXPECT_EQ(p.x[0][g], -0.02);
  EXPECT_EQ(p.column(*p.field("package_vector"), 0)[g], -1.0);
  EXPECT_EQ(p.column(*p.field("package_vector"), 1)[g], 2.0);
  EXPECT_EQ(p.column(*p.field("package_tensor"), 0)[g], 10.0);
  EXPECT_EQ(p.column(*p.field("package_tensor"), 3)[g], -13.0);
  EXPECT_EQ(p.column(*p.field("package_local"), 0)[g], 0.0);
  // A refresh after the source changed.
  p.column(*p.field("package_vector"), 0)[0] = -4.0;
  b.refreshGhosts(p);
  EXPECT_EQ(p.column(*p.field("package_vector"), 0)[g], 4.0);
}

// The health check watches every evolved field and its rate from the registry, a package's too:
// a NaN in one particle's tracer (which no other particle's equations read, so it stays in that
// particle) stops the next step, naming that particle. The particles are reordered at the step's
// start, so the particle is found by its id.
TEST(FieldRegistry, TheHealthCheckWatchesAPackagesEvolvedField) {
  const Scene scene = parseScene(ejecta::test::periodicBlastScene(), "blast.toml");
  const MaterialTable materials = MaterialTable::fromScene(scene);
  Simulation sim(scene, buildParticles(scene, materials), materials, 1);
  sim.addPackage(std::make_shared<PacedClock>());
  sim.initialise();
  sim.step(1.0);  // a healthy step first
  ParticleSet& p = sim.particles();
  const std::size_t k = p.numReal / 3;
  const std::int64_t id = p.id[k];
  p.column(*p.field("tracer"), 0)[k] = std::nan("");
  try {
    sim.step(1.0);
    FAIL() << "a NaN in a package's field went unnoticed";
  } catch (const SimulationError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("non-finite state"), std::string::npos) << message;
    EXPECT_NE(message.find("particle id " + std::to_string(id) + " "), std::string::npos) << message;
  }
}
