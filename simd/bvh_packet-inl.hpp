// Packets of N rays (8 or 16, one or more vectors of lanes) traversing a mesh's BVH together, for
// coherent rays (Wald, Slusallek, Benthin, Wagner 2001), with Embree's hybrid switch: when few of
// the packet's rays still enter a subtree, they walk it one at a time. Written once for every
// width; included in simd/bvh_ray.cpp inside each target's namespace, after RayCore and the sinks
// (no include guard, by design).
//
// No box a lane's single-ray traversal would enter is culled for it (the packet's bounds cull
// only boxes no ray in them enters, with the same scaled entry and exit), and every lane does
// the same watertight triangle test, operation for operation, with its own shear. The packet only
// changes the order in which a ray meets triangles (and adds some it would not have met), and the
// closest-hit rule (ClosestHits) does not depend on that: the answers equal the single-ray ones
// bit for bit.

template <std::size_t N>
class RayPacket {
  using D = hn::CappedTag<float, N>;
  using DI = hn::RebindToSigned<D>;
  static constexpr std::size_t kLanes = hn::MaxLanes(D());
  static_assert(N % kLanes == 0 && N <= 16, "whole vectors; active lanes fit 16 bits");
  // At most this many active rays finish a subtree on their own. With the packet's pre-tests a
  // node or leaf costs the packet little more than one ray's walk; measured on W2 (docs/bvh.md):
  // 2 for 16 and 8 (N / 4 took 3 to 5% longer, 0 as Embree's coherent walk 4% on rows of 16).
  static constexpr int kSwitchThreshold = 2;

