// The isoparametric solid element of any cell type: see solid_full.hpp. The steps are those of
// hex8_full.cpp (small strain: eps = B u, f = int B^T sigma dV, K = int B^T D B dV; NLGEOM: the
// total Lagrangian form with the material and geometric stiffness) with the shape functions and
// the rule of the cell.
#include "abut/element/solid_full.hpp"

#include <algorithm>

#include "abut/material/j2_strain_point.hpp"

namespace abut {
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

template <Hex8MaterialPoint M>
void solid_full_with(const SolidElementInput& in, const M& material, SolidElementResult& out) {
  const int nodes = topology(in.type).nodes;
  const int dofs = 3 * nodes;
  const auto points = static_cast<int>(in.points.size());
  out.force.assign(static_cast<std::size_t>(dofs), 0.0);
  out.stiffness.assign(static_cast<std::size_t>(dofs) * static_cast<std::size_t>(dofs), 0.0);
  out.stress.resize(6 * static_cast<std::size_t>(points));
  out.strain.resize(6 * static_cast<std::size_t>(points));
  out.energy_density.resize(static_cast<std::size_t>(points));
  double n[kMaxCellNodes], dn[kMaxCellNodes][3], grad[kMaxCellNodes][3];
  out.work.resize(12 * static_cast<std::size_t>(dofs));
  double* b = out.work.data();  // B, b[r * dofs + c]
  double* db = b + 6 * dofs;    // D B dV
  out.strain_energy = 0.0;
  out.volume = 0.0;
  out.min_jacobian = 0.0;
  const bool nl = in.nonlinear_geometry;
  const double* u = in.u.data();

  for (int p = 0; p < points; ++p) {
    const QuadraturePoint& q = in.points[static_cast<std::size_t>(p)];
    const double det0 = shape_gradients(in.type, in.X, q.xi, n, dn, grad);
    const double dv = det0 * q.weight;

    // Displacement gradient H_ij = du_i/dX_j; F = I + H.
    double h[3][3] = {};
    for (int a = 0; a < nodes; ++a)
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) h[i][j] += u[3 * a + i] * grad[a][j];
    // delta strain = B delta u with B[r][3a + i] = f[i][I] g_aJ + f[i][J] g_aI for the Voigt row
    // r = (I, J) (halved on the diagonal): small strain f = I; NLGEOM f = F.
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
    const double w = material.evaluate(p, strain, stress, d);
    out.strain_energy += w * dv;
    out.energy_density[static_cast<std::size_t>(p)] = w;
    std::copy(strain, strain + 6, &out.strain[6 * static_cast<std::size_t>(p)]);

    for (int a = 0; a < nodes; ++a) {
      const double* g = grad[a];
      for (int i = 0; i < 3; ++i) {
        const int c = 3 * a + i;
        b[0 * dofs + c] = f[i][0] * g[0];
        b[1 * dofs + c] = f[i][1] * g[1];
        b[2 * dofs + c] = f[i][2] * g[2];
        b[3 * dofs + c] = f[i][0] * g[1] + f[i][1] * g[0];
        b[4 * dofs + c] = f[i][1] * g[2] + f[i][2] * g[1];
        b[5 * dofs + c] = f[i][2] * g[0] + f[i][0] * g[2];
      }
    }
    for (int c = 0; c < dofs; ++c) {
      double s = 0.0;
      for (int r = 0; r < 6; ++r) s += b[r * dofs + c] * stress[r];
      out.force[static_cast<std::size_t>(c)] += s * dv;
    }
    for (int r = 0; r < 6; ++r)
      for (int c = 0; c < dofs; ++c) {
        double s = 0.0;
        for (int k = 0; k < 6; ++k) s += d[6 * r + k] * b[k * dofs + c];
        db[r * dofs + c] = s * dv;
      }
    double* k = out.stiffness.data();
    for (int m = 0; m < dofs; ++m)
      for (int c = m; c < dofs; ++c) {
        double s = 0.0;
        for (int r = 0; r < 6; ++r) s += b[r * dofs + m] * db[r * dofs + c];
        k[m * dofs + c] += s;
      }

    double* sigma = &out.stress[6 * static_cast<std::size_t>(p)];
    if (nl) {
      // Geometric stiffness: K_(ai)(bj) += (grad N_a . S grad N_b) delta_ij dV0.
      const double s3[3][3] = {{stress[0], stress[3], stress[5]},
                               {stress[3], stress[1], stress[4]},
                               {stress[5], stress[4], stress[2]}};
      for (int a = 0; a < nodes; ++a)
        for (int bn = a; bn < nodes; ++bn) {
          double kg = 0.0;
          for (int i = 0; i < 3; ++i)
            kg += grad[a][i] *
                  (s3[i][0] * grad[bn][0] + s3[i][1] * grad[bn][1] + s3[i][2] * grad[bn][2]);
          kg *= dv;
          for (int i = 0; i < 3; ++i) k[(3 * a + i) * dofs + 3 * bn + i] += kg;
        }
      // Cauchy stress sigma = F S F^T / det F; current Jacobian det F det J0.
      const double detf = det3(f);
      double fs[3][3];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          fs[i][j] = f[i][0] * s3[0][j] + f[i][1] * s3[1][j] + f[i][2] * s3[2][j];
      for (int r = 0; r < 6; ++r) {
        const int i = kVoigtI[r], j = kVoigtJ[r];
        sigma[r] = (fs[i][0] * f[j][0] + fs[i][1] * f[j][1] + fs[i][2] * f[j][2]) / detf;
      }
      const double det = detf * det0;
      out.min_jacobian = p == 0 ? det : std::min(out.min_jacobian, det);
      out.volume += det * q.weight;
    } else {
      std::copy(stress, stress + 6, sigma);
      out.min_jacobian = p == 0 ? det0 : std::min(out.min_jacobian, det0);
      out.volume += dv;
    }
  }

  // Mirror the upper triangle: K is symmetric for a material with a symmetric tangent.
  double* k = out.stiffness.data();
  for (int m = 0; m < dofs; ++m)
    for (int c = 0; c < m; ++c) k[m * dofs + c] = k[c * dofs + m];
}

template void solid_full_with<IsotropicElastic>(const SolidElementInput&, const IsotropicElastic&,
                                                SolidElementResult&);
template void solid_full_with<J2StrainPoint>(const SolidElementInput&, const J2StrainPoint&,
                                             SolidElementResult&);

}  // namespace abut
