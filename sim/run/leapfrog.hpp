#pragma once
// The kick-drift-kick leapfrog over the fields a ParticleSet declares (sim/state/field_spec.hpp),
// the seed's eq. 1.9 in its synchronised form. For every Kicked field y with rate y':
//   predict:  y_half = y + dt/2 y'(n),   y = y_half + dt/2 y'(n)   (y predicted to n+1)
//   correct:  y = y_half + dt/2 y'(n+1)
// and positions drift x += dt v_half. Fields are advanced in registry order, one loop each; a
// Cap-limited field's caps are taken just before its kick, from the state the kicks before it
// left (so the crack's cap sees the stress before the stress is kicked: Fracture precedes
// Strength in the registry). The loops are independent per particle, so the result does not
// depend on the thread count.
#include <array>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "sim/state/particles.hpp"

namespace ejecta {

class Leapfrog {
 public:
  // Per-particle caps of a Cap-limited field, from the present state.
  using CapSource = std::function<std::vector<double>(const ParticleSet&)>;

  // A Kicked field the run sets another way (summation density sets rho in the density pass,
  // h tied to the density sets h): it is not advanced.
  void hold(const std::string& field) { held_.insert(field); }
  void setCaps(const std::string& field, CapSource caps) { caps_[field] = std::move(caps); }
  bool holds(const std::string& field) const { return held_.count(field) > 0; }
  // The cap source of a Cap-limited field, or nullptr (individual steps take the caps from here).
  const CapSource* caps(const std::string& field) const {
    const auto at = caps_.find(field);
    return at == caps_.end() ? nullptr : &at->second;
  }

  // First half kick, drift, and the prediction of every evolved field to the end of the step.
  void predict(ParticleSet& p, int dimension, double dt);
  // Second half kick with the rates of the predicted state.
  void correct(ParticleSet& p, int dimension, double dt);

  // The velocity at the half step (the field the positions drift by), which the walls confine
  // with the positions.
  Vec3Array& velocityHalf() { return velocityHalf_; }

 private:
  void kick(ParticleSet& p, const Field& f, int dimension, double half, bool predict);
  void drift(ParticleSet& p, const Field& f, int dimension, double dt);
  std::vector<double>& halfOf(const Field& f, int component);

  std::set<std::string> held_;
  std::map<std::string, CapSource> caps_;
  std::string drifting_;    // the Kicked field the Drifted ones drift by (the velocity)
  Vec3Array velocityHalf_;  // its half-step value, what positions drift by
  std::map<std::string, std::vector<std::vector<double>>> halves_;  // y_half per component
};

}  // namespace ejecta
