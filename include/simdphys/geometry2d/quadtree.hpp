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
  explicit QuadtreeT(const RectT<T>& bounds, Config config = {}) : config_(config) {
    validate(bounds, "Quadtree: bounds");
    if (config.maxDepth < 0 || config.maxDepth > 30)
      throw Error("Quadtree: maxDepth is " + std::to_string(config.maxDepth) +
                  ", must be in [0, 30]");
    if (config.nodeCapacity == 0) throw Error("Quadtree: nodeCapacity must be at least 1");
    nodes_.push_back(Node{bounds, -1, -1, 0, {}, 0});
  }

  const RectT<T>& bounds() const { return nodes_[0].cell; }
  const Config& config() const { return config_; }
  std::size_t size() const { return slots_.size(); }
  bool contains(std::uint32_t id) const { return slots_.count(id) != 0; }

  // The stored rectangle of an object; throws Error if the id is absent.
  const RectT<T>& box(std::uint32_t id) const {
    const Slot& s = slot(id, "Quadtree::box");
    return nodes_[s.node].items[s.index].box;
  }

  // Adds an object. Throws Error on an invalid rectangle or an id already present.
  void insert(std::uint32_t id, const RectT<T>& box) {
    validate(box, "Quadtree::insert: box of id " + std::to_string(id));
    if (contains(id))
      throw Error("Quadtree::insert: id " + std::to_string(id) + " already present");
    int node = 0;
    for (;;) {
      ++nodes_[node].count;
      const int child = childFor(node, box);
      if (child < 0) break;
      node = child;
    }
    put(node, Item{box, id});
    if (nodes_[node].first < 0 && nodes_[node].items.size() > config_.nodeCapacity &&
        nodes_[node].depth < config_.maxDepth)
      split(node);
  }

  // Removes an object; returns false (and changes nothing) if the id is absent.
  bool remove(std::uint32_t id) {
    const auto it = slots_.find(id);
    if (it == slots_.end()) return false;
    const int node = it->second.node;
    take(node, it->second.index);
    slots_.erase(it);
    int merge = -1;
    for (int n = node; n >= 0; n = nodes_[n].parent) {
      --nodes_[n].count;
      if (nodes_[n].first >= 0 && nodes_[n].count <= config_.nodeCapacity / 2) merge = n;
    }
    if (merge >= 0) collapse(merge);
    return true;
  }

  // Moves an object to a new rectangle (after motion). Stays in place when it still belongs to the
  // same node, else is removed and reinserted. Throws Error on an invalid rectangle or an absent
  // id.
  void update(std::uint32_t id, const RectT<T>& box) {
    validate(box, "Quadtree::update: box of id " + std::to_string(id));
    const Slot s = slot(id, "Quadtree::update");
    int node = 0;
    for (int child = childFor(0, box); child >= 0; child = childFor(node, box)) node = child;
    if (node == s.node) {
      nodes_[s.node].items[s.index].box = box;
      return;
    }
    remove(id);
    insert(id, box);
  }

  void clear() {
    const RectT<T> cell = bounds();
    nodes_.assign(1, Node{cell, -1, -1, 0, {}, 0});
    freeBlocks_.clear();
    slots_.clear();
  }

  // Ids of the objects whose rectangle meets `query` (closed), increasing. Each query throws
  // Error on an invalid argument (validate(): a NaN is not a silent "nothing there").
  std::vector<std::uint32_t> query(const RectT<T>& query) const {
    validate(query, "Quadtree::query");
    return collect([&](const RectT<T>& cell) { return intersects(query, cell); },
                   [&](const RectT<T>& box) { return intersects(query, box); });
  }
  // Ids of the objects whose rectangle meets the circle (intersects(circle, rect)), increasing.
  std::vector<std::uint32_t> query(const CircleT<T>& circle) const {
    validate(circle, "Quadtree::query");
    return collect([&](const RectT<T>& cell) { return circleMayMeet(circle, cell); },
                   [&](const RectT<T>& box) { return intersects(circle, box); });
  }
  // Ids of the objects whose rectangle contains the point (closed), increasing.
  std::vector<std::uint32_t> query(const Vec2<T>& point) const {
    validate(point, "Quadtree::query");
    return collect([&](const RectT<T>& cell) { return simdphys::contains(cell, point); },
                   [&](const RectT<T>& box) { return simdphys::contains(box, point); });
  }

  // Every pair of objects whose rectangles meet (closed), as Pair{a, b} with a < b, sorted.
  std::vector<Pair> pairs() const {
    std::vector<Pair> out;
    std::vector<int> stack;
    for (int n = 0; n < int(nodes_.size()); ++n) {
      const Node& node = nodes_[n];
      if (node.depth < 0) continue;  // a freed block
      for (std::size_t i = 0; i < node.items.size(); ++i) {
        const Item& a = node.items[i];
        for (std::size_t j = i + 1; j < node.items.size(); ++j)
          if (intersects(a.box, node.items[j].box)) out.push_back(ordered(a.id, node.items[j].id));
        // Against everything below this node, pruned by cells.
        pushChildren(stack, n, a.box);
        while (!stack.empty()) {
          const Node& below = nodes_[stack.back()];
          const int index = stack.back();
          stack.pop_back();
          for (const Item& b : below.items)
            if (intersects(a.box, b.box)) out.push_back(ordered(a.id, b.id));
          pushChildren(stack, index, a.box);
        }
      }
    }
    std::sort(out.begin(), out.end());
    return out;
  }

  // Diagnostics: the depth of the node holding an object (throws Error if absent), the live
  // nodes, and the depth of the deepest one.
  int depthOf(std::uint32_t id) const { return nodes_[slot(id, "Quadtree::depthOf").node].depth; }
  std::size_t nodeCount() const {
    return std::size_t(
        std::count_if(nodes_.begin(), nodes_.end(), [](const Node& n) { return n.depth >= 0; }));
  }
  int depth() const {
    int d = 0;
    for (const Node& n : nodes_) d = std::max(d, n.depth);
    return d;
  }

  // Checks the structure (for tests): every object is in the node its rectangle belongs to, the
  // index is consistent, subtree counts are right. Throws Error naming the first fault.
  void checkInvariants() const {
    std::size_t total = 0;
    for (int n = 0; n < int(nodes_.size()); ++n) {
      const Node& node = nodes_[n];
      if (node.depth < 0) continue;
      total += node.items.size();
      std::size_t below = node.items.size();
      if (node.first >= 0)
        for (int c = 0; c < 4; ++c) below += nodes_[node.first + c].count;
      if (below != node.count) fail("node " + std::to_string(n) + " has a wrong subtree count");
      for (std::size_t i = 0; i < node.items.size(); ++i) {
        const Item& item = node.items[i];
        const auto it = slots_.find(item.id);
        if (it == slots_.end() || it->second.node != n || it->second.index != i)
          fail("id " + std::to_string(item.id) + " is indexed wrongly");
        if (n != 0 && !insideCell(n, item.box))
          fail("id " + std::to_string(item.id) + " lies outside its node's cell");
        if (childFor(n, item.box) >= 0)
          fail("id " + std::to_string(item.id) + " belongs in a child of its node");
      }
    }
    if (total != slots_.size() || nodes_[0].count != total) fail("objects are lost or duplicated");
  }

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

  [[noreturn]] static void fail(const std::string& what) {
    throw Error("Quadtree::checkInvariants: " + what);
  }

  static Pair ordered(std::uint32_t a, std::uint32_t b) { return a < b ? Pair{a, b} : Pair{b, a}; }

  const Slot& slot(std::uint32_t id, const char* fn) const {
    const auto it = slots_.find(id);
    if (it == slots_.end())
      throw Error(std::string(fn) + ": id " + std::to_string(id) + " is absent");
    return it->second;
  }

  bool insideCell(int n, const RectT<T>& box) const {
    const RectT<T>& cell = nodes_[n].cell;
    return (cell.min.array() <= box.min.array()).all() &&
           (box.max.array() <= cell.max.array()).all();
  }

  // The child of node n the box belongs in: it must lie in n's cell and strictly on one side of
  // both split lines (the children's shared edges). -1 if it stays in n (or n has no children).
  int childFor(int n, const RectT<T>& box) const {
    const Node& node = nodes_[n];
    if (node.first < 0 || !insideCell(n, box)) return -1;
    const Vec2<T> mid = nodes_[node.first].cell.max;  // the -x-y quadrant's max corner
    int quadrant = 0;
    for (int a = 0; a < 2; ++a) {
      if (box.max[a] < mid[a]) continue;
      if (box.min[a] > mid[a]) {
        quadrant |= 1 << a;
        continue;
      }
      return -1;  // touches or crosses this split line
    }
    return node.first + quadrant;
  }

  // Conservative cell test of the circle query: true whenever intersects(circle, box) can be true
  // for a box inside the cell. That test accepts distance d_box <= r + tol max(d_box, r), which
  // forces d_box <= r / (1 - tol); the cell's distance is no larger (a clamp to a larger rectangle,
  // all roundings monotone), so d_cell <= r + 4 tol r can never reject such a cell.
  static bool circleMayMeet(const CircleT<T>& c, const RectT<T>& cell) {
    const Vec2<T> q = Vec2<T>::Zero().cwiseMax(cell.min - c.center).cwiseMin(cell.max - c.center);
    return q.norm() <= c.radius + 4 * kGeometry2dTolerance<T> * c.radius;
  }

  void pushChildren(std::vector<int>& stack, int n, const RectT<T>& box) const {
    const int first = nodes_[n].first;
    if (first < 0) return;
    for (int c = 0; c < 4; ++c)
      if (nodes_[first + c].count > 0 && intersects(box, nodes_[first + c].cell))
        stack.push_back(first + c);
  }

  template <class CellTest, class BoxTest>
  std::vector<std::uint32_t> collect(CellTest&& cellTest, BoxTest&& boxTest) const {
    std::vector<std::uint32_t> out;
    std::vector<int> stack{0};  // the root is always searched: it holds what lies outside it
    while (!stack.empty()) {
      const int n = stack.back();
      stack.pop_back();
      const Node& node = nodes_[n];
      for (const Item& item : node.items)
        if (boxTest(item.box)) out.push_back(item.id);
      if (node.first < 0) continue;
      for (int c = 0; c < 4; ++c) {
        const Node& child = nodes_[node.first + c];
        if (child.count > 0 && cellTest(child.cell)) stack.push_back(node.first + c);
      }
    }
    std::sort(out.begin(), out.end());
    return out;
  }

  void put(int n, const Item& item) {
    slots_[item.id] = Slot{n, nodes_[n].items.size()};
    nodes_[n].items.push_back(item);
  }

  // Removes item `index` of node n by moving the last item into its place.
  void take(int n, std::size_t index) {
    std::vector<Item>& items = nodes_[n].items;
    if (index + 1 != items.size()) {
      items[index] = items.back();
      slots_[items[index].id].index = index;
    }
    items.pop_back();
  }

  int allocateBlock() {
    if (!freeBlocks_.empty()) {
      const int first = freeBlocks_.back();
      freeBlocks_.pop_back();
      return first;
    }
    const int first = int(nodes_.size());
    nodes_.resize(nodes_.size() + 4);
    return first;
  }

  // Gives node n four children and moves down the objects that fit in one (recursively).
  void split(int n) {
    const int first = allocateBlock();
    const RectT<T> cell = nodes_[n].cell;
    const Vec2<T> mid = cell.min + (cell.max - cell.min) / T(2);
    const int depth = nodes_[n].depth + 1;
    for (int q = 0; q < 4; ++q) {
      RectT<T> c;
      c.min.x() = q & 1 ? mid.x() : cell.min.x();
      c.max.x() = q & 1 ? cell.max.x() : mid.x();
      c.min.y() = q & 2 ? mid.y() : cell.min.y();
      c.max.y() = q & 2 ? cell.max.y() : mid.y();
      nodes_[first + q] = Node{c, -1, n, depth, {}, 0};
    }
    nodes_[n].first = first;
    std::vector<Item> items;
    items.swap(nodes_[n].items);
    for (const Item& item : items) {
      const int child = childFor(n, item.box);
      if (child < 0) {
        put(n, item);
        continue;
      }
      ++nodes_[child].count;
      put(child, item);
    }
    for (int q = 0; q < 4; ++q) {
      const Node& c = nodes_[first + q];
      if (c.items.size() > config_.nodeCapacity && c.depth < config_.maxDepth) split(first + q);
    }
  }

  // Moves every object below node n into n and frees its descendants.
  void collapse(int n) {
    const int first = nodes_[n].first;
    if (first < 0) return;
    for (int q = 0; q < 4; ++q) {
      collapse(first + q);
      for (const Item& item : nodes_[first + q].items) put(n, item);
      nodes_[first + q] = Node{RectT<T>{Vec2<T>::Zero(), Vec2<T>::Zero()}, -1, -1, -1, {}, 0};
    }
    nodes_[n].first = -1;
    freeBlocks_.push_back(first);
  }

  Config config_;
  std::vector<Node> nodes_;
  std::vector<int> freeBlocks_;
  std::unordered_map<std::uint32_t, Slot> slots_;
};

using Quadtree = QuadtreeT<float>;
using Quadtreed = QuadtreeT<double>;

}  // namespace simdphys
