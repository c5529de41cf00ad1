#pragma once
// Physical constants of the radiation library, SI units. One definition for every file of
// radiation/ (view factors, radiative balance, wall heat diffusion).

namespace ejecta::radiation {

// Stefan-Boltzmann constant sigma [W m^-2 K^-4]. CODATA 2018 (Tiesinga et al., Rev. Mod. Phys.
// 93, 025010, 2021); exact since the 2019 SI fixed h, k_B and c: sigma = 2 pi^5 k_B^4/(15 h^3 c^2).
inline constexpr double kStefanBoltzmann = 5.670374419e-8;

// Emissivity of granite, 0.45: the seed's value (chapter 4.5, its ref. [27]); the default
// emitter emissivity wherever the caller gives none.
inline constexpr double kGraniteEmissivity = 0.45;

}  // namespace ejecta::radiation
