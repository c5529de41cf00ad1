#pragma once
// The shape tables of geometry files, shared with thermal studies (whose [spacecraft] is a
// geometry file's body without its pose): one reader, so both accept the same keys and units.
#include <filesystem>

#include "core/table_reader.hpp"
#include "radiation/geometry_file.hpp"

namespace ejecta::radiation {

enum class ShapeRole {
  Spacecraft,  // box, cylinder or mesh; shape and size required
  StudyBody,   // the same; a 1 m box when shape or size is not given
  Plate,       // rectangle, disc, sphere or mesh, with a name
};

// The shape of table `t`; a relative mesh path is taken from `base`. Raises the Context's error.
SurfaceShape readShape(const config::TableReader& t, ShapeRole role, const std::filesystem::path& base);

}  // namespace ejecta::radiation
