// The sinks of a ray walk: the closest hit under W2's rule (mesh_bvh.hpp), and any hit. Included
// inside a namespace per path (src/mesh/ for the reference, each SIMD target's namespace in
// simd/bvh_ray.cpp; no include guard, by design). The includer provides ElementHit and kTieWindow
// (bvh_types.hpp), <algorithm> and <limits>.

// The closest hit under W2's rule: the smallest t, and among the hits within kTieWindow of it the
// smallest id. The hits inside the window are kept (up to kMaxTies; beyond, the farthest, then the
// largest ids, give way), since a nearer hit found later narrows the window and may drop its winner
// while keeping another. `bound` is what the traversal culls against: a hit beyond it cannot
// change the answer.
class ClosestHits {
 public:
  static constexpr int kMaxTies = 16;
  explicit ClosestHits(float tMax) : tMax_(tMax), bound_(tMax) {}
  // A ray that hits nothing (tMax = -inf), to be assigned a real one (arrays of rays in packets).
  ClosestHits() : ClosestHits(-std::numeric_limits<float>::infinity()) {}

  float bound() const { return bound_; }

  // A hit; ignored if beyond bound() (a hit tested against an older, wider bound).
  void offer(float t, std::uint32_t id) {
    if (t > bound_) return;
    if (t < tMin_) {
      tMin_ = t;
      bound_ = std::min(tMax_, t * ::simdphys::kTieWindow);
      int kept = 0;
      for (int k = 0; k < count_; ++k)
        if (ties_[k].t <= bound_) ties_[kept++] = ties_[k];
      count_ = kept;
    }
    if (count_ < kMaxTies) {
      ties_[count_++] = {t, id};
      return;
    }
    // Full: the worst entry (farthest, then largest id) gives way to a better one, so equal-t
    // ties keep the smallest ids.
    int worst = 0;
    for (int k = 1; k < count_; ++k)
      if (worse(ties_[k], ties_[worst])) worst = k;
    if (worse(ties_[worst], {t, id})) ties_[worst] = {t, id};
  }

  // The winner: index kNoHit and t = inf if nothing was hit.
  ::simdphys::ElementHit result() const {
    ::simdphys::ElementHit best;
    for (int k = 0; k < count_; ++k)
      if (ties_[k].id < best.index) best = {ties_[k].id, ties_[k].t};
    return best;
  }

 private:
  // A hit inside the window. Not an ElementHit: that one's default initialisation (a miss) would
  // cost every ray 16 stores it never reads, and packets hold 16 of these.
  struct Tie {
    float t;
    std::uint32_t id;
  };
  static bool worse(const Tie& a, const Tie& b) { return a.t > b.t || (a.t == b.t && a.id > b.id); }
  float tMax_, bound_;
  float tMin_ = std::numeric_limits<float>::infinity();
  int count_ = 0;
  Tie ties_[kMaxTies];
};

// The two sinks of a traversal: the closest hit, and any hit (which stops at the first).
struct Closest : ClosestHits {
  using ClosestHits::ClosestHits;
  static constexpr bool kAnyHit = false;
};
struct Any {
  static constexpr bool kAnyHit = true;
  float tMax;
  bool found = false;
  float bound() const { return tMax; }
};
