// Finding a step's contacts (rigid.hpp): pairs of bodies whose bounds, grown by how far they may
// get within the step, overlap (the broadphase of broadphase.hpp), bodies against the world's
// obstacles, and the manifolds of each (rigid/manifold.hpp).
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <variant>
#include <vector>

#include <omp.h>

#include "simdphys/broadphase.hpp"
#include "simdphys/obstacles.hpp"
#include "src/reference/rigid/bodies-inl.hpp"
#include "src/reference/rigid/clip-inl.hpp"
#include "src/reference/rigid/pair_cache-inl.hpp"

namespace simdphys::detail {

inline constexpr std::uint32_t kObstacleBit = 0x80000000u;

// The contact's key: the two bodies' handle slots, or a body's slot and an obstacle's index.
inline std::uint64_t pairKey(std::uint32_t a, std::uint32_t b) {
  return (std::uint64_t(a) << 32) | b;
}

template <class T>
Vec3<T> reach(const BodyT<T>& b) {
  if (b.shape == BodyShape::kSphere) return Vec3<T>::Constant(b.half.x());
  return b.q.toRotationMatrix().cwiseAbs() * b.half;
}

// f(the body's shape where it is): a SphereT, ObbT or PlacedHullT.
template <class T, class F>
auto visitShape(const BodyT<T>& b, F f) {
  if (b.shape == BodyShape::kSphere) return f(b.sphere());
  if (b.shape == BodyShape::kHull) return f(b.placedHull());
  return f(b.box());
}

// The manifold of a against b, from whichever of collide(a, b) and collide(b, a) manifold.hpp
// has, normal from a to b.
template <class T, class SA, class SB>
ManifoldT<T> collideEither(const SA& a, const SB& b, T maxSeparation) {
  if constexpr (requires { collide(a, b, maxSeparation); })
    return collide(a, b, maxSeparation);
  else
    return flipped(collide(b, a, maxSeparation));
}

// The manifold of body a against shape b (body or obstacle), normal from a to b.
template <class T>
ManifoldT<T> collideBody(const BodyT<T>& a, const BodyT<T>& b, T maxSeparation) {
  return visitShape(a, [&](const auto& sa) {
    return visitShape(b, [&](const auto& sb) { return collideEither(sa, sb, maxSeparation); });
  });
}

template <class T>
ManifoldT<T> collideObstacle(const BodyT<T>& a, const ObstacleShape& shape, T maxSeparation) {
  const auto against = [&](const auto& s) -> ManifoldT<T> {
    return visitShape(a, [&](const auto& sa) { return collideEither(sa, s, maxSeparation); });
  };
  if (const auto* p = std::get_if<Plane>(&shape)) return against(cast<T>(*p));
  if (const auto* s = std::get_if<Sphere>(&shape)) return against(cast<T>(*s));
  if (const auto* b = std::get_if<Aabb>(&shape)) {
    const AabbT<T> box = cast<T>(*b);
    return against(ObbT<T>{(box.min + box.max) / 2, (box.max - box.min) / 2, Mat3<T>::Identity()});
  }
  if (const auto* o = std::get_if<Obb>(&shape)) return against(cast<T>(*o));
  return {};  // meshes: collideMesh
}

// Against a mesh: the manifolds of the triangles the body's grown bounds `box` overlap, those
// whose normals agree within kActiveEdgeCosine merged into one (near-coincident points, where two
// triangles share an edge, kept once; then at most four, as box-box keeps them), so a box on flat
// ground of many triangles has one manifold. emit(manifold, sub) for each, `sub` the lowest id of
// its triangles (the manifold's name beside the pair's key); point ids are the triangle's id
// times 1024 plus the triangle manifold's id.
template <class T, class Emit>
void collideMesh(const BodyT<T>& body, const MeshBvh& mesh, const Aabb& box, T maxSeparation,
                 Emit emit) {
  struct Group {
    Vec3<T> normal;  // its first manifold's
    std::uint32_t sub;
    std::array<ContactPointT<T>, 16> points;
    int n = 0;
  };
  std::vector<Group> groups;
  const T weld = T(1e-3) * body.half.maxCoeff();
  const std::span<const std::uint8_t> active = mesh.activeEdges();
  for (const std::uint32_t t : mesh.overlapping(box)) {
    const TriangleT<T> tri = cast<T>(mesh.mesh().triangle(t));
    const ManifoldT<T> m = visitShape(body, [&](const auto& s) {
      if constexpr (std::is_same_v<std::decay_t<decltype(s)>, SphereT<T>>)
        return collide(s, tri, maxSeparation);
      else
        return collide(s, tri, maxSeparation, active[t]);
    });
    if (m.count == 0) continue;
    auto g = std::find_if(groups.begin(), groups.end(), [&](const Group& x) {
      return x.normal.dot(m.normal) > T(kActiveEdgeCosine);
    });
    if (g == groups.end()) g = groups.insert(groups.end(), Group{m.normal, t, {}, 0});
    for (int i = 0; i < m.count; ++i) {
      ContactPointT<T> p = m.points[std::size_t(i)];
      p.id += t * 1024;
      const bool known = std::any_of(g->points.begin(), g->points.begin() + g->n, [&](auto& q) {
        return (q.point - p.point).squaredNorm() <= weld * weld;
      });
      if (known) continue;
      if (g->n == int(g->points.size())) {  // full: down to the four that matter so far
        std::array<int, 4> keep{};
        std::array<ContactPointT<T>, 16> kept;
        const int k = keepFour(g->points, g->n, g->normal, keep);
        for (int j = 0; j < k; ++j) kept[std::size_t(j)] = g->points[std::size_t(keep[j])];
        g->points = kept, g->n = k;
      }
      g->points[std::size_t(g->n++)] = p;
    }
  }
  for (Group& g : groups) {
    ManifoldT<T> m;
    m.normal = g.normal;
    keepFourOf(m, g.points, g.n);
    emit(m, g.sub);
  }
}

// Bounds of an obstacle for the body test; planes are unbounded.
inline bool mayTouch(const ObstacleShape& shape, const Aabb& body) {
  if (std::holds_alternative<Plane>(shape) || std::holds_alternative<MeshObstacle>(shape))
    return true;  // a mesh's own tree answers
  Aabb box;
  if (const auto* s = std::get_if<Sphere>(&shape))
    box = {s->center.array() - s->radius, s->center.array() + s->radius};
  else if (const auto* b = std::get_if<Aabb>(&shape))
    box = *b;
  else if (const auto* o = std::get_if<Obb>(&shape)) {
    const Vec3f r = o->axes.cwiseAbs() * o->halfExtents;
    box = {o->center - r, o->center + r};
  } else
    return false;
  return (box.min.array() <= body.max.array()).all() && (body.min.array() <= box.max.array()).all();
}

// Appends the constraint of manifold m between bodies a and b (b = the static dummy for an
// obstacle), its anchors from the points, its impulses zero (its tangents are the solver's:
// prepareContacts).
template <class T>
void addConstraint(std::vector<ContactConstraintT<T>>& out, const ManifoldT<T>& m, std::uint32_t a,
                   std::uint32_t b, const Vec3<T>& centerA, const Vec3<T>& centerB, T friction,
                   T restitution, bool isStatic, std::uint64_t key, std::uint32_t sub = 0) {
  if (m.count == 0) return;
  ContactConstraintT<T>& c = out.emplace_back();
  c.a = a, c.b = b, c.key = key, c.sub = sub, c.normal = m.normal, c.friction = friction;
  c.restitution = restitution, c.isStatic = isStatic, c.count = m.count;
  for (int i = 0; i < m.count; ++i) {
    ContactPointConstraintT<T>& p = c.points[std::size_t(i)];
    p.rA = m.points[std::size_t(i)].point - centerA;
    p.rB = m.points[std::size_t(i)].point - centerB;
    p.baseSeparation = m.points[std::size_t(i)].separation;
    p.id = m.points[std::size_t(i)].id;
  }
}

// Graph colouring (Box2D v3's constraint graph): each contact takes the first of kColours colours
// in which neither of its moving bodies has a contact yet, so a colour's contacts share no moving
// body and are solved lane-wide at once, in any order, with the same result. Contacts between
// moving bodies are coloured first; contacts with an obstacle or a kinematic body (one moving
// body) take colours after theirs, so the solver meets them last (they stop push-through).
// Contacts no colour takes go to the overflow, solved first, one at a time. The solving order:
// `order` (the contacts' indices, overflow first, then colour by colour, each in the contacts'
// order) and `begin`, each colour's first place in it (kColours + 2 offsets: the overflow, then
// the colours).
inline constexpr int kColours = 24;

struct ColourOrder {
  std::vector<std::uint32_t> order, begin;
};

template <class T>
ColourOrder colourContacts(const std::vector<ContactConstraintT<T>>& contacts,
                           const std::vector<BodyT<T>>& bodies) {
  static_assert(kColours <= 32);
  const std::size_t n = bodies.size();
  // Each moving body's colours taken, a bit each; obstacles and kinematic bodies take none.
  std::vector<std::uint32_t> used(n, 0);
  const auto moving = [&](std::uint32_t b) { return b < n && bodies[b].invMass > 0; };
  const auto usedBy = [&](std::uint32_t b) { return moving(b) ? used[b] : 0u; };
  // Colours for the two kinds, the one-body contacts after the last colour the others take.
  std::vector<int> colour(contacts.size(), -1);
  int twoBodyColours = 0;
  for (int pass = 0; pass < 2; ++pass)
    for (std::size_t i = 0; i < contacts.size(); ++i) {
      const ContactConstraintT<T>& c = contacts[i];
      if ((moving(c.a) && moving(c.b)) != (pass == 0)) continue;
      const int first = pass == 0 ? 0 : std::min(twoBodyColours, kColours - 1);
      // The free colours from `first` on; the lowest of them, if any.
      const std::uint32_t free =
          ~(usedBy(c.a) | usedBy(c.b)) & (~0u << first) & ((std::uint64_t(1) << kColours) - 1);
      if (free == 0) continue;
      const int k = std::countr_zero(free);
      if (moving(c.a)) used[c.a] |= 1u << k;
      if (moving(c.b)) used[c.b] |= 1u << k;
      colour[i] = k;
      if (pass == 0) twoBodyColours = std::max(twoBodyColours, k + 1);
    }
  // Stable by colour, the overflow (-1) first.
  ColourOrder out{std::vector<std::uint32_t>(contacts.size()),
                  std::vector<std::uint32_t>(kColours + 2, 0)};
  for (const int c : colour) ++out.begin[std::size_t(c + 2)];
  for (std::size_t k = 1; k < out.begin.size(); ++k) out.begin[k] += out.begin[k - 1];
  std::vector<std::uint32_t> next(out.begin.begin(), out.begin.end() - 1);
  for (std::uint32_t i = 0; i < contacts.size(); ++i)
    out.order[next[std::size_t(colour[i] + 1)]++] = i;
  return out;
}

// The contacts in solving order: a copy, a thread's buffer reused from step to step (rewritten
// whole each time: the contacts are hundreds of kilobytes, which fresh allocations would fault
// in page by page every step).
template <class T>
std::vector<ContactConstraintT<T>>& orderedCopy(const std::vector<ContactConstraintT<T>>& contacts,
                                                const std::vector<std::uint32_t>& order) {
  static thread_local std::vector<ContactConstraintT<T>> ordered;
  ordered.resize(contacts.size());
  for (std::size_t k = 0; k < contacts.size(); ++k) ordered[k] = contacts[order[k]];
  return ordered;
}

template <class T>
void putInOrder(std::vector<ContactConstraintT<T>>& contacts, const ColourOrder& colours) {
  contacts.swap(orderedCopy(contacts, colours.order));
}

// The pairs of bodies whose boxes overlap (touching counts), A the body of the lower slot, in key
// order, into `out`: those of the cached pairs of grown boxes whose boxes overlap, if every box
// is still inside its grown one; else the cache is made anew (BroadphaseCache) first.
inline void overlappingPairs(const std::vector<Aabb>& boxes, std::span<const std::uint32_t> slots,
                             BroadphaseCache& cache,
                             std::vector<std::pair<std::uint64_t, Pair>>& out) {
  const std::size_t n = boxes.size();
  bool covered =
      cache.slots.size() == n && std::equal(slots.begin(), slots.end(), cache.slots.begin());
  for (std::size_t i = 0; covered && i < n; ++i)
    covered = (cache.grown[i].min.array() <= boxes[i].min.array()).all() &&
              (boxes[i].max.array() <= cache.grown[i].max.array()).all();
  if (!covered) {
    cache.grown.resize(n);
    BoxStream bounds;
    bounds.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3f margin = Vec3f::Constant(0.1f * (boxes[i].max - boxes[i].min).maxCoeff());
      cache.grown[i] = {boxes[i].min - margin, boxes[i].max + margin};
      bounds.push(cache.grown[i]);
    }
    std::vector<Pair> pairs;
    findPairs(bounds, pairs);
    cache.pairs.clear();
    for (const Pair& p : pairs) {
      // A is the body of the lower slot, so the pair keeps its order (and ids) as indices move.
      const Pair ordered = slots[p.a] < slots[p.b] ? p : Pair{p.b, p.a};
      cache.pairs.push_back({pairKey(slots[ordered.a], slots[ordered.b]), ordered});
    }
    std::sort(cache.pairs.begin(), cache.pairs.end(),
              [](const auto& l, const auto& r) { return l.first < r.first; });
    cache.slots.assign(slots.begin(), slots.end());
  }
  out.clear();
  for (const auto& kp : cache.pairs)
    if (overlaps(boxes[kp.second.a], boxes[kp.second.b])) out.push_back(kp);
}

