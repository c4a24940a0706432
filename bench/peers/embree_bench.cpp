// Peer: Embree 3 (Debian's libembree-dev) on W2, the same mesh and rays as rays_bench.cpp, on as
// many threads as the suite (one by default). Single rays with rtcIntersect1 for both sets, and
// for the coherent set 16-ray packets with rtcIntersect16: 4 x 4 tiles of adjacent pixels.
// Build quality: the default (RTC_BUILD_QUALITY_MEDIUM) and HIGH; scene flags none, so Embree's
// traversal is not the robust one (RTC_SCENE_FLAG_ROBUST), and its hit counts show it.
#include <embree3/rtcore.h>
#include <omp.h>

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

#include "bench/rays_common.hpp"

namespace simdphys::bench {
namespace {

class EmbreeScene {
 public:
  EmbreeScene(const Mesh& mesh, RTCBuildQuality quality) {
    const std::string config = "threads=" + std::to_string(omp_get_max_threads());
    device_ = rtcNewDevice(config.c_str());
    scene_ = rtcNewScene(device_);
    rtcSetSceneBuildQuality(scene_, quality);
    RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetGeometryBuildQuality(g, quality);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.vertices.size()));
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
      for (int k = 0; k < 3; ++k) v[3 * i + k] = mesh.vertices[i][k];
    auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), mesh.size()));
    for (std::size_t i = 0; i < mesh.size(); ++i)
      for (int k = 0; k < 3; ++k) idx[3 * i + k] = mesh.triangles[i][k];
    rtcCommitGeometry(g);
    rtcAttachGeometry(scene_, g);
    rtcReleaseGeometry(g);
  }
  ~EmbreeScene() {
    rtcReleaseScene(scene_);
    rtcReleaseDevice(device_);
  }
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  void commit() { rtcCommitScene(scene_); }
  RTCScene scene() const { return scene_; }

 private:
  RTCDevice device_;
  RTCScene scene_;
};

const EmbreeScene& committedScene() {
  static EmbreeScene s(raysWorkload().mesh, RTC_BUILD_QUALITY_MEDIUM);
  static const bool committed = (s.commit(), true);
  (void)committed;
  return s;
}

// Ray i of the stream as Embree takes it (t in [0, inf), no hit yet), and an answer as ours.
RTCRayHit rayHit(const RayStream& rays, std::size_t i) {
  RTCRayHit rh{};
  rh.ray.org_x = rays.origin(0)[i], rh.ray.org_y = rays.origin(1)[i];
  rh.ray.org_z = rays.origin(2)[i];
  rh.ray.dir_x = rays.direction(0)[i], rh.ray.dir_y = rays.direction(1)[i];
  rh.ray.dir_z = rays.direction(2)[i];
  rh.ray.tnear = 0, rh.ray.tfar = std::numeric_limits<float>::infinity();
  rh.ray.mask = ~0u;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  return rh;
}
MeshHit meshHit(const RTCRayHit& rh) {
  return rh.hit.geomID == RTC_INVALID_GEOMETRY_ID ? MeshHit{} : MeshHit{rh.hit.primID, rh.ray.tfar};
}

void intersect1(const RTCScene scene, const RayStream& rays, std::vector<MeshHit>& hits) {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
#pragma omp parallel for schedule(dynamic, 256)
  for (std::int64_t j = 0; j < std::int64_t(rays.size()); ++j) {
    RTCRayHit rh = rayHit(rays, std::size_t(j));
    rtcIntersect1(scene, &context, &rh);
    hits[std::size_t(j)] = meshHit(rh);
  }
}

// Embree's stream API (rtcIntersect1M, the default incoherent context), the stream's rays in calls
// of 4,096: the counterpart of MeshBvh::raycast on a stream. Filling its ray structures is timed,
// as in intersect1 (simdphys reads its own stream as given).
void intersect1M(const RTCScene scene, const RayStream& rays, std::vector<MeshHit>& hits) {
  constexpr std::int64_t kCall = 4096;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  const std::int64_t n = std::int64_t(rays.size());
#pragma omp parallel for schedule(dynamic, 1)
  for (std::int64_t begin = 0; begin < n; begin += kCall) {
    RTCRayHit stream[kCall];
    const std::int64_t count = std::min(kCall, n - begin);
    for (std::int64_t k = 0; k < count; ++k) stream[k] = rayHit(rays, std::size_t(begin + k));
    rtcIntersect1M(scene, &context, stream, unsigned(count), sizeof(RTCRayHit));
    for (std::int64_t k = 0; k < count; ++k) hits[std::size_t(begin + k)] = meshHit(stream[k]);
  }
}

