#include "abut/element/stable_step.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace abut {

namespace {

// Largest eigenvalue of a symmetric 3x3 matrix (closed form; O. K. Smith, "Eigenvalues of a
// symmetric 3x3 matrix", Comm. ACM 4(4), 1961).
double largest_eigenvalue(double a00, double a11, double a22, double a01, double a12, double a02) {
  const double off = a01 * a01 + a12 * a12 + a02 * a02;
  const double q = (a00 + a11 + a22) / 3.0;
  if (off <= 1e-300) return std::max({a00, a11, a22});
  const double b00 = a00 - q, b11 = a11 - q, b22 = a22 - q;
  const double p = std::sqrt((b00 * b00 + b11 * b11 + b22 * b22 + 2.0 * off) / 6.0);
  const double det =
      b00 * (b11 * b22 - a12 * a12) - a01 * (a01 * b22 - a12 * a02) + a02 * (a01 * a12 - b11 * a02);
  const double r = std::clamp(det / (2.0 * p * p * p), -1.0, 1.0);
  return q + 2.0 * p * std::cos(std::acos(r) / 3.0);
}

// G = sum_a b_a b_a^T given by its six components.
double critical_length(double gxx, double gyy, double gzz, double gxy, double gyz, double gxz,
                       double volume, double lambda, double mu) {
  const double trace = gxx + gyy + gzz;
  const double largest = largest_eigenvalue(gxx, gyy, gzz, gxy, gyz, gxz);
  // A negative lambda (nu < 0) only lowers lambda (tr eps)^2: leave it out, conservatively.
  const double stiffness = std::max(lambda, 0.0) * trace + 2.0 * mu * largest;
  return volume * std::sqrt((lambda + 2.0 * mu) / (2.0 * stiffness));
}

}  // namespace

double hex8_critical_length(const Hex8ModalGradient& g, double lambda, double mu) {
  double gxx = 0, gyy = 0, gzz = 0, gxy = 0, gyz = 0, gxz = 0;
  for (int k = 1; k < 7; ++k) {
    gxx += g.gx[k] * g.gx[k];
    gyy += g.gy[k] * g.gy[k];
    gzz += g.gz[k] * g.gz[k];
    gxy += g.gx[k] * g.gy[k];
    gyz += g.gy[k] * g.gz[k];
    gxz += g.gx[k] * g.gz[k];
  }
  return critical_length(8 * gxx, 8 * gyy, 8 * gzz, 8 * gxy, 8 * gyz, 8 * gxz, g.volume, lambda,
                         mu);
}

Hex8ModalGradient hex8_modal_gradient_at(const Hex8& hex, const Nodes& nodes) {
  Hex8Coords x;
  for (int a = 0; a < 8; ++a) {
    const auto node = static_cast<std::size_t>(hex[a]);
    x.x[a] = nodes.x[node];
    x.y[a] = nodes.y[node];
    x.z[a] = nodes.z[node];
  }
  Hex8Modes c;
  hex8_to_modes(x.x, c.x);
  hex8_to_modes(x.y, c.y);
  hex8_to_modes(x.z, c.z);
  Hex8ModalGradient g;
  hex8_modal_gradient(c, g);
  return g;
}

}  // namespace abut
