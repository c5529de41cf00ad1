// The one translation unit that includes Embree (compile cost and a C API kept behind RayScene).
#include "radiation/ray_scene.hpp"

#include <embree3/rtcore.h>

#include <limits>
#include <mutex>
#include <stdexcept>
#include <string>

namespace ejecta::radiation {

struct RayScene::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::uint32_t geometries = 0;
  bool committed = false;
  std::mutex errorMutex;
  std::string lastError;

  // Embree reports errors through a callback; they are collected here and thrown after the call
  // that caused them (throwing through Embree's C frames is not allowed).
  static void onError(void* self, RTCError code, const char* message) {
    if (code == RTC_ERROR_NONE) return;
    auto* impl = static_cast<Impl*>(self);
    const std::lock_guard<std::mutex> lock(impl->errorMutex);
    impl->lastError = message ? message : "unknown Embree error";
  }

  void check(const char* what) {
    const RTCError code = rtcGetDeviceError(device);
    if (code == RTC_ERROR_NONE) return;
    std::string message;
    {
      const std::lock_guard<std::mutex> lock(errorMutex);
      message = lastError.empty() ? "error code " + std::to_string(static_cast<int>(code)) : lastError;
      lastError.clear();
    }
    throw std::runtime_error(std::string("Embree: ") + what + ": " + message);
  }

  std::uint32_t attach(RTCGeometry geometry, const char* what) {
    rtcCommitGeometry(geometry);
    const unsigned id = rtcAttachGeometry(scene, geometry);
    rtcReleaseGeometry(geometry);
    check(what);
    ++geometries;
    return id;
  }

  void requireOpen() const {
    if (committed) throw std::logic_error("RayScene: geometry added after commit()");
  }
};

RayScene::RayScene(const RaySceneOptions& options) : impl_(std::make_unique<Impl>()) {
  std::string config = "verbose=0";
  if (options.buildThreads > 0) config += ",threads=" + std::to_string(options.buildThreads);
  impl_->device = rtcNewDevice(config.c_str());
  if (!impl_->device)
    throw std::runtime_error("Embree: cannot create a device (error " +
                             std::to_string(static_cast<int>(rtcGetDeviceError(nullptr))) + ")");
  rtcSetDeviceErrorFunction(impl_->device, &Impl::onError, impl_.get());
  impl_->scene = rtcNewScene(impl_->device);
  rtcSetSceneFlags(impl_->scene, options.robust ? RTC_SCENE_FLAG_ROBUST : RTC_SCENE_FLAG_NONE);
  rtcSetSceneBuildQuality(impl_->scene,
                          options.highQualityBuild ? RTC_BUILD_QUALITY_HIGH : RTC_BUILD_QUALITY_MEDIUM);
  impl_->check("creating the scene");
}

RayScene::~RayScene() {
  if (!impl_) return;
  if (impl_->scene) rtcReleaseScene(impl_->scene);
  if (impl_->device) rtcReleaseDevice(impl_->device);
}

RayScene::RayScene(RayScene&&) noexcept = default;
RayScene& RayScene::operator=(RayScene&& other) noexcept {
  if (this != &other) {
    if (impl_) {
      if (impl_->scene) rtcReleaseScene(impl_->scene);
      if (impl_->device) rtcReleaseDevice(impl_->device);
    }
    impl_ = std::move(other.impl_);
  }
  return *this;
}

std::uint32_t RayScene::addTriangles(const TriangleMesh& mesh) {
  impl_->requireOpen();
  RTCGeometry g = rtcNewGeometry(impl_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                        3 * sizeof(float), mesh.vertices.size()));
  auto* t = static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                           3 * sizeof(unsigned), mesh.triangles.size()));
  if (!v || !t) {
    rtcReleaseGeometry(g);
    impl_->check("allocating triangle buffers");
    throw std::runtime_error("Embree: cannot allocate triangle buffers");
  }
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
    for (int k = 0; k < 3; ++k) v[3 * i + k] = static_cast<float>(mesh.vertices[i][k]);
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i)
    for (int k = 0; k < 3; ++k) t[3 * i + k] = mesh.triangles[i][k];
  return impl_->attach(g, "adding triangles");
}

std::uint32_t RayScene::addSpheres(std::span<const double> x, std::span<const double> y,
                                   std::span<const double> z, std::span<const double> radius) {
  impl_->requireOpen();
  const std::size_t n = x.size();
  if (y.size() != n || z.size() != n || radius.size() != n)
    throw std::invalid_argument("RayScene::addSpheres: arrays of different lengths");
  RTCGeometry g = rtcNewGeometry(impl_->device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
  auto* p = static_cast<float*>(
      rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), n));
  if (!p) {
    rtcReleaseGeometry(g);
    impl_->check("allocating sphere buffers");
    throw std::runtime_error("Embree: cannot allocate sphere buffers");
  }
  for (std::size_t i = 0; i < n; ++i) {
    p[4 * i + 0] = static_cast<float>(x[i]);
    p[4 * i + 1] = static_cast<float>(y[i]);
    p[4 * i + 2] = static_cast<float>(z[i]);
    p[4 * i + 3] = static_cast<float>(radius[i]);
  }
  return impl_->attach(g, "adding spheres");
}

