#pragma once
// The ray-casting scene: an Embree 3 device and scene behind a small interface (ray_scene.cpp is
// the only file that includes Embree). Geometries are triangle meshes and sets of spheres; rays
// go in blocks of structure-of-arrays and come back with the first hit's geometry and primitive.
// Tracing is const and thread safe: OpenMP threads each trace their own blocks.
#include <cstdint>
#include <memory>
#include <span>

#include "radiation/mesh.hpp"

namespace ejecta::radiation {

enum class TraceMode {
  Single,    // rtcIntersect1, one ray at a time
  Packet16,  // rtcIntersect16, 16 rays a call (the default: fastest here, see the bench)
  Stream,    // rtcIntersectNp over the whole block
};

// Up to kCapacity rays from origin o along direction d (not necessarily unit), tnear = 0, no
// far limit. After RayScene::trace, geometry[i] is the id of the first geometry hit (kMiss:
// none), primitive[i] the triangle or sphere index and distance[i] the ray parameter of the hit.
struct RayBlock {
  static constexpr int kCapacity = 256;  // a multiple of 16
  int count = 0;
  alignas(64) float ox[kCapacity];
  alignas(64) float oy[kCapacity];
  alignas(64) float oz[kCapacity];
  alignas(64) float dx[kCapacity];
  alignas(64) float dy[kCapacity];
  alignas(64) float dz[kCapacity];
  alignas(64) std::uint32_t geometry[kCapacity];
  alignas(64) std::uint32_t primitive[kCapacity];
  alignas(64) float distance[kCapacity];
};

struct RaySceneOptions {
  // Threads for the BVH build (Embree's own TBB pool); 0: Embree's default (all cores).
  int buildThreads = 0;
  // Watertight triangle tests (RTC_SCENE_FLAG_ROBUST): no ray slips through a shared edge, which
  // the enclosure closure tests rely on. Costs a few per cent.
  bool robust = true;
  bool highQualityBuild = false;  // RTC_BUILD_QUALITY_HIGH: slower build, faster traversal
};

class RayScene {
 public:
  static constexpr std::uint32_t kMiss = 0xffffffffu;

  explicit RayScene(const RaySceneOptions& options = {});
  ~RayScene();
  RayScene(RayScene&&) noexcept;
  RayScene& operator=(RayScene&&) noexcept;
  RayScene(const RayScene&) = delete;
  RayScene& operator=(const RayScene&) = delete;

  // Adds geometry before commit(); returns its id (0, 1, 2, ... in the order added).
  // Coordinates are converted to single precision, as Embree stores them.
  std::uint32_t addTriangles(const TriangleMesh& mesh);
  std::uint32_t addSpheres(std::span<const double> x, std::span<const double> y,
                           std::span<const double> z, std::span<const double> radius);
  // Builds the BVH. Throws std::runtime_error with Embree's message on failure.
  void commit();

  void trace(RayBlock& block, TraceMode mode = TraceMode::Packet16) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ejecta::radiation
