#pragma once
// Published colour-map tables (color_map_tables.cpp), for color_map.cpp.
#include <array>
#include <cstdint>

namespace ejecta::render::tables {

extern const std::array<std::array<std::uint8_t, 3>, 256> kViridis;
extern const std::array<std::array<std::uint8_t, 3>, 256> kInferno;

}  // namespace ejecta::render::tables
