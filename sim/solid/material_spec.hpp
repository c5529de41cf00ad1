#pragma once
// A material as a scene gives it ([[materials]]): its equation of state and optional thermal,
// strength, fracture and porosity model tables, in SI.
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace ejecta {

// One optional model table of a material ([materials.thermal], [materials.strength],
// [materials.fracture]): a model name, a library entry, and values in SI by key.
struct ModelSpec {
  bool present = false;
  std::string model;
  std::string library;
  std::vector<std::pair<std::string, double>> values;
  int line = 0;
  const double* find(std::string_view key) const {
    for (const auto& [k, v] : values)
      if (k == key) return &v;
    return nullptr;
  }
  // The value of `key`, or `fallback` where the table does not give it.
  double valueOr(std::string_view key, double fallback) const {
    const double* v = find(key);
    return v ? *v : fallback;
  }
};

struct MaterialSpec {
  std::string name;
  std::string eos = "ideal_gas";  // a kind of sim/eos/eos_catalog.hpp
  double gamma = 1.4;             // ideal gas adiabatic index
  std::string library;            // library entry of the eos (e.g. "granite"); empty: none
  std::vector<std::pair<std::string, double>> parameters;  // overrides, SI
  ModelSpec thermal;              // keys: sim/solid/materials.cpp; docs/scenes.md
  ModelSpec strength;
  ModelSpec fracture;
  ModelSpec porosity;
  int line = 0;                   // source line in the scene file, for later messages
};

}  // namespace ejecta
