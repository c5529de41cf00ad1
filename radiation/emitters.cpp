#include "radiation/emitters.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace ejecta::radiation {

namespace {

std::uint32_t groupIndex(std::vector<std::string>& names, const std::string& name) {
  for (std::size_t g = 0; g < names.size(); ++g)
    if (names[g] == name) return static_cast<std::uint32_t>(g);
  names.push_back(name);
  return static_cast<std::uint32_t>(names.size() - 1);
}

[[noreturn]] void badElement(const char* array, std::size_t i, const std::string& why) {
  throw std::invalid_argument(std::string("emitter ") + array + "[" + std::to_string(i) + "] " + why);
}

}  // namespace

void Emitters::add(double cx, double cy, double cz, double r, double t, double eps,
                   const std::string& groupName) {
  if (!std::isfinite(cx) || !std::isfinite(cy) || !std::isfinite(cz))
    throw std::invalid_argument("emitter centre must be finite");
  if (!(r > 0.0) || !std::isfinite(r)) throw std::invalid_argument("emitter radius must be > 0");
  if (!(t >= 0.0) || !std::isfinite(t)) throw std::invalid_argument("emitter temperature must be >= 0");
  if (!(eps > 0.0 && eps <= 1.0)) throw std::invalid_argument("emitter emissivity must be in (0, 1]");
  x.push_back(cx);
  y.push_back(cy);
  z.push_back(cz);
  radius.push_back(r);
  temperature.push_back(t);
  emissivity.push_back(eps);
  group.push_back(groupIndex(groupNames, groupName));
}

double Emitters::exitance(std::size_t i) const {
  const double t2 = temperature[i] * temperature[i];
  return emissivity[i] * kStefanBoltzmann * t2 * t2;
}

void Emitters::append(const Emitters& other) {
  for (std::size_t i = 0; i < other.size(); ++i)
    add(other.x[i], other.y[i], other.z[i], other.radius[i], other.temperature[i],
        other.emissivity[i], other.groupNames[other.group[i]]);
}

Emitters selectEmitters(const EmitterSource& s, const EmitterSelection& sel) {
  const std::size_t n = s.x.size();
  auto checkLength = [n](std::size_t len, const char* name) {
    if (len != n)
      throw std::invalid_argument(std::string("emitter array ") + name + " has " +
                                  std::to_string(len) + " elements, x has " + std::to_string(n));
  };
  checkLength(s.y.size(), "y");
  checkLength(s.z.size(), "z");
  checkLength(s.radius.size(), "radius");
  checkLength(s.temperature.size(), "temperature");
  if (!s.material.empty()) checkLength(s.material.size(), "material");
  if (!std::isfinite(sel.minTemperature))
    throw std::invalid_argument("emitter minimum temperature must be finite");
  for (std::size_t m = 0; m < sel.emissivityByMaterial.size(); ++m)
    if (!(sel.emissivityByMaterial[m] > 0.0 && sel.emissivityByMaterial[m] <= 1.0))
      throw std::invalid_argument("emissivity of material " + std::to_string(m) + " must be in (0, 1]");
  if (!(sel.defaultEmissivity > 0.0 && sel.defaultEmissivity <= 1.0))
    throw std::invalid_argument("default emissivity must be in (0, 1]");

  Emitters out;
  std::vector<int> groupOfMaterial;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = s.temperature[i];
    if (!std::isfinite(t) || t < 0.0) badElement("temperature", i, "must be finite and >= 0");
    if (t < sel.minTemperature) continue;
    if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i]) || !std::isfinite(s.z[i]))
      badElement("x", i, "(centre) is not finite");
    if (!(s.radius[i] > 0.0) || !std::isfinite(s.radius[i])) badElement("radius", i, "must be > 0");
    const int m = s.material.empty() ? 0 : s.material[i];
    if (m < 0) badElement("material", i, "is negative");
    const auto mu = static_cast<std::size_t>(m);
    const double eps =
        mu < sel.emissivityByMaterial.size() ? sel.emissivityByMaterial[mu] : sel.defaultEmissivity;
    // The group of each material is looked up once (a name per element would cost a string).
    if (mu >= groupOfMaterial.size()) groupOfMaterial.resize(mu + 1, -1);
    if (groupOfMaterial[mu] < 0) {
      const std::string name =
          mu < sel.materialNames.size() ? sel.materialNames[mu] : "material" + std::to_string(m);
      groupOfMaterial[mu] = static_cast<int>(groupIndex(out.groupNames, name));
    }
    out.x.push_back(s.x[i]);
    out.y.push_back(s.y[i]);
    out.z.push_back(s.z[i]);
    out.radius.push_back(s.radius[i]);
    out.temperature.push_back(t);
    out.emissivity.push_back(eps);
    out.group.push_back(static_cast<std::uint32_t>(groupOfMaterial[mu]));
  }
  return out;
}