 public:
  // Lane i traces ray index[i] of `rays` (kAbsentLane: none). The rays are gathered and set up
  // across the lanes with traversalRay's operations (core/traversal_ray.hpp: the same divisions
  // and choices, so the same values bit for bit), which a lane that walks alone (single()) then
  // takes as its TraversalRay.
  RayPacket(const MeshView& mesh, const RaysView& rays, const std::uint32_t* index)
      : mesh_(mesh), index_(index) {
    using R = fields::Ray;
    const D d;
    const DI di;
    const auto zero = hn::Zero(d), one = hn::Set(d, 1.0f);
    for (std::size_t h = 0; h < N; h += kLanes) {
      // Absent lanes read ray 0 (a packet has a ray, so the stream does) and take neutral
      // values: bound -inf (no box or triangle passes it) and direction 1 (a finite inverse).
      const auto raw = hn::BitCast(di, hn::LoadU(hn::RebindToUnsigned<D>(), index + h));
      const auto here = hn::RebindMask(d, hn::Ne(raw, hn::Set(di, -1)));
      const auto at = hn::IfThenElse(hn::RebindMask(di, here), raw, hn::Zero(di));
      present_ |= bitsOf(here) << h;
#if HWY_TARGET != HWY_SCALAR
      // Tiles' rows and rows of the stream are runs of 4 consecutive rays.
      bool runs = false;
      // Held apart from the index (which the packet's stores of ids might alias), read once.
      std::uint32_t starts[(kLanes + 3) / 4];
      if constexpr (kLanes % 4 == 0) {
        for (std::size_t j = 0; j < kLanes / 4; ++j) starts[j] = index[h + 4 * j];
        const auto step = hn::And(hn::Iota(di, 0), hn::Set(di, 3));
        runs = hn::AllTrue(d, here) &&
               hn::AllTrue(di, hn::Eq(raw, hn::Add(hn::Broadcast<0>(raw), step)));
      }
      runs_ = runs_ && runs;
#endif
      auto gather = [&](std::size_t f, hn::Vec<D> absent) {
#if HWY_TARGET != HWY_SCALAR
        if constexpr (kLanes % 4 == 0)
          if (runs) return loadRuns(d, rays[f], starts);
#endif
        return hn::IfThenElse(here, hn::GatherIndex(d, rays[f], at), absent);
      };
      // Every field loaded before the packet stores anything: loads issued among the stores ran
      // slower (docs/bvh.md).
      hn::Vec<D> origin[3], direction[3], inverse[3];
      for (int a = 0; a < 3; ++a) {
        origin[a] = gather(R::origin + std::size_t(a), zero);
        direction[a] = gather(R::direction + std::size_t(a), one);
      }
      const auto tMax = gather(R::tMax, hn::Set(d, -std::numeric_limits<float>::infinity()));
      bool finite = true;
      for (int a = 0; a < 3; ++a) {
        hn::Store(origin[a], d, origin_[a] + h);
        inverse[a] = hn::Div(one, direction[a]);
        hn::Store(inverse[a], d, inverse_[a] + h);
        finite = finite && hn::AllTrue(d, hn::IsFinite(inverse[a]));
      }
      hn::Store(tMax, d, bound_ + h);
      hn::Store(tMax, d, tMax_ + h);
      hn::Store(hn::Set(d, std::numeric_limits<float>::infinity()), d, tMin_ + h);
      hn::Store(hn::Set(hn::RebindToUnsigned<D>(), kNoHit), hn::RebindToUnsigned<D>(), id_ + h);
      const auto dx = direction[0], dy = direction[1], dz = direction[2];
      // kz: the first axis of largest |d|; kx, ky the next two, swapped for a negative d[kz].
      const auto y = hn::Gt(hn::Abs(dy), hn::Abs(dx));
      const auto z = hn::Gt(hn::Abs(dz), hn::IfThenElse(y, hn::Abs(dy), hn::Abs(dx)));
      const auto along = hn::IfThenElse(z, dz, hn::IfThenElse(y, dy, dx));
      const auto next = hn::IfThenElse(z, dx, hn::IfThenElse(y, dz, dy));
      const auto last = hn::IfThenElse(z, dy, hn::IfThenElse(y, dx, dz));
      const auto swapped = hn::Lt(along, zero);
      hn::Store(hn::Div(hn::IfThenElse(swapped, last, next), along), d, sx_ + h);
      hn::Store(hn::Div(hn::IfThenElse(swapped, next, last), along), d, sy_ + h);
      // sz = 1 / d[kz]: the inverse along kz, the same division.
      hn::Store(hn::IfThenElse(z, inverse[2], hn::IfThenElse(y, inverse[1], inverse[0])), d,
                sz_ + h);
      const auto kz = hn::IfThenElse(z, hn::Set(d, 2.0f), hn::IfThenElse(y, one, zero));
      const auto frame = hn::Add(hn::Add(kz, kz), hn::IfThenElse(swapped, one, zero));
      for (int f = 0; f < 6; ++f)
        frameLanes_[f] |= bitsOf(hn::And(here, hn::Eq(frame, hn::Set(d, float(f))))) << h;
      // Absent lanes' inverses are 1: only present lanes can make the packet infinite.
      finite_ = finite_ && finite;
    }
    for (int f = 0; f < 6; ++f) frames_ |= std::uint32_t(frameLanes_[f] != 0) << f;
    bound();
  }

  // Traces the packet and writes each present ray's closest hit at out[index].
  void run(ElementHit* out) {
    if (finite_)
      trace<true>();
    else
      trace<false>();
    write(out);
  }

