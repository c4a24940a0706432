// The README's example: boxes in a stream, their overlapping pairs, a frustum cull.
#include <simdphys/simdphys.hpp>

#include <cstdio>

int main() {
  using namespace simdphys;
  BoxStream boxes;
  for (int i = 0; i < 100; ++i) boxes.push({Vec3f(i * 0.9f, 0, 0), Vec3f(i * 0.9f + 1, 1, 1)});
  std::vector<Pair> pairs;
  findPairs(boxes, pairs);  // 99 neighbours overlap
  Frustum view = Frustum::fromMatrix(perspective(1.0f, 1.5f, 0.1f, 100.0f));
  SphereStream spheres;
  spheres.push({Vec3f(0, 0, -10), 1.0f});
  std::vector<std::uint32_t> visible;
  cull(view, spheres, visible);
  std::printf("path %s: %zu pairs, %zu visible\n", activePath().c_str(), pairs.size(),
              visible.size());
  return pairs.size() == 99 && visible.size() == 1 ? 0 : 1;
}
