// The rigid bodies' solver records (core::SolverBody) as lanes, for the kernels of
// simd/rigid_contacts-inl.hpp and simd/rigid_motion-inl.hpp. Included inside each target's
// namespace (no include guard, by design), after simd/particle_lanes-inl.hpp.

// The lanes' body records (16 floats: v, w, dp, dq, pad) as fields, field k of every lane's
// record in f[k]. A vector loads each lane's record whole, a row per lane, and transposes the
// rows in registers (Box2D v3's 8x8 transpose), rather than gathering field by field; it writes
// back the first `fields` (8: v, w and dp's first two; or 16, all) the same way. One lane reads
// and writes its own.
inline constexpr std::size_t kRecordFloats = sizeof(core::SolverBody) / sizeof(float);
static_assert(kRecordFloats == 16);

inline void loadRecords(ScalarLane, const core::SolverBody* bodies, const std::uint32_t* index,
                        float* f) {
  const float* record = reinterpret_cast<const float*>(bodies + index[0]);
  for (std::size_t k = 0; k < kRecordFloats; ++k) f[k] = record[k];
}
inline void storeRecords(ScalarLane, core::SolverBody* bodies, const std::uint32_t* index,
                         const float* f, std::size_t fields) {
  float* record = reinterpret_cast<float*>(bodies + index[0]);
  for (std::size_t k = 0; k < fields; ++k) record[k] = f[k];
}

#if HWY_TARGET != HWY_SCALAR
// r[0..N) rows of N floats transposed in place: 4x4 within each 128-bit block, then the blocks.
template <class D, class V = LaneOf<D>>
HWY_INLINE void transposeSquare(D d, V* r) {
  constexpr std::size_t N = hn::MaxLanes(D());
  static_assert(N == 4 || N == 8 || N == 16);
  const hn::Repartition<double, D> d64;
  const auto lower64 = [&](V a, V b) {
    return hn::BitCast(d, hn::InterleaveLower(d64, hn::BitCast(d64, a), hn::BitCast(d64, b)));
  };
  const auto upper64 = [&](V a, V b) {
    return hn::BitCast(d, hn::InterleaveUpper(d64, hn::BitCast(d64, a), hn::BitCast(d64, b)));
  };
  for (std::size_t g = 0; g < N; g += 4) {
    const V t0 = hn::InterleaveLower(d, r[g], r[g + 1]),
            t1 = hn::InterleaveLower(d, r[g + 2], r[g + 3]);
    const V t2 = hn::InterleaveUpper(d, r[g], r[g + 1]),
            t3 = hn::InterleaveUpper(d, r[g + 2], r[g + 3]);
    r[g] = lower64(t0, t1), r[g + 1] = upper64(t0, t1);
    r[g + 2] = lower64(t2, t3), r[g + 3] = upper64(t2, t3);
  }
  // Now block b of r[4 g + k] holds column 4 b + k of rows 4 g to 4 g + 3.
  if constexpr (N == 8) {
    for (std::size_t k = 0; k < 4; ++k) {
      const V lo = r[k], hi = r[4 + k];
      r[k] = hn::ConcatLowerLower(d, hi, lo), r[4 + k] = hn::ConcatUpperUpper(d, hi, lo);
    }
  } else if constexpr (N == 16) {
    for (std::size_t k = 0; k < 4; ++k) {
      const V o0 = r[k], o1 = r[4 + k], o2 = r[8 + k], o3 = r[12 + k];
      const V x0 = hn::OddEvenBlocks(hn::SwapAdjacentBlocks(o1), o0);
      const V x1 = hn::OddEvenBlocks(o1, hn::SwapAdjacentBlocks(o0));
      const V y0 = hn::OddEvenBlocks(hn::SwapAdjacentBlocks(o3), o2);
      const V y1 = hn::OddEvenBlocks(o3, hn::SwapAdjacentBlocks(o2));
      r[k] = hn::ConcatLowerLower(d, y0, x0), r[4 + k] = hn::ConcatLowerLower(d, y1, x1);
      r[8 + k] = hn::ConcatUpperUpper(d, y0, x0), r[12 + k] = hn::ConcatUpperUpper(d, y1, x1);
    }
  }
}

template <class D, class V = LaneOf<D>>
HWY_INLINE void loadRecords(D d, const core::SolverBody* bodies, const std::uint32_t* index, V* f) {
  constexpr std::size_t N = hn::MaxLanes(D());
  const float* base = reinterpret_cast<const float*>(bodies);
  for (std::size_t c = 0; c < kRecordFloats; c += N) {
    for (std::size_t i = 0; i < N; ++i)
      f[c + i] = hn::LoadU(d, base + index[i] * kRecordFloats + c);
    transposeSquare(d, f + c);
  }
}

template <class D, class V = LaneOf<D>>
HWY_INLINE void storeRecords(D d, core::SolverBody* bodies, const std::uint32_t* index, const V* f,
                             std::size_t fields) {
  constexpr std::size_t N = hn::MaxLanes(D());
  float* base = reinterpret_cast<float*>(bodies);
  if (N == 16 && fields == 8) {  // fields 8 to 15 ride along as zeros; each row's lower half stored
    V r[N];
    for (std::size_t k = 0; k < N; ++k) r[k] = k < 8 ? f[k] : hn::Zero(d);
    transposeSquare(d, r);
    const hn::Half<D> dh;
    for (std::size_t i = 0; i < N; ++i)
      hn::StoreU(hn::LowerHalf(dh, r[i]), dh, base + index[i] * kRecordFloats);
    return;
  }
  for (std::size_t c = 0; c < fields; c += N) {
    V r[N];
    for (std::size_t k = 0; k < N; ++k) r[k] = f[c + k];
    transposeSquare(d, r);
    for (std::size_t i = 0; i < N; ++i) hn::StoreU(r[i], d, base + index[i] * kRecordFloats + c);
  }
}
#else  // one lane a vector: the record read and written as one lane does
template <class D, class V = LaneOf<D>>
HWY_INLINE void loadRecords(D d, const core::SolverBody* bodies, const std::uint32_t* index, V* f) {
  const float* record = reinterpret_cast<const float*>(bodies + index[0]);
  for (std::size_t k = 0; k < kRecordFloats; ++k) f[k] = hn::Set(d, record[k]);
}
template <class D, class V = LaneOf<D>>
HWY_INLINE void storeRecords(D, core::SolverBody* bodies, const std::uint32_t* index, const V* f,
                             std::size_t fields) {
  float* record = reinterpret_cast<float*>(bodies + index[0]);
  for (std::size_t k = 0; k < fields; ++k) record[k] = hn::GetLane(f[k]);
}
#endif
