// geometry2d/quadtree.hpp, compiled once: the quadtree for float and double.
#include "src/reference/geometry2d/quadtree-inl.hpp"

namespace simdphys {

template class QuadtreeT<float>;
template class QuadtreeT<double>;

}  // namespace simdphys
