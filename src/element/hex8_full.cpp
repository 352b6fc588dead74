// The fully integrated hexahedron (C3D8): see hex8_full.hpp for the formulation and conventions.
#include "abut/element/hex8_full.hpp"

#include <algorithm>

#include "abut/element/hex8.hpp"
#include "abut/element/hex8_gauss.hpp"
#include "abut/material/j2_strain_point.hpp"
#include "abut/mesh/shape_functions.hpp"

namespace abut {

// ---- Material point ------------------------------------------------------------------------

void IsotropicElastic::stress(const double strain[6], double out[6]) const {
  const double mu = young / (2.0 * (1.0 + poisson));
  const double lambda = young * poisson / ((1.0 + poisson) * (1.0 - 2.0 * poisson));
  const double volumetric = lambda * (strain[0] + strain[1] + strain[2]);
  for (int i = 0; i < 3; ++i) out[i] = volumetric + 2.0 * mu * strain[i];
  for (int i = 3; i < 6; ++i) out[i] = mu * strain[i];  // engineering shear: tau = mu gamma
}

void IsotropicElastic::tangent(double d[36]) const {
  const double mu = young / (2.0 * (1.0 + poisson));
  const double lambda = young * poisson / ((1.0 + poisson) * (1.0 - 2.0 * poisson));
  std::fill(d, d + 36, 0.0);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) d[6 * i + j] = lambda;
    d[6 * i + i] = lambda + 2.0 * mu;
  }
  for (int i = 3; i < 6; ++i) d[6 * i + i] = mu;
}

double IsotropicElastic::evaluate(int /*point*/, const double strain[6], double stress_out[6],
                                  double d[36]) const {
  stress(strain, stress_out);
  tangent(d);
  double w = 0.0;
  for (int i = 0; i < 6; ++i) w += stress_out[i] * strain[i];
  return 0.5 * w;
}

// ---- Element ---------------------------------------------------------------------------------

