// Packets of N rays (8 or 16, one or more vectors of lanes) traversing a mesh's BVH together, for
// coherent rays (Wald, Slusallek, Benthin, Wagner 2001), with Embree's hybrid switch: when few of
// the packet's rays still enter a subtree, they walk it one at a time. Written once for every
// width; included in simd/bvh_ray.cpp inside each target's namespace, after RayCore and the sinks
// (no include guard, by design).
//
// Every lane does the single-ray traversal's arithmetic: the same slab test with the same scaled
// entry and exit (so a box the lone ray would enter is never culled), and the same watertight
// triangle test, operation for operation, with the lane's own shear. The packet only changes the
// order in which a ray meets boxes and triangles, and the closest-hit rule (ClosestHits) does not
// depend on that order: the answers equal the single-ray ones bit for bit.

template <std::size_t N>
class RayPacket {
  using D = hn::CappedTag<float, N>;
  static constexpr std::size_t kLanes = hn::MaxLanes(D());
  static_assert(N % kLanes == 0 && N <= 16, "whole vectors; active lanes fit 16 bits");
  // At most this many active rays finish a subtree on their own: a node test across the packet
  // costs about as much as that many single-ray tests (8 boxes a vector), so packets lose below.
  // Measured on W2 (docs/bvh.md): N / 4.
  static constexpr int kSwitchThreshold = int(N / 4);

 public:
  // Lane i traces ray index[i] of `rays` (kAbsentLane: none).
  // The lanes' rays are set up across the lanes, with traversalRay's operations
  // (core/traversal_ray.hpp: the same divisions and choices, so the same values bit for bit); a
  // lane that walks alone (single()) takes its TraversalRay from the stream then.
  RayPacket(const MeshView& mesh, const RaysView& rays, const std::uint32_t* index)
      : mesh_(mesh), rays_(rays), index_(index) {
    using R = fields::Ray;
    alignas(64) float direction[3][N];
    std::uint32_t present = 0;
    for (std::size_t i = 0; i < N; ++i) {
      // An absent lane's bound is -inf: no box or triangle passes it.
      const bool here = index[i] != kAbsentLane;
      present |= std::uint32_t(here) << i;
      for (int a = 0; a < 3; ++a) {
        origin_[a][i] = here ? rays[R::origin + std::size_t(a)][index[i]] : 0.0f;
        direction[a][i] = here ? rays[R::direction + std::size_t(a)][index[i]] : 1.0f;
      }
      bound_[i] = here ? rays[R::tMax][index[i]] : -std::numeric_limits<float>::infinity();
      hits_[i] = Closest(bound_[i]);
    }
    const D d;
    const auto zero = hn::Zero(d), one = hn::Set(d, 1.0f);
    for (std::size_t h = 0; h < N; h += kLanes) {
      const auto dx = hn::Load(d, direction[0] + h), dy = hn::Load(d, direction[1] + h),
                 dz = hn::Load(d, direction[2] + h);
      bool finite = true;
      for (int a = 0; a < 3; ++a) {
        const auto inverse = hn::Div(one, hn::Load(d, direction[a] + h));
        hn::Store(inverse, d, inverse_[a] + h);
        finite = finite && hn::AllTrue(d, hn::IsFinite(inverse));
      }
      // kz: the first axis of largest |d|; kx, ky the next two, swapped for a negative d[kz].
      const auto y = hn::Gt(hn::Abs(dy), hn::Abs(dx));
      const auto z = hn::Gt(hn::Abs(dz), hn::IfThenElse(y, hn::Abs(dy), hn::Abs(dx)));
      const auto along = hn::IfThenElse(z, dz, hn::IfThenElse(y, dy, dx));
      const auto next = hn::IfThenElse(z, dx, hn::IfThenElse(y, dz, dy));
      const auto last = hn::IfThenElse(z, dy, hn::IfThenElse(y, dx, dz));
      const auto swapped = hn::Lt(along, zero);
      hn::Store(hn::Div(hn::IfThenElse(swapped, last, next), along), d, sx_ + h);
      hn::Store(hn::Div(hn::IfThenElse(swapped, next, last), along), d, sy_ + h);
      hn::Store(hn::Div(one, along), d, sz_ + h);
      const auto kz = hn::IfThenElse(z, hn::Set(d, 2.0f), hn::IfThenElse(y, one, zero));
      hn::Store(hn::Add(hn::Add(kz, kz), hn::IfThenElse(swapped, one, zero)), d, frame_ + h);
      // Absent lanes' inverses are 1: only present lanes can make the packet infinite.
      finite_ = finite_ && finite;
    }
    for (std::uint32_t m = present; m != 0; m &= m - 1)
      frames_ |= 1u << int(frame_[__builtin_ctz(m)]);
    bound(present);
  }