Emitters selectVoxelEmitters(const VoxelEmitterSource& s, const EmitterSelection& sel) {
  const std::size_t n = s.x.size();
  auto checkLength = [n](std::size_t len, const std::string& name) {
    if (len != n)
      throw std::invalid_argument("voxel array " + name + " has " + std::to_string(len) +
                                  " elements, x has " + std::to_string(n));
  };
  checkLength(s.y.size(), "y");
  checkLength(s.z.size(), "z");
  checkLength(s.temperature.size(), "temperature");
  for (std::size_t m = 0; m < s.fraction.size(); ++m)
    checkLength(s.fraction[m].size(), "fraction[" + std::to_string(m) + "]");
  if (!(s.voxelVolume > 0.0) || !std::isfinite(s.voxelVolume))
    throw std::invalid_argument("voxel volume must be > 0");
  if (!std::isfinite(sel.minTemperature))
    throw std::invalid_argument("emitter minimum temperature must be finite");
  if (!(sel.defaultEmissivity > 0.0 && sel.defaultEmissivity <= 1.0))
    throw std::invalid_argument("default emissivity must be in (0, 1]");
  const std::size_t materials = std::max<std::size_t>(1, s.fraction.size());
  std::vector<double> eps(materials, sel.defaultEmissivity);
  for (std::size_t m = 0; m < sel.emissivityByMaterial.size(); ++m) {
    if (!(sel.emissivityByMaterial[m] > 0.0 && sel.emissivityByMaterial[m] <= 1.0))
      throw std::invalid_argument("emissivity of material " + std::to_string(m) + " must be in (0, 1]");
    if (m < materials) eps[m] = sel.emissivityByMaterial[m];
  }
  std::vector<std::string> names(materials);
  for (std::size_t m = 0; m < materials; ++m)
    names[m] = m < sel.materialNames.size() ? sel.materialNames[m] : "material" + std::to_string(m);

  Emitters out;
  std::vector<int> groupOfMaterial(materials, -1);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = s.temperature[i];
    if (!std::isfinite(t) || t < 0.0) badElement("temperature", i, "must be finite and >= 0");
    if (t < sel.minTemperature) continue;
    if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i]) || !std::isfinite(s.z[i]))
      badElement("x", i, "(voxel centre) is not finite");
    double total = 0.0, weighted = 0.0, largest = -1.0;
    std::size_t dominant = 0;
    if (s.fraction.empty()) {
      total = 1.0;
      weighted = eps[0];
    }
    for (std::size_t m = 0; m < s.fraction.size(); ++m) {
      const double f = s.fraction[m][i];
      if (!std::isfinite(f) || f < 0.0) badElement("fraction", i, "must be finite and >= 0");
      total += f;
      weighted += f * eps[m];
      if (f > largest) largest = f, dominant = m;
    }
    if (!(total > 0.0)) continue;  // no material in this voxel
    const double fill = s.fractionsAreFill && !s.fraction.empty() ? std::min(total, 1.0) : 1.0;
    if (groupOfMaterial[dominant] < 0)
      groupOfMaterial[dominant] = static_cast<int>(groupIndex(out.groupNames, names[dominant]));
    out.x.push_back(s.x[i]);
    out.y.push_back(s.y[i]);
    out.z.push_back(s.z[i]);
    out.radius.push_back(equalVolumeRadius(fill * s.voxelVolume));
    out.temperature.push_back(t);
    // The mean of values in (0, 1] is in (0, 1]; the clamp keeps rounding there.
    out.emissivity.push_back(std::min(1.0, weighted / total));
    out.group.push_back(static_cast<std::uint32_t>(groupOfMaterial[dominant]));
  }
  return out;
}

double equalVolumeRadius(double volume) {
  if (!(volume > 0.0)) throw std::invalid_argument("emitter volume must be > 0");
  return std::cbrt(3.0 * volume / (4.0 * std::numbers::pi));
}

double opaqueLatticeRadius(double spacing) {
  if (!(spacing > 0.0)) throw std::invalid_argument("lattice spacing must be > 0");
  return 0.5 * std::sqrt(3.0) * spacing;
}

}  // namespace ejecta::radiation
