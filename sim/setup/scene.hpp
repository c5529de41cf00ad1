#pragma once
// Scene: a validated, SI-unit description of one run, as read from a TOML scene file.
// Everything the Simulation assembles comes from here; the engine models no more than this asks.
#include <array>
#include <optional>
#include <string_view>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/input_error.hpp"
#include "sim/io/output_options.hpp"
#include "sim/run/time_options.hpp"
#include "sim/setup/body_spec.hpp"
#include "sim/solid/material_spec.hpp"
#include "sim/sources/gauges.hpp"
#include "sim/sources/source_specs.hpp"
#include "sim/sph/sph_options.hpp"
#include "sim/state/domain.hpp"
#include "sim/state/geometry.hpp"

namespace ejecta {

struct Scene {
  std::string name;
  std::string description;
  std::string sourcePath;                   // file it came from ("<default>" when embedded)
  Geometry geometry = Geometry::Planar;
  DomainBounds domain{};                    // per axis; RZ: axis 0 is r (lower bound = the axis)
  SphOptions sph;
  TimeOptions time;
  std::vector<MaterialSpec> materials;
  std::vector<BodySpec> bodies;             // earlier bodies win where shapes overlap
  std::vector<VoidSpec> voids;              // [[bodies]] entries with void = true
  std::vector<EnergyDepositSpec> deposits;
  std::vector<DetonationSpec> detonations;
  std::vector<GaugeSpec> gauges;
  OutputOptions output;
  FieldsOutputOptions fields;
  CraterAnalysisOptions crater;
  FragmentAnalysisOptions fragments;
  ShieldAnalysisOptions shield;
  ImageOutputOptions images;
  ThermalOutputOptions thermal;
};

// The gauges of a scene, for sim/sources/gauges.hpp.
inline GaugeLayout gaugeLayout(const Scene& scene) {
  return {scene.gauges, scene.geometry, scene.sph.kernel};
}

// Reads and validates a scene file. `overrides` are "dotted.key=value" strings applied before
// validation (the command line's --set). Throws SceneError.
Scene loadScene(const std::string& path, const std::vector<std::string>& overrides = {});
// Same, from TOML text; `sourceName` is used in messages.
Scene parseScene(const std::string& tomlText, const std::string& sourceName,
                 const std::vector<std::string>& overrides = {});

}  // namespace ejecta