  // The packet as a walker of walkBvh (bvh_walk-inl.hpp). kFinite: every ray's inverse direction
  // is finite, so Min/Max bound the slabs (raySlab's rule). An entry is Embree's: a key that is at
  // most every lane's entry distance, and the lanes whose ray may enter the box (per-lane
  // distances would cost a 64-byte row an entry for culling that the key and the lanes' bounds
  // mostly do).
  struct Entry {
    std::uint32_t ref;
    float key;            // a lower bound of the lanes' scaled entry distances: nearest first
    std::uint32_t lanes;  // the lanes whose ray may enter the box, as bits
  };
  template <bool kFinite>
  class Walk {
   public:
    using Entry = RayPacket::Entry;
    explicit Walk(RayPacket& p) : p_(p) {}
    static std::uint32_t ref(const Entry& e) { return e.ref; }
    // No lane whose bound reaches the box; or few, which then walk the subtree alone.
    bool skip(const Entry& e) {
      lanes_ = e.lanes & p_.within(e.key);
      if (__builtin_popcount(lanes_) > kSwitchThreshold) return false;
      for (std::uint32_t m = lanes_; m != 0; m &= m - 1) p_.single(__builtin_ctz(m), e.ref);
      return true;
    }
    bool leaf(const Entry& e) {
      p_.leaf(e.ref, lanes_);
      return false;
    }
    // The nearest child is visited at once when enough lanes enter it (the walk's own pop
    // would find the same lanes); otherwise it is popped and takes the hybrid switch.
    bool expand(const BvhNode& n, Entry& e, Entry* stack, int& top) {
      const int base = top;
      top = p_.template expand<kFinite>(n, lanes_, stack, top);
      if (top == base) return false;
      const std::uint32_t lanes = stack[top - 1].lanes & p_.within(stack[top - 1].key);
      if (__builtin_popcount(lanes) <= kSwitchThreshold) return false;
      e = stack[--top];
      lanes_ = lanes;
      return true;
    }

   private:
    RayPacket& p_;
    std::uint32_t lanes_ = 0;  // the popped entry's active lanes
  };

 private:
  template <bool kFinite>
  void trace() {
    Walk<kFinite> walk(*this);
    walkBvh(mesh_.nodes, mesh_.nodeCount, walk, Entry{0, 0.0f, present_});
  }

  // Each present lane's closest hit at out[index]: the rows' (a lane without a hit holds
  // ElementHit's miss, kNoHit and inf), then the owned lanes' over them.
  void write(ElementHit* out) const {
    bool written = false;
#if HWY_TARGET != HWY_SCALAR
    if constexpr (kLanes % 4 == 0) {
      if (runs_) {  // a run's 4 hits as two 16-byte stores of (id, t) pairs
        const D d;
        const hn::RebindToUnsigned<D> du;
        for (std::size_t h = 0; h < N; h += kLanes) {
          const auto ids = hn::BitCast(d, hn::Load(du, id_ + h)), ts = hn::Load(d, tMin_ + h);
          // Per 128-bit block j: lanes 4j and 4j + 1 interleaved, then 4j + 2 and 4j + 3.
          alignas(64) float pairs[2][kLanes];
          hn::Store(hn::InterleaveLower(d, ids, ts), d, pairs[0]);
          hn::Store(hn::InterleaveUpper(d, ids, ts), d, pairs[1]);
          for (std::size_t r = 0; r < kLanes; r += 4) {
            std::memcpy(out + index_[h + r], pairs[0] + r, 2 * sizeof(ElementHit));
            std::memcpy(out + index_[h + r] + 2, pairs[1] + r, 2 * sizeof(ElementHit));
          }
        }
        written = true;
      }
    }
#endif
    if (!written)
      for (std::uint32_t m = present_ & ~owned_; m != 0; m &= m - 1) {
        const int i = __builtin_ctz(m);
        out[index_[i]] = ElementHit{id_[i], tMin_[i]};
      }
    for (std::uint32_t m = owned_; m != 0; m &= m - 1) {
      const int i = __builtin_ctz(m);
      out[index_[i]] = hits_[i].result();
    }
  }

#if HWY_TARGET != HWY_SCALAR  // one lane: no runs
  // A field's values for lanes that are runs of 4 consecutive rays (starts: the first ray of
  // each), one 4-float load a run where a gather loads lane by lane.
  template <class DV>
  static hn::Vec<DV> loadRuns(DV d, const float* field, const std::uint32_t* starts) {
    if constexpr (hn::MaxLanes(DV()) <= 4) {
      return hn::LoadU(d, field + starts[0]);
    } else {
      const hn::Half<DV> half;
      return hn::Combine(d, loadRuns(half, field, starts + hn::MaxLanes(half) / 4),
                         loadRuns(half, field, starts));
    }
  }
#endif

