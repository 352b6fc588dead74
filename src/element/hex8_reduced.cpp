// The one-point hexahedron of the implicit solver (C3D8R): see hex8_reduced.hpp.
#include "abut/element/hex8_reduced.hpp"

#include <algorithm>

#include "abut/element/hex8.hpp"
#include "abut/material/j2_strain_point.hpp"

namespace abut {

namespace {

constexpr int kVoigtI[6] = {0, 1, 2, 0, 1, 2};
constexpr int kVoigtJ[6] = {0, 1, 2, 1, 2, 0};

double det3(const double m[3][3]) {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
         m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

}  // namespace

template <Hex8MaterialPoint M>
void hex8_reduced_with(const Hex8FullInput& in, const M& material, double hourglass_modulus,
                       Hex8FullResult& out) {
  std::fill(out.force, out.force + 24, 0.0);
  std::fill(out.stiffness, out.stiffness + 24 * 24, 0.0);
  const bool nl = in.nonlinear_geometry;

  Hex8Coords x;
  for (int a = 0; a < 8; ++a) x.x[a] = in.X[a][0], x.y[a] = in.X[a][1], x.z[a] = in.X[a][2];
  Hex8Gradient g;
  hex8_gradient(x, g);
  const double v0 = g.volume;
  double grad[8][3];  // mean gradient b_a / V0
  double bb = 0.0;
  for (int a = 0; a < 8; ++a) {
    grad[a][0] = g.bx[a] / v0, grad[a][1] = g.by[a] / v0, grad[a][2] = g.bz[a] / v0;
    bb += g.bx[a] * g.bx[a] + g.by[a] * g.by[a] + g.bz[a] * g.bz[a];
  }

  // The point: as one Gauss point of hex8_full_with, weight V0.
  double h[3][3] = {};
  for (int a = 0; a < 8; ++a)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) h[i][j] += in.u[a][i] * grad[a][j];
  double f[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) f[i][j] = (i == j ? 1.0 : 0.0) + (nl ? h[i][j] : 0.0);
  double strain[6];
  for (int r = 0; r < 6; ++r) {
    const int i = kVoigtI[r], j = kVoigtJ[r];
    double e = h[i][j] + h[j][i];
    if (nl) e += h[0][i] * h[0][j] + h[1][i] * h[1][j] + h[2][i] * h[2][j];
    strain[r] = r < 3 ? 0.5 * e : e;
  }
  double stress[6], d[36];
  const double w = material.evaluate(0, strain, stress, d);
  out.strain_energy = w * v0;
  for (double& density : out.energy_density) density = w;

  double b[6][24];
  for (int a = 0; a < 8; ++a) {
    const double* ga = grad[a];
    for (int i = 0; i < 3; ++i) {
      const int c = 3 * a + i;
      b[0][c] = f[i][0] * ga[0];
      b[1][c] = f[i][1] * ga[1];
      b[2][c] = f[i][2] * ga[2];
      b[3][c] = f[i][0] * ga[1] + f[i][1] * ga[0];
      b[4][c] = f[i][1] * ga[2] + f[i][2] * ga[1];
      b[5][c] = f[i][2] * ga[0] + f[i][0] * ga[2];
    }
  }
  for (int c = 0; c < 24; ++c) {
    double s = 0.0;
    for (int r = 0; r < 6; ++r) s += b[r][c] * stress[r];
    out.force[c] = s * v0;
  }
  double db[6][24];
  for (int r = 0; r < 6; ++r)
    for (int c = 0; c < 24; ++c) {
      double s = 0.0;
      for (int k = 0; k < 6; ++k) s += d[6 * r + k] * b[k][c];
      db[r][c] = s * v0;
    }
  for (int m = 0; m < 24; ++m)
    for (int n = m; n < 24; ++n) {
      double s = 0.0;
      for (int r = 0; r < 6; ++r) s += b[r][m] * db[r][n];
      out.stiffness[24 * m + n] = s;
    }

  double cauchy[6];
  const double detf = nl ? det3(f) : 1.0;
  if (nl) {
    const double s3[3][3] = {{stress[0], stress[3], stress[5]},
                             {stress[3], stress[1], stress[4]},
                             {stress[5], stress[4], stress[2]}};
    for (int a = 0; a < 8; ++a)
      for (int bn = a; bn < 8; ++bn) {
        double kg = 0.0;
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) kg += grad[a][i] * s3[i][j] * grad[bn][j];
        for (int i = 0; i < 3; ++i) out.stiffness[24 * (3 * a + i) + 3 * bn + i] += kg * v0;
      }
    double fs[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        fs[i][j] = f[i][0] * s3[0][j] + f[i][1] * s3[1][j] + f[i][2] * s3[2][j];
    for (int r = 0; r < 6; ++r) {
      const int i = kVoigtI[r], j = kVoigtJ[r];
      cauchy[r] = (fs[i][0] * f[j][0] + fs[i][1] * f[j][1] + fs[i][2] * f[j][2]) / detf;
    }
  } else {
    std::copy(stress, stress + 6, cauchy);
  }
  for (int p = 0; p < 8; ++p)
    for (int r = 0; r < 6; ++r) out.stress[p][r] = cauchy[r], out.strain[p][r] = strain[r];
  out.min_jacobian = detf * v0 / 8.0;
  out.volume = detf * v0;

  // Hourglass stiffness with the reference gamma vectors.
  double gamma[4][8];
  hex8_hourglass_shape(g, gamma);
  const double k = hourglass_modulus * bb / v0;
  for (int alpha = 0; alpha < 4; ++alpha) {
    double q[3] = {0.0, 0.0, 0.0};
    for (int a = 0; a < 8; ++a)
      for (int i = 0; i < 3; ++i) q[i] += gamma[alpha][a] * in.u[a][i];
    for (int a = 0; a < 8; ++a) {
      for (int i = 0; i < 3; ++i) out.force[3 * a + i] += k * gamma[alpha][a] * q[i];
      for (int bn = a; bn < 8; ++bn) {
        const double kab = k * gamma[alpha][a] * gamma[alpha][bn];
        for (int i = 0; i < 3; ++i) out.stiffness[24 * (3 * a + i) + 3 * bn + i] += kab;
      }
    }
    out.strain_energy += 0.5 * k * (q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
  }

  for (int m = 0; m < 24; ++m)
    for (int n = 0; n < m; ++n) out.stiffness[24 * m + n] = out.stiffness[24 * n + m];
}

template void hex8_reduced_with<IsotropicElastic>(const Hex8FullInput&, const IsotropicElastic&,
                                                  double, Hex8FullResult&);
template void hex8_reduced_with<J2StrainPoint>(const Hex8FullInput&, const J2StrainPoint&, double,
                                               Hex8FullResult&);

}  // namespace abut