  // Traces the packet and writes each present ray's closest hit at out[index].
  void run(ElementHit* out) {
    if (finite_)
      trace<true>();
    else
      trace<false>();
    for (std::size_t i = 0; i < N; ++i)
      if (index_[i] != kAbsentLane) out[index_[i]] = hits_[i].result();
  }

  // The packet as a walker of walkBvh (bvh_walk-inl.hpp). kFinite: every ray's inverse direction
  // is finite, so Min/Max bound the slabs (raySlab's rule).
  struct Entry {
    std::uint32_t ref;
    float key;      // the smallest entry distance over the lanes: nearest subtrees first
    float dist[N];  // per lane, the scaled entry distance, +inf where the ray misses the box
  };
  template <bool kFinite>
  class Walk {
   public:
    using Entry = RayPacket::Entry;
    explicit Walk(RayPacket& p) : p_(p) {}
    static std::uint32_t ref(const Entry& e) { return e.ref; }
    // No active lane; or few, which then walk the subtree alone. The entry's distances are
    // copied to an aligned buffer first: every test below loads them, and in the entry they
    // straddle cache lines (packets ran 5% slower reading them there).
    bool skip(const Entry& e) {
      std::copy_n(e.dist, N, dist_);
      const std::uint32_t active = p_.activeLanes(dist_);
      if (__builtin_popcount(active) > kSwitchThreshold) return false;
      for (std::uint32_t m = active; m != 0; m &= m - 1) p_.single(__builtin_ctz(m), e.ref);
      return true;
    }
    bool leaf(const Entry& e) {
      p_.leaf(e.ref, dist_);
      return false;
    }
    // Children are pushed, not visited at once: each popped entry takes the hybrid switch.
    bool expand(const BvhNode& n, Entry&, Entry* stack, int& top) {
      top = p_.template expand<kFinite>(n, dist_, stack, top);
      return false;
    }

   private:
    RayPacket& p_;
    alignas(64) float dist_[N];  // the popped entry's
  };

 private:
  template <bool kFinite>
  void trace() {
    Entry root;
    root.ref = 0;
    root.key = 0;
    std::fill_n(root.dist, N, 0.0f);
    Walk<kFinite> walk(*this);
    walkBvh(mesh_.nodes, mesh_.nodeCount, walk, root);
  }

  // The packet's bounds for the node pre-test (Wald, Benthin, Boulos 2007's interval frustum, as
  // Embree's hybrid traversal culls a node for a whole packet): the range of its origins and
  // inverse directions per axis. Only for a packet in one octant with finite, non-zero inverses,
  // where each face's distance is monotone in origin and inverse.
  void bound(std::uint32_t present) {
    cull_ = finite_ && present != 0;
    if (!cull_) return;
    const std::size_t first = std::size_t(__builtin_ctz(present));
    for (int a = 0; a < 3; ++a) {
      // Finite inverses have the direction's sign (a -0 direction's is -inf, not finite).
      negative_[a] = inverse_[a][first] < 0;
      originLo_[a] = originHi_[a] = origin_[a][first];
      inverseLo_[a] = inverseHi_[a] = inverse_[a][first];
    }
    for (std::uint32_t m = present; m != 0; m &= m - 1) {
      const std::size_t i = std::size_t(__builtin_ctz(m));
      for (int a = 0; a < 3; ++a) {
        const float inverse = inverse_[a][i];
        cull_ = cull_ && (inverse < 0) == negative_[a] && inverse != 0;
        originLo_[a] = std::min(originLo_[a], origin_[a][i]);
        originHi_[a] = std::max(originHi_[a], origin_[a][i]);
        inverseLo_[a] = std::min(inverseLo_[a], inverse);
        inverseHi_[a] = std::max(inverseHi_[a], inverse);
      }
    }
  }