  // A mask's lanes as the low bits of an integer (of at most 16 lanes). AVX-512's masks are
  // those bits already, where StoreMaskBits would pass them through memory.
  template <class DM = D>
  static std::uint32_t bitsOf(hn::Mask<DM> m) {
#if HWY_TARGET <= HWY_AVX3
    return std::uint32_t(m.raw) & ((1u << hn::MaxLanes(DM())) - 1);
#else
    std::uint8_t b[8] = {};
    hn::StoreMaskBits(DM(), m, b);
    return std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8;
#endif
  }
  // Lanes h.. of a lane set, as a mask.
  static hn::Mask<D> maskOf(std::uint32_t lanes, std::size_t h) {
#if HWY_TARGET <= HWY_AVX3
    return hn::Mask<D>{static_cast<typename hn::Mask<D>::Raw>(lanes >> h)};
#else
    std::uint8_t b[8] = {std::uint8_t(lanes >> h), std::uint8_t(lanes >> h >> 8)};
    return hn::LoadMaskBits(D(), b);
#endif
  }

  // The lanes whose bound is at least t, as bits.
  std::uint32_t within(float t) const {
    const D d;
    std::uint32_t bits = 0;
    for (std::size_t h = 0; h < N; h += kLanes)
      bits |= bitsOf(hn::Le(hn::Set(d, t), hn::Load(d, bound_ + h))) << h;
    return bits;
  }

  // The packet's bounds for the node pre-test (Wald, Benthin, Boulos 2007's interval frustum, as
  // Embree's hybrid traversal culls a node for a whole packet): the range of its origins and
  // inverse directions per axis. Only for a packet in one octant with finite, non-zero inverses,
  // where each face's distance is monotone in origin and inverse.
  void bound() {
    cull_ = finite_ && present_ != 0;
    if (!cull_) return;
    const D d;
    const auto inf = hn::Set(d, std::numeric_limits<float>::infinity()), zero = hn::Zero(d);
    for (int a = 0; a < 3; ++a) {
      auto originLo = inf, originHi = hn::Neg(inf), inverseLo = inf, inverseHi = hn::Neg(inf);
      std::uint32_t negative = 0, zeroes = 0;
      for (std::size_t h = 0; h < N; h += kLanes) {
        const auto here = maskOf(present_, h);
        const auto origin = hn::Load(d, origin_[a] + h), inverse = hn::Load(d, inverse_[a] + h);
        originLo = hn::Min(originLo, hn::IfThenElse(here, origin, inf));
        originHi = hn::Max(originHi, hn::IfThenElse(here, origin, hn::Neg(inf)));
        inverseLo = hn::Min(inverseLo, hn::IfThenElse(here, inverse, inf));
        inverseHi = hn::Max(inverseHi, hn::IfThenElse(here, inverse, hn::Neg(inf)));
        // Finite inverses have the direction's sign (a -0 direction's is -inf, not finite).
        negative |= bitsOf(hn::And(here, hn::Lt(inverse, zero))) << h;
        zeroes |= bitsOf(hn::And(here, hn::Eq(inverse, zero))) << h;
      }
      negative_[a] = negative != 0;
      cull_ = cull_ && zeroes == 0 && (negative == 0 || negative == present_);
      originLo_[a] = hn::GetLane(hn::MinOfLanes(d, originLo));
      originHi_[a] = hn::GetLane(hn::MaxOfLanes(d, originHi));
      inverseLo_[a] = hn::GetLane(hn::MinOfLanes(d, inverseLo));
      inverseHi_[a] = hn::GetLane(hn::MaxOfLanes(d, inverseHi));
    }
  }

