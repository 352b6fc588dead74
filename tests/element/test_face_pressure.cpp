// Faces of the cell types (element/shape_functions.hpp): face shape functions and rules, and the
// nodal forces of a uniform pressure, against their closed forms: the shares of a flat face
// (Zienkiewicz, Taylor & Zhu 2013, section 6.9; CalculiX 2.20 prints the same, -1/12 and 1/3 on
// a quad8 face and 0 and 1/3 on a tri6 face: docs/notes/ccx_element_conventions.md) and, on a
// curved face, the total force -p times the vector area (1/2) closed integral of x cross dx over
// the face's boundary (Stokes), whatever the face's shape inside.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "abut/mesh/shape_functions.hpp"

namespace abut {
namespace {

constexpr FaceType kFaceTypes[] = {FaceType::tri3,  FaceType::tri6,  FaceType::quad4,
                                   FaceType::quad8, FaceType::quad9, FaceType::quad16};

// Natural coordinates of the face nodes.
std::vector<std::array<double, 2>> face_nodes(FaceType t) {
  const auto lattice = face_lattice(t);  // Lagrange: -1 + 2 s / p
  if (!lattice.empty()) {
    const double p = t == FaceType::quad9 ? 2.0 : 3.0;
    std::vector<std::array<double, 2>> x;
    for (const auto& st : lattice) x.push_back({-1 + 2 * st[0] / p, -1 + 2 * st[1] / p});
    return x;
  }
  if (face_corner_count(t) == 4) {
    std::vector<std::array<double, 2>> x = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    if (t == FaceType::quad8) x.insert(x.end(), {{0, -1}, {1, 0}, {0, 1}, {-1, 0}});
    return x;
  }
  std::vector<std::array<double, 2>> x = {{0, 0}, {1, 0}, {0, 1}};
  if (t == FaceType::tri6) x.insert(x.end(), {{0.5, 0}, {0.5, 0.5}, {0, 0.5}});
  return x;
}

TEST(FaceShapeFunctions, KroneckerPartitionOfUnityAndDerivatives) {
  for (const FaceType t : kFaceTypes) {
    const auto nat = face_nodes(t);
    const int nodes = face_node_count(t);
    ASSERT_EQ(static_cast<int>(nat.size()), nodes);
    double n[kMaxFaceNodes], dn[kMaxFaceNodes][2];
    for (int b = 0; b < nodes; ++b) {
      face_shape_functions(t, nat[b].data(), n, dn);
      for (int a = 0; a < nodes; ++a) EXPECT_NEAR(n[a], a == b ? 1.0 : 0.0, 1e-15);
    }
    const double xi[2] = {0.23, 0.31};
    face_shape_functions(t, xi, n, dn);
    double sum = 0.0;
    for (int a = 0; a < nodes; ++a) sum += n[a];
    EXPECT_NEAR(sum, 1.0, 1e-15);
    constexpr double h = 1e-6;
    for (int r = 0; r < 2; ++r) {
      double xp[2] = {xi[0], xi[1]}, xm[2] = {xi[0], xi[1]}, np[kMaxFaceNodes], nm[kMaxFaceNodes],
             scratch[kMaxFaceNodes][2];
      xp[r] += h;
      xm[r] -= h;
      face_shape_functions(t, xp, np, scratch);
      face_shape_functions(t, xm, nm, scratch);
      for (int a = 0; a < nodes; ++a) EXPECT_NEAR(dn[a][r], (np[a] - nm[a]) / (2 * h), 1e-9);
    }
  }
}

// int over the unit triangle of xi^a eta^b = a! b! / (a + b + 2)!; over [-1,1]^2 of xi^4 eta^4 =
// (2/5)^2, of xi^8 eta^8 (2/9)^2.
TEST(FaceShapeFunctions, RulesIntegrateTheirDegreeExactly) {
  const auto integrate = [](FaceType t, int a, int b) {
    double s = 0.0;
    for (const FacePoint& q : face_quadrature(t))
      s += q.weight * std::pow(q.xi[0], a) * std::pow(q.xi[1], b);
    return s;
  };
  EXPECT_NEAR(integrate(FaceType::tri3, 1, 0), 1.0 / 6.0, 1e-15);
  EXPECT_NEAR(integrate(FaceType::tri6, 4, 0), 24.0 / 720.0, 1e-12);
  EXPECT_NEAR(integrate(FaceType::tri6, 2, 2), 4.0 / 720.0, 1e-12);
  EXPECT_NEAR(integrate(FaceType::tri6, 1, 3), 6.0 / 720.0, 1e-12);
  EXPECT_NEAR(integrate(FaceType::quad8, 4, 4), 0.16, 1e-14);
  EXPECT_NEAR(integrate(FaceType::quad9, 5, 4), 0.0, 1e-14);
  EXPECT_NEAR(integrate(FaceType::quad16, 8, 8), 4.0 / 81.0, 1e-14);
  EXPECT_NEAR(integrate(FaceType::quad4, 2, 2), 4.0 / 9.0, 1e-15);
}

// A flat face in the plane z = 0 (nodes counter-clockwise seen from +z, the outside), scaled
// and sheared, under p: every node's force is -p A share along +z. The Lagrange faces' shares are
// the products of the Newton-Cotes weights of their edges (Simpson 1/6, 4/6, 1/6; the 3/8 rule
// 1/8, 3/8, 3/8, 1/8): quad9 1/36, 4/36, 16/36; quad16 1/64, 3/64, 9/64.
TEST(FacePressure, SharesOfAFlatFace) {
  struct Case {
    FaceType type;
    double corner, midside, interior;
  };
  const Case cases[] = {{FaceType::tri3, 1.0 / 3.0, 0.0, 0.0},
                        {FaceType::tri6, 0.0, 1.0 / 3.0, 0.0},
                        {FaceType::quad4, 0.25, 0.0, 0.0},
                        {FaceType::quad8, -1.0 / 12.0, 1.0 / 3.0, 0.0},
                        {FaceType::quad9, 1.0 / 36.0, 4.0 / 36.0, 16.0 / 36.0},
                        {FaceType::quad16, 1.0 / 64.0, 3.0 / 64.0, 9.0 / 64.0}};
  const double p = 2.5;
  for (const Case& c : cases) {
    const auto nat = face_nodes(c.type);
    std::vector<double> x;
    for (const auto& q : nat) x.insert(x.end(), {3.0 * q[0] + 0.5 * q[1], 2.0 * q[1], 0.0});
    // Area: the map's determinant 6 times the reference area (4 or 1/2).
    const double area = 6.0 * (face_corner_count(c.type) == 4 ? 4.0 : 0.5);
    std::vector<double> f(x.size());
    face_pressure_forces(c.type, x, p, f);
    for (std::size_t a = 0; a < nat.size(); ++a) {
      const int corners = face_corner_count(c.type), order = c.type == FaceType::quad16 ? 3 : 2;
      const auto edge_nodes = static_cast<std::size_t>(corners * (1 + (order - 1)));
      const double share = a < static_cast<std::size_t>(corners) ? c.corner
                           : a < edge_nodes                      ? c.midside
                                                                 : c.interior;
      EXPECT_NEAR(f[3 * a], 0.0, 1e-13);
      EXPECT_NEAR(f[3 * a + 1], 0.0, 1e-13);
      EXPECT_NEAR(f[3 * a + 2], -p * area * share, 1e-13);
    }
  }
}

// Curved quadratic faces (quad9: its centre node off the plane too): the total force is -p times
// the vector area, computed along the boundary (each edge a parabola through its corners and
// midside node, 10 Gauss points).
TEST(FacePressure, TotalOnACurvedFaceIsPressureTimesVectorArea) {
  for (const FaceType t : {FaceType::tri6, FaceType::quad8, FaceType::quad9}) {
    const auto nat = face_nodes(t);
    std::vector<double> x;
    for (const auto& q : nat) {
      const double u = q[0], v = q[1];
      x.insert(x.end(),
               {u + 0.1 * v * v, v - 0.05 * u * u, 0.3 * u * u + 0.2 * u * v - 0.25 * v * v});
    }
    const int corners = face_corner_count(t);
    double vector_area[3] = {0, 0, 0};
    // 10-point Gauss-Legendre on [0, 1] along each edge a -> m -> b: x(s) = quadratic.
    const double g[5] = {0.1488743389816312, 0.4333953941292472, 0.6794095682990244,
                         0.8650633666889845, 0.9739065285171717};
    const double w[5] = {0.2955242247147529, 0.2692667193099963, 0.2190863625159820,
                         0.1494513491505806, 0.0666713443086881};
    for (int k = 0; k < corners; ++k) {
      const int a = k, b = (k + 1) % corners, m = corners + k;
      for (int i = 0; i < 10; ++i) {
        const double s = 0.5 * (1.0 + (i < 5 ? -g[i] : g[i - 5])), ws = 0.5 * w[i % 5];
        const double na = (1 - s) * (1 - 2 * s), nm = 4 * s * (1 - s), nb = s * (2 * s - 1);
        const double da = 4 * s - 3, dm = 4 - 8 * s, db = 4 * s - 1;
        double p[3], dp[3];
        for (int c = 0; c < 3; ++c) {
          p[c] = na * x[3 * a + c] + nm * x[3 * m + c] + nb * x[3 * b + c];
          dp[c] = da * x[3 * a + c] + dm * x[3 * m + c] + db * x[3 * b + c];
        }
        vector_area[0] += 0.5 * ws * (p[1] * dp[2] - p[2] * dp[1]);
        vector_area[1] += 0.5 * ws * (p[2] * dp[0] - p[0] * dp[2]);
        vector_area[2] += 0.5 * ws * (p[0] * dp[1] - p[1] * dp[0]);
      }
    }
    const double p = 1.7;
    std::vector<double> f(x.size());
    face_pressure_forces(t, x, p, f);
    for (int c = 0; c < 3; ++c) {
      double total = 0.0;
      for (std::size_t a = 0; a < nat.size(); ++a) total += f[3 * a + c];
      EXPECT_NEAR(total, -p * vector_area[c], 1e-12);
    }
  }
}

}  // namespace
}  // namespace abut
