// Ray streams against a MeshBvh: how each mode schedules the rays (packets of coherent groups,
// single rays in an order that keeps the tree in cache), chunks spread over the threads.
#include <algorithm>
#include <cmath>
#include <vector>

#include "src/core/radix_sort.hpp"
#include "src/mesh/mesh_internal.hpp"
#include "src/views.hpp"

namespace simdphys {
namespace {

// Rays in chunks: each a kernel call of its own, chunks spread over the threads (each ray is
// independent, so the answers do not depend on the thread count or the order).
constexpr std::size_t kChunk = 256;
// Below this many single rays, ordering them costs more than the cache misses it saves.
constexpr std::size_t kOrderFrom = 4096;

// The chunk of `rays` from `begin` as a view of its own: the mesh kernels read ray by ray, so it
// needs no padding (padded = count).
simd::RaysView chunk(simd::RaysView rays, std::size_t begin) {
  for (const float*& f : rays.field) f += begin;
  rays.count = rays.padded = std::min(kChunk, rays.count - begin);
  return rays;
}

int octant(const RayStream& rays, std::size_t i) {
  int o = 0;
  for (int a = 0; a < 3; ++a) o |= int(std::signbit(rays.direction(a)[i])) << a;
  return o;
}

// Whether the rays present (kAbsentLane: none) all point into one octant: kAuto's coherence test.
bool sameOctant(const RayStream& rays, const std::uint32_t* lanes, std::size_t n) {
  int first = -1;
  for (std::size_t i = 0; i < n; ++i) {
    if (lanes[i] == simd::kAbsentLane) continue;
    const int o = octant(rays, lanes[i]);
    if (first >= 0 && o != first) return false;
    first = o;
  }
  return true;
}

// Traces rays[index[k]] one at a time, in chunks over the threads. With enough of them, in an
// order that keeps the tree in cache: rays that enter no child of the root are answered at once;
// the others are sorted by where they enter it (simd::meshRayKeys), copied in that order and
// traced. Neighbours in that order walk the same nodes to the same leaves, where random rays over
// a large mesh would miss the cache at nearly every node (Pharr et al.'s memory-coherent ray
// tracing; Moon et al. sort on a hit point estimate). docs/bvh.md has the measurements.
void traceSingles(const MeshBvh& bvh, const RayStream& rays,
                  const std::vector<std::uint32_t>& index, std::span<ElementHit> out) {
  const simd::MeshView mesh = meshView(bvh.bvh(), bvh.blocks());
  const simd::RaysView all = view(rays);
  const std::size_t n = index.size();
  const auto chunks = [](std::size_t count) { return std::int64_t((count + kChunk - 1) / kChunk); };
  if (n < kOrderFrom) {
#pragma omp parallel for schedule(dynamic, 1)
    for (std::int64_t c = 0; c < chunks(n); ++c) {
      const std::size_t begin = std::size_t(c) * kChunk;
      simd::meshClosestHitsOf(mesh, all, index.data() + begin, std::min(kChunk, n - begin),
                              out.data());
    }
    return;
  }
  std::vector<std::uint32_t> keys(n);
#pragma omp parallel for schedule(static)
  for (std::int64_t c = 0; c < chunks(n); ++c) {
    const std::size_t begin = std::size_t(c) * kChunk;
    simd::meshRayKeys(mesh, all, index.data() + begin, std::min(kChunk, n - begin),
                      keys.data() + begin);
  }
  // The entering rays as records (read in stream order), so that reordering them moves one cache
  // line a ray rather than gathering seven fields from seven places.
  struct Record {
    float field[fields::Ray::kCount];  // origin, direction, tMax
    std::uint32_t index;
  };
  std::vector<Record> entering;
  std::vector<std::uint32_t> enteringKeys;
  entering.reserve(n), enteringKeys.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::uint32_t i = index[k];
    if (keys[k] == simd::kMissKey) {
      out[i] = ElementHit{};
      continue;
    }
    Record& r = entering.emplace_back(Record{{}, i});
    for (std::size_t f = 0; f < fields::Ray::kCount; ++f) r.field[f] = all[f][i];
    enteringKeys.push_back(keys[k]);
  }
  RadixSorter sorter;
  const auto& order = sorter.sort(enteringKeys.data(), enteringKeys.size());
  // The rays in that order as a stream of their own (7 fields, then the hits' t), and their ids.
  const std::size_t m = entering.size();
  std::vector<float> sorted(8 * m);
  std::vector<std::uint32_t> ids(m);
  const auto field = [&](int f) { return sorted.data() + f * m; };
  for (std::size_t k = 0; k < m; ++k)
    for (int f = 0; f < 7; ++f) field(f)[k] = entering[order[k]].field[f];
  simd::RaysView sortedRays{{}, m, m};
  for (std::size_t f = 0; f < fields::Ray::kCount; ++f) sortedRays.field[f] = field(int(f));
#pragma omp parallel for schedule(dynamic, 1)
  for (std::int64_t c = 0; c < chunks(m); ++c) {
    const std::size_t begin = std::size_t(c) * kChunk;
    const simd::RaysView v = chunk(sortedRays, begin);
    simd::meshClosestHits(mesh, v, ids.data() + begin, field(7) + begin);
  }
  for (std::size_t k = 0; k < m; ++k) out[entering[order[k]].index] = {ids[k], field(7)[k]};
}

// Groups of rays (rows of the stream or tiles of its image) as packets; with kAuto, the groups
// whose rays do not share an octant go to traceSingles instead.
void tracePackets(const MeshBvh& bvh, const RayStream& rays, std::span<ElementHit> out,
                  const RayStreamOptions& options) {
  // 16 by default: measured faster than 8 on AVX-512 and AVX2, equal on SSE4 (docs/bvh.md).
  const std::uint32_t width = options.packetSize != 0 ? options.packetSize : 16;
  const std::size_t n = rays.size();
  // Tiles: 4 rays wide, width / 4 rows high.
  const std::size_t imageWidth = options.imageWidth;
  const std::size_t tilesX = imageWidth ? (imageWidth + 3) / 4 : 0;
  const std::size_t tileRows = width / 4;
  const std::size_t imageRows = imageWidth ? (n + imageWidth - 1) / imageWidth : 0;
  const std::size_t groups =
      imageWidth ? tilesX * ((imageRows + tileRows - 1) / tileRows) : (n + width - 1) / width;
  const auto lane = [&](std::size_t g, std::uint32_t i) -> std::uint32_t {
    std::size_t at;
    if (imageWidth == 0) {
      at = g * width + i;
    } else {
      const std::size_t x = g % tilesX * 4 + i % 4, y = g / tilesX * tileRows + i / 4;
      if (x >= imageWidth) return simd::kAbsentLane;
      at = y * imageWidth + x;
    }
    return at < n ? std::uint32_t(at) : simd::kAbsentLane;
  };
  const bool onlyCoherent = options.mode == RayStreamOptions::Mode::kAuto;
  const simd::MeshView mesh = meshView(bvh.bvh(), bvh.blocks());
  const simd::RaysView all = view(rays);
  // Each batch of groups makes its packets as it traces them: an index of the whole stream
  // (3 MB for W2's camera) would be written and read once, on fresh pages, every call.
  const std::size_t perBatch = kChunk / width;
  const std::int64_t batches = std::int64_t((groups + perBatch - 1) / perBatch);
  std::vector<std::uint32_t> singles;
#pragma omp parallel for schedule(dynamic, 1)
  for (std::int64_t b = 0; b < batches; ++b) {
    std::uint32_t packets[kChunk], alone[kChunk];
    std::size_t packed = 0, lone = 0;
    const std::size_t first = std::size_t(b) * perBatch;
    for (std::size_t g = first; g < std::min(groups, first + perBatch); ++g) {
      std::uint32_t* lanes = packets + packed;
      bool any = false;
      for (std::uint32_t i = 0; i < width; ++i)
        lanes[i] = lane(g, i), any = any || lanes[i] != simd::kAbsentLane;
      if (!any) continue;  // a tile past the stream's end (an image wider than the stream)
      if (!onlyCoherent || sameOctant(rays, lanes, width)) {
        packed += width;
        continue;
      }
      for (std::uint32_t i = 0; i < width; ++i)
        if (lanes[i] != simd::kAbsentLane) alone[lone++] = lanes[i];
    }
    if (packed != 0)
      simd::meshClosestHitPackets(mesh, all, packets, packed / width, int(width), out.data());
    // Each ray's answer is its own: the order singles are gathered in does not change them.
    if (lone != 0) {
#pragma omp critical(simdphys_stream_singles)
      singles.insert(singles.end(), alone, alone + lone);
    }
  }
  traceSingles(bvh, rays, singles, out);
}

}  // namespace

