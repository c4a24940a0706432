// Peer: Embree 3 (Debian's libembree-dev) on W2, the same mesh and rays as rays_bench.cpp, on as
// many threads as the suite (one by default), used as Embree's documentation asks:
// - camera rays (the coherent set) with an intersect context flagged COHERENT: single rays with
//   rtcIntersect1, and packets of the image's 4 x 2 and 4 x 4 tiles with rtcIntersect8 and
//   rtcIntersect16, the tiles simdphys's packet8 and packet16 trace. rtcInitIntersectContext sets
//   INCOHERENT, with which Embree 3.13.5's packet intersectors trace each active lane singly
//   (bvh_intersector_hybrid.cpp): only COHERENT reaches its packet traversal.
// - random rays (the incoherent set) with the default INCOHERENT context: rtcIntersect1, and the
//   stream API rtcIntersect1M.
// Scenes: the default flags (Embree's fast, non-robust triangle test, whose hit count shows it)
// and RTC_SCENE_FLAG_ROBUST (the watertight test, for the exact hit count), both at the default
// build quality (RTC_BUILD_QUALITY_MEDIUM); the build is also timed at HIGH. One device for every
// scene, as an application keeps it: a new device per build costs Embree 4-11%.
#include <embree3/rtcore.h>
#include <omp.h>

#include <algorithm>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "bench/rays_common.hpp"

