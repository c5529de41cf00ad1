#pragma once
// MaterialTable: per-material models, indexed by the particles' material id.
#include <memory>
#include <string>
#include <vector>

#include "sim/eos.hpp"

namespace ejecta {

struct Scene;

struct Material {
  std::string name;
  std::shared_ptr<const EquationOfState> eos;
};

class MaterialTable {
 public:
  MaterialTable() = default;
  explicit MaterialTable(std::vector<Material> materials) : materials_(std::move(materials)) {}
  static MaterialTable fromScene(const Scene& scene);

  std::size_t size() const { return materials_.size(); }
  const Material& operator[](std::size_t i) const { return materials_[i]; }
  void add(Material m) { materials_.push_back(std::move(m)); }

 private:
  std::vector<Material> materials_;
};

}  // namespace ejecta
