#include "sim/state/builtin_fields.hpp"

#include <cmath>
#include <limits>
#include <utility>

namespace ejecta {

namespace {

FieldStorage member(std::vector<double> ParticleSet::*m) {
  FieldStorage s;
  s.kind = FieldStorage::Kind::Scalar;
  s.scalar = m;
  return s;
}
FieldStorage member(Vec3Array ParticleSet::*m) {
  FieldStorage s;
  s.kind = FieldStorage::Kind::Vector;
  s.vector = m;
  return s;
}
FieldStorage member(StressArray ParticleSet::*m) {
  FieldStorage s;
  s.kind = FieldStorage::Kind::Stress;
  s.stress = m;
  return s;
}
FieldStorage member(std::vector<int> ParticleSet::*m) {
  FieldStorage s;
  s.kind = FieldStorage::Kind::Int32;
  s.int32 = m;
  return s;
}
FieldStorage member(std::vector<std::int64_t> ParticleSet::*m) {
  FieldStorage s;
  s.kind = FieldStorage::Kind::Int64;
  s.int64 = m;
  return s;
}

FieldSpec kicked(FieldSpec f, std::string rate) {
  f.evolution = Evolution::Kicked;
  f.rate = std::move(rate);
  return f;
}

FieldSpec vector3(FieldSpec f) {
  f.components = 3;
  f.parity = MirrorParity::Vector;
  return f;
}

FieldSpec gridded(FieldSpec f, double absent = 0.0) {
  f.grid = true;
  f.absent = absent;
  return f;
}

FieldSpec halo(FieldSpec f) {
  f.halo = true;
  return f;
}

Field derived(FieldSpec f, double (*value)(const ParticleSet&, std::size_t)) {
  f.derive = value;
  return {std::move(f), FieldStorage{}};
}

constexpr FieldOutput kParticles = FieldOutput::Particles;
constexpr FieldOutput kRestart = FieldOutput::Restart;
constexpr FieldOutput kNone = FieldOutput::None;

std::vector<Field> coreFields() {
  FieldSpec position = vector3(scalarField("position", "m",
                                      "particle position: 1D (x,0,0), 2D (x,y,0), RZ (r,z,0)", kParticles));
  position.evolution = Evolution::Drifted;
  position.rate = "velocity";
  position.spatial = true;
  position.writeDimensionOnly = true;
  position.halo = true;
  FieldSpec velocity = halo(kicked(vector3(scalarField("velocity", "m/s",
                                                  "particle velocity; RZ: (v_r, v_z, v_phi)", kParticles)),
                                   "acceleration"));
  velocity.spatial = true;
  FieldSpec omega = halo(scalarField("omega", "1", "grad-h correction factor", kNone));
  omega.fill = 1.0;  // 1 when h is not tied to the density
  FieldSpec material = halo(scalarField("material", "1", "index into the run's material table", kParticles));
  material.type = FieldType::Int32;
  FieldSpec id = halo(scalarField("id", "1", "stable particle identity", kParticles));
  id.type = FieldType::Int64;
  FieldSpec temperature = gridded(scalarField("temperature", "K", "temperature T0 + u / c_v of the material", kParticles));
  temperature.required = false;  // snapshots written before the thermal model lack it
  return {
      {position, member(&ParticleSet::x)},
      {velocity, member(&ParticleSet::v)},
      {halo(gridded(kicked(scalarField("density", "kg/m^3", "mass density", kParticles), "drho_dt"))),
       member(&ParticleSet::rho)},
      {temperature, member(&ParticleSet::temperature)},
      {halo(gridded(scalarField("pressure", "Pa", "pressure from the equation of state", kParticles))),
       member(&ParticleSet::P)},
      {halo(gridded(kicked(scalarField("internal_energy", "J/kg", "specific internal energy", kParticles),
                                  "du_dt"))),
       member(&ParticleSet::u)},
      {halo(gridded(kicked(scalarField("smoothing_length", "m", "SPH smoothing length h", kParticles),
                                  "dh_dt"))),
       member(&ParticleSet::h)},
      {halo(gridded(scalarField("sound_speed", "m/s",
                                  "signal speed: the equation of state's sound speed; for materials with "
                                  "strength the longitudinal speed sqrt(c^2 + 4G/(3 rho))",
                                  kParticles))),
       member(&ParticleSet::cs)},
      derived(gridded(scalarField("speed", "m/s", "magnitude of the velocity", kNone)),
              [](const ParticleSet& p, std::size_t i) {
                return std::sqrt(p.v[0][i] * p.v[0][i] + p.v[1][i] * p.v[1][i] + p.v[2][i] * p.v[2][i]);
              }),
      derived(gridded(scalarField("velocity_x", "m/s", "velocity, x component (RZ: radial)", kNone)),
              [](const ParticleSet& p, std::size_t i) { return p.v[0][i]; }),
      derived(gridded(scalarField("velocity_y", "m/s", "velocity, y component (RZ: axial)", kNone)),
              [](const ParticleSet& p, std::size_t i) { return p.v[1][i]; }),
      derived(gridded(scalarField("velocity_z", "m/s", "velocity, z component", kNone)),
              [](const ParticleSet& p, std::size_t i) { return p.v[2][i]; }),
      {halo(scalarField("mass", "kg", "particle mass; RZ: whole ring; 2D planar: per metre of depth",
                          kParticles)),
       member(&ParticleSet::mass)},
      {material, member(&ParticleSet::material)},
      {id, member(&ParticleSet::id)},
      {vector3(scalarField("acceleration", "m/s^2", "acceleration of the last force evaluation", kRestart)),
       member(&ParticleSet::a)},
      {scalarField("du_dt", "J/kg/s", "rate of change of specific internal energy", kRestart),
       member(&ParticleSet::du_dt)},
      {scalarField("drho_dt", "kg/m^3/s", "rate of change of density (continuity)", kRestart),
       member(&ParticleSet::drho_dt)},
      {scalarField("dh_dt", "m/s", "rate of change of smoothing length", kRestart), member(&ParticleSet::dh_dt)},
      {omega, member(&ParticleSet::omega)},
      {halo(scalarField("divv", "1/s", "velocity divergence estimate", kNone)), member(&ParticleSet::divv)},
      {halo(scalarField("curlv", "1/s", "|curl v| estimate", kNone)), member(&ParticleSet::curlv)},
      {halo(scalarField("area_density", "kg/m^2", "RZ: 2 pi r rho, the 2D summation", kNone)),
       member(&ParticleSet::areaDensity)},
  };
}

std::vector<Field> fractureFields() {
  FieldSpec crack = halo(kicked(scalarField("crack", "1", "crack fraction D^(1/3)", kRestart), "dcrack_dt"));
  crack.limit = KickLimit::Cap;
  return {
      derived(gridded(scalarField("damage", "1", "damage D in [0, 1] (1: no tension, no shear)", kParticles)),
              [](const ParticleSet& p, std::size_t i) { return p.damage(i); }),
      {crack, member(&ParticleSet::crack)},
      {scalarField("dcrack_dt", "1/s", "rate of the crack fraction", kRestart), member(&ParticleSet::dcrack_dt)},
  };
}

std::vector<Field> strengthFields(int components) {
  FieldSpec stress = halo(kicked(scalarField("stress", "Pa",
                                        components == 6 ? "deviatoric stress: xx, yy, zz, xy, xz, yz"
                                                        : "deviatoric stress: xx, yy, zz, xy (RZ: rr, zz, "
                                                          "theta-theta, rz)",
                                        kParticles),
                                 "dstress_dt"));
  stress.components = components;
  stress.parity = MirrorParity::SymmetricTensor;
  FieldSpec rate = scalarField("dstress_dt", "Pa/s", "rate of the deviatoric stress", kRestart);
  rate.components = components;
  return {
      {stress, member(&ParticleSet::stress)},
      {gridded(scalarField("plastic_strain", "1", "equivalent plastic strain", kParticles)),
       member(&ParticleSet::plasticStrain)},
      {rate, member(&ParticleSet::dstress_dt)},
      {kicked(scalarField("total_strain", "1", "equivalent total strain", kRestart), "strain_rate"),
       member(&ParticleSet::totalStrain)},
      {scalarField("strain_rate", "1/s", "equivalent strain rate", kRestart), member(&ParticleSet::strainRate)},
  };
}

std::vector<Field> burnFields() {
  return {
      {gridded(scalarField("burn_fraction", "1",
                      "programmed-burn fraction F in [0, 1] (the factor on the JWL pressure)", kParticles),
               1.0),  // nothing burns: every particle is burnt
       member(&ParticleSet::burnFraction)},
      {scalarField("lighting_time", "s", "programmed-burn lighting time (-inf: not an explosive)", kRestart),
       member(&ParticleSet::lightingTime)},
  };
}

std::vector<Field> viscositySwitchFields() {
  FieldSpec alpha = kicked(scalarField("viscosity_alpha", "1",
                                  "artificial-viscosity coefficient alpha of the Morris-Monaghan switch",
                                  kParticles),
                           "dalpha_dt");
  alpha.limit = KickLimit::Clamp;  // the range is the scene's [alpha_min, alpha]
  alpha.halo = true;
  return {
      {alpha, member(&ParticleSet::alpha)},
      {scalarField("dalpha_dt", "1/s", "rate of the viscosity switch's alpha", kRestart),
       member(&ParticleSet::dalpha_dt)},
  };
}

}  // namespace

std::vector<Field> builtinFields(FieldGroup group, int stressComponents) {
  switch (group) {
    case FieldGroup::Core: return coreFields();
    case FieldGroup::Fracture: return fractureFields();
    case FieldGroup::Strength: return strengthFields(stressComponents);
    case FieldGroup::Burn: return burnFields();
    case FieldGroup::ViscositySwitch: return viscositySwitchFields();
    case FieldGroup::Package: break;
  }
  return {};
}

const std::vector<Field>& allBuiltinFields() {
  static const std::vector<Field> all = [] {
    std::vector<Field> out;
    for (FieldGroup g : {FieldGroup::Core, FieldGroup::Fracture, FieldGroup::Strength, FieldGroup::Burn,
                         FieldGroup::ViscositySwitch})
      for (Field& f : builtinFields(g)) out.push_back(std::move(f));
    return out;
  }();
  return all;
}

}  // namespace ejecta