// Packets of 16 rays: the 4 x 4 tiles of the image (rays are in scanline order).
void intersect16(const RTCScene scene, const RayStream& rays, std::vector<MeshHit>& hits) {
  constexpr std::uint32_t w = scenes::kCameraWidth, h = scenes::kCameraHeight;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
#pragma omp parallel for schedule(dynamic, 16)
  for (std::int64_t tile = 0; tile < std::int64_t(w / 4 * (h / 4)); ++tile) {
    const std::uint32_t tx = std::uint32_t(tile) % (w / 4) * 4,
                        ty = std::uint32_t(tile) / (w / 4) * 4;
    alignas(64) RTCRayHit16 p;
    alignas(64) int valid[16];
    std::size_t index[16];
    for (int k = 0; k < 16; ++k) {
      const std::size_t i = std::size_t(ty + k / 4) * w + tx + k % 4;
      index[k] = i;
      valid[k] = -1;
      p.ray.org_x[k] = rays.origin(0)[i], p.ray.org_y[k] = rays.origin(1)[i];
      p.ray.org_z[k] = rays.origin(2)[i];
      p.ray.dir_x[k] = rays.direction(0)[i], p.ray.dir_y[k] = rays.direction(1)[i];
      p.ray.dir_z[k] = rays.direction(2)[i];
      p.ray.tnear[k] = 0, p.ray.tfar[k] = std::numeric_limits<float>::infinity();
      p.ray.mask[k] = ~0u, p.ray.time[k] = 0, p.ray.flags[k] = 0;
      p.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
    }
    rtcIntersect16(valid, scene, &context, &p);
    for (int k = 0; k < 16; ++k)
      hits[index[k]] = p.hit.geomID[k] == RTC_INVALID_GEOMETRY_ID
                           ? MeshHit{}
                           : MeshHit{p.hit.primID[k], p.ray.tfar[k]};
  }
}

template <class Intersect>
void registerIntersect(RaysKind kind, const char* method, Intersect intersect) {
  registerOnce(raysTask(kind), method, "peer", raysCount(kind),
               [kind, intersect](benchmark::State& state) {
                 const RaySet& set = raySet(kind);
                 const RTCScene scene = committedScene().scene();
                 std::vector<MeshHit> hits(set.rays.size());
                 for (auto _ : state) {
                   intersect(scene, set.rays, hits);
                   benchmark::DoNotOptimize(hits.data());
                 }
                 reportRays(state, set, hits, /*peer=*/true);
               });
}

void registerEmbree() {
  registerIntersect(RaysKind::kCoherent, "embree_intersect1", intersect1);
  registerIntersect(RaysKind::kCoherent, "embree_intersect16", intersect16);
  registerIntersect(RaysKind::kIncoherent, "embree_intersect1", intersect1);
  registerIntersect(RaysKind::kIncoherent, "embree_intersect1M", intersect1M);
  for (auto [method, quality] : {std::pair{"embree_medium", RTC_BUILD_QUALITY_MEDIUM},
                                 std::pair{"embree_high", RTC_BUILD_QUALITY_HIGH}}) {
    registerOnce("rays/build", method, "peer", kRaysTriangles, [quality](benchmark::State& state) {
      for (auto _ : state) {
        // The geometry's copy into Embree's buffers is not timed: only the build.
        state.PauseTiming();
        auto s = std::make_unique<EmbreeScene>(raysWorkload().mesh, quality);
        state.ResumeTiming();
        s->commit();
        state.PauseTiming();
        s.reset();
        state.ResumeTiming();
      }
      state.SetItemsProcessed(std::int64_t(state.iterations() * kRaysTriangles));
    });
  }
}

const bool kRegistered = (registerEmbree(), true);

}  // namespace
}  // namespace simdphys::bench
