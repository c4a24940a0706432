// W6: frustum culling of 1,000,000 spheres and boxes, with the disagreement with a double-
// precision cull beside the speed; "planes" culls the same data every iteration (16 or 24 MiB,
// which may stay in the last-level cache), "planes_dram" cycles through copies of it, at least
// 128 MiB in all (4x the 32 MiB L3 of the reference machine), so each iteration reads from DRAM.
#include "bench_common.hpp"
#include "testing/cull_reference.hpp"
#include "testing/kernels.hpp"

namespace simdphys::bench {
namespace {

template <class T>
std::vector<double> widened(std::span<const T> v) {
  return {v.begin(), v.end()};
}

// Objects whose visibility in float differs from the same test in double on the double inputs.
std::size_t disagreementWithDouble(const std::vector<std::uint32_t>& visible, bool spheres) {
  const auto& w = cullWorkload();
  const Frustumd f = Frustumd::fromMatrix(w.viewProjection);
  std::vector<std::uint32_t> exact;
  if (spheres) {
    const SphereStream& s = w.spheres;
    reference::cullSpheres<double>(f, widened(s.field(fields::Sphere::x).view()),
                                   widened(s.field(fields::Sphere::y).view()),
                                   widened(s.field(fields::Sphere::z).view()),
                                   widened(s.field(fields::Sphere::r).view()), exact);
  } else {
    const BoundsStream& b = w.boxes;
    reference::cullBoxes<double>(
        f, widened(b.field(fields::Bounds::cx).view()), widened(b.field(fields::Bounds::cy).view()),
        widened(b.field(fields::Bounds::cz).view()), widened(b.field(fields::Bounds::ex).view()),
        widened(b.field(fields::Bounds::ey).view()), widened(b.field(fields::Bounds::ez).view()),
        exact);
  }
  std::vector<std::uint32_t> diff;
  std::set_symmetric_difference(visible.begin(), visible.end(), exact.begin(), exact.end(),
                                std::back_inserter(diff));
  return diff.size();
}

template <class Cull>
void cullBody(benchmark::State& state, bool spheres, Cull cullNow) {
  const auto& w = cullWorkload();
  const std::size_t n = w.spheres.size();
  std::vector<std::uint32_t> visible;
  for (auto _ : state) {
    cullNow(w, visible);
    benchmark::DoNotOptimize(visible.data());
  }
  state.SetItemsProcessed(std::int64_t(state.iterations() * n));
  // Bytes read: four floats a sphere, six a box.
  state.SetBytesProcessed(std::int64_t(state.iterations() * n * (spheres ? 4 : 6) * 4));
  state.counters["error"] = double(disagreementWithDouble(visible, spheres));
  checkExact(state, visible.size(),
             spheres ? workloads::kCullSpheresVisible : workloads::kCullBoxesVisible);
}

// The cull of `stream` from main memory: copies of it, at least kDramBytes in all, culled in turn,
// so that a copy has left the cache by the time it comes round again.
constexpr std::size_t kDramBytes = std::size_t(128) << 20;
template <class Stream>
void cullFromMemory(benchmark::State& state, const Stream& stream, bool spheres) {
  const std::size_t bytes = stream.size() * (spheres ? 4 : 6) * sizeof(float);
  static const std::vector<Stream> copies(kDramBytes / bytes + 1, stream);
  std::size_t next = 0;
  cullBody(state, spheres, [&](const workloads::CullWorkload& w, std::vector<std::uint32_t>& v) {
    cull(w.frustum, copies[next++ % copies.size()], v);
  });
  state.counters["copies"] = double(copies.size());
}

}  // namespace

void registerCullBenchmarks() {
  const std::size_t n = cullWorkload().spheres.size();
  registerPerPath("cull_spheres", "planes", n, [](benchmark::State& state) {
    cullBody(state, true, [](const auto& w, auto& v) { cull(w.frustum, w.spheres, v); });
  });
  registerPerPath("cull_boxes", "planes", n, [](benchmark::State& state) {
    cullBody(state, false, [](const auto& w, auto& v) { cull(w.frustum, w.boxes, v); });
  });
  registerBestPath("cull_spheres", "planes_dram", n, [](benchmark::State& state) {
    cullFromMemory(state, cullWorkload().spheres, true);
  });
  registerBestPath("cull_boxes", "planes_dram", n, [](benchmark::State& state) {
    cullFromMemory(state, cullWorkload().boxes, false);
  });
  auto autovec = [](bool spheres) {
    return [spheres](benchmark::State& state) {
      cullBody(state, spheres, [spheres](const workloads::CullWorkload& w, auto& v) {
        v.resize(w.spheres.padded());
        v.resize(spheres ? simd::cullSpheresAutovec(planes(w.frustum), view(w.spheres), v.data())
                         : simd::cullBoundsAutovec(planes(w.frustum), view(w.boxes), v.data()));
      });
    };
  };
  registerPerPath("cull_spheres", "autovec", n, autovec(true), false);
  registerPerPath("cull_boxes", "autovec", n, autovec(false), false);
}

}  // namespace simdphys::bench
