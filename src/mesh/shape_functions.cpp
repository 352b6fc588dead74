// Shape functions and integration rules of every cell type: see shape_functions.hpp.
#include "abut/mesh/shape_functions.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "abut/core/triangle_rule.hpp"

namespace abut {
namespace {

void hex8(const double xi[3], double* n, double (*dn)[3]) {
  const auto& nat = topology(CellType::hex8).natural;
  for (int a = 0; a < 8; ++a) {
    const double x = 1.0 + xi[0] * nat[a][0], y = 1.0 + xi[1] * nat[a][1],
                 z = 1.0 + xi[2] * nat[a][2];
    n[a] = 0.125 * x * y * z;
    dn[a][0] = 0.125 * nat[a][0] * y * z;
    dn[a][1] = 0.125 * nat[a][1] * x * z;
    dn[a][2] = 0.125 * nat[a][2] * x * y;
  }
}

void hex20(const double xi[3], double* n, double (*dn)[3]) {
  const auto& nat = topology(CellType::hex20).natural;
  for (int a = 0; a < 20; ++a) {
    const double xa = nat[a][0], ya = nat[a][1], za = nat[a][2];
    const double x = 1.0 + xi[0] * xa, y = 1.0 + xi[1] * ya, z = 1.0 + xi[2] * za;
    if (a < 8) {
      const double s = xi[0] * xa + xi[1] * ya + xi[2] * za - 2.0;
      n[a] = 0.125 * x * y * z * s;
      dn[a][0] = 0.125 * xa * y * z * (s + x);
      dn[a][1] = 0.125 * ya * x * z * (s + y);
      dn[a][2] = 0.125 * za * x * y * (s + z);
    } else if (xa == 0.0) {
      const double q = 1.0 - xi[0] * xi[0];
      n[a] = 0.25 * q * y * z;
      dn[a][0] = -0.5 * xi[0] * y * z;
      dn[a][1] = 0.25 * q * ya * z;
      dn[a][2] = 0.25 * q * y * za;
    } else if (ya == 0.0) {
      const double q = 1.0 - xi[1] * xi[1];
      n[a] = 0.25 * x * q * z;
      dn[a][0] = 0.25 * xa * q * z;
      dn[a][1] = -0.5 * xi[1] * x * z;
      dn[a][2] = 0.25 * x * q * za;
    } else {
      const double q = 1.0 - xi[2] * xi[2];
      n[a] = 0.25 * x * y * q;
      dn[a][0] = 0.25 * xa * y * q;
      dn[a][1] = 0.25 * x * ya * q;
      dn[a][2] = -0.5 * xi[2] * x * y;
    }
  }
}

// Volume coordinates L0..L3 and their derivatives dL_a / dxi_r.
constexpr double kTetDl[4][3] = {{-1, -1, -1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

void tet4(const double xi[3], double* n, double (*dn)[3]) {
  n[0] = 1.0 - xi[0] - xi[1] - xi[2];
  n[1] = xi[0];
  n[2] = xi[1];
  n[3] = xi[2];
  for (int a = 0; a < 4; ++a)
    for (int r = 0; r < 3; ++r) dn[a][r] = kTetDl[a][r];
}

void tet10(const double xi[3], double* n, double (*dn)[3]) {
  const double l[4] = {1.0 - xi[0] - xi[1] - xi[2], xi[0], xi[1], xi[2]};
  for (int a = 0; a < 4; ++a) {
    n[a] = l[a] * (2.0 * l[a] - 1.0);
    for (int r = 0; r < 3; ++r) dn[a][r] = (4.0 * l[a] - 1.0) * kTetDl[a][r];
  }
  for (const EdgeTopology& e : topology(CellType::tet10).edges) {
    n[e.mid] = 4.0 * l[e.a] * l[e.b];
    for (int r = 0; r < 3; ++r)
      dn[e.mid][r] = 4.0 * (kTetDl[e.a][r] * l[e.b] + l[e.a] * kTetDl[e.b][r]);
  }
}

void wedge6(const double xi[3], double* n, double (*dn)[3]) {
  const double t[3] = {1.0 - xi[0] - xi[1], xi[0], xi[1]};
  const double dt[3][2] = {{-1, -1}, {1, 0}, {0, 1}};
  for (int a = 0; a < 6; ++a) {
    const int k = a % 3;
    const double side = a < 3 ? -1.0 : 1.0;
    const double h = 0.5 * (1.0 + side * xi[2]);
    n[a] = t[k] * h;
    dn[a][0] = dt[k][0] * h;
    dn[a][1] = dt[k][1] * h;
    dn[a][2] = 0.5 * side * t[k];
  }
}

// The 1-D Lagrange polynomials of order P on the equispaced points x_m = -1 + 2m/P, and their
// derivatives: l_m(x) = prod_{q != m} (x - x_q) / (x_m - x_q).
template <int P>
void lagrange_1d(double x, double* l, double* dl) {
  double node[P + 1];
  for (int m = 0; m <= P; ++m) node[m] = -1.0 + 2.0 * m / P;
  for (int m = 0; m <= P; ++m) {
    double value = 1.0, slope = 0.0;
    for (int q = 0; q <= P; ++q) {
      if (q == m) continue;
      const double d = 1.0 / (node[m] - node[q]);
      slope = slope * (x - node[q]) * d + value * d;
      value *= (x - node[q]) * d;
    }
    l[m] = value;
    dl[m] = slope;
  }
}

// The lattice index of a node from its natural coordinate -1 + 2i/P.
inline int lattice_index(double natural, int order) {
  return static_cast<int>(std::lround(0.5 * (natural + 1.0) * order));
}

// Lagrange hexahedron of order P: N_a = l_i(xi) l_j(eta) l_k(zeta) for node a at lattice (i, j, k).
template <int P>
void lagrange_hex(CellType type, const double xi[3], double* n, double (*dn)[3]) {
  double l[3][P + 1], dl[3][P + 1];
  for (int r = 0; r < 3; ++r) lagrange_1d<P>(xi[r], l[r], dl[r]);
  const CellTopology& t = topology(type);
  for (int a = 0; a < t.nodes; ++a) {
    const auto& nat = t.natural[static_cast<std::size_t>(a)];
    const int i = lattice_index(nat[0], P), j = lattice_index(nat[1], P),
              k = lattice_index(nat[2], P);
    n[a] = l[0][i] * l[1][j] * l[2][k];
    dn[a][0] = dl[0][i] * l[1][j] * l[2][k];
    dn[a][1] = l[0][i] * dl[1][j] * l[2][k];
    dn[a][2] = l[0][i] * l[1][j] * dl[2][k];
  }
}

// The Lagrange quadrilateral of order P (quad9, quad16): N_a = l_s(xi) l_t(eta).
template <int P>
void lagrange_quad(FaceType type, const double xi[2], double* n, double (*dn)[2]) {
  double l[2][P + 1], dl[2][P + 1];
  for (int r = 0; r < 2; ++r) lagrange_1d<P>(xi[r], l[r], dl[r]);
  const auto lattice = face_lattice(type);
  for (std::size_t a = 0; a < lattice.size(); ++a) {
    const int s = lattice[a][0], t = lattice[a][1];
    n[a] = l[0][s] * l[1][t];
    dn[a][0] = dl[0][s] * l[1][t];
    dn[a][1] = l[0][s] * dl[1][t];
  }
}

// Tensor-product Gauss-Legendre rule of m points per direction on [-1, 1]^3, xi fastest.
template <int M>
constexpr std::array<QuadraturePoint, M * M * M> gauss_cube(const double (&x)[M],
                                                            const double (&w)[M]) {
  std::array<QuadraturePoint, M * M * M> out{};
  for (int k = 0; k < M; ++k)
    for (int j = 0; j < M; ++j)
      for (int i = 0; i < M; ++i)
        out[i + M * (j + M * k)] = {{x[i], x[j], x[k]}, w[i] * w[j] * w[k]};
  return out;
}

constexpr double kG1[1] = {0.0}, kW1[1] = {2.0};
constexpr double kG2[2] = {-0.57735026918962576451, 0.57735026918962576451}, kW2[2] = {1.0, 1.0};
constexpr double kG3[3] = {-0.77459666924148337704, 0.0, 0.77459666924148337704},
                 kW3[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};

// 4 points: +-sqrt(3/7 -+ 2/7 sqrt(6/5)), weights (18 +- sqrt 30) / 36 (Abramowitz & Stegun,
// table 25.4).
constexpr double kG4[4] = {-0.86113631159405257522, -0.33998104358485626480, 0.33998104358485626480,
                           0.86113631159405257522},
                 kW4[4] = {0.34785484513745385737, 0.65214515486254614263, 0.65214515486254614263,
                           0.34785484513745385737};
// 5 points: 0, +-(1/3) sqrt(5 -+ 2 sqrt(10/7)) (the same table).
constexpr double kG5[5] = {-0.90617984593866399280, -0.53846931010568309104, 0.0,
                           0.53846931010568309104, 0.90617984593866399280},
                 kW5[5] = {0.23692688505618908751, 0.47862867049936646804, 0.56888888888888888889,
                           0.47862867049936646804, 0.23692688505618908751};

constexpr auto kCube1 = gauss_cube(kG1, kW1);
constexpr auto kCube2 = gauss_cube(kG2, kW2);
constexpr auto kCube3 = gauss_cube(kG3, kW3);
constexpr auto kCube4 = gauss_cube(kG4, kW4);

constexpr std::array<QuadraturePoint, 1> kTet1 = {{{{0.25, 0.25, 0.25}, 1.0 / 6.0}}};
constexpr double kTetA = 0.58541019662496845446, kTetB = 0.13819660112501051518;
constexpr std::array<QuadraturePoint, 4> kTet4Points = {{{{kTetB, kTetB, kTetB}, 1.0 / 24.0},
                                                         {{kTetA, kTetB, kTetB}, 1.0 / 24.0},
                                                         {{kTetB, kTetA, kTetB}, 1.0 / 24.0},
                                                         {{kTetB, kTetB, kTetA}, 1.0 / 24.0}}};
// Wedge: the triangle's 3-point rule at (1/6, 1/6), (2/3, 1/6), (1/6, 2/3) (degree 2, weights
// 1/6) on each of the 2 Gauss levels zeta = -+1/sqrt 3, the triangle fastest.
constexpr double kW = 1.0 / 6.0, kWg = 0.57735026918962576451;
constexpr std::array<QuadraturePoint, 6> kWedge6Points = {{{{kW, kW, -kWg}, kW},
                                                           {{4 * kW, kW, -kWg}, kW},
                                                           {{kW, 4 * kW, -kWg}, kW},
                                                           {{kW, kW, kWg}, kW},
                                                           {{4 * kW, kW, kWg}, kW},
                                                           {{kW, 4 * kW, kWg}, kW}}};

// Face rules.
constexpr std::array<FacePoint, 4> kQuad2x2 = {
    {{{-0.57735026918962576451, -0.57735026918962576451}, 1.0},
     {{0.57735026918962576451, -0.57735026918962576451}, 1.0},
     {{-0.57735026918962576451, 0.57735026918962576451}, 1.0},
     {{0.57735026918962576451, 0.57735026918962576451}, 1.0}}};
template <int M>
constexpr std::array<FacePoint, M * M> gauss_square(const double (&x)[M], const double (&w)[M]) {
  std::array<FacePoint, M * M> out{};
  for (int j = 0; j < M; ++j)
    for (int i = 0; i < M; ++i) out[i + M * j] = {{x[i], x[j]}, w[i] * w[j]};
  return out;
}
constexpr auto kQuad3x3 = gauss_square(kG3, kW3);
constexpr auto kQuad5x5 = gauss_square(kG5, kW5);
constexpr std::array<FacePoint, 1> kTri1 = {{{{1.0 / 3.0, 1.0 / 3.0}, 0.5}}};
// Dunavant's degree-4 rule (core/triangle_rule.hpp), its weights halved for the reference
// triangle of area 1/2.
constexpr std::array<FacePoint, 6> tri_degree4() {
  std::array<FacePoint, 6> out{};
  for (std::size_t q = 0; q < 6; ++q)
    out[q] = {{kTriangleDegree4[q].l1, kTriangleDegree4[q].l2}, 0.5 * kTriangleDegree4[q].weight};
  return out;
}
constexpr auto kTri6Points = tri_degree4();

constexpr double kQuadCorner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};

}  // namespace

void face_shape_functions(FaceType type, const double xi[2], double* n, double (*dn)[2]) {
  const double x = xi[0], y = xi[1];
  switch (type) {
    case FaceType::quad4:
      for (int a = 0; a < 4; ++a) {
        const double xa = kQuadCorner[a][0], ya = kQuadCorner[a][1];
        n[a] = 0.25 * (1 + xa * x) * (1 + ya * y);
        dn[a][0] = 0.25 * xa * (1 + ya * y);
        dn[a][1] = 0.25 * ya * (1 + xa * x);
      }
      return;
    case FaceType::quad8:
      for (int a = 0; a < 4; ++a) {
        const double xa = kQuadCorner[a][0], ya = kQuadCorner[a][1];
        const double s = xa * x + ya * y - 1.0;
        n[a] = 0.25 * (1 + xa * x) * (1 + ya * y) * s;
        dn[a][0] = 0.25 * xa * (1 + ya * y) * (s + 1 + xa * x);
        dn[a][1] = 0.25 * ya * (1 + xa * x) * (s + 1 + ya * y);
      }
      for (int k = 0; k < 4; ++k) {  // midside of corners k, k + 1
        const double xm = 0.5 * (kQuadCorner[k][0] + kQuadCorner[(k + 1) % 4][0]);
        const double ym = 0.5 * (kQuadCorner[k][1] + kQuadCorner[(k + 1) % 4][1]);
        if (xm == 0.0) {
          n[4 + k] = 0.5 * (1 - x * x) * (1 + ym * y);
          dn[4 + k][0] = -x * (1 + ym * y);
          dn[4 + k][1] = 0.5 * (1 - x * x) * ym;
        } else {
          n[4 + k] = 0.5 * (1 + xm * x) * (1 - y * y);
          dn[4 + k][0] = 0.5 * xm * (1 - y * y);
          dn[4 + k][1] = -y * (1 + xm * x);
        }
      }
      return;
    case FaceType::quad9:
      return lagrange_quad<2>(type, xi, n, dn);
    case FaceType::quad16:
      return lagrange_quad<3>(type, xi, n, dn);
    case FaceType::tri3:
    case FaceType::tri6: {
      const double l[3] = {1.0 - x - y, x, y};
      constexpr double dl[3][2] = {{-1, -1}, {1, 0}, {0, 1}};
      if (type == FaceType::tri3) {
        for (int a = 0; a < 3; ++a) {
          n[a] = l[a];
          dn[a][0] = dl[a][0];
          dn[a][1] = dl[a][1];
        }
        return;
      }
      for (int a = 0; a < 3; ++a) {
        n[a] = l[a] * (2 * l[a] - 1);
        for (int r = 0; r < 2; ++r) dn[a][r] = (4 * l[a] - 1) * dl[a][r];
        const int b = (a + 1) % 3;
        n[3 + a] = 4 * l[a] * l[b];
        for (int r = 0; r < 2; ++r) dn[3 + a][r] = 4 * (dl[a][r] * l[b] + l[a] * dl[b][r]);
      }
      return;
    }
  }
}

std::span<const FacePoint> face_quadrature(FaceType type) {
  switch (type) {
    case FaceType::quad4:
      return kQuad2x2;
    case FaceType::quad8:
    case FaceType::quad9:
      return kQuad3x3;
    case FaceType::quad16:
      return kQuad5x5;
    case FaceType::tri3:
      return kTri1;
    case FaceType::tri6:
      return kTri6Points;
  }
  return {};
}

namespace {

// At a point of a face with nodes at x: its shape functions n and x_xi x x_eta, the outward normal
// times the area per unit natural area.
void face_point(FaceType type, std::span<const double> x, const double xi[2], double* n,
                double area[3]) {
  double dn[kMaxFaceNodes][2];
  face_shape_functions(type, xi, n, dn);
  double t1[3] = {0, 0, 0}, t2[3] = {0, 0, 0};
  for (int a = 0; a < face_node_count(type); ++a)
    for (int i = 0; i < 3; ++i) {
      t1[i] += x[static_cast<std::size_t>(3 * a + i)] * dn[a][0];
      t2[i] += x[static_cast<std::size_t>(3 * a + i)] * dn[a][1];
    }
  area[0] = t1[1] * t2[2] - t1[2] * t2[1];
  area[1] = t1[2] * t2[0] - t1[0] * t2[2];
  area[2] = t1[0] * t2[1] - t1[1] * t2[0];
}

}  // namespace

void face_pressure_forces(FaceType type, std::span<const double> x, double p, std::span<double> f) {
  const int nodes = face_node_count(type);
  double n[kMaxFaceNodes], area[3];
  std::fill(f.begin(), f.begin() + 3 * nodes, 0.0);
  for (const FacePoint& q : face_quadrature(type)) {
    face_point(type, x, q.xi, n, area);
    for (int a = 0; a < nodes; ++a)
      for (int i = 0; i < 3; ++i)
        f[static_cast<std::size_t>(3 * a + i)] -= p * q.weight * n[a] * area[i];
  }
}

void shape_functions(CellType type, const double xi[3], double* n, double (*dn)[3]) {
  switch (type) {
    case CellType::hex8:
      return hex8(xi, n, dn);
    case CellType::hex20:
      return hex20(xi, n, dn);
    case CellType::tet4:
      return tet4(xi, n, dn);
    case CellType::tet10:
      return tet10(xi, n, dn);
    case CellType::wedge6:
      return wedge6(xi, n, dn);
    case CellType::hex27:
      return lagrange_hex<2>(type, xi, n, dn);
    case CellType::hex64:
      return lagrange_hex<3>(type, xi, n, dn);
  }
}

std::span<const QuadraturePoint> quadrature(CellType type, Integration rule) {
  const bool full = rule == Integration::full;
  switch (type) {
    case CellType::hex8:
      return full ? std::span<const QuadraturePoint>(kCube2) : kCube1;
    case CellType::hex20:
      return full ? std::span<const QuadraturePoint>(kCube3) : kCube2;
    case CellType::tet4:
      return full ? std::span<const QuadraturePoint>(kTet1) : std::span<const QuadraturePoint>();
    case CellType::tet10:
      return full ? std::span<const QuadraturePoint>(kTet4Points)
                  : std::span<const QuadraturePoint>();
    case CellType::wedge6:
      return full ? std::span<const QuadraturePoint>(kWedge6Points)
                  : std::span<const QuadraturePoint>();
    case CellType::hex27:
      return full ? std::span<const QuadraturePoint>(kCube3) : std::span<const QuadraturePoint>();
    case CellType::hex64:
      return full ? std::span<const QuadraturePoint>(kCube4) : std::span<const QuadraturePoint>();
  }
  return {};
}

double shape_gradients(CellType type, std::span<const double> X, const double xi[3], double* n,
                       double (*dn)[3], double (*grad)[3]) {
  shape_functions(type, xi, n, dn);
  return natural_to_spatial(topology(type).nodes, dn, X.data(), grad);
}

double min_jacobian(CellType type, std::span<const double> X) {
  double n[kMaxCellNodes], dn[kMaxCellNodes][3], grad[kMaxCellNodes][3];
  double smallest = 0.0;
  bool first = true;
  for (const QuadraturePoint& q : quadrature(type, Integration::full)) {
    const double det = shape_gradients(type, X, q.xi, n, dn, grad);
    smallest = first ? det : std::min(smallest, det);
    first = false;
  }
  return smallest;
}

double cell_volume(CellType type, std::span<const double> X) {
  double n[kMaxCellNodes], dn[kMaxCellNodes][3], grad[kMaxCellNodes][3];
  double volume = 0.0;
  for (const QuadraturePoint& q : quadrature(type, Integration::full))
    volume += q.weight * shape_gradients(type, X, q.xi, n, dn, grad);
  return volume;
}

double face_area(FaceType type, std::span<const double> x) {
  double n[kMaxFaceNodes], c[3];
  double area = 0.0;
  for (const FacePoint& q : face_quadrature(type)) {
    face_point(type, x, q.xi, n, c);
    area += q.weight * std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
  }
  return area;
}

FaceSubdivision subdivide_face(FaceType type, int n) {
  return subdivide_reference_face(face_corner_count(type) == 4, n);
}

}  // namespace abut