namespace simdphys::bench {
namespace {

RTCDevice device() {
  static const RTCDevice d = [] {
    const std::string config = "threads=" + std::to_string(omp_get_max_threads());
    return rtcNewDevice(config.c_str());
  }();
  return d;
}

class EmbreeScene {
 public:
  EmbreeScene(const Mesh& mesh, RTCBuildQuality quality, RTCSceneFlags flags)
      : scene_(rtcNewScene(device())) {
    rtcSetSceneFlags(scene_, flags);
    rtcSetSceneBuildQuality(scene_, quality);
    RTCGeometry g = rtcNewGeometry(device(), RTC_GEOMETRY_TYPE_TRIANGLE);
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
  ~EmbreeScene() { rtcReleaseScene(scene_); }
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  void commit() { rtcCommitScene(scene_); }
  RTCScene scene() const { return scene_; }

 private:
  RTCScene scene_;
};

RTCScene committedScene(RTCSceneFlags flags) {
  auto make = [](RTCSceneFlags f) {
    auto s = std::make_unique<EmbreeScene>(raysWorkload().mesh, RTC_BUILD_QUALITY_MEDIUM, f);
    s->commit();
    return s;
  };
  static const auto plain = make(RTC_SCENE_FLAG_NONE), robust = make(RTC_SCENE_FLAG_ROBUST);
  return (flags == RTC_SCENE_FLAG_ROBUST ? robust : plain)->scene();
}

RTCIntersectContext context(RTCIntersectContextFlags flags) {
  RTCIntersectContext c;
  rtcInitIntersectContext(&c);
  c.flags = flags;
  return c;
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
ElementHit meshHit(const RTCRayHit& rh) {
  return rh.hit.geomID == RTC_INVALID_GEOMETRY_ID ? ElementHit{}
                                                  : ElementHit{rh.hit.primID, rh.ray.tfar};
}

using Intersect = void (*)(RTCScene, RTCIntersectContextFlags, const RayStream&,
                           std::vector<ElementHit>&);

void intersect1(RTCScene scene, RTCIntersectContextFlags flags, const RayStream& rays,
                std::vector<ElementHit>& hits) {
  RTCIntersectContext c = context(flags);
#pragma omp parallel for schedule(dynamic, 256)
  for (std::int64_t j = 0; j < std::int64_t(rays.size()); ++j) {
    RTCRayHit rh = rayHit(rays, std::size_t(j));
    rtcIntersect1(scene, &c, &rh);
    hits[std::size_t(j)] = meshHit(rh);
  }
}

// Embree's stream API (rtcIntersect1M), the stream's rays in calls of 4,096: the counterpart of
// MeshBvh::raycast on a stream. Filling its ray structures is timed, as in intersect1 (simdphys
// reads its own stream as given).
void intersect1M(RTCScene scene, RTCIntersectContextFlags flags, const RayStream& rays,
                 std::vector<ElementHit>& hits) {
  constexpr std::int64_t kCall = 4096;
  RTCIntersectContext c = context(flags);
  const std::int64_t n = std::int64_t(rays.size());
#pragma omp parallel for schedule(dynamic, 1)
  for (std::int64_t begin = 0; begin < n; begin += kCall) {
    RTCRayHit stream[kCall];
    const std::int64_t count = std::min(kCall, n - begin);
    for (std::int64_t k = 0; k < count; ++k) stream[k] = rayHit(rays, std::size_t(begin + k));
    rtcIntersect1M(scene, &c, stream, unsigned(count), sizeof(RTCRayHit));
    for (std::int64_t k = 0; k < count; ++k) hits[std::size_t(begin + k)] = meshHit(stream[k]);
  }
}

// Packets of K rays: the image's 4 x (K / 4) tiles (rays are in scanline order), row by row of
// tiles, as simdphys's packets (RayStreamOptions::imageWidth).
template <int K, class Packet,
          void (*IntersectK)(const int*, RTCScene, RTCIntersectContext*, Packet*)>
void intersectTiles(RTCScene scene, RTCIntersectContextFlags flags, const RayStream& rays,
                    std::vector<ElementHit>& hits) {
  constexpr std::uint32_t w = workloads::kCameraWidth, h = workloads::kCameraHeight, rows = K / 4;
  static_assert(w % 4 == 0 && h % rows == 0);
  RTCIntersectContext c = context(flags);
#pragma omp parallel for schedule(dynamic, 16)
  for (std::int64_t tile = 0; tile < std::int64_t(w / 4 * (h / rows)); ++tile) {
    const std::uint32_t tx = std::uint32_t(tile) % (w / 4) * 4,
                        ty = std::uint32_t(tile) / (w / 4) * rows;
    alignas(64) Packet p;
    alignas(64) int valid[K];
    std::size_t index[K];
    for (int k = 0; k < K; ++k) {
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
    IntersectK(valid, scene, &c, &p);
    for (int k = 0; k < K; ++k)
      hits[index[k]] = p.hit.geomID[k] == RTC_INVALID_GEOMETRY_ID
                           ? ElementHit{}
                           : ElementHit{p.hit.primID[k], p.ray.tfar[k]};
  }
}
constexpr Intersect intersect8 = intersectTiles<8, RTCRayHit8, rtcIntersect8>;
constexpr Intersect intersect16 = intersectTiles<16, RTCRayHit16, rtcIntersect16>;

void registerIntersect(RaysKind kind, const std::string& method, Intersect intersect) {
  const RTCIntersectContextFlags flags = kind == RaysKind::kCoherent
                                             ? RTC_INTERSECT_CONTEXT_FLAG_COHERENT
                                             : RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
  for (const RTCSceneFlags scene : {RTC_SCENE_FLAG_NONE, RTC_SCENE_FLAG_ROBUST}) {
    const std::string name =
        "embree_" + std::string(scene == RTC_SCENE_FLAG_ROBUST ? "robust_" : "") + method;
    registerOnce(raysTask(kind), name, "peer", raysCount(kind),
                 [kind, intersect, flags, scene](benchmark::State& state) {
                   const RaySet& set = raySet(kind);
                   const RTCScene s = committedScene(scene);
                   std::vector<ElementHit> hits(set.rays.size());
                   for (auto _ : state) {
                     intersect(s, flags, set.rays, hits);
                     benchmark::DoNotOptimize(hits.data());
                   }
                   reportRays(state, set, hits, /*peer=*/true);
                 });
  }
}

void registerEmbree() {
  registerIntersect(RaysKind::kCoherent, "intersect1", intersect1);
  registerIntersect(RaysKind::kCoherent, "intersect8", intersect8);
  registerIntersect(RaysKind::kCoherent, "intersect16", intersect16);
  registerIntersect(RaysKind::kIncoherent, "intersect1", intersect1);
  registerIntersect(RaysKind::kIncoherent, "intersect1M", intersect1M);
  for (auto [method, quality] : {std::pair{"embree_medium", RTC_BUILD_QUALITY_MEDIUM},
                                 std::pair{"embree_high", RTC_BUILD_QUALITY_HIGH}}) {
    registerOnce("rays/build", method, "peer", kRaysTriangles, [quality](benchmark::State& state) {
      device();  // created once, outside the timing
      for (auto _ : state) {
        // The geometry's copy into Embree's buffers is not timed: only the build.
        state.PauseTiming();
        auto s = std::make_unique<EmbreeScene>(raysWorkload().mesh, quality, RTC_SCENE_FLAG_NONE);
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