namespace {

double det3(const double m[3][3]) {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
         m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

// Voigt rows (xx yy zz xy yz zx) as index pairs of the symmetric tensor.
constexpr int kVoigtI[6] = {0, 1, 2, 0, 1, 2};
constexpr int kVoigtJ[6] = {0, 1, 2, 1, 2, 0};

}  // namespace

double hex8_gauss_gradient(const double X[8][3], int p, double grad[8][3]) {
  return natural_to_spatial(8, kHex8GaussTable.dn[p], &X[0][0], grad);
}

template <Hex8MaterialPoint M>
void hex8_full_with(const Hex8FullInput& in, const M& material, Hex8FullResult& out) {
  std::fill(out.force, out.force + 24, 0.0);
  std::fill(out.stiffness, out.stiffness + 24 * 24, 0.0);
  out.strain_energy = 0.0;
  out.volume = 0.0;
  out.min_jacobian = 0.0;
  const bool nl = in.nonlinear_geometry;

  for (int p = 0; p < 8; ++p) {
    double grad[8][3];
    const double det0 = hex8_gauss_gradient(in.X, p, grad);
    const double dv = det0;  // Gauss weight 1

    // Displacement gradient H_ij = du_i/dX_j; F = I + H.
    double h[3][3] = {};
    for (int a = 0; a < 8; ++a)
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) h[i][j] += in.u[a][i] * grad[a][j];
    // Operator between nodal displacements and the strain: delta strain = B delta u, with
    // B[r][3a + i] = f[i][I] g_aJ + f[i][J] g_aI for the Voigt row r = (I, J) (halved on the
    // diagonal): small strain f = I; NLGEOM f = F (delta E = sym(F^T grad delta u)).
    double f[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) f[i][j] = (i == j ? 1.0 : 0.0) + (nl ? h[i][j] : 0.0);

    double strain[6];
    for (int r = 0; r < 6; ++r) {
      const int i = kVoigtI[r], j = kVoigtJ[r];
      double e = h[i][j] + h[j][i];  // engineering: the tensor component times 2 for shears
      if (nl) e += h[0][i] * h[0][j] + h[1][i] * h[1][j] + h[2][i] * h[2][j];
      strain[r] = r < 3 ? 0.5 * e : e;
    }

    double stress[6], d[36];
    const double w = material.evaluate(p, strain, stress, d);
    out.strain_energy += w * dv;
    out.energy_density[p] = w;
    for (int r = 0; r < 6; ++r) out.strain[p][r] = strain[r];

    double b[6][24];
    for (int a = 0; a < 8; ++a) {
      const double* g = grad[a];
      for (int i = 0; i < 3; ++i) {
        const int c = 3 * a + i;
        b[0][c] = f[i][0] * g[0];
        b[1][c] = f[i][1] * g[1];
        b[2][c] = f[i][2] * g[2];
        b[3][c] = f[i][0] * g[1] + f[i][1] * g[0];
        b[4][c] = f[i][1] * g[2] + f[i][2] * g[1];
        b[5][c] = f[i][2] * g[0] + f[i][0] * g[2];
      }
    }

    // f += B^T stress dV.
    for (int c = 0; c < 24; ++c) {
      double s = 0.0;
      for (int r = 0; r < 6; ++r) s += b[r][c] * stress[r];
      out.force[c] += s * dv;
    }

    // K += B^T D B dV (upper triangle; mirrored at the end).
    double db[6][24];
    for (int r = 0; r < 6; ++r)
      for (int c = 0; c < 24; ++c) {
        double s = 0.0;
        for (int k = 0; k < 6; ++k) s += d[6 * r + k] * b[k][c];
        db[r][c] = s * dv;
      }
    for (int m = 0; m < 24; ++m)
      for (int n = m; n < 24; ++n) {
        double s = 0.0;
        for (int r = 0; r < 6; ++r) s += b[r][m] * db[r][n];
        out.stiffness[24 * m + n] += s;
      }

    if (nl) {
      // Geometric stiffness: K_(ai)(bj) += (grad N_a . S grad N_b) delta_ij dV0.
      const double s3[3][3] = {{stress[0], stress[3], stress[5]},
                               {stress[3], stress[1], stress[4]},
                               {stress[5], stress[4], stress[2]}};
      double sg[8][3];  // S grad N_b
      for (int bn = 0; bn < 8; ++bn)
        for (int i = 0; i < 3; ++i)
          sg[bn][i] = s3[i][0] * grad[bn][0] + s3[i][1] * grad[bn][1] + s3[i][2] * grad[bn][2];
      for (int a = 0; a < 8; ++a)
        for (int bn = a; bn < 8; ++bn) {
          const double kg =
              (grad[a][0] * sg[bn][0] + grad[a][1] * sg[bn][1] + grad[a][2] * sg[bn][2]) * dv;
          for (int i = 0; i < 3; ++i) out.stiffness[24 * (3 * a + i) + 3 * bn + i] += kg;
        }

      // Cauchy stress sigma = F S F^T / det F; current Jacobian det(dx/dxi) = det F det J0.
      const double detf = det3(f);
      double fs[3][3];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          fs[i][j] = f[i][0] * s3[0][j] + f[i][1] * s3[1][j] + f[i][2] * s3[2][j];
      for (int r = 0; r < 6; ++r) {
        const int i = kVoigtI[r], j = kVoigtJ[r];
        out.stress[p][r] = (fs[i][0] * f[j][0] + fs[i][1] * f[j][1] + fs[i][2] * f[j][2]) / detf;
      }
      const double det = detf * det0;
      out.min_jacobian = p == 0 ? det : std::min(out.min_jacobian, det);
      out.volume += det;
    } else {
      for (int r = 0; r < 6; ++r) out.stress[p][r] = stress[r];
      out.min_jacobian = p == 0 ? det0 : std::min(out.min_jacobian, det0);
      out.volume += det0;
    }
  }

  // Mirror the upper triangle: K is symmetric for a material with a symmetric tangent.
  for (int m = 0; m < 24; ++m)
    for (int n = 0; n < m; ++n) out.stiffness[24 * m + n] = out.stiffness[24 * n + m];
}

template void hex8_full_with<IsotropicElastic>(const Hex8FullInput&, const IsotropicElastic&,
                                               Hex8FullResult&);
template void hex8_full_with<J2StrainPoint>(const Hex8FullInput&, const J2StrainPoint&,
                                            Hex8FullResult&);

void hex8_full(const Hex8FullInput& in, const IsotropicElastic& material, Hex8FullResult& out) {
  hex8_full_with(in, material, out);
}

}  // namespace abut