  // The children some ray of the packet may enter, as bits: a child whose box no ray in the
  // packet's bounds enters is culled at once, 8 children a pass, before any per-ray test. Exact
  // for culling: rounding is monotone, so each lane's near distance is at least the bounds' least
  // (the near face less the origin farthest along the ray, times the inverse at either end), its
  // far distance at most their most, and the per-lane test, scaled alike, passes only where this
  // one does.
  std::uint32_t maybeEntered(const BvhNode& n) const {
    const hn::CappedTag<float, BvhNode::kWidth> d;
    constexpr std::size_t kChildren = hn::MaxLanes(d);
    float most = -std::numeric_limits<float>::infinity();
    for (std::size_t i = 0; i < N; ++i) most = std::max(most, bound_[i]);
    const float* lo[3] = {n.minX, n.minY, n.minZ};
    const float* hi[3] = {n.maxX, n.maxY, n.maxZ};
    std::uint32_t bits = 0;
    for (std::size_t c = 0; c < std::size_t(BvhNode::kWidth); c += kChildren) {
      auto enter = hn::Zero(d), exit = hn::Set(d, most);
      for (int a = 0; a < 3; ++a) {
        const bool neg = negative_[a];
        const auto inverseLo = hn::Set(d, inverseLo_[a]), inverseHi = hn::Set(d, inverseHi_[a]);
        const auto toNear = hn::Sub(hn::LoadU(d, (neg ? hi[a] : lo[a]) + c),
                                    hn::Set(d, neg ? originLo_[a] : originHi_[a]));
        const auto toFar = hn::Sub(hn::LoadU(d, (neg ? lo[a] : hi[a]) + c),
                                   hn::Set(d, neg ? originHi_[a] : originLo_[a]));
        enter = hn::Max(enter, hn::Min(hn::Mul(toNear, inverseLo), hn::Mul(toNear, inverseHi)));
        exit = hn::Min(exit, hn::Max(hn::Mul(toFar, inverseLo), hn::Mul(toFar, inverseHi)));
      }
      enter = hn::Mul(enter, hn::Set(d, detail::kEnterScale));
      std::uint8_t b[8] = {};
      hn::StoreMaskBits(d, hn::Le(enter, hn::Mul(exit, hn::Set(d, detail::kExitScale))), b);
      bits |= std::uint32_t(b[0]) << c;
    }
    return bits;
  }

  // The lanes whose ray enters the subtree before its bound, as bits.
  std::uint32_t activeLanes(const float* dist) const {
    const D d;
    std::uint32_t bits = 0;
    for (std::size_t h = 0; h < N; h += kLanes) {
      std::uint8_t b[8] = {};
      hn::StoreMaskBits(d, hn::Le(hn::LoadU(d, dist + h), hn::Load(d, bound_ + h)), b);
      bits |= (std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8) << h;
    }
    return bits;
  }

  // Lane i walks the subtree alone, with its own closest-hit state.
  void single(int i, std::uint32_t ref) {
    const detail::TraversalRay ray = detail::traversalRay(rays_, index_[i]);
    if (ray.finiteInverse) {
      RayCore<Closest, true> core(mesh_, ray, hits_[i]);
      traverseRay(mesh_.nodes, mesh_.nodeCount, core, ref);
    } else {
      RayCore<Closest, false> core(mesh_, ray, hits_[i]);
      traverseRay(mesh_.nodes, mesh_.nodeCount, core, ref);
    }
    bound_[i] = hits_[i].bound();
  }

  // Each child box against the packet's active rays (rays in lanes, one box broadcast); the
  // children some ray enters go on the stack, farthest first. Returns the new top.
  template <bool kFinite>
  int expand(const BvhNode& n, const float* dist, Entry* stack, int top) const {
    const D d;
    const auto inf = hn::Set(d, std::numeric_limits<float>::infinity());
    const auto zero = hn::Zero(d);
    Entry kids[BvhNode::kWidth];
    int count = 0;
    const float* lo[3] = {n.minX, n.minY, n.minZ};
    const float* hi[3] = {n.maxX, n.maxY, n.maxZ};
    std::uint32_t candidates = ~0u;
    if constexpr (kFinite)
      if (cull_) candidates = maybeEntered(n);
    for (int k = 0; k < BvhNode::kWidth; ++k) {
      if (n.child[k] == BvhNode::kEmpty || !((candidates >> k) & 1)) continue;
      Entry& kid = kids[count];
      bool any = false;
      auto key = inf;
      for (std::size_t h = 0; h < N; h += kLanes) {
        const auto bound = hn::Load(d, bound_ + h);
        const auto active = hn::Le(hn::LoadU(d, dist + h), bound);
        hn::Vec<D> origin[3], inverse[3], enter;
        for (int a = 0; a < 3; ++a)
          origin[a] = hn::Load(d, origin_[a] + h), inverse[a] = hn::Load(d, inverse_[a] + h);
        // The near face by the sign bit of the direction (that of its inverse, -0 giving -inf),
        // per lane, as RayCore picks it per ray.
        // A packet in one octant (cull_) has the same faces in every lane.
        auto faces = [&](int a, hn::Vec<D>& nearFace, hn::Vec<D>& farFace) {
          const auto boxLo = hn::Set(d, lo[a][k]), boxHi = hn::Set(d, hi[a][k]);
          if (cull_) {
            nearFace = negative_[a] ? boxHi : boxLo, farFace = negative_[a] ? boxLo : boxHi;
            return;
          }
          const auto negative = hn::Lt(inverse[a], zero);
          nearFace = hn::IfThenElse(negative, boxHi, boxLo);
          farFace = hn::IfThenElse(negative, boxLo, boxHi);
        };
        const auto hit = hn::And(active, raySlab<kFinite>(d, faces, origin, inverse, bound, enter));
        const auto kept = hn::IfThenElse(hit, enter, inf);
        hn::StoreU(kept, d, kid.dist + h);
        if (hn::AllFalse(d, hit)) continue;
        any = true;
        key = hn::Min(key, hn::MinOfLanes(d, kept));
      }
      if (!any) continue;
      kid.ref = n.child[k];
      kid.key = hn::GetLane(key);
      prefetch(mesh_, kid.ref);
      ++count;
    }
    // Insertion sort by key onto the stack, farthest first: the nearest is popped next.
    const int base = top;
    for (int c = 0; c < count; ++c) {
      int j = top++;
      while (j > base && stack[j - 1].key < kids[c].key) stack[j] = stack[j - 1], --j;
      stack[j] = kids[c];
    }
    return top;
  }

