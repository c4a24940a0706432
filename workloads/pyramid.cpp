// W5's pyramid (pyramid.hpp).
#include "pyramid.hpp"

#include <algorithm>

namespace simdphys::workloads {

std::vector<Vec3f> pyramidCenters(int base) {
  std::vector<Vec3f> centers;
  centers.reserve(pyramidBoxCount(base));
  for (int k = 0; k < base; ++k) {
    const int n = base - k;
    // Centred on the y axis: n boxes of pitch 1 span [-n/2, n/2].
    const double first = -0.5 * double(n - 1);
    for (int row = 0; row < n; ++row)
      for (int col = 0; col < n; ++col)
        centers.emplace_back(float(first + col), float(0.5 + k), float(first + row));
  }
  return centers;
}

PyramidMeasures measurePyramid(std::span<const Vec3f> start, std::span<const Vec3f> end) {
  PyramidMeasures m;
  for (std::size_t i = 0; i < start.size(); ++i) {
    const double d = (end[i].cast<double>() - start[i].cast<double>()).norm();
    m.maxDisplacement = std::max(m.maxDisplacement, d);
    if (!(d <= 0.5)) m.standing = false;
  }
  return m;
}

}  // namespace simdphys::workloads
