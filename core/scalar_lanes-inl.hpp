// One float as a lane, for the lane-generic kernels of core/ (ray_slab-inl.hpp) run by scalar
// code: the Highway operations they call, with the same results on one lane (Max and Min as x86's
// maxps and minps: the second operand unless the first is greater, or smaller). Included inside
// the includer's namespace before them (no include guard, by design): for vectors argument-
// dependent lookup finds Highway's own.

struct ScalarLane {};  // the "descriptor" of a one-float lane
inline float Set(ScalarLane, float x) { return x; }
inline float Zero(ScalarLane) { return 0.0f; }
inline float Sub(float a, float b) { return a - b; }
inline float Mul(float a, float b) { return a * b; }
inline float Max(float a, float b) { return a > b ? a : b; }
inline float Min(float a, float b) { return a < b ? a : b; }
inline bool Gt(float a, float b) { return a > b; }
inline bool Lt(float a, float b) { return a < b; }
inline bool Le(float a, float b) { return a <= b; }
inline float IfThenElse(bool m, float a, float b) { return m ? a : b; }
