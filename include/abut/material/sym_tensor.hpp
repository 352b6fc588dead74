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

// Deviatoric part s - tr(s)/3 I; on plain arrays in Sym3 order for T = double or Lanes
// (lanes.hpp).
template <class T>
inline void deviator_of(const T s[6], T out[6]) {
  const T mean = (s[0] + s[1] + s[2]) / 3.0;
  for (int i = 0; i < 3; ++i) out[i] = s[i] - mean;
  for (int i = 3; i < 6; ++i) out[i] = s[i];
}
inline Sym3 deviator(const Sym3& s) {
  Sym3 d;
  deviator_of(s.c.data(), d.c.data());
  return d;
}

// Full contraction a:b; on plain arrays as above.
template <class T>
inline T double_dot_of(const T a[6], const T b[6]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + 2.0 * (a[3] * b[3] + a[4] * b[4] + a[5] * b[5]);
}
inline double double_dot(const Sym3& a, const Sym3& b) {
  return double_dot_of(a.c.data(), b.c.data());
}

// von Mises equivalent stress sqrt(3/2 s:s) with s the deviator.
double von_mises(const Sym3& stress);

// Q S Q^T (rotation of a symmetric tensor by the orthogonal Q).
Sym3 rotate(const Mat3& q, const Sym3& s);

// The same on plain arrays (s and out in Sym3 order, q row-major), for T = double or Lanes
// (lanes.hpp): rotate() is this with T = double.
template <class T>
inline void rotate_sym(const T q[9], const T s[6], T out[6]) {
  const T a[9] = {s[0], s[3], s[5], s[3], s[1], s[4], s[5], s[4], s[2]};
  T qa[9];
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      qa[3 * i + j] = q[3 * i] * a[j] + q[3 * i + 1] * a[3 + j] + q[3 * i + 2] * a[6 + j];
    }
  }
  const auto entry = [&](int i, int j) {
    return qa[3 * i] * q[3 * j] + qa[3 * i + 1] * q[3 * j + 1] + qa[3 * i + 2] * q[3 * j + 2];
  };
  out[0] = entry(0, 0);
  out[1] = entry(1, 1);
  out[2] = entry(2, 2);
  out[3] = entry(0, 1);
  out[4] = entry(1, 2);
  out[5] = entry(2, 0);
}

// Rotation increment of Hughes and Winget (1980, IJNME 15:1862, eq. 29): the Cayley transform
// Q = (I - W dt/2)^-1 (I + W dt/2) of the spin W, written in closed form with the axial vector
// w of W dt/2: Q = I + 2 (Omega + Omega^2) / (1 + |w|^2), Omega = skew(w). Exactly orthogonal,
// and exactly the incremental rotation when W is the mid-step spin of a rigid rotation.
Mat3 cayley_rotation(const Mat3& half_step_spin);

// The same on plain arrays, for T = double or Lanes: cayley_rotation() is this with T = double.
template <class T>
inline void cayley_rotation_of(const T half_step_spin[9], T q[9]) {
  // Axial vector of the skew tensor W dt/2: W_32, W_13, W_21.
  const T wx = half_step_spin[7], wy = half_step_spin[2], wz = half_step_spin[3];
  const T zero{};
  const T omega[9] = {zero, -wz, wy, wz, zero, -wx, -wy, wx, zero};
  const T factor = 2.0 / (1.0 + wx * wx + wy * wy + wz * wz);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const T omega2 = omega[3 * i] * omega[j] + omega[3 * i + 1] * omega[3 + j] +
                       omega[3 * i + 2] * omega[6 + j];
      q[3 * i + j] = (i == j ? 1.0 : 0.0) + factor * (omega[3 * i + j] + omega2);
    }
  }
}

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
