#pragma once
// Several doubles processed as one SIMD vector (the GCC/Clang vector extension): arithmetic and
// comparisons act lane by lane, l[i] reads or writes lane i. Kernels written as templates over
// the value type (double or Lanes) evaluate kLanes elements at once with exactly the arithmetic
// of one, operation for operation, so results do not depend on which lane an element takes.
// The width follows the build's instruction set (CMake option ABUT_NATIVE): eight doubles with
// AVX-512, else four (without AVX the compiler splits them into SSE2 pairs). The results are the
// same for any width.
#include <cmath>

namespace abut {

#if defined(__AVX512F__)
inline constexpr int kLanes = 8;
#else
inline constexpr int kLanes = 4;
#endif
using Lanes = double __attribute__((vector_size(sizeof(double) * kLanes)));

// The few functions templates over double and Lanes need, lane by lane (min and max as std::min
// and std::max). A condition on Lanes is a vector of masks: `c ? a : b` selects lane by lane.
inline double sqrt_of(double x) { return std::sqrt(x); }
inline Lanes sqrt_of(Lanes x) {
  for (int l = 0; l < kLanes; ++l) x[l] = std::sqrt(x[l]);
  return x;
}
inline double pow_of(double x, double y) { return std::pow(x, y); }
inline Lanes pow_of(Lanes x, double y) {
  for (int l = 0; l < kLanes; ++l) x[l] = std::pow(x[l], y);
  return x;
}
template <class T>
inline T min_of(T a, T b) {
  return b < a ? b : a;
}
template <class T>
inline T max_of(T a, T b) {
  return a < b ? b : a;
}

}  // namespace abut
