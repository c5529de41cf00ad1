// The porosity package (sim/run/packages/porosity_package.hpp) in runs: a porous body starts at
// its bulk density with alpha_0 and the pressure it was given; snapshots carry the distention
// and a restart resumes bit for bit (P-alpha and epsilon-alpha, with and without strength); a
// porous solid's matrix stress follows the matrix's strain; a bad [materials.porosity] table is
// refused naming the file, the material and the reason.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "sim/io/snapshot.hpp"
#include "sim/run/packages/porosity_package.hpp"
#include "sim/run/run.hpp"
#include "sim/setup/embedded_scenes.hpp"
#include "sim/setup/scene.hpp"
#include "sim/solid/materials.hpp"
#include "sim/solid/strain_porosity.hpp"
#include "support/material_scene_error.hpp"

namespace ejecta {
namespace {

namespace fs = std::filesystem;

fs::path tempDir(const std::string& tag) {
  return fs::temp_directory_path() / ("ejecta_porosity_" + tag + "_" + std::to_string(::getpid()));
}

RunOptions compactionRun(const fs::path& dir, const std::string& tEnd,
                         const std::string& scene = "compaction_1d") {
  RunOptions options;
  options.outDir = dir.string();
  options.threads = 1;
  options.sceneSource = std::string(findEmbeddedScene("verification/" + scene));
  options.overrides = {"time.t_end=" + tEnd, "output.snapshot_interval=\"1 us\"",
                       "bodies[0].spacing=\"0.1 mm\""};
  return options;
}

ParticleSet snapshotAt(const fs::path& dir, int index, SnapshotInfo& info) {
  char name[32];
  std::snprintf(name, sizeof name, "snap_%04d.h5", index);
  return readSnapshot((dir / "snapshots" / name).string(), info);
}

const std::vector<double>& distention(const ParticleSet& p) {
  return p.column(*p.field(PorosityPackage::kDistention), 0);
}

TEST(PorosityPackage, APorousBodyStartsAtRestWithItsInitialDistention) {
  const fs::path dir = tempDir("start");
  fs::remove_all(dir);
  const RunOptions options = compactionRun(dir, "1 us");
  ASSERT_TRUE(runScene(parseScene(options.sceneSource, "compaction_1d.toml", options.overrides),
                       options).ok);
  SnapshotInfo info;
  const ParticleSet p = snapshotAt(dir, 0, info);
  ASSERT_GT(p.numReal, 0u);
  for (std::size_t i = 0; i < p.numReal; ++i) {
    EXPECT_DOUBLE_EQ(distention(p)[i], 1.275);
    // Given P = 0: the matrix sits at its reference density (2117.647 x 1.275 = 2700 to the
    // scene's 7 digits), so u ~ 0 and |P| is the residue of that rounding, ~1e-7 of Pe.
    EXPECT_LT(std::abs(p.P[i]), 1e-6 * 0.08e9) << i;
  }
  // One microsecond later the wall has compacted the first particles and the wave is on.
  const ParticleSet q = snapshotAt(dir, 1, info);
  double least = 2.0;
  for (double a : distention(q)) least = std::min(least, a);
  EXPECT_LT(least, 1.01);
  fs::remove_all(dir);
}

// An elastic matrix for the porous slab (a porous solid).
void addElasticMatrix(RunOptions& options) {
  options.overrides.push_back("materials[0].strength.model=\"elastic\"");
  options.overrides.push_back("materials[0].strength.shear_modulus=\"26 GPa\"");
}

// Both models: P-alpha's distention and its rate; epsilon-alpha's strain and the most
// compressive strain reached, from which its distention follows; with an elastic matrix
// ("...:solid") also the stress, the compaction factor and the state each step started from.
class PorosityRestart : public ::testing::TestWithParam<const char*> {};

TEST_P(PorosityRestart, ResumesBitForBit) {
  const std::string param = GetParam();
  const bool solid = param.ends_with(":solid");
  const std::string scene = param.substr(0, param.find(':'));
  const fs::path straight = tempDir("straight"), resumed = tempDir("resumed");
  fs::remove_all(straight);
  fs::remove_all(resumed);
  RunOptions a = compactionRun(straight, "3 us", scene);
  RunOptions b = compactionRun(resumed, "2 us", scene);
  if (solid) {
    addElasticMatrix(a);
    addElasticMatrix(b);
  }
  ASSERT_TRUE(runScene(parseScene(a.sceneSource, scene + ".toml", a.overrides), a).ok);
  ASSERT_TRUE(runScene(parseScene(b.sceneSource, scene + ".toml", b.overrides), b).ok);
  RunOptions extend;
  extend.threads = 1;
  extend.restartOverrides = {"time.t_end=\"3 us\""};
  const RunOutcome outcome = restartRun(resumed.string(), extend);
  ASSERT_TRUE(outcome.ok) << outcome.error;
  SnapshotInfo ia, ib;
  const ParticleSet p = snapshotAt(straight, 3, ia), q = snapshotAt(resumed, 3, ib);
  ASSERT_EQ(p.numReal, q.numReal);
  EXPECT_EQ(ia.step, ib.step);
  for (std::size_t i = 0; i < p.numReal; ++i) {
    ASSERT_EQ(std::bit_cast<std::uint64_t>(distention(p)[i]),
              std::bit_cast<std::uint64_t>(distention(q)[i])) << i;
    ASSERT_EQ(std::bit_cast<std::uint64_t>(p.rho[i]), std::bit_cast<std::uint64_t>(q.rho[i])) << i;
    ASSERT_EQ(std::bit_cast<std::uint64_t>(p.P[i]), std::bit_cast<std::uint64_t>(q.P[i])) << i;
    if (solid) {
      ASSERT_EQ(std::bit_cast<std::uint64_t>(p.stress[0][i]),
                std::bit_cast<std::uint64_t>(q.stress[0][i])) << i;
    }
  }
  fs::remove_all(straight);
  fs::remove_all(resumed);
}

INSTANTIATE_TEST_SUITE_P(BothModels, PorosityRestart,
                         ::testing::Values("compaction_1d", "compaction_epsalpha_1d",
                                           "compaction_1d:solid", "compaction_epsalpha_1d:solid"));

// epsilon-alpha's history in a run: a 10 mm slab of the every-regime aluminium compacts
// against the wall (2.1 GPa behind the shock, in the power-law regime), then the release from
// its free end unloads it. Each particle's history holds the most compressive strain it
// reached, and its distention is the loading curve's there carried elastically back: below the
// curve at its present strain (with the history lost, alpha would follow the curve back up).
TEST(PorosityPackage, EpsilonAlphaCompactionOutlivesTheRelease) {
  const fs::path dir = tempDir("release");
  fs::remove_all(dir);
  RunOptions options = compactionRun(dir, "12 us", "compaction_epsalpha_1d");
  options.overrides.push_back("bodies[0].max=[\"10 mm\"]");
  const Scene scene = parseScene(options.sceneSource, "compaction_epsalpha_1d.toml", options.overrides);
  ASSERT_TRUE(runScene(scene, options).ok);
  const MaterialTable materials = MaterialTable::fromScene(scene);
  const auto* model = dynamic_cast<const EpsilonAlphaModel*>(materials[0].porosity.get());
  ASSERT_NE(model, nullptr);
  SnapshotInfo info;
  const ParticleSet p = snapshotAt(dir, 12, info);
  const std::vector<double>& eps = p.column(*p.field(PorosityPackage::kStrain), 0);
  const std::vector<double>& least = p.column(*p.field(PorosityPackage::kLeastStrain), 0);
  int released = 0;
  for (std::size_t i = 0; i < p.numReal; ++i) {
    ASSERT_LE(least[i], eps[i]) << i;
    EXPECT_DOUBLE_EQ(distention(p)[i], model->distention(eps[i], least[i])) << i;
    if (least[i] < model->transitionStrain() && eps[i] > least[i] + 0.01) {
      ++released;
      // The pores reopen by the elastic law only (measured 6-10% of what the curve would give
      // back; the bound is a fifth).
      const double atLeast = model->loadingDistention(least[i]);
      EXPECT_LT(distention(p)[i] - atLeast, 0.2 * (model->loadingDistention(eps[i]) - atLeast)) << i;
    }
  }
  // Most of the slab was compacted into the power law and has given back > 1% of strain.
  EXPECT_GT(released, static_cast<int>(p.numReal / 2)) << released << " of " << p.numReal;
  fs::remove_all(dir);
}

// A porous solid's matrix takes only its own share of the strain (JBM08's compaction factor f
// with the -S (dalpha/dt)/alpha term: docs/porosity.md, "The matrix's share of the strain").
// Under uniaxial strain, elastic, the matrix's deviatoric stress then depends on the matrix's
// density alone: S_s,xx = alpha S_xx = -(4/3) G ln(rho_s / rho_s0), whatever path the pores took
// to close. The JBM08 slab (P-alpha and epsilon-alpha) with an elastic matrix, through the
// precursor and the compaction shock, with global steps and on time bins (":individual").
class PorousSolid : public ::testing::TestWithParam<const char*> {};

TEST_P(PorousSolid, MatrixStressFollowsTheMatrixStrainAlone) {
  const std::string param = GetParam();
  const bool individual = param.ends_with(":individual");
  const std::string scene = param.substr(0, param.find(':'));
  const fs::path dir = tempDir(std::string("solid_") + scene);
  fs::remove_all(dir);
  RunOptions options = compactionRun(dir, "6 us", scene);
  addElasticMatrix(options);
  if (individual) options.overrides.push_back("time.stepping=\"individual\"");
  const double G = 26e9;
  const Scene parsed = parseScene(options.sceneSource, scene + ".toml", options.overrides);
  ASSERT_TRUE(runScene(parsed, options).ok);
  const MaterialTable materials = MaterialTable::fromScene(parsed);
  const double rhoS0 = parsed.bodies[0].density * materials[0].porosity->initialDistention();
  SnapshotInfo info;
  const ParticleSet p = snapshotAt(dir, 6, info);
  // The compacted plateau between the wall's start-up layer (x < 1 mm) and the shock (~9 mm at
  // 6 us); the precursor ahead of the shock, elastic, to the free end's release (x > 30 mm).
  double plateau = 0.0, precursor = 0.0, precursorStress = 0.0;
  int inPlateau = 0;
  for (std::size_t i = 0; i < p.numReal; ++i) {
    const double x = p.x[0][i], alpha = distention(p)[i];
    const double exact = -4.0 / 3.0 * G * std::log(alpha * p.rho[i] / rhoS0);
    const double error = std::abs(alpha * p.stress[0][i] - exact);
    if (x > 1e-3 && x < 6e-3) {
      plateau = std::max(plateau, error / std::abs(exact));
      ++inPlateau;
    } else if (x > 12e-3 && x < 30e-3) {
      precursor = std::max(precursor, error);
      precursorStress = std::max(precursorStress, std::abs(exact));
    }
  }
  ASSERT_GT(inPlateau, 40);
  // The plateau (matrix stress 0.44-0.51 GPa): measured within 16.5% (P-alpha) and 5.8%
  // (epsilon-alpha) with global steps, 9.1% and 1.6% on time bins, whose steps are shorter in the
  // shock: f is each step's share, used in the next step, and the front compacts in a few steps.
  // Without the alpha term 19.8%, 9.1%, 12.5% and 4.4%; with the matrix strained as the bulk
  // (f = 1) a factor 26-29 off (the bulk's strain, ln(rho/rho_0) ~ 0.26 against the matrix's
  // ~0.017, would give ~8.9 GPa).
  const bool palpha = scene == "compaction_1d";
  const double bound = individual ? (palpha ? 0.11 : 0.025) : (palpha ? 0.18 : 0.07);
  EXPECT_LT(plateau, bound) << param;
  // The precursor is elastic compaction with no shock: to 1e-4 of its stress (measured
  // 1.6e-5 to 4.0e-5; 5e-4 to 1e-3 without the alpha term).
  EXPECT_LT(precursor, 1e-4 * precursorStress) << param;
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(BothModels, PorousSolid,
                         ::testing::Values("compaction_1d", "compaction_epsalpha_1d",
                                           "compaction_1d:individual",
                                           "compaction_epsalpha_1d:individual"));

std::string withPorosity(const std::string& eos, const std::string& table) {
  return "[scene]\nname = \"p\"\ndimension = \"1d\"\n[time]\nt_end = 1e-6\n"
         "[[materials]]\nname = \"rubble\"\n" + eos + "\n[materials.porosity]\n" + table +
         "\n[[bodies]]\nname = \"b\"\nmaterial = \"rubble\"\nshape = \"box\"\nmin = [0.0]\n"
         "max = [0.01]\nspacing = 0.001\ndensity = 2000.0\npressure = 0.0\n";
}

TEST(PorosityPackage, BadTablesAreRefusedWithTheirReason) {
  const std::string granite = "eos = \"tillotson\"\nlibrary = \"granite\"";
  const std::string crush = "elastic_pressure = \"0.1 GPa\"\nsolid_pressure = \"1 GPa\"\n";
  auto error = [&](const std::string& eos, const std::string& table) {
    return test::materialSceneError(withPorosity(eos, "model = \"p_alpha\"\n" + table));
  };
  const std::string both = error(granite, crush + "porosity = 0.3\ninitial_distention = 1.4");
  EXPECT_NE(both.find("bad.toml"), std::string::npos) << both;
  EXPECT_NE(both.find("material 'rubble'"), std::string::npos) << both;
  EXPECT_NE(both.find("exactly one of porosity"), std::string::npos) << both;
  EXPECT_NE(error(granite, crush).find("exactly one of porosity"), std::string::npos);
  EXPECT_NE(error(granite, crush + "porosity = 1.0").find("must be below 1"), std::string::npos);
  EXPECT_NE(error(granite, "porosity = 0.3\nelastic_pressure = 1e8").find("solid_pressure"),
            std::string::npos);
  EXPECT_NE(error("eos = \"ideal_gas\"", crush + "porosity = 0.3").find("matrix density"),
            std::string::npos);
  EXPECT_NE(error(granite, crush + "porosity = 0.3\nporous_sound_speed = \"9 km/s\"")
                .find("porous_sound_speed"),
            std::string::npos);
  const std::string unknown = error(granite, crush + "porosity = 0.3\nalpha_0 = 1.4");
  EXPECT_NE(unknown.find("alpha_0"), std::string::npos) << unknown;
  EXPECT_EQ(error(granite, crush + "porosity = 0.3"), "no error");
  // A key of the other model is named with the model it belongs to.
  const std::string other = error(granite, crush + "porosity = 0.3\nkappa = 0.9");
  EXPECT_NE(other.find("porosity.kappa does not apply to model \"p_alpha\"; it applies only to "
                       "\"epsilon_alpha\""),
            std::string::npos)
      << other;
}

TEST(PorosityPackage, BadEpsilonAlphaTablesAreRefusedWithTheirReason) {
  const std::string granite = "eos = \"tillotson\"\nlibrary = \"granite\"";
  const std::string sand = "porosity = 0.44\nkappa = 0.988\ntransition_distention = 1.29\n";
  auto error = [&](const std::string& table) {
    return test::materialSceneError(withPorosity(granite, "model = \"epsilon_alpha\"\n" + table));
  };
  EXPECT_EQ(error(sand + "sound_speed_ratio = 0.33\nelastic_strain = 1e-4"), "no error");
  EXPECT_NE(error("porosity = 0.44\nkappa = 0.9").find("needs transition_distention"),
            std::string::npos);
  const std::string kappa = error("porosity = 0.44\nkappa = 1.2\ntransition_distention = 1.29");
  EXPECT_NE(kappa.find("material 'rubble'"), std::string::npos) << kappa;
  EXPECT_NE(kappa.find("kappa must lie in (0, 1)"), std::string::npos) << kappa;
  EXPECT_NE(error(sand + "sound_speed_ratio = 1.5").find("sound_speed_ratio"), std::string::npos);
  EXPECT_NE(error("porosity = 0.44\nkappa = 0.9\ntransition_distention = 2.5")
                .find("transition_distention (alpha_x) must lie in"),
            std::string::npos);
  const std::string pressure = error(sand + "elastic_pressure = \"1 MPa\"");
  EXPECT_NE(pressure.find("porosity.elastic_pressure does not apply to model \"epsilon_alpha\""),
            std::string::npos)
      << pressure;
}

}  // namespace
}  // namespace ejecta
