#include "sim/run/packages/smoothing_length_cap_package.hpp"

namespace ejecta {

void SmoothingLengthCapPackage::registerFields(ParticleSet& p) {
  const bool carried = p.field(kCap) != nullptr;  // read back from a snapshot
  FieldSpec cap;
  cap.name = kCap;
  cap.units = "m";
  cap.description = "largest smoothing length the particle may take (sph.h_max_factor x its first h)";
  cap.output = FieldOutput::Restart;
  p.declare(cap);
  if (carried) return;
  std::vector<double>& values = p.column(*p.field(kCap), 0);
  for (std::size_t i = 0; i < p.size(); ++i) values[i] = factor_ * p.h[i];
}

const double* SmoothingLengthCapPackage::caps(const ParticleSet& p) {
  const Field* f = p.field(kCap);
  return f ? p.column(*f, 0).data() : nullptr;
}

}  // namespace ejecta
