// Pair finding: sweep and prune along x inside the cells of a y-z grid.
#include <algorithm>
#include <cmath>
#include <limits>

#include "../core/radix_sort.hpp"
#include "../views.hpp"
#include "simdphys/broadphase.hpp"
#include "simdphys/bvh.hpp"

namespace simdphys {
namespace reference {
#include "sweep-inl.hpp"
}  // namespace reference

namespace {

// Boxes per grid cell the grid aims at: few enough that the sweep's candidate lists along x stay
// short, many enough that boxes spanning two cells stay rare. Chosen by measurement (see
// docs/broadphase.md).
constexpr double kBoxesPerCell = 2048;
// Cells are at least this many average box sizes wide, so few boxes are copied into two cells.
constexpr double kMinCellInBoxes = 4;

struct Grid {
  int ny = 1, nz = 1;
  float originY = 0, originZ = 0, scaleY = 0, scaleZ = 0;
  // Monotonic in the coordinate, so the cell of a point inside a box lies within the box's cells.
  int cellY(float y) const { return std::clamp(int((y - originY) * scaleY), 0, ny - 1); }
  int cellZ(float z) const { return std::clamp(int((z - originZ) * scaleZ), 0, nz - 1); }
};

Grid chooseGrid(const BoxStream& b, PairMethod method) {
  Grid g;
  const std::size_t n = b.size();
  if (method != PairMethod::kGridSweep || n == 0) return g;
  float loY = std::numeric_limits<float>::infinity(), hiY = -loY, loZ = loY, hiZ = -loY;
  double sizeY = 0, sizeZ = 0;
  for (std::size_t i = 0; i < n; ++i) {
    loY = std::min(loY, b.minY()[i]), hiY = std::max(hiY, b.maxY()[i]);
    loZ = std::min(loZ, b.minZ()[i]), hiZ = std::max(hiZ, b.maxZ()[i]);
    sizeY += b.maxY()[i] - b.minY()[i], sizeZ += b.maxZ()[i] - b.minZ()[i];
  }
  const double perAxis = std::sqrt(double(n) / kBoxesPerCell);
  auto cells = [&](double extent, double meanSize) {
    double limit = meanSize > 0 ? extent / (kMinCellInBoxes * meanSize) : perAxis;
    return int(std::clamp(std::min(perAxis, limit), 1.0, 256.0));
  };
  g.ny = cells(double(hiY) - loY, sizeY / double(n));
  g.nz = cells(double(hiZ) - loZ, sizeZ / double(n));
  g.originY = loY, g.originZ = loZ;
  g.scaleY = hiY > loY ? float(g.ny / (double(hiY) - loY)) : 0.0f;
  g.scaleZ = hiZ > loZ ? float(g.nz / (double(hiZ) - loZ)) : 0.0f;
  return g;
}

// The boxes copied into their cells, each cell sorted by minX and followed by sentinels.
struct CellStreams {
  std::vector<float> minX, maxX, minY, maxY, minZ, maxZ;
  std::vector<std::uint32_t> id;
  std::vector<std::int32_t> loY, loZ;
  std::vector<std::size_t> begin, count;

  simd::SweepCell cell(const Grid& g, int cy, int cz) const {
    std::size_t c = std::size_t(cy) * g.nz + cz, at = begin[c];
    return {minX.data() + at, maxX.data() + at, minY.data() + at, maxY.data() + at,
            minZ.data() + at, maxZ.data() + at, id.data() + at,   loY.data() + at,
            loZ.data() + at,  count[c],         cy,               cz};
  }
};

CellStreams fillCells(const BoxStream& b, const Grid& g) {
  const std::size_t n = b.size(), cells = std::size_t(g.ny) * g.nz;
  std::vector<std::int32_t> y0(n), y1(n), z0(n), z1(n);
  CellStreams s;
  s.count.assign(cells, 0);
  for (std::size_t i = 0; i < n; ++i) {
    y0[i] = g.cellY(b.minY()[i]), y1[i] = g.cellY(b.maxY()[i]);
    z0[i] = g.cellZ(b.minZ()[i]), z1[i] = g.cellZ(b.maxZ()[i]);
    for (int cy = y0[i]; cy <= y1[i]; ++cy)
      for (int cz = z0[i]; cz <= z1[i]; ++cz) ++s.count[std::size_t(cy) * g.nz + cz];
  }
  s.begin.resize(cells);
  std::size_t total = 0;
  for (std::size_t c = 0; c < cells; ++c) s.begin[c] = total, total += s.count[c] + kStreamPad;
  const float inf = std::numeric_limits<float>::infinity();
  s.minX.assign(total, inf), s.minY.assign(total, inf), s.minZ.assign(total, inf);
  s.maxX.assign(total, -inf), s.maxY.assign(total, -inf), s.maxZ.assign(total, -inf);
  s.id.assign(total, 0), s.loY.assign(total, 0), s.loZ.assign(total, 0);
  std::vector<std::size_t> cursor = s.begin;
  // Visiting the boxes in minX order leaves every cell sorted.
  for (std::uint32_t i : sortedOrder(b.minX().data(), n)) {
    for (int cy = y0[i]; cy <= y1[i]; ++cy) {
      for (int cz = z0[i]; cz <= z1[i]; ++cz) {
        std::size_t k = cursor[std::size_t(cy) * g.nz + cz]++;
        s.minX[k] = b.minX()[i], s.minY[k] = b.minY()[i], s.minZ[k] = b.minZ()[i];
        s.maxX[k] = b.maxX()[i], s.maxY[k] = b.maxY()[i], s.maxZ[k] = b.maxZ()[i];
        s.id[k] = i, s.loY[k] = y0[i], s.loZ[k] = z0[i];
      }
    }
  }
  return s;
}

void bvhPairs(const BoxStream& b, std::vector<Pair>& pairs) {
  Bvh tree(b);
  std::vector<std::uint32_t> hits;
  for (std::uint32_t i = 0; i < b.size(); ++i) {
    hits.clear();
    tree.query(b[i], hits);
    for (std::uint32_t j : hits)
      if (j > i) pairs.push_back({i, j});
  }
}

}  // namespace

void findPairs(const BoxStream& b, std::vector<Pair>& pairs, PairMethod method) {
  pairs.clear();
  if (method == PairMethod::kBvh) return bvhPairs(b, pairs);
  const Grid g = chooseGrid(b, method);
  const CellStreams s = fillCells(b, g);
  const bool ref = referencePathActive();
  for (int cy = 0; cy < g.ny; ++cy) {
    for (int cz = 0; cz < g.nz; ++cz) {
      simd::SweepCell cell = s.cell(g, cy, cz);
      if (ref)
        reference::sweepCellScalar(cell, pairs);
      else
        simd::sweepCell(cell, pairs);
    }
  }
}

std::uint64_t countOverlapsBrute(const BoxStream& boxes, std::span<const Aabb> queries) {
  for (std::size_t q = 0; q < queries.size(); ++q)
    validate(queries[q], "countOverlapsBrute: query " + std::to_string(q));
  if (referencePathActive()) {
    std::uint64_t count = 0;
    for (const Aabb& q : queries)
      for (std::size_t i = 0; i < boxes.size(); ++i) count += overlaps(q, boxes[i]);
    return count;
  }
  std::vector<simd::Box> qs;
  for (const Aabb& q : queries) qs.push_back(box(q));
  return simd::countOverlapsBrute(view(boxes), qs.data(), qs.size());
}

}  // namespace simdphys
