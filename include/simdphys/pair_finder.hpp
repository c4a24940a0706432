// The pair finder of the 3D and 2D broadphases (broadphase.hpp, geometry2d/broadphase.hpp): one
// class over boxes or rectangles, pairs in one sorted order, and the events between two updates
// that a contact cache keys its contacts on.
#pragma once

#include <memory>
#include <vector>

#include "simdphys/core.hpp"

namespace simdphys {

// How the overlapping pairs changed from one update of a pair finder to the next. Each list is
// sorted ascending (by a, then b), as the finders return their pairs.
struct PairEvents {
  std::vector<Pair> began;      // overlapping now, not at the previous update
  std::vector<Pair> persisted;  // overlapping at both
  std::vector<Pair> ended;      // overlapping at the previous update, not now
};

// Finds every overlapping pair (closed test) of a stream of boxes (PairFinder) or rectangles
// (PairFinder2d), each once as (a, b) with a < b, sorted ascending by a, then b: the same vector
// whatever the method, the path and the number of threads. Keeps its working memory from call to
// call, as a world's broadphase does from step to step, and the pairs of its last update(), which
// the next update compares its own with. Pairs name elements by index: after the stream is
// reordered, the events compare the new indices. Methods: PairMethod, PairMethod2d; the default
// is the first.
template <class Stream, class Method>
class PairFinderOf {
 public:
  PairFinderOf();
  ~PairFinderOf();
  PairFinderOf(PairFinderOf&&) noexcept;
  PairFinderOf& operator=(PairFinderOf&&) noexcept;

  // Replaces `pairs` with the overlapping pairs of `stream`. Runs on the active path.
  void find(const Stream& stream, std::vector<Pair>& pairs, Method method = Method{}) {
    findWith(stream, pairs, method);
  }
  // Finds the pairs as find() does, keeps them as pairs(), and returns how they changed since the
  // previous update (on the first, or after reset(), every pair began). If it throws, nothing
  // has changed.
  const PairEvents& update(const Stream& stream, Method method = Method{}) {
    findWith(stream, found_, method);
    return advance();
  }
  // The pairs of the last update (began and persisted together), sorted.
  const std::vector<Pair>& pairs() const { return pairs_; }
  // What the last update changed.
  const PairEvents& events() const { return events_; }
  // Forgets the pairs and the events: the next update reports each of its pairs as began and none
  // as ended, as the first update does.
  void reset() {
    pairs_.clear();
    events_ = {};
  }

 private:
  void findWith(const Stream& stream, std::vector<Pair>& pairs, Method method);
  // Makes found_ (sorted) the current pairs and the events its difference from the previous ones.
  const PairEvents& advance();

  struct Scratch;
  std::unique_ptr<Scratch> scratch_;
  std::vector<Pair> found_, pairs_;
  PairEvents events_;
};

}  // namespace simdphys
