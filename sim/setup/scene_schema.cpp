// The scene's schema: the keys allowed in every table (sim/setup/scene_sections.hpp).
#include "sim/setup/scene_sections.hpp"

namespace ejecta::scene_detail {

// The schema: allowed keys of every table, by schema path ("bodies[]" = any element).
const SchemaTables& schemaTables() {
  static const std::map<std::string_view, KeyList> tables = [] {
    const KeyList axis{"min", "max", "boundary", "lower", "upper"};
    return std::map<std::string_view, KeyList>{
        {"",
         {"scene", "domain", "sph", "time", "output", "fields", "crater", "materials", "bodies",
          "energy_deposits", "detonations", "gauges", "images", "thermal"}},
        {"scene", {"name", "description", "dimension"}},
        {"domain", {"x", "y", "z"}},
        {"domain.x", axis},
        {"domain.y", axis},
        {"domain.z", axis},
        {"sph",
         {"kernel", "density", "smoothing_length", "eta", "relaxation", "courant", "force_factor",
          "h_min_factor", "viscosity", "conductivity", "form", "artificial_stress"}},
        {"sph.viscosity", {"alpha", "beta", "epsilon", "balsara", "switch", "alpha_min", "decay",
                            "reconstruction"}},
        {"sph.conductivity", {"alpha"}},
        {"sph.artificial_stress", {"epsilon", "n"}},
        {"time", {"t_end", "dt_max", "dt_min", "max_steps"}},
        {"output", {"snapshot_interval", "snapshots"}},
        {"fields",
         {"grids", "voxel", "normalise", "every", "level_set", "extrude", "region_min",
          "region_max"}},
        {"crater", {"enabled", "materials", "resolution"}},
        {"materials[]",
         {"name", "eos", "gamma", "library", "parameters", "thermal", "strength", "fracture"}},
        {"materials[].parameters", {"*"}},  // keys depend on the eos: checked in readMaterials
        {"materials[].thermal",
         {"library", "specific_heat", "mean_atomic_mass", "molar_mass", "initial_temperature",
          "melt_temperature"}},
        {"materials[].strength",
         {"model", "library", "shear_modulus", "yield_stress", "A", "B", "n", "C", "m",
          "reference_strain_rate", "room_temperature", "cohesion", "friction_intact",
          "strength_limit", "friction_damaged", "cohesion_damaged"}},
        {"materials[].fracture",
         {"model", "weibull_k", "weibull_m", "tensile_strength", "erosion_strain",
          "crack_speed_factor", "max_crack_increment", "seed"}},
        {"bodies[]",
         {"name", "material", "shape", "min", "max", "center", "radius", "inner_radius",
          "outer_radius", "point", "normal", "lattice", "spacing", "density", "pressure",
          "internal_energy", "velocity", "damage", "void", "depth"}},
        {"energy_deposits[]",
         {"name", "energy", "body", "center", "radius", "profile", "width", "time"}},
        {"detonations[]", {"name", "material", "point", "line_to", "time", "velocity"}},
        {"gauges[]", {"name", "position"}},
        {"images", {"fields", "log", "every", "size", "cut", "cut_at", "camera", "grids", "surface"}},
        {"images.camera", {"position", "target", "up", "fov_degrees"}},
        {"thermal", {"study", "times", "hot_material"}},
    };
  }();
  return tables;
}

const KeyList* allowedKeys(std::string_view schemaPath) {
  const SchemaTables& tables = schemaTables();
  const auto it = tables.find(schemaPath);
  return it == tables.end() ? nullptr : &it->second;
}

}  // namespace ejecta::scene_detail
