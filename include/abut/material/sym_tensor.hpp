#pragma once
// Small 3x3 tensors for material-point kernels: a symmetric tensor in 6 components and a
// general tensor in 9 (row-major). Plain aggregates so that element kernels keep them in
// registers; no allocation.
#include <array>

namespace abut {

// Symmetric tensor, components in the order xx, yy, zz, xy, yz, zx.
struct Sym3 {
  std::array<double, 6> c{};
  double& operator[](int i) { return c[i]; }
  double operator[](int i) const { return c[i]; }
};

// General tensor, row-major: m[3*i + j] = A_ij.
using Mat3 = std::array<double, 9>;

inline double trace(const Sym3& s) { return s[0] + s[1] + s[2]; }

inline Sym3 add(const Sym3& a, const Sym3& b) {
  Sym3 s;
  for (int i = 0; i < 6; ++i) s[i] = a[i] + b[i];
  return s;
}

// Deviatoric part s - tr(s)/3 I.
inline Sym3 deviator(const Sym3& s) {
  const double mean = trace(s) / 3.0;
  return {{s[0] - mean, s[1] - mean, s[2] - mean, s[3], s[4], s[5]}};
}

// Full contraction a:b.
inline double double_dot(const Sym3& a, const Sym3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + 2.0 * (a[3] * b[3] + a[4] * b[4] + a[5] * b[5]);
}

// von Mises equivalent stress sqrt(3/2 s:s) with s the deviator.
double von_mises(const Sym3& stress);

// Q S Q^T (rotation of a symmetric tensor by the orthogonal Q).
Sym3 rotate(const Mat3& q, const Sym3& s);

// Rotation increment of Hughes and Winget (1980, IJNME 15:1862, eq. 29): the Cayley transform
// Q = (I - W dt/2)^-1 (I + W dt/2) of the spin W, written in closed form with the axial vector
// w of W dt/2: Q = I + 2 (Omega + Omega^2) / (1 + |w|^2), Omega = skew(w). Exactly orthogonal,
// and exactly the incremental rotation when W is the mid-step spin of a rigid rotation.
Mat3 cayley_rotation(const Mat3& half_step_spin);

// Eigen-decomposition of a symmetric tensor by cyclic Jacobi rotations (Golub and Van Loan,
// Matrix Computations, 4th ed., §8.5). vectors[3*i + k] is component i of eigenvector k.
struct SymEigen {
  std::array<double, 3> values{};
  Mat3 vectors{};
};
SymEigen eigen_symmetric(const Sym3& s);

// sum_k value_k n_k (x) n_k from a spectral representation.
Sym3 from_spectral(const std::array<double, 3>& values, const Mat3& vectors);

}  // namespace abut
