// The catalog of strength models (sim/solid/strength_catalog.hpp): every row builds from its
// required keys, its keys are documented and reach the scene schema, an unknown model or a key
// of another model is refused by name, and a model defined here, outside the catalog, builds
// through the same path (a new model is one file, a catalog row and a test).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/input_error.hpp"
#include "sim/solid/materials.hpp"
#include "sim/solid/model_keys.hpp"
#include "sim/solid/strength_catalog.hpp"
#include "sim/solid/strength_library.hpp"

namespace ejecta {
namespace {

ModelSpec strengthTable(std::string_view model, std::vector<std::pair<std::string, double>> values) {
  ModelSpec s;
  s.present = true;
  s.model = std::string(model);
  s.values = std::move(values);
  return s;
}

// The row's required keys, the k-th set to (k + 1) MPa-ish: a valid set for every model of the
// catalog (Collins needs friction_intact > 0 and strength_limit > cohesion).
ModelSpec requiredOnly(const StrengthModelRow& row) {
  std::vector<std::pair<std::string, double>> values{{"shear_modulus", 25e9}};
  double v = 1e6;
  for (std::string_view key : row.required) {
    values.emplace_back(std::string(key), v);
    v += 1e6;
  }
  return strengthTable(row.name, std::move(values));
}

// The message buildStrength throws for `spec` under `rows`, or "no error".
std::string buildError(const ModelSpec& spec,
                       const std::vector<StrengthModelRow>& rows = strengthCatalog()) {
  std::optional<double> melt;
  try {
    buildStrength(spec, rows, melt);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "no error";
}

TEST(StrengthCatalog, ListsTheFiveModelsInKeyReferenceOrder) {
  std::vector<std::string_view> names;
  for (const StrengthModelRow& r : strengthCatalog()) names.push_back(r.name);
  EXPECT_EQ(names, (std::vector<std::string_view>{"elastic", "von_mises", "johnson_cook", "collins",
                                                  "drucker_prager"}));
}

TEST(StrengthCatalog, EveryRowBuildsFromItsRequiredKeys) {
  for (const StrengthModelRow& row : strengthCatalog()) {
    std::optional<double> melt;
    const StrengthModel m = buildStrength(requiredOnly(row), strengthCatalog(), melt);
    EXPECT_EQ(m.shearModulus, 25e9) << row.name;
    EXPECT_FALSE(melt.has_value()) << row.name;  // no library: no melting point from it
    const double flow = m.flowStress(0.0, 1.0, 300.0, 1000.0, 1e8, 0.0);
    EXPECT_FALSE(std::isnan(flow)) << row.name;
    EXPECT_GT(flow, 0.0) << row.name;
    EXPECT_EQ(m.flowStress(0.0, 1.0, 1000.0, 1000.0, 1e8, 0.0), 0.0) << row.name;  // molten
    EXPECT_EQ(m.yieldCarriesDamage(), row.name == "collins" || row.name == "drucker_prager")
        << row.name;
    // Each required key is needed: without it the model is refused, naming the key.
    for (std::string_view key : row.required) {
      ModelSpec less = requiredOnly(row);
      std::erase_if(less.values, [&](const auto& kv) { return kv.first == key; });
      EXPECT_NE(buildError(less).find("strength." + std::string(key) + " is required for model \"" +
                                      std::string(row.name) + "\""),
                std::string::npos)
          << row.name << " " << key;
    }
  }
  // Johnson-Cook's constants come from a library entry instead, which says so in the message.
  EXPECT_NE(buildError(strengthTable("johnson_cook", {{"shear_modulus", 25e9}}))
                .find("strength.A is required for model \"johnson_cook\" without a library"),
            std::string::npos);
  ModelSpec library = strengthTable("johnson_cook", {});
  library.library = "Al-2024-T351";
  std::optional<double> melt;
  const StrengthModel al = buildStrength(library, strengthCatalog(), melt);
  EXPECT_EQ(al.shearModulus, findStrengthEntry("Al-2024-T351")->shearModulus);
  EXPECT_EQ(melt, 775.0);
  EXPECT_DOUBLE_EQ(al.flowStress(0.0, 1.0, 294.0, 775.0), 265e6);
}

TEST(StrengthCatalog, RowsAreDocumentedAndReachTheSceneSchema) {
  const ModelFamily& family = strengthModelFamily();
  ASSERT_EQ(family.models.size(), strengthCatalog().size());
  for (std::size_t i = 0; i < strengthCatalog().size(); ++i) {
    const StrengthModelRow& row = strengthCatalog()[i];
    EXPECT_FALSE(row.doc.empty()) << row.name;
    EXPECT_NE(row.make, nullptr) << row.name;
    EXPECT_EQ(family.models[i].name, row.name);
    EXPECT_EQ(family.models[i].doc, row.doc);
    EXPECT_EQ(family.models[i].keys.front(), "shear_modulus") << row.name;
    for (const config::KeySpec& k : row.keys) {
      EXPECT_FALSE(k.doc.empty()) << row.name << " " << k.name;
      EXPECT_FALSE(k.defaultText.empty()) << row.name << " " << k.name;
      EXPECT_NE(k.kind, config::KeyKind::Unspecified) << row.name << " " << k.name;
      const config::KeySpec* inSchema = config::findKey(family.keys, k.name);
      ASSERT_NE(inSchema, nullptr) << row.name << " " << k.name;
      EXPECT_EQ(inSchema->doc, k.doc);
    }
    for (std::string_view key : row.required)
      EXPECT_NE(config::findKey(row.keys, key), nullptr) << row.name << " requires " << key;
  }
  const config::KeySpec* model = config::findKey(family.keys, "model");
  ASSERT_NE(model, nullptr);
  EXPECT_EQ(model->allowed,
            (std::vector<std::string_view>{"elastic", "von_mises", "johnson_cook", "collins",
                                           "drucker_prager"}));
}

TEST(StrengthCatalog, AnUnknownModelIsRefusedWithTheListOfModels) {
  const std::string e = buildError(strengthTable("mohr_coulomb", {{"shear_modulus", 25e9}}));
  EXPECT_NE(e.find("strength.model \"mohr_coulomb\" is not a strength model"), std::string::npos) << e;
  EXPECT_NE(e.find("\"elastic\", \"von_mises\", \"johnson_cook\", \"collins\", \"drucker_prager\""),
            std::string::npos) << e;
  // Through the material table (a spec built in code, not read from a scene, which checks the
  // name itself): the SceneError names the material. It used to fall back to Johnson-Cook.
  MaterialSpec spec;
  spec.name = "rock";
  spec.line = 7;
  spec.strength = strengthTable("mohr_coulomb", {{"shear_modulus", 25e9}});
  try {
    MaterialTable::fromSpecs({spec}, "scene.toml");
    ADD_FAILURE() << "an unknown strength model was accepted";
  } catch (const SceneError& err) {
    const std::string what = err.what();
    EXPECT_NE(what.find("scene.toml:7: material 'rock': strength.model \"mohr_coulomb\""),
              std::string::npos) << what;
  }
}

TEST(StrengthCatalog, AKeyOfAnotherModelIsRefusedNamingTheModel) {
  ModelSpec elastic = strengthTable("elastic", {{"shear_modulus", 25e9}, {"A", 1e8}});
  EXPECT_NE(buildError(elastic).find("strength.A does not apply to model \"elastic\"; strength.A "
                                     "applies only to model \"johnson_cook\""),
            std::string::npos)
      << buildError(elastic);
  ModelSpec jc = requiredOnly(*findStrengthModel(strengthCatalog(), "johnson_cook"));
  jc.values.emplace_back("yield_stress", 1e8);
  EXPECT_NE(buildError(jc).find("applies only to model \"von_mises\""), std::string::npos)
      << buildError(jc);
  ModelSpec vm = requiredOnly(*findStrengthModel(strengthCatalog(), "von_mises"));
  vm.values.emplace_back("cohesion_damaged", 1e4);
  EXPECT_NE(buildError(vm).find("strength.cohesion_damaged applies only to model \"collins\""),
            std::string::npos)
      << buildError(vm);
}

// A test-only model, defined as a model file would define it: linear hardening Y0 + H eps_p.
class LinearHardening final : public YieldSurface {
 public:
  LinearHardening(double y0, double h) : y0_(y0), h_(h) {}
  double flowStress(double epsP, double, double, double, double, double) const override {
    return y0_ + h_ * epsP;
  }

 private:
  double y0_, h_;
};

StrengthModelRow linearHardeningRow() {
  using namespace config::keys;
  return {"linear_hardening",
          "test only: Y = Y0 + H eps_p",
          {quantity("initial_yield", Dimension::Pressure, "required", "Y0"),
           quantity("hardening", Dimension::Pressure, "0", "H")},
          {"initial_yield"},
          [](const ModelSpec& s, const StrengthLibraryEntry*) -> std::shared_ptr<const YieldSurface> {
            return std::make_shared<LinearHardening>(s.valueOr("initial_yield", 0.0),
                                                     s.valueOr("hardening", 0.0));
          }};
}

TEST(StrengthCatalog, AModelOutsideTheCatalogBuildsThroughTheSamePath) {
  std::vector<StrengthModelRow> rows = strengthCatalog();
  rows.push_back(linearHardeningRow());
  std::optional<double> melt;
  const StrengthModel m = buildStrength(
      strengthTable("linear_hardening", {{"shear_modulus", 30e9}, {"initial_yield", 2e8}, {"hardening", 1e9}}),
      rows, melt);
  EXPECT_EQ(m.flowStress(0.1, 1.0, 300.0, 1000.0), 2e8 + 1e9 * 0.1);
  EXPECT_EQ(m.flowStress(0.1, 1.0, 1000.0, 1000.0), 0.0);  // melting is the catalog's, not the model's
  EXPECT_FALSE(m.yieldCarriesDamage());
  EXPECT_NE(buildError(strengthTable("linear_hardening", {{"shear_modulus", 30e9}}), rows)
                .find("strength.initial_yield is required for model \"linear_hardening\""),
            std::string::npos);
  EXPECT_NE(buildError(strengthTable("von_mises", {{"shear_modulus", 30e9}, {"yield_stress", 1e8},
                                                   {"hardening", 1e9}}),
                       rows)
                .find("strength.hardening does not apply to model \"von_mises\"; strength.hardening "
                      "applies only to model \"linear_hardening\""),
            std::string::npos);
  // The shipped catalog does not know it.
  EXPECT_NE(buildError(strengthTable("linear_hardening", {{"shear_modulus", 30e9}}))
                .find("is not a strength model"),
            std::string::npos);
}

}  // namespace
}  // namespace ejecta
