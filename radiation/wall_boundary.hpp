#pragma once
// Boundary conditions of the wall heat model. Each face of the wall (hot: facing the emitters,
// x = 0; cold: the inside, x = thickness) either has a fixed temperature or exchanges a flux
//   q_net = absorptivity * q_incident(t, y) - emissivity * sigma * (T^4 - T_sink^4)   [W/m^2]
// (the radiative balance of radiative_balance.hpp; insulated: no incident flux and zero
// emissivity). In 2D the two ends of the face (y = 0 and y = length) are insulated or held at a
// fixed temperature. Where a fixed face meets fixed ends, the face's temperature wins.
// docs/thermal_wall.md.
#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "radiation/layered_wall.hpp"
#include "radiation/radiative_balance.hpp"
#include "radiation/wall_materials.hpp"

namespace ejecta::radiation {

struct FaceCondition {
  enum class Kind { Flux, FixedTemperature };
  Kind kind = Kind::Flux;
  SurfaceFlux incident;          // empty: no incident flux
  double absorptivity = 1.0;     // fraction of `incident` absorbed, [0, 1]
  double emissivity = 0.0;       // re-radiation to the sink, [0, 1]
  double sinkTemperature = 0.0;  // what the face radiates to [K] (deep space: ~3 K, negligible)
  double temperature = 0.0;      // FixedTemperature [K]

  bool radiates() const { return kind == Kind::Flux && emissivity > 0.0; }

  static FaceCondition insulated() { return {}; }
  static FaceCondition fixed(double temperature) {
    FaceCondition f;
    f.kind = Kind::FixedTemperature;
    f.temperature = temperature;
    return f;
  }
  static FaceCondition radiating(double emissivity, double sinkTemperature = 0.0) {
    FaceCondition f;
    f.emissivity = emissivity;
    f.sinkTemperature = sinkTemperature;
    return f;
  }
  static FaceCondition irradiated(SurfaceFlux incident, double absorptivity, double emissivity,
                                  double sinkTemperature = 0.0) {
    FaceCondition f = radiating(emissivity, sinkTemperature);
    f.incident = std::move(incident);
    f.absorptivity = absorptivity;
    return f;
  }
  // Irradiated, with the optical properties of the surface material.
  static FaceCondition irradiated(SurfaceFlux incident, const WallMaterial& surface,
                                  double sinkTemperature = 0.0) {
    return irradiated(std::move(incident), surface.absorptivity, surface.emissivity,
                      sinkTemperature);
  }
};

// The ends of the face in 2D runs.
struct EndCondition {
  enum class Kind { Insulated, FixedTemperature };
  Kind kind = Kind::Insulated;
  double temperature = 0.0;      // FixedTemperature [K]
};

struct WallBoundaries {
  FaceCondition hot;                                // x = 0
  FaceCondition cold = FaceCondition::insulated();  // x = wall thickness
  EndCondition ends;                                // y = 0 and y = face length (2D only)
};

// Throws std::invalid_argument naming the face and the bad value.
inline void validateBoundaries(const WallBoundaries& b) {
  auto checkTemperature = [](double t, const std::string& where) {
    if (!(t >= 0.0 && t < 1e9))
      throw std::invalid_argument("wall boundary, " + where + ": temperature must be >= 0 K");
  };
  for (const auto& [face, name] : {std::pair{&b.hot, "hot face"}, {&b.cold, "cold face"}}) {
    if (face->kind == FaceCondition::Kind::FixedTemperature) {
      checkTemperature(face->temperature, name);
      continue;
    }
    if (!(face->absorptivity >= 0.0 && face->absorptivity <= 1.0))
      throw std::invalid_argument(std::string("wall boundary, ") + name +
                                  ": absorptivity must lie in [0, 1]");
    if (!(face->emissivity >= 0.0 && face->emissivity <= 1.0))
      throw std::invalid_argument(std::string("wall boundary, ") + name +
                                  ": emissivity must lie in [0, 1]");
    checkTemperature(face->sinkTemperature, std::string(name) + " sink");
  }
  if (b.ends.kind == EndCondition::Kind::FixedTemperature)
    checkTemperature(b.ends.temperature, "face ends");
}

// A node on a flux face: where it is and what drives it.
struct FluxFaceNode {
  std::size_t node;
  double width;                  // control width along the face [m] (1 in 1D)
  double y;                      // position along the face [m]
  const FaceCondition* face;
};

// The temperature each node is held at, or a negative value for a free node.
inline std::vector<double> fixedTemperatures(const WallGrid& g, const WallBoundaries& b) {
  std::vector<double> fixed(g.size(), -1.0);
  if (g.is2D() && b.ends.kind == EndCondition::Kind::FixedTemperature)
    for (int i = 0; i < g.nx(); ++i)
      fixed[g.index(i, 0)] = fixed[g.index(i, g.ny() - 1)] = b.ends.temperature;
  for (int j = 0; j < g.ny(); ++j) {
    if (b.hot.kind == FaceCondition::Kind::FixedTemperature)
      fixed[g.index(0, j)] = b.hot.temperature;
    if (b.cold.kind == FaceCondition::Kind::FixedTemperature)
      fixed[g.index(g.nx() - 1, j)] = b.cold.temperature;
  }
  return fixed;
}

// The free nodes of the flux faces that exchange anything (incident flux or re-radiation).
inline std::vector<FluxFaceNode> fluxFaceNodes(const WallGrid& g, const WallBoundaries& b,
                                               const std::vector<double>& fixed) {
  std::vector<FluxFaceNode> nodes;
  auto add = [&](const FaceCondition& face, int i) {
    if (face.kind != FaceCondition::Kind::Flux || (!face.incident && face.emissivity == 0.0))
      return;
    for (int j = 0; j < g.ny(); ++j)
      if (fixed[g.index(i, j)] < 0.0)
        nodes.push_back({g.index(i, j), g.faceWidth(j), g.facePosition(j), &face});
  };
  add(b.hot, 0);
  add(b.cold, g.nx() - 1);
  return nodes;
}

// The absorbed part w * alpha * q(t, y) of a face node's flux [W/m^2 in 1D, W/m in 2D].
inline double absorbedFlux(const FluxFaceNode& n, double t) {
  return n.face->incident ? n.width * n.face->absorptivity * n.face->incident(t, n.y) : 0.0;
}

// The re-radiated part -w * eps * sigma * (T^4 - T_sink^4).
inline double emittedFlux(const FluxFaceNode& n, double temperature) {
  return n.width * netAbsorbedFlux(0.0, 0.0, n.face->emissivity, temperature,
                                   n.face->sinkTemperature);
}

}  // namespace ejecta::radiation
