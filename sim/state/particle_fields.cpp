#include "sim/state/particle_fields.hpp"

#include <cmath>
#include <stdexcept>

namespace ejecta {

const std::vector<ParticleFieldInfo>& particleScalarFields() {
  static const std::vector<ParticleFieldInfo> fields{
      {"density", "kg/m^3", "mass density"},
      {"temperature", "K", "temperature"},
      {"pressure", "Pa", "pressure"},
      {"internal_energy", "J/kg", "specific internal energy"},
      {"sound_speed", "m/s", "sound speed"},
      {"damage", "1", "fracture damage D (0 intact, 1 fully damaged)"},
      {"plastic_strain", "1", "equivalent plastic strain"},
      {"speed", "m/s", "magnitude of the velocity"},
      {"velocity_x", "m/s", "velocity, x component (RZ: radial)"},
      {"velocity_y", "m/s", "velocity, y component (RZ: axial)"},
      {"velocity_z", "m/s", "velocity, z component"},
      {"smoothing_length", "m", "smoothing length h"},
      {"burn_fraction", "1", "programmed-burn fraction (1 where nothing burns)"},
  };
  return fields;
}

const ParticleFieldInfo* findParticleScalarField(std::string_view name) {
  for (const ParticleFieldInfo& f : particleScalarFields())
    if (f.name == name) return &f;
  return nullptr;
}

std::string particleScalarFieldList() {
  std::string out;
  for (const ParticleFieldInfo& f : particleScalarFields())
    out += (out.empty() ? "'" : ", '") + std::string(f.name) + "'";
  return out;
}

std::vector<double> particleScalarField(const ParticleSet& p, std::string_view name) {
  const std::size_t n = p.numReal;
  auto copy = [n](const std::vector<double>& a) {
    return a.size() >= n ? std::vector<double>(a.begin(), a.begin() + n) : std::vector<double>(n, 0.0);
  };
  if (name == "density") return copy(p.rho);
  if (name == "temperature") return copy(p.temperature);
  if (name == "pressure") return copy(p.P);
  if (name == "internal_energy") return copy(p.u);
  if (name == "sound_speed") return copy(p.cs);
  if (name == "plastic_strain") return copy(p.plasticStrain);
  if (name == "smoothing_length") return copy(p.h);
  if (name == "burn_fraction") return p.hasBurn() ? copy(p.burnFraction) : std::vector<double>(n, 1.0);
  if (name == "velocity_x") return copy(p.v[0]);
  if (name == "velocity_y") return copy(p.v[1]);
  if (name == "velocity_z") return copy(p.v[2]);
  std::vector<double> out(n, 0.0);
  if (name == "damage") {
    for (std::size_t i = 0; i < n; ++i) out[i] = p.damage(i);
    return out;
  }
  if (name == "speed") {
    for (std::size_t i = 0; i < n; ++i)
      out[i] = std::sqrt(p.v[0][i] * p.v[0][i] + p.v[1][i] * p.v[1][i] + p.v[2][i] * p.v[2][i]);
    return out;
  }
  throw std::invalid_argument("unknown particle field '" + std::string(name) +
                              "' (known: " + particleScalarFieldList() + ")");
}

}  // namespace ejecta
