#pragma once
// Empirical similitude laws of an underwater TNT explosion's shock wave (docs/undex.md,
// "References: Cole and Swisdak, and where they apply"): the peak pressure
//   P_max = K (W^(1/3) / R)^alpha
// and the decay constant theta of P_max exp(-(t - t_a) / theta), the time to fall to P_max / e,
//   theta = k W^(1/3) (W^(1/3) / R)^beta,
// W the charge's mass [kg] of TNT and R the distance from its centre [m]. The one place these
// constants live: the command line and the tests use them from here.

namespace ejecta::exact {

struct SimilitudeLaw {
  double peakCoefficient = 0.0;   // K [Pa]
  double peakExponent = 0.0;      // alpha
  double decayCoefficient = 0.0;  // k [s / kg^(1/3)]
  double decayExponent = 0.0;     // beta

  double peakPressure(double chargeMass, double distance) const;  // [Pa]
  double decayTime(double chargeMass, double distance) const;     // theta [s]
};

// R. H. Cole, "Underwater Explosions", Princeton 1948, ch. 7: 21,600 psi and 58 us in lb and ft
// (P_max = 21600 (W^(1/3)/R)^1.13 psi, theta = 58 W^(1/3) (W^(1/3)/R)^(-0.22) us), converted to
// kg, m and Pa (1 lb = 0.45359237 kg, 1 ft = 0.3048 m, 1 psi = 6894.757 Pa).
inline constexpr SimilitudeLaw kColeTnt{52.39e6, 1.13, 92.5e-6, -0.22};

// M. M. Swisdak, "Explosion Effects and Properties, Part II: Explosion Effects in Water", NSWC
// TR 76-116, 1978, fitted in SI: P_max = 52.4 (W^(1/3)/R)^1.13 MPa (Cole's law) and
// theta = 0.084 W^(1/3) (W^(1/3)/R)^(-0.23) ms, a different fit from Cole's theta (10-12% shorter
// at 0.25-1 m from 1 kg).
inline constexpr SimilitudeLaw kSwisdakTnt{52.4e6, 1.13, 84.0e-6, -0.23};

// Cole's law holds from about 12 charge radii out (to ~240): Zamyshlyayev & Yakovlev's near-field
// formula, as usually quoted, takes over inside, the two meeting at 11.9 charge radii.
inline constexpr double kColeInnerLimitChargeRadii = 12.0;

}  // namespace ejecta::exact