void RayScene::commit() {
  rtcCommitScene(impl_->scene);
  impl_->check("building the BVH");
  impl_->committed = true;
}

namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

void traceSingle(RTCScene scene, RayBlock& b) {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  for (int i = 0; i < b.count; ++i) {
    RTCRayHit rh;
    rh.ray.org_x = b.ox[i];
    rh.ray.org_y = b.oy[i];
    rh.ray.org_z = b.oz[i];
    rh.ray.tnear = 0.0f;
    rh.ray.dir_x = b.dx[i];
    rh.ray.dir_y = b.dy[i];
    rh.ray.dir_z = b.dz[i];
    rh.ray.time = 0.0f;
    rh.ray.tfar = kInfinity;
    rh.ray.mask = 0xffffffffu;
    rh.ray.id = 0;
    rh.ray.flags = 0;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene, &context, &rh);
    b.geometry[i] = rh.hit.geomID;
    b.primitive[i] = rh.hit.primID;
    b.distance[i] = rh.ray.tfar;
  }
}

void tracePackets(RTCScene scene, RayBlock& b) {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  alignas(64) RTCRayHit16 rh;
  alignas(64) int valid[16];
  for (int base = 0; base < b.count; base += 16) {
    for (int l = 0; l < 16; ++l) {
      const int i = base + l;
      const bool active = i < b.count;
      valid[l] = active ? -1 : 0;
      rh.ray.org_x[l] = active ? b.ox[i] : 0.0f;
      rh.ray.org_y[l] = active ? b.oy[i] : 0.0f;
      rh.ray.org_z[l] = active ? b.oz[i] : 0.0f;
      rh.ray.tnear[l] = 0.0f;
      rh.ray.dir_x[l] = active ? b.dx[i] : 1.0f;
      rh.ray.dir_y[l] = active ? b.dy[i] : 0.0f;
      rh.ray.dir_z[l] = active ? b.dz[i] : 0.0f;
      rh.ray.time[l] = 0.0f;
      rh.ray.tfar[l] = kInfinity;
      rh.ray.mask[l] = 0xffffffffu;
      rh.ray.id[l] = static_cast<unsigned>(l);
      rh.ray.flags[l] = 0;
      rh.hit.geomID[l] = RTC_INVALID_GEOMETRY_ID;
      rh.hit.instID[0][l] = RTC_INVALID_GEOMETRY_ID;
    }
    rtcIntersect16(valid, scene, &context, &rh);
    for (int l = 0; l < 16 && base + l < b.count; ++l) {
      b.geometry[base + l] = rh.hit.geomID[l];
      b.primitive[base + l] = rh.hit.primID[l];
      b.distance[base + l] = rh.ray.tfar[l];
    }
  }
}

void traceStream(RTCScene scene, RayBlock& b) {
  constexpr int n = RayBlock::kCapacity;
  alignas(64) float tnear[n], time[n], ngx[n], ngy[n], ngz[n], u[n], v[n];
  alignas(64) unsigned mask[n], id[n], flags[n], inst[n];
  for (int i = 0; i < b.count; ++i) {
    tnear[i] = 0.0f;
    time[i] = 0.0f;
    b.distance[i] = kInfinity;
    mask[i] = 0xffffffffu;
    id[i] = static_cast<unsigned>(i);
    flags[i] = 0;
    b.geometry[i] = RTC_INVALID_GEOMETRY_ID;
    inst[i] = RTC_INVALID_GEOMETRY_ID;
  }
  RTCRayHitNp rh;
  rh.ray = {b.ox, b.oy, b.oz, tnear, b.dx, b.dy, b.dz, time, b.distance, mask, id, flags};
  rh.hit.Ng_x = ngx;
  rh.hit.Ng_y = ngy;
  rh.hit.Ng_z = ngz;
  rh.hit.u = u;
  rh.hit.v = v;
  rh.hit.primID = b.primitive;
  rh.hit.geomID = b.geometry;
  rh.hit.instID[0] = inst;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  rtcIntersectNp(scene, &context, &rh, static_cast<unsigned>(b.count));
}

}  // namespace

void RayScene::trace(RayBlock& block, TraceMode mode) const {
  if (!impl_->committed) throw std::logic_error("RayScene::trace before commit()");
  if (block.count < 0 || block.count > RayBlock::kCapacity)
    throw std::invalid_argument("RayScene::trace: bad block count");
  switch (mode) {
    case TraceMode::Single: traceSingle(impl_->scene, block); break;
    case TraceMode::Packet16: tracePackets(impl_->scene, block); break;
    case TraceMode::Stream: traceStream(impl_->scene, block); break;
  }
}

}  // namespace ejecta::radiation
