// The definitions of simdphys/geometry2d/quadtree.hpp (the quadtree's member functions): included
// by quadtree.cpp, which instantiates the class for float and double, and by any file of src/ that
// wants them inlined.
#pragma once

#include "simdphys/geometry2d/quadtree.hpp"
#include "src/reference/geometry2d/collisions-inl.hpp"
#include "src/reference/geometry2d/point_tests-inl.hpp"

namespace simdphys {

template <class T>
QuadtreeT<T>::QuadtreeT(const RectT<T>& bounds, Config config) : config_(config) {
  validate(bounds, "Quadtree: bounds");
  if (config.maxDepth < 0 || config.maxDepth > 30)
    throw Error("Quadtree: maxDepth is " + std::to_string(config.maxDepth) +
                ", must be in [0, 30]");
  if (config.nodeCapacity == 0) throw Error("Quadtree: nodeCapacity must be at least 1");
  nodes_.push_back(Node{bounds, -1, -1, 0, {}, 0});
}

template <class T>
const RectT<T>& QuadtreeT<T>::box(std::uint32_t id) const {
  const Slot& s = slot(id, "Quadtree::box");
  return nodes_[s.node].items[s.index].box;
}

template <class T>
void QuadtreeT<T>::insert(std::uint32_t id, const RectT<T>& box) {
  validate(box, "Quadtree::insert: box of id " + std::to_string(id));
  if (contains(id)) throw Error("Quadtree::insert: id " + std::to_string(id) + " already present");
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

template <class T>
bool QuadtreeT<T>::remove(std::uint32_t id) {
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

template <class T>
void QuadtreeT<T>::update(std::uint32_t id, const RectT<T>& box) {
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

template <class T>
void QuadtreeT<T>::clear() {
  const RectT<T> cell = bounds();
  nodes_.assign(1, Node{cell, -1, -1, 0, {}, 0});
  freeBlocks_.clear();
  slots_.clear();
}

template <class T>
std::vector<std::uint32_t> QuadtreeT<T>::query(const RectT<T>& query) const {
  validate(query, "Quadtree::query");
  return collect([&](const RectT<T>& cell) { return intersects(query, cell); },
                 [&](const RectT<T>& box) { return intersects(query, box); });
}

template <class T>
std::vector<std::uint32_t> QuadtreeT<T>::query(const CircleT<T>& circle) const {
  validate(circle, "Quadtree::query");
  return collect([&](const RectT<T>& cell) { return circleMayMeet(circle, cell); },
                 [&](const RectT<T>& box) { return intersects(circle, box); });
}

template <class T>
std::vector<std::uint32_t> QuadtreeT<T>::query(const Vec2<T>& point) const {
  validate(point, "Quadtree::query");
  return collect([&](const RectT<T>& cell) { return simdphys::contains(cell, point); },
                 [&](const RectT<T>& box) { return simdphys::contains(box, point); });
}

template <class T>
std::vector<Pair> QuadtreeT<T>::pairs() const {
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

template <class T>
std::size_t QuadtreeT<T>::nodeCount() const {
  return std::size_t(
      std::count_if(nodes_.begin(), nodes_.end(), [](const Node& n) { return n.depth >= 0; }));
}

template <class T>
int QuadtreeT<T>::depth() const {
  int d = 0;
  for (const Node& n : nodes_) d = std::max(d, n.depth);
  return d;
}

template <class T>
void QuadtreeT<T>::checkInvariants() const {
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

template <class T>
void QuadtreeT<T>::fail(const std::string& what) {
  throw Error("Quadtree::checkInvariants: " + what);
}

template <class T>
const typename QuadtreeT<T>::Slot& QuadtreeT<T>::slot(std::uint32_t id, const char* fn) const {
  const auto it = slots_.find(id);
  if (it == slots_.end())
    throw Error(std::string(fn) + ": id " + std::to_string(id) + " is absent");
  return it->second;
}

template <class T>
bool QuadtreeT<T>::insideCell(int n, const RectT<T>& box) const {
  const RectT<T>& cell = nodes_[n].cell;
  return (cell.min.array() <= box.min.array()).all() && (box.max.array() <= cell.max.array()).all();
}

template <class T>
int QuadtreeT<T>::childFor(int n, const RectT<T>& box) const {
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

template <class T>
bool QuadtreeT<T>::circleMayMeet(const CircleT<T>& c, const RectT<T>& cell) {
  const Vec2<T> q = Vec2<T>::Zero().cwiseMax(cell.min - c.center).cwiseMin(cell.max - c.center);
  return q.norm() <= c.radius + 4 * kGeometry2dTolerance<T> * c.radius;
}

template <class T>
void QuadtreeT<T>::pushChildren(std::vector<int>& stack, int n, const RectT<T>& box) const {
  const int first = nodes_[n].first;
  if (first < 0) return;
  for (int c = 0; c < 4; ++c)
    if (nodes_[first + c].count > 0 && intersects(box, nodes_[first + c].cell))
      stack.push_back(first + c);
}

template <class T>
template <class CellTest, class BoxTest>
std::vector<std::uint32_t> QuadtreeT<T>::collect(CellTest&& cellTest, BoxTest&& boxTest) const {
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

template <class T>
void QuadtreeT<T>::put(int n, const Item& item) {
  slots_[item.id] = Slot{n, nodes_[n].items.size()};
  nodes_[n].items.push_back(item);
}

template <class T>
void QuadtreeT<T>::take(int n, std::size_t index) {
  std::vector<Item>& items = nodes_[n].items;
  if (index + 1 != items.size()) {
    items[index] = items.back();
    slots_[items[index].id].index = index;
  }
  items.pop_back();
}

template <class T>
int QuadtreeT<T>::allocateBlock() {
  if (!freeBlocks_.empty()) {
    const int first = freeBlocks_.back();
    freeBlocks_.pop_back();
    return first;
  }
  const int first = int(nodes_.size());
  nodes_.resize(nodes_.size() + 4);
  return first;
}

template <class T>
void QuadtreeT<T>::split(int n) {
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

template <class T>
void QuadtreeT<T>::collapse(int n) {
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

}  // namespace simdphys
