// W6: frustum culling of 1,000,000 spheres and boxes, with the disagreement with a double-
// precision cull beside the speed.
#include "bench_common.hpp"
#include "simd/kernels.hpp"
#include "src/reference/cull.hpp"
#include "src/views.hpp"

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
    reference::cullSpheres<double>(f, widened(s.x().view()), widened(s.y().view()),
                                   widened(s.z().view()), widened(s.r().view()), exact);
  } else {
    const BoundsStream& b = w.boxes;
    reference::cullBoxes<double>(f, widened(b.cx().view()), widened(b.cy().view()),
                                 widened(b.cz().view()), widened(b.ex().view()),
                                 widened(b.ey().view()), widened(b.ez().view()), exact);
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
             spheres ? scenes::kCullSpheresVisible : scenes::kCullBoxesVisible);
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
  auto autovec = [](bool spheres) {
    return [spheres](benchmark::State& state) {
      cullBody(state, spheres, [spheres](const scenes::CullWorkload& w, auto& v) {
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