  // The leaf's triangles against the active rays, one triangle broadcast across the rays. The
  // shear's axes differ between rays of different dominant axes, so rays are taken a frame at a
  // time (coherent packets have one): each lane then runs the scalar test's operations.
  void leaf(std::uint32_t ref, const float* dist) {
    const D d;
    const TriangleBlock& block = mesh_.blocks[BvhNode::leafFirst(ref) / TriangleBlock::kWidth];
    const std::uint32_t count = BvhNode::leafCount(ref);
    for (std::uint32_t frames = frames_; frames != 0; frames &= frames - 1) {
      const int frame = __builtin_ctz(frames);
      const int kz = frame / 2;
      int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
      if (frame & 1) std::swap(kx, ky);
      for (std::uint32_t l = 0; l < count; ++l) {
        for (std::size_t h = 0; h < N; h += kLanes) {
          const auto bound = hn::Load(d, bound_ + h);
          const auto lanes = hn::And(hn::Le(hn::LoadU(d, dist + h), bound),
                                     hn::Eq(hn::Load(d, frame_ + h), hn::Set(d, float(frame))));
          if (hn::AllFalse(d, lanes)) continue;
          const auto sx = hn::Load(d, sx_ + h), sy = hn::Load(d, sy_ + h);
          auto relative = [&](int q, int k) {
            return hn::Sub(hn::Set(d, block.v[q][k][l]), hn::Load(d, origin_[k] + h));
          };
          hn::Vec<D> px[3], py[3], pz[3];
          for (int q = 0; q < 3; ++q) {
            pz[q] = relative(q, kz);
            px[q] = hn::Sub(relative(q, kx), hn::Mul(sx, pz[q]));
            py[q] = hn::Sub(relative(q, ky), hn::Mul(sy, pz[q]));
          }
          hn::Vec<D> t;
          const auto hit =
              hn::And(lanes, watertightSheared(d, px, py, pz, hn::Load(d, sz_ + h), bound, t));
          if (hn::AllFalse(d, hit)) continue;
          alignas(64) float ts[kLanes];
          hn::Store(t, d, ts);
          std::uint8_t bits[8] = {};
          hn::StoreMaskBits(d, hit, bits);
          for (unsigned m = unsigned(bits[0]) | unsigned(bits[1]) << 8; m != 0; m &= m - 1) {
            const std::size_t i = h + std::size_t(__builtin_ctz(m));
            hits_[i].offer(ts[i - h], block.id[l]);
            bound_[i] = hits_[i].bound();
          }
        }
      }
    }
  }

  const MeshView& mesh_;
  const RaysView& rays_;
  const std::uint32_t* index_;
  // Per lane: its closest-hit state, and what the packet tests read.
  Closest hits_[N];
  alignas(64) float bound_[N];
  alignas(64) float origin_[3][N];
  alignas(64) float inverse_[3][N];
  alignas(64) float sx_[N], sy_[N], sz_[N];
  alignas(64) float frame_[N];  // 2 kz + (kx, ky swapped), as a float for a float compare
  std::uint32_t frames_ = 0;    // the frames present, as bits
  bool finite_ = true;
  // The packet's bounds (bound()): whether they cull, and per axis the direction's sign, the
  // origins' and inverses' least and most.
  bool cull_ = true;
  bool negative_[3] = {};
  float originLo_[3] = {}, originHi_[3] = {}, inverseLo_[3] = {}, inverseHi_[3] = {};
};

// Packets of N.
template <std::size_t N>
void closestHitPackets(const MeshView& mesh, const RaysView& rays, const std::uint32_t* index,
                       std::size_t packets, ElementHit* out) {
  for (std::size_t p = 0; p < packets; ++p) RayPacket<N>(mesh, rays, index + p * N).run(out);
}
