// The scene's schema (sim/setup/scene_schema.hpp) is the one source of its keys: docs/scenes.md
// holds exactly the key reference generated from it, every key is documented, the defaults it
// states are those the code applies, and the reader's unknown-key errors list its keys.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include <toml++/toml.h>

#include "core/table_reader.hpp"
#include "core/units.hpp"
#include "sim/eos/eos_catalog.hpp"
#include "sim/io/output_options.hpp"
#include "sim/run/time_options.hpp"
#include "sim/setup/scene.hpp"
#include "sim/setup/scene_schema.hpp"
#include "sim/solid/fracture.hpp"
#include "sim/solid/porosity.hpp"
#include "sim/solid/strain_porosity.hpp"
#include "sim/solid/material_spec.hpp"
#include "sim/solid/model_keys.hpp"
#include "sim/solid/strength_models/johnson_cook.hpp"
#include "sim/solid/thermal.hpp"
#include "sim/sph/sph_options.hpp"

namespace ejecta {
namespace {

using config::KeyKind;
using config::KeySpec;

std::string readFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(SceneKeyReference, DocsHoldTheGeneratedReference) {
  const std::filesystem::path doc = std::filesystem::path(EJECTA_SOURCE_DIR) / "docs/scenes.md";
  const std::string text = readFile(doc);
  ASSERT_FALSE(text.empty()) << doc;
  EXPECT_EQ(keyReferenceIn(text), sceneKeyReferenceMarkdown())
      << "docs/scenes.md's key reference is not the one the schema generates. Regenerate it: "
         "build/apps/ejecta keys --write docs/scenes.md (or paste `ejecta keys --markdown` "
         "between the markers)";
  // Regenerating a current doc changes nothing.
  EXPECT_EQ(withCurrentKeyReference(text), text);
}

TEST(SceneKeyReference, EveryKeyIsDescribed) {
  for (const SceneTable& t : sceneTables()) {
    for (const KeySpec& k : t.keys) {
      const std::string where = std::string(t.path) + " " + std::string(k.name);
      EXPECT_FALSE(k.doc.empty()) << where;
      EXPECT_NE(k.kind, KeyKind::Unspecified) << where;
      if (k.kind != KeyKind::AnyKey) {
        EXPECT_FALSE(k.defaultText.empty()) << where;
      }
      if (k.kind == KeyKind::Enum) {
        EXPECT_FALSE(k.allowed.empty()) << where;
      }
      if (k.kind == KeyKind::Table) {
        // A sub-table key has its own table in the schema, except [domain]'s inline axes.
        const std::string sub = (t.path.empty() ? "" : std::string(t.path) + ".") + std::string(k.name);
        const std::string arr = std::string(k.name) + "[]";
        EXPECT_TRUE(sceneSchema().count(sub) || sceneSchema().count(arr)) << where;
      }
    }
  }
  for (const EosKind& kind : eosKinds()) {
    EXPECT_FALSE(kind.doc.empty()) << kind.name;
    for (const EosParameter& p : kind.parameters) EXPECT_FALSE(p.doc.empty()) << p.key;
  }
  for (const SceneShape& shape : sceneShapes()) {
    EXPECT_FALSE(shape.doc.empty()) << shape.name;
    for (std::string_view k : shape.keys)
      EXPECT_NE(config::findKey(sceneSchema().at("bodies[]"), k), nullptr) << k;
  }
  for (const ModelFamily* f : {&strengthModelFamily(), &fractureModelFamily(), &porosityModelFamily()})
    for (const ModelKind& m : f->models) {
      EXPECT_FALSE(m.doc.empty()) << m.name;
      for (std::string_view k : m.keys) EXPECT_NE(config::findKey(f->keys, k), nullptr) << k;
    }
}

// `v = <text>` as a TOML document; throws toml::parse_error when the text is not a TOML value.
toml::table parseValue(std::string_view text) {
  std::string doc = "v = ";
  doc += text;
  return toml::parse(doc);
}

// The default as a number in SI, when the schema writes it as a TOML value.
std::optional<double> defaultValue(std::string_view path, std::string_view key) {
  const config::KeyList& keys = sceneSchema().at(path);
  const KeySpec* k = config::findKey(keys, key);
  if (!k) ADD_FAILURE() << path << " " << key << ": not in the schema";
  if (!k) return std::nullopt;
  const toml::table t = parseValue(k->defaultText);
  const toml::node& v = *t.get("v");
  if (v.is_boolean()) return *v.value<bool>() ? 1.0 : 0.0;
  if (v.is_string()) return parseQuantity(*v.value<std::string>(), k->dimension);
  return v.value<double>();
}

TEST(SceneKeyReference, DefaultsAreTheCodes) {
  const SphOptions sph;
  const TimeOptions time;
  const OutputOptions out;
  const FieldsOutputOptions fields;
  const CraterAnalysisOptions crater;
  const ImageOutputOptions images;
  const ImageCamera camera;
  const MaterialSpec material;
  const JohnsonCookParameters jc;
  const ThermalModel thermal;
  const FractureModel fracture;
  const PalphaParameters porosity;
  const EpsilonAlphaParameters strainPorosity;
  const std::vector<std::tuple<std::string_view, std::string_view, double>> cases = {
      {"sph", "eta", sph.eta},
      {"sph", "relaxation", sph.relaxation},
      {"sph", "courant", sph.courant},
      {"sph", "force_factor", sph.forceFactor},
      {"sph", "h_min_factor", sph.hMinFactor},
      {"sph", "h_max_factor", sph.hMaxFactor},
      {"sph.viscosity", "alpha", sph.alpha},
      {"sph.viscosity", "beta", sph.beta},
      {"sph.viscosity", "epsilon", sph.epsilon},
      {"sph.viscosity", "balsara", sph.balsara ? 1.0 : 0.0},
      {"sph.viscosity", "alpha_min", sph.alphaMin},
      {"sph.viscosity", "decay", sph.alphaDecay},
      {"sph.conductivity", "alpha", sph.conductivity},
      {"sph.artificial_stress", "n", sph.artificialStressExponent},
      {"time", "dt_max", time.dtMax},
      {"time", "dt_min", time.dtMin},
      {"time", "max_steps", static_cast<double>(time.maxSteps)},
      {"time", "closing_speed", time.closingSpeed ? 1.0 : 0.0},
      {"output", "snapshot_interval", out.snapshotInterval},
      {"output", "snapshots", out.snapshots ? 1.0 : 0.0},
      {"fields", "voxel", fields.voxel},
      {"fields", "every", fields.every},
      {"fields", "level_set", fields.levelSet ? 1.0 : 0.0},
      {"fields", "extrude", fields.extrude},
      {"crater", "enabled", crater.enabled ? 1.0 : 0.0},
      {"crater", "resolution", crater.resolution},
      {"images", "every", images.every},
      {"images", "size", images.size},
      {"images", "surface", images.surface ? 1.0 : 0.0},
      {"images.camera", "fov_degrees", camera.fovDegrees},
      {"materials[]", "gamma", material.gamma},
      {"materials[].thermal", "initial_temperature", thermal.initialTemperature},
      {"materials[].thermal", "molar_mass", kAirMolarMass * 1e3},
      {"materials[].strength", "reference_strain_rate", jc.referenceStrainRate},
      {"materials[].strength", "room_temperature", jc.roomTemperature},
      {"materials[].strength", "cohesion_damaged", 0.0},
      {"materials[].fracture", "crack_speed_factor", fracture.crackSpeedFactor},
      {"materials[].fracture", "max_crack_increment", fracture.maxCrackIncrement},
      {"materials[].fracture", "seed", static_cast<double>(fracture.seed)},
      {"materials[].porosity", "crush_exponent", porosity.crushExponent},
      {"materials[].porosity", "transition_exponent", porosity.transitionExponent},
      {"materials[].porosity", "max_distention_change", porosity.maxChangePerStep},
      {"materials[].porosity", "max_distention_change", strainPorosity.maxChangePerStep},
      {"materials[].porosity", "elastic_strain", -strainPorosity.elasticStrain},
      {"materials[].porosity", "sound_speed_ratio", strainPorosity.soundSpeedRatio},
      {"materials[].porosity", "thermal_strain", strainPorosity.thermalStrain ? 1.0 : 0.0},
  };
  for (const auto& [path, key, code] : cases)
    EXPECT_EQ(defaultValue(path, key), code) << path << "." << key;
}

TEST(SceneKeyReference, TomlDefaultsFitTheirKind) {
  for (const SceneTable& t : sceneTables())
    for (const KeySpec& k : t.keys) {
      toml::table doc;
      try {
        doc = parseValue(k.defaultText);
      } catch (const toml::parse_error&) {
        continue;  // prose: "required", "the bodies at rest", ...
      }
      const toml::node& v = *doc.get("v");
      const std::string where = std::string(t.path) + " " + std::string(k.name);
      switch (k.kind) {
        case KeyKind::Number:
        case KeyKind::Quantity:
          if (v.is_string()) {
            EXPECT_NO_THROW(parseQuantity(*v.value<std::string>(), k.dimension)) << where;
          } else {
            EXPECT_TRUE(v.is_number()) << where;
          }
          break;
        case KeyKind::Integer: EXPECT_TRUE(v.is_integer()) << where; break;
        case KeyKind::Bool: EXPECT_TRUE(v.is_boolean()) << where; break;
        case KeyKind::String: EXPECT_TRUE(v.is_string()) << where; break;
        case KeyKind::Enum: {
          ASSERT_TRUE(v.is_string()) << where;
          bool allowed = false;
          for (std::string_view a : k.allowed) allowed = allowed || a == *v.value<std::string>();
          EXPECT_TRUE(allowed) << where;
          break;
        }
        case KeyKind::Vector3: EXPECT_TRUE(v.is_array() && v.as_array()->size() == 3) << where; break;
        default: EXPECT_TRUE(v.is_array()) << where; break;
      }
    }
  // The list defaults the reader keeps.
  EXPECT_EQ(sceneSchema().at("fields")[0].defaultText,
            "[\"density\", \"temperature\", \"pressure\", \"damage\", \"fractions\"]");
  EXPECT_EQ(FieldsOutputOptions{}.grids,
            (std::vector<std::string>{"density", "temperature", "pressure", "damage", "fractions"}));
}

std::string errorOf(const std::string& toml) {
  try {
    parseScene(toml, "k.toml");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

const char* kMinimal = R"([scene]
name = "k"
dimension = "1d"
[time]
t_end = 1
[[materials]]
name = "gas"
[[bodies]]
name = "b"
material = "gas"
shape = "box"
min = [0]
max = [1]
spacing = 0.1
density = 1
pressure = 1
)";

TEST(SceneKeyReference, UnknownKeysListTheSchemasKeys) {
  ASSERT_EQ(errorOf(kMinimal), "");
  EXPECT_EQ(errorOf(std::string(kMinimal) + "[sph]\nkernal = \"wendland_c2\"\n"),
            "k.toml:18: key 'sph.kernal': unknown key; allowed keys here: kernel, density, "
            "smoothing_length, eta, relaxation, courant, force_factor, h_min_factor, h_max_factor, "
            "viscosity, conductivity, form, gradients, volume_elements, volume_exponent, "
            "dissipation, artificial_stress");
  EXPECT_NE(errorOf(std::string(kMinimal) + "[materials.fracture]\nmodel = \"none\"\nsed = 2\n")
                .find("allowed keys here: model, weibull_k, weibull_m, tensile_strength, "
                      "erosion_strain, crack_speed_factor, max_crack_increment, seed"),
            std::string::npos);
  // An enum's values are the schema's.
  const std::string bad = errorOf(std::string(kMinimal) + "[sph]\nkernel = \"x\"\n");
  for (std::string_view v : config::findKey(sceneSchema().at("sph"), "kernel")->allowed)
    EXPECT_NE(bad.find(std::string(v).insert(0, "'") + "'"), std::string::npos) << bad;
}

// Readers that list names alone (radiation/'s files) still build their schema from strings.
TEST(SceneKeyReference, NameOnlyKeyLists) {
  const config::SchemaTables schema{{"", {"name", "shape"}}, {"faces[]", {"*"}}};
  const config::KeyList& keys = schema.at("");
  EXPECT_EQ(config::joinKeys(keys), "name, shape");
  EXPECT_TRUE(config::contains(keys, "shape"));
  EXPECT_FALSE(config::contains(keys, "size"));
  EXPECT_TRUE(config::contains(schema.at("faces[]"), "anything"));
  std::string names;
  for (std::string_view k : keys) names += k;
  EXPECT_EQ(names, "nameshape");
}

}  // namespace
}  // namespace ejecta
