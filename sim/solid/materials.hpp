#pragma once
// MaterialTable: per-material models, indexed by the particles' material id.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sim/eos/eos.hpp"
#include "sim/solid/fracture.hpp"
#include "sim/solid/material_spec.hpp"
#include "sim/solid/porosity_model.hpp"
#include "sim/solid/strength.hpp"
#include "sim/solid/thermal.hpp"

namespace ejecta {

struct Scene;

// One material: its equation of state, thermal model, and optional strength and fracture.
// A material without strength is a fluid (no deviatoric stress, no tension limit).
struct Material {
  std::string name;
  std::shared_ptr<const EquationOfState> eos;
  ThermalModel thermal;
  std::optional<StrengthModel> strength;
  FractureModel fracture;  // kind None: never fails
  // Pores below the resolution: P-alpha (sim/solid/porosity.hpp) or epsilon-alpha
  // (sim/solid/strain_porosity.hpp); null where the material has none.
  std::shared_ptr<const PorosityModel> porosity;
};

class MaterialTable {
 public:
  MaterialTable() = default;
  explicit MaterialTable(std::vector<Material> materials) : materials_(std::move(materials)) {}
  // The materials as specified, in order; throws SceneError naming `sourcePath`, the line and
  // the material for a bad model.
  static MaterialTable fromSpecs(const std::vector<MaterialSpec>& specs, const std::string& sourcePath);
  // fromSpecs of the scene's materials (defined in sim/setup/, which knows the Scene).
  static MaterialTable fromScene(const Scene& scene);

  std::size_t size() const { return materials_.size(); }
  const Material& operator[](std::size_t i) const { return materials_[i]; }
  void add(Material m) { materials_.push_back(std::move(m)); }
  bool anyStrength() const;
  bool anyFracture() const;
  bool anyPorosity() const;
  bool anyPhaseChanges() const;

 private:
  std::vector<Material> materials_;
};

}  // namespace ejecta
