#pragma once
// What the force pass knows about one pair (i, j) once it has found j within reach: separation,
// relative velocity and the kernel gradients, shared by every pair term (sim/sph/terms/*.hpp).
#include <cstddef>
#include <cstdint>

namespace ejecta {

struct Pair {
  std::uint32_t j = 0;
  double dx[3] = {0.0, 0.0, 0.0};  // x_i - x_j [m], components beyond the dimension 0
  double dv[3] = {0.0, 0.0, 0.0};  // v_i - v_j [m/s]
  double r2 = 0.0, r = 0.0, rInv = 0.0;
  double vdotx = 0.0;              // v_ij . x_ij [m^2/s]; negative when approaching
  double hj = 0.0;                 // smoothing length of j [m]
  double dWi = 0.0, dWj = 0.0;     // dW/dr at h_i and at h_j (0 beyond each support)
  double dWavg = 0.0;              // their mean, for the symmetric terms
  double mj = 0.0;                 // mass of j [kg]
  double sigmaJ = 0.0;             // density of j, or its ring area density in RZ
  double sigmaIJ = 0.0;            // mean of sigma_i and sigma_j
};

// The particles whose per-particle values a pass's terms compute (each term's refresh): indices
// [begin, end) themselves, or entries [begin, end) of an ascending list (individual time steps:
// only the active particles and their partners are read, sim/sph/hydro_force.cpp).
struct TermParticles {
  const std::size_t* list = nullptr;  // nullptr: the indices themselves
  std::size_t begin = 0, end = 0;
  std::size_t count() const { return end - begin; }
  std::size_t operator[](std::size_t k) const { return list ? list[begin + k] : begin + k; }
};

// The state of particle i the pair terms read, loaded once per particle.
struct PairOrigin {
  std::size_t i = 0;
  double h = 0.0, cs = 0.0, rho = 0.0, u = 0.0, P = 0.0;
  double sigma = 0.0;  // rho, or the ring area density in RZ
};

}  // namespace ejecta
