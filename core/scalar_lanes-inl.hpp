// One float as a lane, for the lane-generic kernels of core/ (ray_slab-inl.hpp) run by scalar
// code: the Highway operations they call, with the same results on one lane (Max and Min as x86's
// maxps and minps: the second operand unless the first is greater, or smaller). Included inside
// the includer's namespace before them (no include guard, by design), after <cmath> and
// <cstddef>: for vectors argument-dependent lookup finds Highway's own. A mask is a bool.

struct ScalarLane {};  // the "descriptor" of a one-float lane
inline float Set(ScalarLane, float x) { return x; }
inline float Zero(ScalarLane) { return 0.0f; }
inline std::size_t Lanes(ScalarLane) { return 1; }
inline bool FirstN(ScalarLane, std::size_t n) { return n > 0; }
inline float LoadU(ScalarLane, const float* p) { return *p; }
inline float Load(ScalarLane, const float* p) { return *p; }
inline void StoreU(float x, ScalarLane, float* p) { *p = x; }
inline void Store(float x, ScalarLane, float* p) { *p = x; }
inline float Sub(float a, float b) { return a - b; }
inline float Mul(float a, float b) { return a * b; }
inline float Max(float a, float b) { return a > b ? a : b; }
inline float Min(float a, float b) { return a < b ? a : b; }
inline bool Gt(float a, float b) { return a > b; }
inline bool Lt(float a, float b) { return a < b; }
inline bool Le(float a, float b) { return a <= b; }
inline bool Ge(float a, float b) { return a >= b; }
inline bool Eq(float a, float b) { return a == b; }
inline float Neg(float x) { return -x; }
inline float Abs(float x) { return std::abs(x); }
inline float Sqrt(float x) { return std::sqrt(x); }
inline bool And(bool a, bool b) { return a & b; }
inline bool Or(bool a, bool b) { return a | b; }
inline bool Not(bool a) { return !a; }
inline bool AllFalse(ScalarLane, bool m) { return !m; }
inline bool AllTrue(ScalarLane, bool m) { return m; }
inline std::size_t CountTrue(ScalarLane, bool m) { return m; }
inline float IfThenElse(bool m, float a, float b) { return m ? a : b; }
// Fused where the includer's Highway target has FMA (as Highway's own are), else a product and
// a sum.
#if defined(HWY_NATIVE_FMA) && HWY_NATIVE_FMA
inline float MulAdd(float m, float x, float a) { return std::fma(m, x, a); }
inline float MulSub(float m, float x, float s) { return std::fma(m, x, -s); }
inline float NegMulAdd(float m, float x, float a) { return std::fma(-m, x, a); }
#else
inline float MulAdd(float m, float x, float a) { return m * x + a; }
inline float MulSub(float m, float x, float s) { return m * x - s; }
inline float NegMulAdd(float m, float x, float a) { return a - m * x; }
#endif
