#include "sim/run/packages/phase_fractions_package.hpp"

namespace ejecta {

void PhaseFractionsPackage::registerFields(ParticleSet& p) {
  auto fraction = [](const char* name, const char* description) {
    FieldSpec f = scalarField(name, "1", description, FieldOutput::Particles);
    f.grid = true;
    return f;
  };
  p.declare(fraction(kMeltFraction, "mass fraction molten: liquid or vapour (docs/thermal.md)"));
  p.declare(fraction(kVapourFraction, "mass fraction vaporised (docs/thermal.md)"));
}

void PhaseFractionsPackage::updateState(ParticleSet& p, const PackageContext& c) {
  std::vector<double>& melt = p.column(*p.field(kMeltFraction), 0);
  std::vector<double>& vapour = p.column(*p.field(kVapourFraction), 0);
  for (std::size_t i = 0; i < p.numReal; ++i) {
    if (!selected(c.active, i)) continue;
    const ThermalModel& t = c.materials[static_cast<std::size_t>(p.material[i])].thermal;
    melt[i] = t.meltFraction(p.u[i]);
    vapour[i] = t.vapourFraction(p.u[i]);
  }
}

}  // namespace ejecta
