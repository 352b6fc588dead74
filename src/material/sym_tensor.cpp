#include "abut/material/sym_tensor.hpp"

#include <cmath>

namespace abut {

double von_mises(const Sym3& stress) {
  const Sym3 s = deviator(stress);
  return std::sqrt(1.5 * double_dot(s, s));
}

Sym3 rotate(const Mat3& q, const Sym3& s) {
  Sym3 out;
  rotate_sym(q.data(), s.c.data(), out.c.data());
  return out;
}

Mat3 cayley_rotation(const Mat3& half_step_spin) {
  Mat3 q;
  cayley_rotation_of(half_step_spin.data(), q.data());
  return q;
}

SymEigen eigen_symmetric(const Sym3& s) {
  double a[3][3] = {{s[0], s[3], s[5]}, {s[3], s[1], s[4]}, {s[5], s[4], s[2]}};
  double v[3][3] = {{1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}};
  constexpr int pairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};
  const double scale = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2] +
                       2.0 * (a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2]);
  // Jacobi converges quadratically; a 3x3 needs about four sweeps to reach round-off.
  for (int sweep = 0; sweep < 32; ++sweep) {
    const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
    if (off <= 1e-34 * scale) break;
    for (const auto& pq : pairs) {
      const int p = pq[0], q = pq[1];
      if (a[p][q] == 0.0) continue;
      // Rotation angle that annihilates a_pq (Golub and Van Loan, Algorithm 8.5.1): the
      // smaller root t = tan(theta) of t^2 + 2 tau t - 1 = 0.
      const double tau = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
      const double t = (tau >= 0.0 ? 1.0 : -1.0) / (std::abs(tau) + std::sqrt(1.0 + tau * tau));
      const double c = 1.0 / std::sqrt(1.0 + t * t);
      const double sn = t * c;
      for (int k = 0; k < 3; ++k) {  // A <- A J
        const double akp = a[k][p], akq = a[k][q];
        a[k][p] = c * akp - sn * akq;
        a[k][q] = sn * akp + c * akq;
      }
      for (int k = 0; k < 3; ++k) {  // A <- J^T A
        const double apk = a[p][k], aqk = a[q][k];
        a[p][k] = c * apk - sn * aqk;
        a[q][k] = sn * apk + c * aqk;
      }
      for (int k = 0; k < 3; ++k) {  // V <- V J
        const double vkp = v[k][p], vkq = v[k][q];
        v[k][p] = c * vkp - sn * vkq;
        v[k][q] = sn * vkp + c * vkq;
      }
    }
  }
  SymEigen out;
  for (int k = 0; k < 3; ++k) {
    out.values[k] = a[k][k];
    for (int i = 0; i < 3; ++i) out.vectors[3 * i + k] = v[i][k];
  }
  return out;
}

Sym3 from_spectral(const std::array<double, 3>& values, const Mat3& n) {
  Sym3 s;
  constexpr int row[6] = {0, 1, 2, 0, 1, 2};
  constexpr int col[6] = {0, 1, 2, 1, 2, 0};
  for (int c = 0; c < 6; ++c) {
    const int i = row[c], j = col[c];
    s[c] = values[0] * n[3 * i] * n[3 * j] + values[1] * n[3 * i + 1] * n[3 * j + 1] +
           values[2] * n[3 * i + 2] * n[3 * j + 2];
  }
  return s;
}

}  // namespace abut