// Below this many body pairs the manifolds are found on one thread: starting threads costs more.
inline constexpr std::size_t kParallelPairs = 256;

// The step's contacts, body pairs first (in the order of their keys) and obstacle contacts
// after (colourContacts then orders them for the solver). `slots`: each
// body's handle slot. maxSeparation of a pair: the speculative distance plus the distance the
// two may close within dt. The pairs' manifolds are found on `threads` threads (0: OpenMP's
// default), each into the pair's own slot, then taken in key order: the same at any count. A
// pair whose manifold in `cached` (last step's, by key) is still reusable takes it
// (pair_cache-inl.hpp); the pairs' manifolds go to `nextPairs`, by key, for the next step.
template <class T>
void findContacts(std::vector<ContactConstraintT<T>>& contacts, const std::vector<BodyT<T>>& bodies,
                  std::span<const std::uint32_t> slots, const std::vector<PairGeometryT<T>>& cached,
                  std::vector<PairGeometryT<T>>& nextPairs, BroadphaseCache& broadphase,
                  const Obstacles& obstacles, const RigidSettings& s, T dt, int threads,
                  T& deepest) {
  const auto n = std::uint32_t(bodies.size());
  const std::uint32_t dummy = n;
  std::vector<T> travel(n);
  std::vector<Aabb> boxes(n);
  std::vector<Mat3<T>> rotation(n);  // each body's, for the pairs' cached manifolds
  for (std::uint32_t i = 0; i < n; ++i) {
    rotation[i] = bodies[i].q.toRotationMatrix();
    travel[i] = bodies[i].v.norm() * dt;
    const Vec3<T> r = reach(bodies[i]).array() + T(s.speculativeDistance) / 2 + travel[i];
    // Rounded outward to float: the grown box covers the body in either precision.
    const Vec3f lo = (bodies[i].x - r).template cast<float>().array() -
                     1e-4f * (1 + r.template cast<float>().array());
    const Vec3f hi = (bodies[i].x + r).template cast<float>().array() +
                     1e-4f * (1 + r.template cast<float>().array());
    boxes[i] = {lo, hi};
  }
  std::vector<std::pair<std::uint64_t, Pair>> keyed;
  overlappingPairs(boxes, slots, broadphase, keyed);
  std::erase_if(keyed, [&](const auto& kp) {
    const auto [a, b] = kp.second;
    return (bodies[a].invMass == 0 && bodies[b].invMass == 0) ||
           (bodies[a].island != 0 && bodies[b].island != 0);  // both asleep
  });
  contacts.clear();
  contacts.reserve(keyed.size() + n);
  // Each pair's cached manifold, by a walk through both in key order.
  std::vector<const PairGeometryT<T>*> previous(keyed.size(), nullptr);
  for (std::size_t i = 0, j = 0; i < keyed.size(); ++i) {
    while (j < cached.size() && cached[j].key < keyed[i].first) ++j;
    if (j < cached.size() && cached[j].key == keyed[i].first) previous[i] = &cached[j];
  }
  deepest = 0;
  const auto record = [&](const ManifoldT<T>& m) {
    for (int i = 0; i < m.count; ++i)
      deepest = std::max(deepest, -m.points[std::size_t(i)].separation);
  };
  // A thread's buffer, reused from step to step; named here, outside the parallel loop, where
  // the name is the calling thread's.
  static thread_local std::vector<ManifoldT<T>> found;
  std::vector<ManifoldT<T>>& manifolds = found;
  manifolds.resize(keyed.size());
  static thread_local std::vector<PairGeometryT<T>> foundPairs;  // each pair's, as `manifolds`
  std::vector<PairGeometryT<T>>& geometry = foundPairs;
  geometry.resize(keyed.size());
  const int t = keyed.size() < kParallelPairs ? 1 : threads > 0 ? threads : omp_get_max_threads();
#pragma omp parallel for schedule(static) num_threads(t)
  for (std::size_t i = 0; i < keyed.size(); ++i) {
    const auto [ia, ib] = keyed[i].second;
    const BodyT<T>&a = bodies[ia], &b = bodies[ib];
    const Mat3<T>&Ra = rotation[ia], &Rb = rotation[ib];
    if (s.reuseManifolds && previous[i] && reusable(*previous[i], a, Ra, b)) {
      manifolds[i] = reused(*previous[i], a, Ra, b, Rb);
      geometry[i] = *previous[i];
      continue;
    }
    manifolds[i] = collideBody(a, b, T(s.speculativeDistance) + travel[ia] + travel[ib]);
    if (manifolds[i].count > 0)
      geometry[i] = pairGeometry(keyed[i].first, manifolds[i], a, Ra, b, Rb);
  }
  nextPairs.clear();
  for (std::size_t i = 0; i < keyed.size(); ++i) {
    const auto& [key, p] = keyed[i];
    const BodyT<T>&a = bodies[p.a], &b = bodies[p.b];
    record(manifolds[i]);
    if (manifolds[i].count == 0) continue;
    addConstraint(contacts, manifolds[i], p.a, p.b, a.x, b.x, std::sqrt(a.friction * b.friction),
                  std::max(a.restitution, b.restitution), false, key);
    nextPairs.push_back(geometry[i]);
  }
  const std::span<const ObstacleShape> shapes = obstacles.shapes();
  for (std::uint32_t i = 0; i < n; ++i) {
    // Kinematic bodies pass through obstacles; sleeping ones rest where they are.
    if (bodies[i].invMass == 0 || bodies[i].island != 0) continue;
    for (std::uint32_t o = 0; o < shapes.size(); ++o) {
      if (!mayTouch(shapes[o], boxes[i])) continue;
      const std::uint64_t key = pairKey(slots[i], kObstacleBit | o);
      if (const auto* mesh = std::get_if<MeshObstacle>(&shapes[o])) {
        collideMesh(bodies[i], **mesh, boxes[i], T(s.speculativeDistance) + travel[i],
                    [&](const ManifoldT<T>& m, std::uint32_t sub) {
                      record(m);
                      addConstraint(contacts, m, i, dummy, bodies[i].x, Vec3<T>(Vec3<T>::Zero()),
                                    bodies[i].friction, bodies[i].restitution, true, key, sub);
                    });
        continue;
      }
      const ManifoldT<T> m =
          collideObstacle(bodies[i], shapes[o], T(s.speculativeDistance) + travel[i]);
      record(m);
      // Obstacles carry the world's friction of the body (W5: 0.6 on every contact).
      addConstraint(contacts, m, i, dummy, bodies[i].x, Vec3<T>(Vec3<T>::Zero()),
                    bodies[i].friction, bodies[i].restitution, true, key);
    }
  }
}

}  // namespace simdphys::detail
