// The one view of a stream that kernels take: a pointer per field, named by the stream's layout
// (simdphys/stream_fields.hpp), the live count and the padded count. Plain pointers only, so it
// crosses from the library (src/) to the kernels (simd/) with no Eigen and no Highway type.
#pragma once

#include <cstddef>

namespace simdphys::core {

// Fields: a layout of stream_fields.hpp. T: const float to read (any code), float for the
// stream's owner writing in place. Arrays hold `padded` elements (a multiple of kStreamPad);
// those from `count` on are the layout's inert padding, so kernels read whole vectors.
template <class Fields, class T = const float>
struct View {
  T* field[Fields::kCount];
  std::size_t count, padded;

  T* operator[](std::size_t f) const { return field[f]; }
};

}  // namespace simdphys::core
