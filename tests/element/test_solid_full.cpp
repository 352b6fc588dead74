// The isoparametric solid elements of every cell type (element/solid_full.hpp): shape functions
// and rules, the patch test on an irregular patch with interior nodes (MacNeal & Harder, "A
// proposed standard set of problems to test finite element accuracy", Finite Elements in Analysis
// and Design 1, 1985), the zero-energy modes of one element, agreement with the 8-node hexahedron
// of hex8_full.hpp, and the consistent tangent against finite differences.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "abut/element/hex8_full.hpp"
#include "abut/element/solid_full.hpp"
#include "abut/mesh/shape_functions.hpp"
#include "cell_grid.hpp"
#include "dense_checks.hpp"

namespace abut {
namespace {

constexpr IsotropicElastic kSteel{210000.0, 0.3};

struct Rule {
  CellType type;
  Integration integration;
  const char* name;
  int zero_modes;  // of one unconstrained element
};

// Zero-energy modes of one element: 6 rigid-body modes, plus for C3D20R the 6 of its 2x2x2 rule:
// 60 dofs minus at most 8 x 6 = 48 independent strains leaves at least 12 (Zienkiewicz, Taylor &
// Zhu 2013, section 6.11.2, the count of constraints per point); the element has no more.
constexpr Rule kRules[] = {{CellType::hex8, Integration::full, "C3D8", 6},
                           {CellType::hex20, Integration::full, "C3D20", 6},
                           {CellType::hex20, Integration::reduced, "C3D20R", 12},
                           {CellType::tet4, Integration::full, "C3D4", 6},
                           {CellType::tet10, Integration::full, "C3D10", 6},
                           {CellType::wedge6, Integration::full, "C3D6", 6},
                           {CellType::hex27, Integration::full, "hex27", 6},
                           {CellType::hex64, Integration::full, "hex64", 6}};

// ---- Shape functions and rules ---------------------------------------------------------------

TEST(ShapeFunctions, KroneckerPartitionOfUnityAndDerivatives) {
  for (const CellType type : kCellTypes) {
    const CellTopology& t = topology(type);
    SCOPED_TRACE(std::string(t.name));
    double n[kMaxCellNodes], dn[kMaxCellNodes][3];
    for (int b = 0; b < t.nodes; ++b) {
      shape_functions(type, t.natural[b].data(), n, dn);
      for (int a = 0; a < t.nodes; ++a) EXPECT_NEAR(n[a], a == b ? 1.0 : 0.0, 1e-15);
    }
    // At an arbitrary inner point: sum N = 1, sum dN = 0, dN by central differences.
    const double xi[3] = {0.21, 0.17, type == CellType::wedge6 ? -0.37 : 0.13};
    shape_functions(type, xi, n, dn);
    double sum = 0.0, dsum[3] = {0, 0, 0};
    for (int a = 0; a < t.nodes; ++a) {
      sum += n[a];
      for (int r = 0; r < 3; ++r) dsum[r] += dn[a][r];
    }
    EXPECT_NEAR(sum, 1.0, 1e-15);
    for (int r = 0; r < 3; ++r) EXPECT_NEAR(dsum[r], 0.0, 1e-14);
    constexpr double h = 1e-6;
    for (int r = 0; r < 3; ++r) {
      double xp[3] = {xi[0], xi[1], xi[2]}, xm[3] = {xi[0], xi[1], xi[2]};
      xp[r] += h;
      xm[r] -= h;
      double np[kMaxCellNodes], nm[kMaxCellNodes], scratch[kMaxCellNodes][3];
      shape_functions(type, xp, np, scratch);
      shape_functions(type, xm, nm, scratch);
      for (int a = 0; a < t.nodes; ++a) EXPECT_NEAR(dn[a][r], (np[a] - nm[a]) / (2 * h), 1e-9);
    }
  }
}

// Integrals over the reference cells, in closed form: the cube [-1,1]^3 has volume 8 and
// int xi^4 eta^2 = (2/5)(2/3)(2) = 8/15; the unit tetrahedron 1/6 and int xi^a eta^b zeta^c =
// a! b! c! / (a + b + c + 3)! (e.g. int xi^2 = 1/60, int xi eta = 1/120); the wedge 1 and
// int zeta^2 = (1/2)(2/3) = 1/3.
TEST(ShapeFunctions, RulesIntegrateTheirDegreeExactly) {
  const auto integrate = [](CellType type, Integration rule, auto f) {
    double s = 0.0;
    for (const QuadraturePoint& q : quadrature(type, rule)) s += q.weight * f(q.xi);
    return s;
  };
  const auto one = [](const double*) { return 1.0; };
  EXPECT_NEAR(integrate(CellType::hex8, Integration::full, one), 8.0, 1e-15);
  EXPECT_NEAR(integrate(CellType::hex8, Integration::reduced, one), 8.0, 1e-15);
  EXPECT_NEAR(integrate(CellType::hex20, Integration::full,
                        [](const double* x) { return std::pow(x[0], 4) * x[1] * x[1]; }),
              8.0 / 15.0, 1e-14);
  EXPECT_NEAR(integrate(CellType::hex20, Integration::reduced,
                        [](const double* x) { return x[0] * x[0] * x[1] * x[1]; }),
              8.0 / 9.0, 1e-14);
  EXPECT_NEAR(integrate(CellType::tet4, Integration::full, one), 1.0 / 6.0, 1e-15);
  EXPECT_NEAR(
      integrate(CellType::tet10, Integration::full, [](const double* x) { return x[0] * x[0]; }),
      1.0 / 60.0, 1e-15);
  EXPECT_NEAR(
      integrate(CellType::tet10, Integration::full, [](const double* x) { return x[0] * x[1]; }),
      1.0 / 120.0, 1e-15);
  EXPECT_NEAR(
      integrate(CellType::wedge6, Integration::full, [](const double* x) { return x[2] * x[2]; }),
      1.0 / 3.0, 1e-15);
  EXPECT_NEAR(integrate(CellType::hex27, Integration::full,
                        [](const double* x) { return std::pow(x[0], 4) * x[1] * x[1]; }),
              8.0 / 15.0, 1e-14);
  EXPECT_NEAR(integrate(CellType::hex64, Integration::full,
                        [](const double* x) { return std::pow(x[0] * x[1], 6) * x[2] * x[2]; }),
              (2.0 / 7.0) * (2.0 / 7.0) * (2.0 / 3.0), 1e-14);
  EXPECT_TRUE(quadrature(CellType::tet10, Integration::reduced).empty());
  EXPECT_TRUE(quadrature(CellType::hex64, Integration::reduced).empty());
}

// ---- Element ---------------------------------------------------------------------------------

void evaluate(const Rule& rule, const Nodes& nodes, const std::vector<std::int32_t>& cell,
              const std::vector<double>& u_global, bool nlgeom, SolidElementResult& out) {
  std::vector<double> X, u;
  for (const std::int32_t a : cell) {
    const Vec3 p = nodes.position(static_cast<std::size_t>(a));
    X.insert(X.end(), {p.x, p.y, p.z});
    for (int k = 0; k < 3; ++k) u.push_back(u_global[3 * a + k]);
  }
  SolidElementInput in{rule.type, quadrature(rule.type, rule.integration), X, u, nlgeom};
  solid_full_with(in, kSteel, out);
}

// The patch test: a 2x2x2 patch of the unit cube whose inner corner is moved off centre (so no
// element is regular), boundary nodes displaced by a linear field u = A x, inner nodes solved
// for. The exact solution is the linear field: inner displacements and the stress at every point
// must reproduce it to round-off (constant strain eps = sym A, stress = D eps).
TEST(SolidFull, PatchTestOnAnIrregularPatch) {
  const double A[3][3] = {{1e-3, 2e-4, -3e-4}, {-1e-4, -5e-4, 4e-4}, {2.5e-4, 1.5e-4, 7e-4}};
  const double eps[6] = {A[0][0],           A[1][1],           A[2][2],
                         A[0][1] + A[1][0], A[1][2] + A[2][1], A[2][0] + A[0][2]};
  double sigma[6];
  kSteel.stress(eps, sigma);
  for (const Rule& rule : kRules) {
    SCOPED_TRACE(rule.name);
    const auto g =
        test::cell_grid(rule.type, 2, 2, 2, {1.0, 1.0, 1.0}, [](int i, int j, int k, Vec3 p) {
          if (i == 1 && j == 1 && k == 1) p += Vec3{0.13, -0.08, 0.06};
          return p;
        });
    const std::size_t dofs = 3 * g.nodes.size();
    std::vector<double> u(dofs, 0.0);
    std::vector<std::size_t> inner;  // free dofs
    for (std::size_t a = 0; a < g.nodes.size(); ++a) {
      const Vec3 x = g.nodes.position(a);
      for (int i = 0; i < 3; ++i) {
        if (g.on_boundary[a])
          u[3 * a + i] = A[i][0] * x.x + A[i][1] * x.y + A[i][2] * x.z;
        else
          inner.push_back(3 * a + static_cast<std::size_t>(i));
      }
    }
    ASSERT_FALSE(inner.empty());
    // Residual r(u) with inner dofs 0 and the tangent's inner block: K_ii du_i = -r_i.
    std::vector<double> r(dofs, 0.0), k(dofs * dofs, 0.0);
    SolidElementResult out;
    for (const auto& cell : g.cells) {
      evaluate(rule, g.nodes, cell, u, false, out);
      const std::size_t m = 3 * cell.size();
      for (std::size_t p = 0; p < m; ++p) {
        const std::size_t gp = 3 * static_cast<std::size_t>(cell[p / 3]) + p % 3;
        r[gp] += out.force[p];
        for (std::size_t q = 0; q < m; ++q)
          k[gp * dofs + 3 * static_cast<std::size_t>(cell[q / 3]) + q % 3] +=
              out.stiffness[p * m + q];
      }
    }
    const std::size_t n = inner.size();
    std::vector<double> kii(n * n), ri(n);
    for (std::size_t p = 0; p < n; ++p) {
      ri[p] = -r[inner[p]];
      for (std::size_t q = 0; q < n; ++q) kii[p * n + q] = k[inner[p] * dofs + inner[q]];
    }
    const std::vector<double> du = test::solve_dense(kii, ri);
    for (std::size_t p = 0; p < n; ++p) u[inner[p]] = du[p];
    for (std::size_t a = 0; a < g.nodes.size(); ++a) {
      if (g.on_boundary[a]) continue;
      const Vec3 x = g.nodes.position(a);
      for (int i = 0; i < 3; ++i)
        EXPECT_NEAR(u[3 * a + i], A[i][0] * x.x + A[i][1] * x.y + A[i][2] * x.z, 1e-14);
    }
    for (const auto& cell : g.cells) {
      evaluate(rule, g.nodes, cell, u, false, out);
      for (std::size_t p = 0; p < out.energy_density.size(); ++p)
        for (int c = 0; c < 6; ++c) EXPECT_NEAR(out.stress[6 * p + c], sigma[c], 1e-8);
    }
  }
}

// One distorted element of each type: its stiffness has exactly the zero eigenvalues of its
// rigid-body motions (and, for C3D20R, of its rule), none spurious.
TEST(SolidFull, ZeroEnergyModesOfOneElement) {
  for (const Rule& rule : kRules) {
    SCOPED_TRACE(rule.name);
    const CellTopology& t = topology(rule.type);
    // The reference cell scaled, sheared and with its nodes moved by fixed amounts.
    Nodes nodes;
    std::vector<std::int32_t> cell;
    for (int a = 0; a < t.nodes; ++a) {
      const auto& x = t.natural[a];
      const double wobble = 0.04 * std::sin(1.7 * a + 0.3);
      nodes.add(a + 1, {2.0 * x[0] + 0.3 * x[1] + wobble, 1.5 * x[1] - 0.2 * x[2] - wobble,
                        1.2 * x[2] + 0.1 * x[0] + 0.5 * wobble});
      cell.push_back(a);
    }
    SolidElementResult out;
    evaluate(rule, nodes, cell, std::vector<double>(3 * t.nodes, 0.0), false, out);
    ASSERT_GT(out.min_jacobian, 0.0);
    const std::size_t m = 3 * static_cast<std::size_t>(t.nodes);
    const std::vector<double> lambda = test::jacobi_eigenvalues(out.stiffness, static_cast<int>(m));
    const double largest = lambda.back();
    int zeros = 0;
    for (const double l : lambda) {
      EXPECT_GT(l, -1e-10 * largest);
      if (l < 1e-10 * largest) ++zeros;
    }
    EXPECT_EQ(zeros, rule.zero_modes);
    // The smallest non-zero eigenvalue is well above round-off.
    EXPECT_GT(lambda[static_cast<std::size_t>(rule.zero_modes)], 1e-6 * largest);
  }
}

// With CellType::hex8 and the 2x2x2 rule the element is the C3D8 of hex8_full.hpp.
TEST(SolidFull, Hex8IsTheFullyIntegratedHexahedron) {
  const double X[8][3] = {{0, 0, 0},        {1.1, 0.1, -0.05}, {1.3, 1.2, 0.1},  {-0.1, 0.9, 0.05},
                          {0.1, -0.1, 1.0}, {1.0, 0.05, 1.2},  {1.2, 1.1, 0.95}, {0.05, 1.05, 1.1}};
  for (const bool nlgeom : {false, true}) {
    auto reference = std::make_unique<Hex8FullInput>();
    std::vector<double> xs, us;
    for (int a = 0; a < 8; ++a)
      for (int i = 0; i < 3; ++i) {
        reference->X[a][i] = X[a][i];
        reference->u[a][i] = 0.02 * std::sin(3.0 * a + i);
        xs.push_back(X[a][i]);
        us.push_back(reference->u[a][i]);
      }
    reference->nonlinear_geometry = nlgeom;
    auto expected = std::make_unique<Hex8FullResult>();
    hex8_full(*reference, kSteel, *expected);
    SolidElementResult out;
    solid_full_with({CellType::hex8, quadrature(CellType::hex8, Integration::full), xs, us, nlgeom},
                    kSteel, out);
    const double fscale =
        std::abs(*std::max_element(expected->force, expected->force + 24,
                                   [](double a, double b) { return std::abs(a) < std::abs(b); }));
    for (int c = 0; c < 24; ++c) EXPECT_NEAR(out.force[c], expected->force[c], 1e-13 * fscale);
    for (int c = 0; c < 576; ++c)
      EXPECT_NEAR(out.stiffness[c], expected->stiffness[c],
                  1e-13 * std::abs(expected->stiffness[0]));
    for (int p = 0; p < 8; ++p)
      for (int c = 0; c < 6; ++c) EXPECT_NEAR(out.stress[6 * p + c], expected->stress[p][c], 1e-9);
    EXPECT_NEAR(out.strain_energy, expected->strain_energy, 1e-13 * expected->strain_energy);
    EXPECT_NEAR(out.volume, expected->volume, 1e-14);
  }
}

// NLGEOM: the stiffness is the derivative of the force (central differences, relative 1e-6),
// on a distorted cell of each type under a finite deformation.
TEST(SolidFull, ConsistentTangentWithGeometricNonlinearity) {
  for (const Rule& rule : kRules) {
    SCOPED_TRACE(rule.name);
    const CellTopology& t = topology(rule.type);
    Nodes nodes;
    std::vector<std::int32_t> cell;
    std::vector<double> u;
    for (int a = 0; a < t.nodes; ++a) {
      const auto& x = t.natural[a];
      nodes.add(a + 1, {x[0] + 0.1 * x[1], x[1] - 0.05 * x[2], x[2] + 0.02 * std::cos(a)});
      cell.push_back(a);
      u.insert(u.end(),
               {0.05 * std::sin(a + 0.5), -0.04 * std::cos(2.0 * a), 0.03 * std::sin(3.0 * a)});
    }
    SolidElementResult out, plus, minus;
    evaluate(rule, nodes, cell, u, true, out);
    const std::size_t m = u.size();
    double kmax = 0.0;
    for (const double v : out.stiffness) kmax = std::max(kmax, std::abs(v));
    constexpr double h = 1e-7;
    for (std::size_t q = 0; q < m; ++q) {
      std::vector<double> up = u, um = u;
      up[q] += h;
      um[q] -= h;
      evaluate(rule, nodes, cell, up, true, plus);
      evaluate(rule, nodes, cell, um, true, minus);
      for (std::size_t p = 0; p < m; ++p)
        EXPECT_NEAR(out.stiffness[p * m + q], (plus.force[p] - minus.force[p]) / (2 * h),
                    1e-6 * kmax);
    }
  }
}

}  // namespace
}  // namespace abut
