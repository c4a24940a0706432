// Pair finding: sweep and prune along x inside the cells of a y-z grid.
#include <algorithm>
#include <cmath>
#include <limits>

#include <omp.h>

#include "../core/radix_sort.hpp"
#include "../views.hpp"
#include "pair_finder.hpp"
#include "simdphys/broadphase.hpp"
#include "simdphys/bvh.hpp"

namespace simdphys {
namespace {

// Boxes per grid cell the grid aims at: few enough that the sweep's candidate lists along x stay
// short, many enough that boxes spanning two cells stay rare. Chosen by measurement (see
// docs/broadphase.md).
constexpr double kBoxesPerCell = 1024;
// Cells are at least this many average box sizes wide, so few boxes are copied into two cells.
constexpr double kMinCellInBoxes = 4;

struct Grid {
  int ny = 1, nz = 1;
  float originY = 0, originZ = 0, scaleY = 0, scaleZ = 0;
  // Monotonic in the coordinate, so the cell of a point inside a box lies within the box's cells.
  // Clamped in float before the conversion, since converting a float beyond int's range (or NaN)
  // is undefined: the offset overflows to inf for boxes spanning more than FLT_MAX, and the scale
  // is inf for a denormal extent, where 0 * inf is NaN (cell 0, as for any offset not above 0).
  static int cell(float offset, float scale, int n) {
    const float v = offset * scale;
    return v > 0 ? int(std::min(v, float(n - 1))) : 0;
  }
  int cellY(float y) const { return cell(y - originY, scaleY, ny); }
  int cellZ(float z) const { return cell(z - originZ, scaleZ, nz); }
};

Grid chooseGrid(const BoxStream& b, PairMethod method) {
  Grid g;
  const std::size_t n = b.size();
  if (method != PairMethod::kGridSweep || n == 0) return g;
  float loY = std::numeric_limits<float>::infinity(), hiY = -loY, loZ = loY, hiZ = -loY;
  double sizeY = 0, sizeZ = 0;
  using F = fields::Box;
  for (std::size_t i = 0; i < n; ++i) {
    loY = std::min(loY, b.field(F::minY)[i]), hiY = std::max(hiY, b.field(F::maxY)[i]);
    loZ = std::min(loZ, b.field(F::minZ)[i]), hiZ = std::max(hiZ, b.field(F::maxZ)[i]);
    sizeY += double(b.field(F::maxY)[i]) - b.field(F::minY)[i];
    sizeZ += double(b.field(F::maxZ)[i]) - b.field(F::minZ)[i];
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

// A box as copied into one of its cells: 32 bytes, so the scatter into cells writes one
// stream per cell rather than nine.
struct Entry {
  float minX, maxX, minY, maxY, minZ, maxZ;
  std::uint32_t id;
  std::int16_t loY, loZ;
};
static_assert(sizeof(Entry) == 32);

// One cell's boxes transposed to the SoA the sweep kernels read, followed by sentinels.
struct CellBuffer {
  std::vector<float> minX, maxX, minY, maxY, minZ, maxZ;
  std::vector<std::uint32_t> id;
  std::vector<std::int32_t> loY, loZ;

  std::vector<float> keys;
  RadixSorter sorter;

  // Sorts the cell's entries by minX (ties in id order, as the entries come) while transposing
  // them. The cell is small enough to stay in cache, unlike a global sort's scattered reads.
  simd::SweepCell load(const Entry* e, std::size_t n, int cy, int cz) {
    const float inf = std::numeric_limits<float>::infinity();
    const std::size_t size = n + kStreamPad;
    // Only the sentinels need setting: the entries are written below.
    for (auto* v : {&minX, &minY, &minZ}) v->resize(size), std::fill(v->begin() + n, v->end(), inf);
    for (auto* v : {&maxX, &maxY, &maxZ})
      v->resize(size), std::fill(v->begin() + n, v->end(), -inf);
    id.resize(size), loY.resize(size), loZ.resize(size), keys.resize(n);
    for (std::size_t k = 0; k < n; ++k) keys[k] = e[k].minX;
    const auto& order = sorter.sort(keys.data(), n);
    for (std::size_t k = 0; k < n; ++k) {
      const Entry& from = e[order[k]];
      minX[k] = from.minX, maxX[k] = from.maxX, minY[k] = from.minY, maxY[k] = from.maxY;
      minZ[k] = from.minZ, maxZ[k] = from.maxZ, id[k] = from.id;
      loY[k] = from.loY, loZ[k] = from.loZ;
    }
    return {minX.data(), maxX.data(), minY.data(), maxY.data(), minZ.data(), maxZ.data(),
            id.data(),   loY.data(),  loZ.data(),  n,           cy,          cz};
  }
};

// Each box's partners after it, ascending.
void bvhPairs(const BoxStream& b, std::vector<Pair>& pairs) {
  Bvh tree(b);
  std::vector<std::uint32_t> hits;
  for (std::uint32_t i = 0; i < b.size(); ++i) {
    hits.clear();
    tree.query(b[i], hits);
    std::sort(hits.begin(), hits.end());
    for (std::uint32_t j : hits)
      if (j > i) pairs.push_back({i, j});
  }
}

}  // namespace

template <>
struct PairFinder::Scratch {
  std::vector<std::int16_t> y0, y1, z0, z1;  // the cells each box covers
  std::vector<std::uint32_t> begin, cursor;  // per cell, into entries
  std::vector<Entry> entries;                // cell by cell, each in id order
  std::vector<CellBuffer> buffers;           // one per thread
  std::vector<std::vector<Pair>> rowPairs;   // one per grid row, dealt to the sorter
  PairSorter sorter;

  template <class Sweep>
  void run(const BoxStream& b, std::vector<Pair>& pairs, PairMethod method, Sweep sweep) {
    const Grid g = chooseGrid(b, method);
    const std::size_t n = b.size(), cells = std::size_t(g.ny) * g.nz;
    y0.resize(n), y1.resize(n), z0.resize(n), z1.resize(n);
    begin.assign(cells + 1, 0);
    using F = fields::Box;
    for (std::size_t i = 0; i < n; ++i) {
      y0[i] = std::int16_t(g.cellY(b.field(F::minY)[i]));
      y1[i] = std::int16_t(g.cellY(b.field(F::maxY)[i]));
      z0[i] = std::int16_t(g.cellZ(b.field(F::minZ)[i]));
      z1[i] = std::int16_t(g.cellZ(b.field(F::maxZ)[i]));
      for (int cy = y0[i]; cy <= y1[i]; ++cy)
        for (int cz = z0[i]; cz <= z1[i]; ++cz) ++begin[std::size_t(cy) * g.nz + cz + 1];
    }
    for (std::size_t c = 0; c < cells; ++c) begin[c + 1] += begin[c];
    entries.resize(begin[cells]);
    cursor.assign(begin.begin(), begin.end() - 1);
    for (std::uint32_t i = 0; i < n; ++i) {
      Entry e{b.field(F::minX)[i],
              b.field(F::maxX)[i],
              b.field(F::minY)[i],
              b.field(F::maxY)[i],
              b.field(F::minZ)[i],
              b.field(F::maxZ)[i],
              i,
              y0[i],
              z0[i]};
      for (int cy = y0[i]; cy <= y1[i]; ++cy)
        for (int cz = z0[i]; cz <= z1[i]; ++cz) entries[cursor[std::size_t(cy) * g.nz + cz]++] = e;
    }
    // Rows are independent; each fills its own list and deals it while it is in cache.
    rowPairs.resize(g.ny);
    sorter.begin(std::size_t(g.ny), n);
    buffers.resize(std::size_t(omp_get_max_threads()));
    // A few thousand boxes (a world's bodies, every step) sweep in well under a millisecond, less
    // than OpenMP's threads take to start and meet at the barrier (and far less than they spin
    // there when the other core is busy).
#pragma omp parallel for schedule(dynamic) if (n >= 20'000)
    for (int cy = 0; cy < g.ny; ++cy) {
      CellBuffer& buffer = buffers[std::size_t(omp_get_thread_num())];
      rowPairs[cy].clear();
      for (int cz = 0; cz < g.nz; ++cz) {
        std::size_t c = std::size_t(cy) * g.nz + cz;
        sweep(buffer.load(entries.data() + begin[c], begin[c + 1] - begin[c], cy, cz),
              rowPairs[cy]);
      }
      sorter.deal(std::size_t(cy), rowPairs[cy]);
    }
    sorter.finish(pairs);
  }
};

template <>
void PairFinder::findWith(const BoxStream& b, std::vector<Pair>& pairs, PairMethod method) {
  const bool plain = detail::plainLoopsActive();
  if (method == PairMethod::kBvh) {
    if (plain) throw Error("PairFinder: the BVH method has no plain-loop form");
    pairs.clear();
    return bvhPairs(b, pairs);
  }
  if (plain) return scratch_->run(b, pairs, method, simd::sweepCellAutovec);
  if (referencePathActive())
    return scratch_->run(b, pairs, method, reference::sweepScalar<simd::SweepCell>);
  scratch_->run(b, pairs, method, simd::sweepCell);
}

template class PairFinderOf<BoxStream, PairMethod>;

void findPairs(const BoxStream& b, std::vector<Pair>& pairs, PairMethod method) {
  PairFinder().find(b, pairs, method);
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
