#pragma once
// Monte Carlo view factors and incident radiative flux by ray casting (docs/view_factors.md).
//
// From a receiving patch, rays start at area-uniform points and leave in cosine-weighted
// directions about the local normal; the view factor F to a target is the fraction of rays whose
// first hit is that target (the definition F_ij = (1/A_i) int int cos t_i cos t_j / (pi s^2)
// dA_j dA_i, sampled exactly). The incident flux (irradiation from the hot material) is
//   q = sigma * mean over rays of (eps T^4 of what the ray hits first)  [W/m^2],
// 0 for rays that escape or hit a cold surface: q = sum_k eps_k sigma T_k^4 F_k over the
// emitters k, without reflections (each emitter is grey and diffuse, and seen directly).
//
// Sampling: R independent replicates (16 by default) of a scrambled Sobol' sequence, or of
// independent random points. The estimate is the mean of the replicate means, its standard
// error their standard deviation / sqrt(R): an honest error even for quasi-random points. The
// ray count doubles (each replicate's sequence is extended) until every view factor's standard
// error is below an absolute tolerance (and the flux's below a relative one), up to a maximum.
// Deterministic for a given seed, independent of the thread count.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "radiation/emitters.hpp"
#include "radiation/mesh.hpp"
#include "radiation/ray_scene.hpp"
#include "radiation/sampling.hpp"

namespace ejecta::radiation {

struct Estimate {
  double value = 0.0;
  double standardError = 0.0;
};

// A surface that blocks rays and is itself no receiver: the asteroid's surface. With a
// temperature > 0 it also emits eps sigma T^4 (its rays count as the group "occluder").
struct Occluder {
  TriangleMesh mesh;          // empty: no occluder
  double temperature = 0.0;   // [K]
  double emissivity = kGraniteEmissivity;
};

// Everything the rays can hit.
struct RadiationScene {
  TriangleMesh surfaces;      // receiving and blocking patches (spacecraft, plates); may be empty
  Emitters emitters;
  Occluder occluder;
};

struct SamplingOptions {
  // > 0: cast (at least) this many rays per receiver, no adaptivity. Rounded up to replicates x
  // a power of two (>= 256).
  std::uint64_t rays = 0;
  // Adaptive: stop when the standard error of every view factor is <= absoluteTolerance and,
  // when relativeTolerance > 0, the flux's is <= relativeTolerance x flux.
  double absoluteTolerance = 1e-3;
  double relativeTolerance = 0.0;
  std::uint64_t minRays = 1u << 16;   // adaptive start (a smaller start can show a false zero error)
  std::uint64_t maxRays = 1u << 24;   // adaptive limit per receiver
  int replicates = 16;                // >= 2; the standard error has replicates - 1 degrees of freedom
  std::uint64_t seed = 0x5eed;
  sampling::Sampler sampler = sampling::Sampler::Sobol;
  TraceMode trace = TraceMode::Packet16;
};

// What the rays from one receiver hit first. Fractions sum to 1 over toPatch, toGroup,
// toOccluder, toSpace and toBackFace.
struct ReceiverResult {
  std::uint64_t rays = 0;             // rays cast
  int replicates = 0;
  bool converged = true;              // false: the adaptive loop stopped at maxRays
  std::vector<Estimate> toPatch;      // view factor to each surface patch (front side)
  std::vector<Estimate> toGroup;      // ... to each emitter group
  Estimate toEmitters;                // ... to all emitters
  Estimate toOccluder;
  Estimate toSpace;                   // escaped
  // Rays that struck the back of a surface triangle: none in a closed, outward-facing mesh; a
  // non-zero value points at flipped normals or an open mesh.
  Estimate toBackFace;
  Estimate flux;                      // incident flux [W/m^2] from emitters and a hot occluder
  std::vector<Estimate> fluxFromGroup;
  Estimate fluxFromOccluder;
};

class ViewFactorSolver {
 public:
  // Validates the meshes (MeshError) and builds the ray-casting scene.
  explicit ViewFactorSolver(RadiationScene scene, const RaySceneOptions& rayOptions = {});
  ~ViewFactorSolver();
  ViewFactorSolver(ViewFactorSolver&&) noexcept;
  ViewFactorSolver& operator=(ViewFactorSolver&&) noexcept;

  const RadiationScene& scene() const;

  // From a surface patch (by index or name; std::invalid_argument if unknown or of zero area).
  ReceiverResult fromPatch(std::size_t patch, const SamplingOptions& options = {}) const;
  ReceiverResult fromPatch(const std::string& name, const SamplingOptions& options = {}) const;
  // From a differential element at `point` facing `normal` (cosine-weighted hemisphere).
  ReceiverResult fromPoint(const Vec3& point, const Vec3& normal,
                           const SamplingOptions& options = {}) const;
  // Uniform directions over the whole sphere about `point`: each fraction times 4 pi is the
  // solid angle [sr] that target fills as seen from the point (occlusion included), and `flux`
  // is the fluence rate, the integral of the incident radiance over all directions [W/m^2]
  // (what a small black sphere absorbs per unit cross-section).
  ReceiverResult allDirectionsFrom(const Vec3& point, const SamplingOptions& options = {}) const;
  // Solid angle [sr] of all emitters seen from `point` (4 pi x allDirectionsFrom().toEmitters).
  Estimate emitterSolidAngle(const Vec3& point, const SamplingOptions& options = {}) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ejecta::radiation