void MeshBvh::raycast(const RayStream& rays, std::span<ElementHit> out,
                      const RayStreamOptions& options) const {
  if (out.size() != rays.size())
    throw Error("MeshBvh::raycast: " + std::to_string(out.size()) + " hits for " +
                std::to_string(rays.size()) + " rays");
  if (options.packetSize != 0 && options.packetSize != 8 && options.packetSize != 16)
    throw Error("MeshBvh::raycast: packetSize " + std::to_string(options.packetSize) +
                " is not 0, 8 or 16");
  const bool ref = referencePathActive();
  if (!ref && options.mode != RayStreamOptions::Mode::kSingle) {
    tracePackets(*this, rays, out, options);
    return;
  }
  const std::int64_t chunks = std::int64_t((rays.size() + kChunk - 1) / kChunk);
#pragma omp parallel for schedule(dynamic, 1)
  for (std::int64_t c = 0; c < chunks; ++c) {
    const std::size_t begin = std::size_t(c) * kChunk;
    const simd::RaysView v = chunk(view(rays), begin);
    if (ref) {
      for (std::size_t i = 0; i < v.count; ++i)
        out[begin + i] = reference::closestHit(bvh_, blocks_, detail::traversalRay(v, i));
      continue;
    }
    std::uint32_t id[kChunk];
    float t[kChunk];
    simd::meshClosestHits(meshView(bvh_, blocks_), v, id, t);
    for (std::size_t i = 0; i < v.count; ++i) out[begin + i] = {id[i], t[i]};
  }
}

void MeshBvh::occluded(const RayStream& rays, std::span<std::uint8_t> out) const {
  if (out.size() != rays.size())
    throw Error("MeshBvh::occluded: " + std::to_string(out.size()) + " results for " +
                std::to_string(rays.size()) + " rays");
  const bool ref = referencePathActive();
  const std::int64_t chunks = std::int64_t((rays.size() + kChunk - 1) / kChunk);
#pragma omp parallel for schedule(dynamic, 1)
  for (std::int64_t c = 0; c < chunks; ++c) {
    const std::size_t begin = std::size_t(c) * kChunk;
    const simd::RaysView v = chunk(view(rays), begin);
    if (!ref) {
      simd::meshAnyHits(meshView(bvh_, blocks_), v, out.data() + begin);
      continue;
    }
    for (std::size_t i = 0; i < v.count; ++i)
      out[begin + i] = reference::anyHit(bvh_, blocks_, detail::traversalRay(v, i));
  }
}

}  // namespace simdphys
