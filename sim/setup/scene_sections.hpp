#pragma once
// The sections of the scene reader (sim/setup/scene.cpp): each reads its tables of a scene into
// the Scene, checked against the schema (scene_schema.cpp). Internal to sim/setup/.
#include <set>
#include <string>

#include "sim/setup/scene.hpp"
#include "core/table_reader.hpp"

namespace ejecta::scene_detail {

using namespace ejecta::config;  // the shared TOML reader (core/table_reader.hpp)

// The scene's schema, and the keys of one of its tables (nullptr: no such table).
const SchemaTables& schemaTables();
const KeyList* allowedKeys(std::string_view schemaPath);

// --set: applies "dotted.key=value" to the document before it is validated.
void applyOverride(toml::table& root, const std::string& text, const std::string& sourceName);

// [scene], [domain], [sph], [time], [output]           (scene_run_sections.cpp)
void readScene(const TableReader& root, Scene& scene);
void readDomain(const TableReader& root, Scene& scene);
void readTime(const TableReader& root, TimeOptions& time);
void readSph(const TableReader& root, SphOptions& sph);
// sph.gradients = "iad" against the geometry, the stepping and the materials (after those).
void checkGradientScheme(const TableReader& root, const Scene& scene);
// sph.volume_elements = "generalised" against the geometry, the stepping and the materials.
void checkVolumeElements(const TableReader& root, const Scene& scene);
// sph.dissipation = "riemann" against the materials.
void checkDissipation(const TableReader& root, const Scene& scene);
// tEnd: the run's length (read first), against which the snapshot cadence is checked.
void readOutput(const TableReader& root, OutputOptions& out, double tEnd);
// [fields], [crater], [images], [thermal]              (scene_output_sections.cpp)
void readFields(const TableReader& root, Scene& scene);
void readCrater(const TableReader& root, Scene& scene);
void readImages(const TableReader& root, Scene& scene);
void readThermal(const TableReader& root, Scene& scene);
// [fragments], [shield]                                (scene_analysis_sections.cpp)
void readFragments(const TableReader& root, Scene& scene);
void readShield(const TableReader& root, Scene& scene);
// [[materials]]                                        (scene_materials.cpp)
void readMaterials(const TableReader& root, Scene& scene);
// [[bodies]], shapes, voids                            (scene_bodies.cpp)
void readBodies(const TableReader& root, Scene& scene);
// [[energy_deposits]], [[detonations]], [[gauges]]     (scene_sources.cpp)
void readDeposits(const TableReader& root, Scene& scene);
void readDetonations(const TableReader& root, Scene& scene);
void readGauges(const TableReader& root, Scene& scene);

// Shared by the sections.
// Names within one list must be unique: bodies and deposits are reported by name.
void checkUniqueName(const TableReader& r, std::set<std::string>& seen, const std::string& name);
// "[x]", "[x, y]", "[r, z]", "[x, y, z]": how a vector is written in this geometry.
std::string vectorLayout(Geometry g);
// Bounding box of the part of the domain a shape may occupy ([-inf, inf] where unbounded).
struct Box {
  std::array<double, 3> lo{}, hi{};
};
Box domainBox(const Scene& scene);
void readShape(const TableReader& r, const Scene& scene, ShapeSpec& shape);

}  // namespace ejecta::scene_detail
