// A quadtree over axis-aligned rectangles with user ids (the book's chapter 6): insert, remove,
// update after motion, queries by rectangle, circle and point, and broad-phase pair finding.
//
// Placement. Each node covers a closed cell; a node that holds more than `nodeCapacity` objects
// and is shallower than `maxDepth` splits into four quadrants at its cell's center. An object
// lives in the smallest node whose cell contains it entirely, as the book does, with one
// refinement: an object goes down into a quadrant only if it lies strictly on that quadrant's
// side of both split lines, so an object that touches a split line (not only one that crosses it)
// stays in the parent. Objects in different quadrants are then strictly apart and can never
// touch, which keeps the closed (touching counts) pair finding exact without looking across
// borders. Objects that stick out of the root's bounds, or lie entirely outside them, stay in the
// root: nothing is ever lost or clipped, only searched more often.
//
// The cost of straddling: small objects on a split line stay high in the tree and are tested
// against everything below them. A loose quadtree (cells enlarged twofold, objects placed by
// center and size) bounds that cost; this reference keeps the book's strict cells, whose answers
// are easier to check. Nodes whose subtree falls to nodeCapacity / 2 objects or fewer merge back
// (hysteresis against split-merge thrashing when an object moves back and forth).
//
// Answers are exact and deterministic: queries return ids in increasing order, pairs as
// Pair{a, b}, a < b, each overlapping pair once, sorted; both equal brute force over all objects
// with the same closed tests (intersects(rect, rect) is exact; the circle query uses
// intersects(circle, rect) and prunes cells with a test proven no stricter, see circleMayMeet).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "simdphys/core.hpp"
#include "simdphys/geometry2d/collisions.hpp"
#include "simdphys/geometry2d/point_tests.hpp"
#include "simdphys/geometry2d/primitives.hpp"

namespace simdphys {

template <class T>
class QuadtreeT {
 public:
  struct Config {
    int maxDepth = 8;              // the root has depth 0; nodes at maxDepth never split
    std::size_t nodeCapacity = 8;  // objects a node holds before it splits (>= 1)
  };

  // Throws Error on invalid bounds (non-finite, min > max) or config (maxDepth not in [0, 30],
  // nodeCapacity 0).
  explicit QuadtreeT(const RectT<T>& bounds, Config config = {});

  const RectT<T>& bounds() const { return nodes_[0].cell; }
  const Config& config() const { return config_; }
  std::size_t size() const { return slots_.size(); }
  bool contains(std::uint32_t id) const { return slots_.count(id) != 0; }

  // The stored rectangle of an object; throws Error if the id is absent.
  const RectT<T>& box(std::uint32_t id) const;

  // Adds an object. Throws Error on an invalid rectangle or an id already present.
  void insert(std::uint32_t id, const RectT<T>& box);

  // Removes an object; returns false (and changes nothing) if the id is absent.
  bool remove(std::uint32_t id);

  // Moves an object to a new rectangle (after motion). Stays in place when it still belongs to the
  // same node, else is removed and reinserted. Throws Error on an invalid rectangle or an absent
  // id.
  void update(std::uint32_t id, const RectT<T>& box);

  void clear();

  // Ids of the objects whose rectangle meets `query` (closed), increasing. Each query throws
  // Error on an invalid argument (validate(): a NaN is not a silent "nothing there").
  std::vector<std::uint32_t> query(const RectT<T>& query) const;
  // Ids of the objects whose rectangle meets the circle (intersects(circle, rect)), increasing.
  std::vector<std::uint32_t> query(const CircleT<T>& circle) const;
  // Ids of the objects whose rectangle contains the point (closed), increasing.
  std::vector<std::uint32_t> query(const Vec2<T>& point) const;

  // Every pair of objects whose rectangles meet (closed), as Pair{a, b} with a < b, sorted.
  std::vector<Pair> pairs() const;

  // Diagnostics: the depth of the node holding an object (throws Error if absent), the live
  // nodes, and the depth of the deepest one.
  int depthOf(std::uint32_t id) const { return nodes_[slot(id, "Quadtree::depthOf").node].depth; }
  std::size_t nodeCount() const;
  int depth() const;

  // Checks the structure (for tests): every object is in the node its rectangle belongs to, the
  // index is consistent, subtree counts are right. Throws Error naming the first fault.
  void checkInvariants() const;

 private:
  struct Item {
    RectT<T> box;
    std::uint32_t id;
  };
  struct Node {
    RectT<T> cell;
    int first;   // index of the first of four children (quadrants -x-y, +x-y, -x+y, +x+y), or -1
    int parent;  // -1 for the root
    int depth;   // -1 for a node of a freed block
    std::vector<Item> items;
    std::size_t count;  // objects in this node and below
  };
  struct Slot {
    int node;
    std::size_t index;
  };

  [[noreturn]] static void fail(const std::string& what);

  static Pair ordered(std::uint32_t a, std::uint32_t b) { return a < b ? Pair{a, b} : Pair{b, a}; }

  const Slot& slot(std::uint32_t id, const char* fn) const;

  bool insideCell(int n, const RectT<T>& box) const;

  // The child of node n the box belongs in: it must lie in n's cell and strictly on one side of
  // both split lines (the children's shared edges). -1 if it stays in n (or n has no children).
  int childFor(int n, const RectT<T>& box) const;

  // Conservative cell test of the circle query: true whenever intersects(circle, box) can be true
  // for a box inside the cell. That test accepts distance d_box <= r + tol max(d_box, r), which
  // forces d_box <= r / (1 - tol); the cell's distance is no larger (a clamp to a larger rectangle,
  // all roundings monotone), so d_cell <= r + 4 tol r can never reject such a cell.
  static bool circleMayMeet(const CircleT<T>& c, const RectT<T>& cell);

  void pushChildren(std::vector<int>& stack, int n, const RectT<T>& box) const;

  template <class CellTest, class BoxTest>
  std::vector<std::uint32_t> collect(CellTest&& cellTest, BoxTest&& boxTest) const;

  void put(int n, const Item& item);

  // Removes item `index` of node n by moving the last item into its place.
  void take(int n, std::size_t index);

  int allocateBlock();

  // Gives node n four children and moves down the objects that fit in one (recursively).
  void split(int n);

  // Moves every object below node n into n and frees its descendants.
  void collapse(int n);

  Config config_;
  std::vector<Node> nodes_;
  std::vector<int> freeBlocks_;
  std::unordered_map<std::uint32_t, Slot> slots_;
};

using Quadtree = QuadtreeT<float>;
using Quadtreed = QuadtreeT<double>;

}  // namespace simdphys