  // The children some ray of the packet may enter, as bits, and in `enter` a lower bound of the
  // scaled distance where each ray does: a child whose box no ray in the packet's bounds enters
  // is culled at once, 8 children a pass, before any per-ray test. Exact for culling: rounding is
  // monotone, so each lane's near distance is at least the bounds' least (the near face less the
  // origin farthest along the ray, times the inverse at either end), its far distance at most
  // their most, and the per-lane test, scaled alike, passes only where this one does.
  // Boxes come as rows of 8: lo[axis][box], hi[axis][box].
  std::uint32_t maybeEntered(const float* const (&lo)[3], const float* const (&hi)[3],
                             float* enterOut) const {
    const hn::CappedTag<float, BvhNode::kWidth> d;
    constexpr std::size_t kChildren = hn::MaxLanes(d);
    const D dp;
    auto mostV = hn::Load(dp, bound_);
    for (std::size_t h = kLanes; h < N; h += kLanes)
      mostV = hn::Max(mostV, hn::Load(dp, bound_ + h));
    const float most = hn::GetLane(hn::MaxOfLanes(dp, mostV));
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
      hn::StoreU(enter, d, enterOut + c);
      bits |= bitsOf<decltype(d)>(hn::Le(enter, hn::Mul(exit, hn::Set(d, detail::kExitScale))))
              << c;
    }
    return bits;
  }

  // The block's triangles among `leaf` (bits) whose box some ray of the packet may enter, as bits:
  // the node pre-test on the triangles' bounds, which the leaf's box holds exactly (both are the
  // vertices' min and max), so the same monotone rounding argument keeps every triangle a lane
  // could hit.
  std::uint32_t maybeHit(const TriangleBlock& block, std::uint32_t leaf) const {
    const hn::CappedTag<float, BvhNode::kWidth> d;
    constexpr std::size_t kBoxes = hn::MaxLanes(d);
    alignas(32) float lo[3][BvhNode::kWidth], hi[3][BvhNode::kWidth], enter[BvhNode::kWidth];
    for (int a = 0; a < 3; ++a)
      for (std::size_t c = 0; c < std::size_t(BvhNode::kWidth); c += kBoxes) {
        const auto v0 = hn::Load(d, block.v[0][a] + c), v1 = hn::Load(d, block.v[1][a] + c),
                   v2 = hn::Load(d, block.v[2][a] + c);
        hn::Store(hn::Min(v0, hn::Min(v1, v2)), d, lo[a] + c);
        hn::Store(hn::Max(v0, hn::Max(v1, v2)), d, hi[a] + c);
      }
    const float* const los[3] = {lo[0], lo[1], lo[2]};
    const float* const his[3] = {hi[0], hi[1], hi[2]};
    return maybeEntered(los, his, enter) & leaf;
  }

  // Lane i's hits as a ClosestHits from now on (it walks alone, or met a tie): the one hit its
  // rows held offered to a fresh one, which is the state that offer left in it.
  Closest& own(int i) {
    if (!(owned_ >> i & 1)) {
      owned_ |= 1u << i;
      std::construct_at(&hits_[i], tMax_[i]);
      if (found_ >> i & 1) hits_[i].offer(tMin_[i], id_[i]);
    }
    return hits_[i];
  }

  // A shear frame's axes (frame = 2 kz + whether kx and ky are swapped for a negative d[kz]).
  static void axesOf(int frame, int& kx, int& ky, int& kz) {
    kz = frame / 2, kx = (kz + 1) % 3, ky = (kx + 1) % 3;
    if (frame & 1) std::swap(kx, ky);
  }

  // Lane i's ray as the single-ray walk takes it, from the lanes (traversalRay's values, set up
  // across the lanes with its operations) rather than from the stream again.
  detail::TraversalRay traversalRay(int i) const {
    detail::TraversalRay r;
    int frame = 0;
    while (!(frameLanes_[frame] >> i & 1)) ++frame;
    axesOf(frame, r.kx, r.ky, r.kz);
    r.ox = origin_[0][i], r.oy = origin_[1][i], r.oz = origin_[2][i];
    r.sx = sx_[i], r.sy = sy_[i], r.sz = sz_[i];
    r.tMax = tMax_[i];
    r.finiteInverse = true;
    for (int a = 0; a < 3; ++a) {
      r.origin[a] = origin_[a][i], r.inverse[a] = inverse_[a][i];
      r.negative[a] = std::signbit(r.inverse[a]);  // the direction's (1 / -0 is -inf)
      r.finiteInverse = r.finiteInverse && std::isfinite(r.inverse[a]);
    }
    return r;
  }

  // Lane i's hit (t, id), as ClosestHits::offer takes it: held in the rows while the lane holds
  // at most one hit (nothing held, or a nearer hit whose window leaves out the one held: the
  // state offer would leave is that one hit), else offered to the lane's own ClosestHits.
  void offer(int i, float t, std::uint32_t id) {
    const std::uint32_t bit = 1u << i;
    if (!(owned_ & bit)) {
      if (t > bound_[i]) return;
      const float window = std::min(t * kTieWindow, tMax_[i]);
      if (!(found_ & bit) || (t < tMin_[i] && tMin_[i] > window)) {
        found_ |= bit;
        tMin_[i] = t, id_[i] = id, bound_[i] = window;
        return;
      }
    }
    Closest& hits = own(i);
    hits.offer(t, id);
    bound_[i] = hits.bound();
  }

  // Lane i as the sink of a single-ray walk.
  class LaneHits {
   public:
    static constexpr bool kAnyHit = false;
    LaneHits(RayPacket& packet, int i) : packet_(packet), i_(i) {}
    float bound() const { return packet_.bound_[i_]; }
    void offer(float t, std::uint32_t id) { packet_.offer(i_, t, id); }

   private:
    RayPacket& packet_;
    int i_;
  };

  // Lane i walks the subtree alone, its hits offered as the leaf offers them.
  void single(int i, std::uint32_t ref) {
    const detail::TraversalRay ray = traversalRay(i);
    LaneHits hits(*this, i);
    if (ray.finiteInverse) {
      RayCore<LaneHits, true> core(mesh_, ray, hits);
      traverseRay(mesh_.nodes, mesh_.nodeCount, core, ref);
    } else {
      RayCore<LaneHits, false> core(mesh_, ray, hits);
      traverseRay(mesh_.nodes, mesh_.nodeCount, core, ref);
    }
  }

  // The active lanes whose ray enters child k of n, as bits, and in `key` the least of their
  // entry distances: the box broadcast against the rays in lanes, each lane with the single-ray
  // test's arithmetic (near face by the sign bit of its direction: that of the inverse, -0 giving
  // -inf, as RayCore picks it per ray).
  template <bool kFinite>
  std::uint32_t entering(const BvhNode& n, int k, std::uint32_t lanes, float& key) const {
    const D d;
    const auto inf = hn::Set(d, std::numeric_limits<float>::infinity());
    const auto zero = hn::Zero(d);
    const float* const lo[3] = {n.minX, n.minY, n.minZ};
    const float* const hi[3] = {n.maxX, n.maxY, n.maxZ};
    std::uint32_t entered = 0;
    auto least = inf;
    for (std::size_t h = 0; h < N; h += kLanes) {
      const auto active = maskOf(lanes, h);
      if (hn::AllFalse(d, active)) continue;
      const auto bound = hn::Load(d, bound_ + h);
      hn::Vec<D> origin[3], inverse[3], enter;
      for (int a = 0; a < 3; ++a)
        origin[a] = hn::Load(d, origin_[a] + h), inverse[a] = hn::Load(d, inverse_[a] + h);
      auto faces = [&](int a, hn::Vec<D>& nearFace, hn::Vec<D>& farFace) {
        const auto boxLo = hn::Set(d, lo[a][k]), boxHi = hn::Set(d, hi[a][k]);
        if (cull_) {  // one octant: the same faces in every lane
          nearFace = negative_[a] ? boxHi : boxLo, farFace = negative_[a] ? boxLo : boxHi;
          return;
        }
        const auto negative = hn::Lt(inverse[a], zero);
        nearFace = hn::IfThenElse(negative, boxHi, boxLo);
        farFace = hn::IfThenElse(negative, boxLo, boxHi);
      };
      const auto hit = hn::And(active, raySlab<kFinite>(d, faces, origin, inverse, bound, enter));
      entered |= bitsOf(hit) << h;
      least = hn::Min(least, hn::IfThenElse(hit, enter, inf));
    }
    key = hn::GetLane(hn::MinOfLanes(d, least));
    return entered;
  }

  // The children some ray may enter go on the stack, farthest first; returns the new top. A
  // packet in one octant takes the children its bounds pass (maybeEntered); a leaf among them is
  // tested against the active lanes one by one, but a node is passed all of them: testing every
  // passing node against the lanes, as Embree's coherent walk does, culled too little to pay for
  // itself on tiles (docs/bvh.md). Other packets test each child against the lanes.
  template <bool kFinite>
  int expand(const BvhNode& n, std::uint32_t lanes, Entry* stack, int top) const {
    const bool cull = kFinite && cull_;
    alignas(32) float enter[BvhNode::kWidth];
    std::uint32_t candidates = 0;
    if (cull) {
      const float* const lo[3] = {n.minX, n.minY, n.minZ};
      const float* const hi[3] = {n.maxX, n.maxY, n.maxZ};
      candidates = maybeEntered(lo, hi, enter);  // an empty slot's inverted box fails it
    } else {
      for (int k = 0; k < BvhNode::kWidth; ++k)
        candidates |= std::uint32_t(n.child[k] != BvhNode::kEmpty) << k;
    }
    // Each candidate is fetched as it comes (one loop: a second one's exit cost a misprediction
    // a node), and a child node's own leaves with it, a level ahead, into the second-level cache
    // (a leaf's own fetch, when its parent is expanded, finds them there): a coherent packet
    // visits most of them, and would otherwise wait for each block on arrival.
    const int base = top;
    for (; candidates != 0; candidates &= candidates - 1) {
      const int k = __builtin_ctz(candidates);
      prefetchAll(mesh_, n.child[k]);
      if (n.leafSpan[k] != BvhNode::kEmpty)
        core::prefetchLines<2>(mesh_.blocks + BvhNode::leafFirst(n.leafSpan[k]),
                               BvhNode::leafCount(n.leafSpan[k]) * sizeof(TriangleBlock));
      Entry kid{n.child[k], cull ? enter[k] : 0.0f, lanes};
      if (!cull || BvhNode::isLeaf(kid.ref)) {
        float key;
        kid.lanes = entering<kFinite>(n, k, lanes, key);
        if (kid.lanes == 0) continue;
        if (!cull) kid.key = key;
      }
      // Inserted by key, farthest first: the nearest is popped next.
      int j = top++;
      while (j > base && stack[j - 1].key < kid.key) stack[j] = stack[j - 1], --j;
      stack[j] = kid;
    }
    return top;
  }

  // The leaf's triangles against the active rays, one triangle broadcast across the rays. The
  // shear's axes differ between rays of different dominant axes, so rays are taken a frame at a
  // time (coherent packets have one): each lane then runs the scalar test's operations. Every
  // triangle is tested against the bounds the leaf started with (the rule does not depend on the
  // order hits are offered); then a lane with one hit, no hit held or one its window drops, keeps
  // it in the rows, and the others offer theirs to their own ClosestHits.
  void leaf(std::uint32_t ref, std::uint32_t lanes) {
    const D d;
    const hn::RebindToUnsigned<D> du;
    const TriangleBlock& block = mesh_.blocks[TriangleBlock::of(ref)];
    // The leaf's lanes of its block: the others belong to other leaves, or repeat.
    const std::uint32_t leaf = ((1u << BvhNode::leafCount(ref)) - 1)
                               << TriangleBlock::firstLane(ref);
    const std::uint32_t triangles = cull_ ? maybeHit(block, leaf) : leaf;
    if (triangles == 0) return;
    const auto inf = hn::Set(d, std::numeric_limits<float>::infinity());
    const auto none = hn::Set(d, std::numeric_limits<float>::quiet_NaN());
    for (std::uint32_t frames = frames_; frames != 0; frames &= frames - 1) {
      const int frame = __builtin_ctz(frames);
      const std::uint32_t inFrame = lanes & frameLanes_[frame];
      if (inFrame == 0) continue;
      int kx, ky, kz;
      axesOf(frame, kx, ky, kz);
      for (std::size_t h = 0; h < N; h += kLanes) {
        if (((inFrame >> h) & ((1u << kLanes) - 1)) == 0) continue;
        const auto active = maskOf(inFrame, h);
        const auto bound = hn::Load(d, bound_ + h);
        const auto sx = hn::Load(d, sx_ + h), sy = hn::Load(d, sy_ + h), sz = hn::Load(d, sz_ + h);
        // Per triangle, its t where a lane hits it and NaN elsewhere; per lane, the nearest hit.
        alignas(64) float ts[TriangleBlock::kWidth][kLanes];
        auto seen = hn::FirstN(d, 0), several = seen;
        auto nearest = inf;
        auto nearestId = hn::Zero(du);
        for (std::uint32_t m = triangles; m != 0; m &= m - 1) {
          const int l = __builtin_ctz(m);
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
          const auto hit = hn::And(active, watertightSheared<false>(d, px, py, pz, sz, bound, t));
          hn::Store(hn::IfThenElse(hit, t, none), d, ts[l]);
          // A lane's first hit is its nearest so far even at t = inf (a ray with tMax = inf).
          const auto nearer = hn::And(hit, hn::Or(hn::Not(seen), hn::Lt(t, nearest)));
          several = hn::Or(several, hn::And(hit, seen));
          seen = hn::Or(seen, hit);
          nearest = hn::IfThenElse(nearer, t, nearest);
          nearestId =
              hn::IfThenElse(hn::RebindMask(du, nearer), hn::Set(du, block.id[l]), nearestId);
        }
        if (hn::AllFalse(d, seen)) continue;
        const auto tMin = hn::Load(d, tMin_ + h);
        const auto found = maskOf(found_, h);
        const auto window =
            hn::Min(hn::Mul(nearest, hn::Set(d, kTieWindow)), hn::Load(d, tMax_ + h));
        // ClosestHits::offer's outcome for one hit: held alone when nothing was, or when it is
        // nearer and the window it sets leaves out the hit held.
        const auto alone = hn::AndNot(hn::Or(several, maskOf(owned_, h)), seen);
        const auto keep = hn::And(
            alone, hn::Or(hn::Not(found), hn::And(hn::Lt(nearest, tMin), hn::Gt(tMin, window))));
        hn::Store(hn::IfThenElse(keep, nearest, tMin), d, tMin_ + h);
        hn::Store(hn::IfThenElse(keep, window, bound), d, bound_ + h);
        hn::Store(hn::IfThenElse(hn::RebindMask(du, keep), nearestId, hn::Load(du, id_ + h)), du,
                  id_ + h);
        const std::uint32_t kept = bitsOf(keep) << h;
        found_ |= kept;
        for (std::uint32_t rest = (bitsOf(seen) << h) & ~kept; rest != 0; rest &= rest - 1) {
          const int i = __builtin_ctz(rest);
          for (std::uint32_t m = triangles; m != 0; m &= m - 1) {
            const int l = __builtin_ctz(m);
            const float t = ts[l][std::size_t(i) - h];
            if (t == t) offer(i, t, block.id[l]);
          }
        }
      }
    }
  }

  const MeshView& mesh_;
  const std::uint32_t* index_;
  // Per lane: its closest hit in rows while it holds at most one (found_: one, at tMin_ with id_),
  // else in hits_ (owned_), and what the packet tests read.
  alignas(64) float bound_[N];
  alignas(64) float tMax_[N], tMin_[N];
  alignas(64) std::uint32_t id_[N];
  std::uint32_t found_ = 0, owned_ = 0;
  // Built by own() when a lane takes one: few do, and 16 of them span 36 lines a packet would
  // otherwise write every time.
  union {
    Closest hits_[N];
  };
  alignas(64) float origin_[3][N];
  alignas(64) float inverse_[3][N];
  alignas(64) float sx_[N], sy_[N], sz_[N];
  std::uint32_t present_ = 0;         // the lanes with a ray, as bits
  bool runs_ = true;                  // every lane present, in runs of 4 consecutive rays
  std::uint32_t frames_ = 0;          // the frames present, as bits
  std::uint32_t frameLanes_[6] = {};  // per frame, its lanes
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
