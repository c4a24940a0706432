// Compaction of 32-bit lanes, included inside each target's namespace (no include guard, by
// design). AVX-512 has an instruction for it. Elsewhere, Highway 1.0.3's CompressStore rebuilds
// a 1 KiB lookup table on the stack on every call (a non-static constexpr array): measured, it
// made AVX2 culling 8 times slower than AVX-512. This uses the same idea, lane indices packed
// into nibbles, with the table built once at compile time (kCompressNibbles, kernels.hpp).

// Stores the lanes of v selected by m, in order, at out (writing a whole vector) and returns
// how many there are.
template <class D, class V, class M>
HWY_INLINE std::size_t compressStore32(D d, V v, M m, hn::TFromD<D>* out) {
#if HWY_TARGET == HWY_AVX3 || HWY_TARGET == HWY_AVX3_DL
  // Compress in a register, then store: the memory form of vpcompressd is microcoded and slow
  // on AMD Zen 4.
  hn::StoreU(hn::Compress(v, m), d, out);
  return hn::CountTrue(d, m);
#else
  static_assert(hn::MaxLanes(D()) <= 8, "the nibble table covers 8 lanes");
  const hn::RebindToUnsigned<D> du;
  std::uint8_t bits[8] = {};
  hn::StoreMaskBits(d, m, bits);
  const auto shifts = hn::ShiftLeft<2>(hn::Iota(du, 0));
  const auto lanes =
      hn::And(hn::Shr(hn::Set(du, kCompressNibbles[bits[0]]), shifts), hn::Set(du, 0xFu));
  hn::StoreU(hn::TableLookupLanes(v, hn::IndicesFromVec(d, lanes)), d, out);
  return std::size_t(__builtin_popcount(bits[0]));
#endif
}

// Writes the indices i < padded (ascending) of the lanes where `keep(d, i)` holds to `out`, which
// has room for `padded` indices, and returns how many. The selection loop of every kernel that
// answers "which elements of this stream ...".
template <class Keep>
std::size_t selectIndices(std::size_t padded, std::uint32_t* out, Keep keep) {
  const hn::ScalableTag<float> d;
  const hn::RebindToUnsigned<decltype(d)> du;
  const std::size_t n = hn::Lanes(d);
  auto index = hn::Iota(du, 0);
  std::size_t count = 0;
  for (std::size_t i = 0; i < padded; i += n) {
    count += compressStore32(du, index, hn::RebindMask(du, keep(d, i)), out + count);
    index = hn::Add(index, hn::Set(du, static_cast<std::uint32_t>(n)));
  }
  return count;
}
