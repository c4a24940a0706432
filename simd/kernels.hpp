// The interface between the library and its SIMD kernels. Plain pointers and counts only: no
// Highway and no Eigen types cross it, so each kernel file is compiled once per instruction set
// and chosen at run time (see dispatch.cpp). Streams cross as core::View (core/view.hpp): kernels
// read whole vectors up to `padded` and rely on the padding value to produce no result.
//
// A batch kernel is declared here once, as a Kernel object with its signature; its file defines
// it per target and exports it with one SIMDPHYS_EXPORT line (simd/export.hpp). Its plain-loop
// baseline, the same computation left to the compiler's auto-vectoriser (the benchmarks' honest
// second baseline), is the kernel of the same name with "Autovec" appended, same signature, same
// file (docs/architecture.md, "How to add a kernel").
#pragma once

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/cloth_step.hpp"
#include "core/particle_step.hpp"
#include "core/rigid_solve.hpp"
#include "core/view.hpp"
#include "simdphys/core.hpp"
#include "simdphys/stream_fields.hpp"

namespace simdphys {
struct BvhNode;  // bvh.hpp: plain arrays, no Eigen

namespace detail {
// A primitive as the BVH builder moves it (32 bytes): its box as two rows, the id in the first
// row's unused lane. The builder partitions these in place, so every pass over a range reads
// memory in order (Embree's PrimRef).
struct alignas(32) BvhPrimRef {
  float lo[4], hi[4];  // lo[3]: the id's bits; hi[3]: 0

  BvhPrimRef() = default;
  BvhPrimRef(const float (&l)[3], const float (&h)[3], std::uint32_t id)
      : lo{l[0], l[1], l[2], std::bit_cast<float>(id)}, hi{h[0], h[1], h[2], 0} {}
  std::uint32_t id() const { return std::bit_cast<std::uint32_t>(lo[3]); }
  // Twice the centre: only the ordering matters, and halving would round.
  float centroid(int a) const { return lo[a] + hi[a]; }
};
}  // namespace detail
}  // namespace simdphys

namespace simdphys::simd {

// ---- dispatch --------------------------------------------------------------------------------
// Names of the compiled SIMD targets this CPU supports, best first ("avx512", "avx2", ...).
std::vector<std::string> supportedTargets();
// Makes the named target the one HWY_DYNAMIC_DISPATCH calls. Returns false if unsupported.
bool selectTarget(const std::string& name);

// A kernel compiled once per target, called as a function: each call runs the chosen target's
// code (Highway's dispatch table, read through `chosen`). Defined by SIMDPHYS_EXPORT.
template <class Signature>
class Kernel;
template <class R, class... A>
class Kernel<R(A...)> {
 public:
  using Function = R (*)(A...);
  constexpr explicit Kernel(Function (*chosen)()) : chosen_(chosen) {}
  R operator()(A... a) const { return chosen_()(a...); }

 private:
  Function (*chosen_)();
};
// The common kind: the elements of a stream view that a query selects, their indices ascending in
// `out` (room for the view's `padded` count: kernels store whole vectors), their number returned.
template <class Query, class View>
using SelectKernel = Kernel<std::size_t(const Query& query, const View& view, std::uint32_t* out)>;

// For compress-inl.hpp: entry m lists, a nibble per lane from the lowest, the indices of the
// set bits of m (the lanes a mask of 8 lanes keeps).
inline constexpr auto kCompressNibbles = [] {
  std::array<std::uint32_t, 256> table{};
  for (unsigned m = 0; m < 256; ++m)
    for (unsigned lane = 0, k = 0; lane < 8; ++lane)
      if (m >> lane & 1) table[m] |= lane << (4 * k++);
  return table;
}();

// ---- views: the streams as kernels read them (the layouts of simdphys/stream_fields.hpp) -------
using BoxesView = core::View<fields::Box>;
using SpheresView = core::View<fields::Sphere>;
using BoundsView = core::View<fields::Bounds>;
using TrianglesView = core::View<fields::Triangle>;
using ObbsView = core::View<fields::Obb>;
using CirclesView = core::View<fields::Circle>;
using RectsView = core::View<fields::Rect>;
using OrientedRectsView = core::View<fields::OrientedRect>;
using ParticlesView = core::View<fields::Particle, float>;  // stepped in place

// One box as a query.
struct Box {
  float minX, minY, minZ, maxX, maxY, maxZ;
};
// Six planes n.p + d >= 0 inside, SoA.
struct Planes {
  float nx[6], ny[6], nz[6], d[6];
};

// ---- W1: box overlap --------------------------------------------------------------------------
// Brute force: for each query, the number of boxes it overlaps (closed test); returns the total.
extern const Kernel<std::uint64_t(const BoxesView&, const Box*, std::size_t)> countOverlapsBrute,
    countOverlapsBruteAutovec;

// Tree queries (bvh.hpp): the total number of (query, box) overlaps, and the ids overlapping one
// query appended to `out`.
extern const Kernel<std::uint64_t(const BvhNode* nodes, std::size_t nodeCount, const Box* queries,
                                  std::size_t nQueries)>
    bvhCountOverlaps;
extern const Kernel<void(const BvhNode* nodes, std::size_t nodeCount, const Box& query,
                         std::vector<std::uint32_t>& out)>
    bvhQuery;

// ---- BVH build (src/bvh/build.cpp) ------------------------------------------------------------
// Binned SAH: the three kernels of the builder's passes over a range of primitives. Boxes are rows
// (x, y, z, -) so one 4-lane operation grows all three axes; the fourth lane is ignored.
struct alignas(16) BvhBox {
  float lo[4], hi[4];
};
inline constexpr int kBvhBins = 16;
// The bins of a range: on axis a, a primitive goes to bin
// clamp(int((centroid(a) - origin[a]) * scale[a]), 0, bins - 1), a scale of 0 putting all in
// bin 0 (a NaN from an infinite centroid included).
struct BvhBinFrame {
  float origin[3], scale[3];
  int bins = kBvhBins;  // the bins in use, 2 to kBvhBins
};
struct BvhBins {
  BvhBox box[3][kBvhBins];
  std::uint32_t count[3][kBvhBins];
};
// Both sides of a split: their boxes and the boxes of their centroids, and the left's size.
struct BvhSides {
  BvhBox box[2], centroids[2];
  std::size_t left;
};
extern const Kernel<void(const detail::BvhPrimRef* prims, std::size_t n, const BvhBinFrame& frame,
                         BvhBins& bins)>
    bvhBin;
// Moves the primitives whose bin on `axis` is below `split` before the others (Hoare's scheme,
// in place) and measures both sides on the way.
extern const Kernel<void(detail::BvhPrimRef* prims, std::size_t n, const BvhBinFrame& frame,
                         int axis, int split, BvhSides& sides)>
    bvhPartition;
// The box and centroid box of the primitives.
extern const Kernel<void(const detail::BvhPrimRef* prims, std::size_t n, BvhBox& box,
                         BvhBox& centroids)>
    bvhBounds;

// ---- W1: broadphase pairs -------------------------------------------------------------------
// One cell of the sweep grid: its boxes sorted by minX, each with its id and the first grid row
// (loY) and column (loZ) it covers, followed by kStreamPad sentinel entries (minX = +inf).
struct SweepCell {
  const float *minX, *maxX, *minY, *maxY, *minZ, *maxZ;
  const std::uint32_t* id;
  const std::int32_t *loY, *loZ;
  std::size_t count;
  std::int32_t cellY, cellZ;
};
// Appends the overlapping pairs of the cell that belong to it: a pair shared by several cells
// belongs to the cell holding the low corner of the two boxes' intersection, so it is reported
// once. Pairs are (smaller id, larger id), in sweep order.
extern const Kernel<void(const SweepCell&cell, std::vector<Pair>&out)> sweepCell, sweepCellAutovec;

// ---- geometry3d batch forms (geometry3d/batch.hpp) -------------------------------------------
// Which elements of a stream one shape touches: indices ascending in `out` (room for `padded`),
// their number returned. Sums in the scalar reference's order, unfused, so every path agrees.
struct SphereQuery {
  float x, y, z, r;
  float tolerance;  // kGeometryTolerance of point_tests.hpp, passed in to keep one definition
};
extern const SelectKernel<SphereQuery, SpheresView> sphereOverlapsSpheres,
    sphereOverlapsSpheresAutovec;
extern const SelectKernel<SphereQuery, BoxesView> sphereOverlapsBoxes, sphereOverlapsBoxesAutovec;
extern const Kernel<std::size_t(float, float, float, const BoxesView&, std::uint32_t*)>
    pointInBoxes, pointInBoxesAutovec;
// For every box, the point of it closest to (x, y, z), in three padded arrays.
extern const Kernel<void(float, float, float, const BoxesView&, float*, float*, float*)>
    closestPointsOnBoxes, closestPointsOnBoxesAutovec;

// The closest element a ray hits, t in [0, tMax] (the scalar raycast's rules), ties to the
// smaller index; index = kNoHit when none (core.hpp's ElementHit). The ray's direction is unit.
struct RayQuery {
  float ox, oy, oz, dx, dy, dz, tMax;
};
extern const Kernel<ElementHit(const RayQuery&, const BoxesView&)> rayClosestBox,
    rayClosestBoxAutovec;
extern const Kernel<ElementHit(const RayQuery&, const SpheresView&)> rayClosestSphere,
    rayClosestSphereAutovec;
// The ray's watertight precomputation (Woop, Benthin, Wald 2013; raycast.hpp's WatertightRay).
struct WatertightQuery {
  float ox, oy, oz;
  int kx, ky, kz;
  float sx, sy, sz, tMax;
};
extern const Kernel<ElementHit(const WatertightQuery&, const TrianglesView&)> rayClosestTriangle,
    rayClosestTriangleAutovec;

// ---- geometry3d: one OBB against many (obb_batch.cpp) ------------------------------------------
// No value makes a separating-axis test fail, so the kernel masks the lanes >= count instead of
// trusting the padding.
struct ObbQuery {
  float center[3], half[3], axis[3][3];
  float tolerance;  // kGeometryTolerance, passed in to keep one definition
};
// The indices (ascending, room for `padded`) of the boxes for which intersect.hpp's
// intersects(query, box) holds, bit for bit; returns their number. The plain-loop baseline (every
// axis, no early exit, left to the auto-vectoriser) has the same contract.
extern const SelectKernel<ObbQuery, ObbsView> obbOverlapsObbs, obbOverlapsObbsAutovec;

// ---- W6: frustum culling ----------------------------------------------------------------------
// Writes the indices of visible objects, ascending, to `out` (room for `padded` indices) and
// returns how many. The plain-loop baselines have the same contract.
extern const SelectKernel<Planes, SpheresView> cullSpheres, cullSpheresAutovec;
extern const SelectKernel<Planes, BoundsView> cullBounds, cullBoundsAutovec;

// ---- geometry2d batch forms (geometry2d/batch.hpp, geometry2d/broadphase.hpp) ----------------
// One shape of each kind as the kernels take it. `tolerance` is kGeometry2dTolerance<float>,
// passed in to keep one definition.
struct CircleQuery2d {
  float x, y, r, tolerance;
};
struct RectQuery2d {
  float minX, minY, maxX, maxY;
};
struct OrientedRectQuery2d {
  float cx, cy, hx, hy, cos, sin, tolerance;
};
struct PointQuery2d {
  float x, y, tolerance;
};
// Which elements a shape meets (closed tests), indices ascending in `out` (room for `padded`),
// their number returned: exactly what intersects(query, element) and contains(element, point) of
// geometry2d/ answer element by element, their arithmetic mirrored operation for operation.
extern const SelectKernel<CircleQuery2d, CirclesView> circleOverlapsCircles,
    circleOverlapsCirclesAutovec;
extern const SelectKernel<RectQuery2d, RectsView> rectOverlapsRects, rectOverlapsRectsAutovec;
extern const SelectKernel<OrientedRectQuery2d, OrientedRectsView> orientedRectOverlapsOrientedRects,
    orientedRectOverlapsOrientedRectsAutovec;
extern const SelectKernel<PointQuery2d, CirclesView> pointInCircles, pointInCirclesAutovec;
extern const SelectKernel<PointQuery2d, RectsView> pointInRects, pointInRectsAutovec;
extern const SelectKernel<PointQuery2d, OrientedRectsView> pointInOrientedRects,
    pointInOrientedRectsAutovec;

// 2D broadphase. One horizontal band's rectangles sorted by minX, each with its id and the first
// band it covers (loBand), followed by kStreamPad sentinel entries (minX = +inf): the sweep
// appends, for each rectangle k in that order, the pairs with the rectangles after it that overlap
// it (closed) and belong to this band, as (smaller id, larger id). A pair belongs to the band
// holding the low edge of the two rectangles' intersection, max(loBand), so it is reported once.
struct SortedRects2d {
  const float *minX, *maxX, *minY, *maxY;
  const std::uint32_t* id;
  const std::int32_t* loBand;
  std::size_t count;
  std::int32_t band;
};
extern const Kernel<void(const SortedRects2d&rects, std::vector<Pair>&out)> sweepRects2d,
    sweepRects2dAutovec;
// Every overlapping pair (i, j), i < j, of a rectangle stream, appended in ascending order.
extern const Kernel<void(const RectsView&v, std::vector<Pair>&out)> bruteRects2d,
    bruteRects2dAutovec;

// ---- particles (particles.hpp, src/particles/step.cpp) ------------------------------------------
// One substep of the particles [begin, end) (begin a multiple of 16), in place, against every
// obstacle row in order (with a tree, the rows it finds near each vector's paths; a mesh's
// triangles through `queries`, lane by lane): bit for bit what
// the float reference's stepParticle gives each particle (src/reference/particles/step-inl.hpp),
// and what they met, counted as it counts. Whole vectors are read and written up to end rounded up
// to a vector (within `padded`); lanes past `end` and pinned ones (inverse mass not > 0) are
// written back unchanged.
extern const Kernel<core::ParticleCounts(
    const ParticlesView&particles, std::size_t begin, std::size_t end,
    const core::ObstacleRow*obstacles, std::size_t obstacleCount,
    const core::ObstacleQueries*queries, const core::ParticleStepParams&params)>
    stepParticles, stepParticlesAutovec;

// ---- meshes: rays against a mesh's BVH (mesh_bvh.hpp, bvh_ray.cpp) ----------------------------
}  // namespace simdphys::simd
namespace simdphys {
struct TriangleBlock;  // mesh_bvh.hpp: plain arrays, no Eigen
}
namespace simdphys::simd {
// A mesh's tree: leaf reference first / 8 is the leaf's block of triangles.
struct MeshView {
  const BvhNode* nodes;
  std::size_t nodeCount;
  const TriangleBlock* blocks;
};
// Rays (fields::Ray): origin, direction (non-zero), tMax (>= 0). Read ray by ray, so, unlike the
// streams above, a view of them need not be padded (padded == count: a chunk of a stream, a
// single ray as a view of one).
using RaysView = core::View<fields::Ray>;
// Per ray, the closest hit under mesh_bvh.hpp's rule (index kNoHit and t = inf for a miss), or
// whether any triangle is hit (1 / 0): bit for bit what the reference traversal answers.
extern const Kernel<void(const MeshView& mesh, const RaysView& rays, std::uint32_t* id, float* t)>
    meshClosestHits;
extern const Kernel<void(const MeshView& mesh, const RaysView& rays, std::uint8_t* hit)>
    meshAnyHits;

// ---- meshes: ray packets (mesh_bvh.hpp, bvh_packet-inl.hpp) -------------------------------------
// A packet's lane without a ray (a tile past the image's edge, the stream's tail).
inline constexpr std::uint32_t kAbsentLane = ~0u;
// Rays traced in packets of `width` (8 or 16): packet p is the rays index[p * width + i] of `rays`
// (kAbsentLane: none); each ray's closest hit is written at out[its index], equal to what
// meshClosestHits answers for it.
extern const Kernel<void(const MeshView& mesh, const RaysView& rays, const std::uint32_t* index,
                         std::size_t packets, int width, ElementHit* out)>
    meshClosestHitPackets;
// The rays index[0, n) of `rays` one at a time, in that order, each hit written at out[its index].
extern const Kernel<void(const MeshView& mesh, const RaysView& rays, const std::uint32_t* index,
                         std::size_t n, ElementHit* out)>
    meshClosestHitsOf;
// For ordering rays so that neighbours walk the same nodes: per ray index[k] of `rays`, key[k] is
// kMissKey if the ray enters no child of the root (it then hits nothing: the traversal's own first
// test), else the Morton code (9 bits an axis, within the root's bounds) of the point where it
// enters its nearest root child.
inline constexpr std::uint32_t kMissKey = ~0u;
extern const Kernel<void(const MeshView& mesh, const RaysView& rays, const std::uint32_t* index,
                         std::size_t n, std::uint32_t* key)>
    meshRayKeys;

// ---- cloth (cloth.hpp): one step of a cloth, all its substeps -----------------------------------
// The streams end bit for bit where the float reference (src/reference/cloth/step-inl.hpp) leaves
// them. `grid` null: the network's batches; else the grid's families (the same springs).
struct ClothStepInput {
  core::ClothView<float> view;
  core::SpringNetwork network;
  const core::SpringGrid* grid;
  core::Tethers tethers;
  const core::ObstacleRow* rows;  // planes, spheres, OBBs (AABBs as OBBs) and meshes
  std::size_t nRows;
  const core::ObstacleQueries* queries;  // a mesh row's entries (null: no mesh)
  float* quads;  // scratch for a network's kernel: 4 floats a slot (x, y, z, w), or null
  core::ClothStepParams params;
  int threads;  // OpenMP threads (1: none); the result does not depend on it
};
extern const Kernel<void(const ClothStepInput&)> stepCloth, stepClothAutovec;

// ---- rigid bodies (simd/rigid.cpp) -----------------------------------------------------------
// The contact passes of a substep over the rows, batch after batch (each batch's lanes share no
// moving body), moving the bodies' velocities: warm starting (the accumulated impulses applied),
// a solve pass (normal impulses with the pass's bias, then friction), and restitution; and once
// a step, before them, the points' masses and normal velocities. They follow the reference's
// arithmetic (src/reference/rigid/solver-inl.hpp) lane-wide.
extern const Kernel<void(const core::ContactRows&, const core::SolverBody*)> prepareContacts,
    prepareContactsAutovec;
extern const Kernel<void(const core::ContactRows&, core::SolverBody*)> warmStartContacts,
    warmStartContactsAutovec;
extern const Kernel<void(const core::ContactRows&, core::SolverBody*, const core::ContactPass&)>
    solveContacts, solveContactsAutovec;
extern const Kernel<void(const core::ContactRows&, core::SolverBody*, float threshold)>
    restituteContacts, restituteContactsAutovec;
// The bodies' records moved over a substep of h (the reference's integratePositions).
extern const Kernel<void(core::SolverBody*, const core::BodyFrames&, float h)> integrateBodies,
    integrateBodiesAutovec;

}  // namespace simdphys::simd
