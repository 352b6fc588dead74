// Cell-wise segment-to-segment integration of S2S contact (mortar.hpp, issue 27 item 3).
//
// Sources: the contact patch test (Taylor & Papadopoulos 1991, "On a patch test for contact
// problems in two dimensions"; Crisfield 2000, "Re-visiting the contact patch test", IJNME
// 48:435): a uniform contact pressure across a non-matching interface must be transmitted
// exactly, i.e. load every node with its consistent share int N_i p dA of the pressure over the
// true contact area. Mortar integration over the overlap of the two meshes (Puso & Laursen 2004,
// CMAME 193:601) passes it; point-wise integration does not where integration points straddle
// the other body's border (they touch with all their area or none) or a kink of the other side's
// shape functions.
//
// The patch test here: a block's bottom (n1 x n1 facets, 1 x 1) rotated and offset by random
// fractions of an element (fixed seed) over a larger plate (n2 x n2 facets), both rigid, at a
// uniform penetration d: with the linear penalty law the pressure is pfac d everywhere, and every
// plate node must carry -pfac d int_{footprint} N_i dA, every block node pfac d int N_i dA (its
// whole bottom is covered), to round-off, in symmetric and one-way contact. The reference
// clips the footprint (one polygon) against each plate facet here, independently of the cells.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>
#include <vector>

#include "abut/contact/interface.hpp"
#include "abut/contact/mortar.hpp"
#include "fixtures.hpp"

namespace abut {
namespace {

using testing::add_plate;
using testing::World;
using P2 = std::array<double, 2>;

// A unit square cell over half of a larger facet: area 1/2 and the integrals of the bilinear
// shape functions over x in [1/2, 1] by hand; the other facet's shape functions reproduce the
// overlap's first moment (sum_b w_b X_b = int x dA: they interpolate x exactly).
TEST(Mortar, HalfCoveredCellIntegratesBothSidesExactly) {
  const QuadCorners own{Vec3{0, 0, 0}, Vec3{0, 1, 0}, Vec3{1, 1, 0}, Vec3{1, 0, 0}};  // faces -z
  const QuadCorners other{Vec3{0.5, -1, -0.01}, Vec3{2, -1, -0.01}, Vec3{2, 2, -0.01},
                          Vec3{0.5, 2, -0.01}};
  const std::int32_t id = 7;
  const CellOverlap o = overlap_cell(own, {}, {0, 0, 1}, {&id, 1}, {&other, 1});
  ASSERT_EQ(o.count, 1);
  EXPECT_EQ(o.facet[0], 7);
  EXPECT_NEAR(o.area, 0.5, 1e-14);
  // Own corners (x, y): 0 (0,0), 1 (0,1), 2 (1,1), 3 (1,0); int over x in [1/2,1] of (1-x) = 1/8,
  // of x = 3/8; over y in [0,1] of y or (1-y): 1/2.
  EXPECT_NEAR(o.own[0], 1.0 / 16.0, 1e-14);
  EXPECT_NEAR(o.own[1], 1.0 / 16.0, 1e-14);
  EXPECT_NEAR(o.own[2], 3.0 / 16.0, 1e-14);
  EXPECT_NEAR(o.own[3], 3.0 / 16.0, 1e-14);
  double area = 0.0, mx = 0.0, my = 0.0;
  for (int b = 0; b < 4; ++b) {
    area += o.target[0][b];
    mx += o.target[0][b] * other[b].x;
    my += o.target[0][b] * other[b].y;
  }
  EXPECT_NEAR(area, 0.5, 1e-14);
  EXPECT_NEAR(mx, 0.5 * 0.75, 1e-14);
  EXPECT_NEAR(my, 0.5 * 0.5, 1e-14);
}

// Reference: int over (polygon inside facet [xa,xb] x [ya,yb]) of the facet's N at node corner
// (cx, cy) of it, by clipping against the rectangle's four half-planes and the edge-midpoint
// rule on a fan (exact for the bilinear N of a rectangle).
double nodal_share(const std::vector<P2>& polygon, double xa, double xb, double ya, double yb,
                   double cx, double cy) {
  std::vector<P2> poly = polygon;
  auto clip = [&](int axis, double bound, bool keep_above) {
    std::vector<P2> out;
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const P2 s = poly[i], t = poly[(i + 1) % poly.size()];
      const bool si = keep_above ? s[axis] >= bound : s[axis] <= bound;
      const bool ti = keep_above ? t[axis] >= bound : t[axis] <= bound;
      if (si) out.push_back(s);
      if (si != ti) {
        const double r = (bound - s[axis]) / (t[axis] - s[axis]);
        out.push_back({s[0] + r * (t[0] - s[0]), s[1] + r * (t[1] - s[1])});
      }
    }
    poly = out;
  };
  clip(0, xa, true), clip(0, xb, false), clip(1, ya, true), clip(1, yb, false);
  auto n = [&](const P2& p) {  // 1 at (cx, cy), 0 at the other corners
    const double u = cx == xa ? (xb - p[0]) / (xb - xa) : (p[0] - xa) / (xb - xa);
    const double v = cy == ya ? (yb - p[1]) / (yb - ya) : (p[1] - ya) / (yb - ya);
    return u * v;
  };
  double s = 0.0;
  for (std::size_t i = 1; i + 1 < poly.size(); ++i) {
    const P2 &a = poly[0], &b = poly[i], &c = poly[i + 1];
    const double area = 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
    const P2 ab{0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])},
        bc{0.5 * (b[0] + c[0]), 0.5 * (b[1] + c[1])}, ca{0.5 * (c[0] + a[0]), 0.5 * (c[1] + a[1])};
    s += area / 3.0 * (n(ab) + n(bc) + n(ca));
  }
  return s;
}

// Area and first moments of the part of `polygon` inside the unit square (the bilinear shares
// of nodal_share sum to 1, x and y there).
std::array<double, 3> moments_in_unit_square(const std::vector<P2>& polygon) {
  std::array<double, 3> m{};
  for (const P2 corner : {P2{0, 0}, P2{1, 0}, P2{1, 1}, P2{0, 1}}) {
    const double share = nodal_share(polygon, 0, 1, 0, 1, corner[0], corner[1]);
    m[0] += share;
    m[1] += share * corner[0];
    m[2] += share * corner[1];
  }
  return m;
}

// Triangles (tetrahedra's and wedges' faces, triangular shells) are quads whose fourth node
// repeats the third; the bilinear map collapses the edge eta = 1 into that corner, where it cannot
// be inverted. A triangle under a unit square cell with its third corner inside the cell, and the
// same with the roles swapped: the weights are the integrals of the triangle's area coordinates
// over the overlap, which reproduce its area and first moments (the area coordinates interpolate
// x and y exactly; three moments fix the three weights), and the square's side as in the test
// above. Reference: the overlap clipped here against the square, independently of the cells.
// (Before the inverse map knew triangles, Newton's method at the collapsed corner returned
// weights that made a tetrahedral sphere's contact gap -2.8 km.)
TEST(Mortar, TriangleFacetsIntegrateTheirAreaCoordinatesExactly) {
  const std::vector<P2> triangle{{-1.0, -0.5}, {2.0, -1.0}, {0.4, 0.7}};
  const auto exact = moments_in_unit_square(triangle);
  const QuadCorners square_down{Vec3{0, 0, 0}, Vec3{0, 1, 0}, Vec3{1, 1, 0}, Vec3{1, 0, 0}};
  const QuadCorners tri_up{
      Vec3{triangle[0][0], triangle[0][1], -0.01}, Vec3{triangle[1][0], triangle[1][1], -0.01},
      Vec3{triangle[2][0], triangle[2][1], -0.01}, Vec3{triangle[2][0], triangle[2][1], -0.01}};
  auto check_triangle = [&](const std::array<double, 4>& w, const QuadCorners& c) {
    EXPECT_EQ(w[3], 0.0);
    double area = 0.0, mx = 0.0, my = 0.0;
    for (int b = 0; b < 4; ++b) {
      EXPECT_GE(w[b], 0.0);
      area += w[b];
      mx += w[b] * c[b].x;
      my += w[b] * c[b].y;
    }
    EXPECT_NEAR(area, exact[0], 1e-14);
    EXPECT_NEAR(mx, exact[1], 1e-14);
    EXPECT_NEAR(my, exact[2], 1e-14);
  };
  const std::int32_t id = 3;
  const CellOverlap below = overlap_cell(square_down, {}, {0, 0, 1}, {&id, 1}, {&tri_up, 1});
  ASSERT_EQ(below.count, 1);
  EXPECT_NEAR(below.area, exact[0], 1e-14);
  check_triangle(below.target[0], tri_up);
  // The triangle is the cell (facing -z, so its corners turn the other way), the square below.
  const QuadCorners tri_down{tri_up[1], tri_up[0], tri_up[2], tri_up[2]};
  const QuadCorners square_up{Vec3{0, 0, -0.02}, Vec3{1, 0, -0.02}, Vec3{1, 1, -0.02},
                              Vec3{0, 1, -0.02}};
  const CellOverlap above = overlap_cell(tri_down, {}, {0, 0, 1}, {&id, 1}, {&square_up, 1});
  ASSERT_EQ(above.count, 1);
  EXPECT_NEAR(above.area, exact[0], 1e-14);
  check_triangle(above.own, tri_down);
  double area = 0.0;
  for (int b = 0; b < 4; ++b) area += above.target[0][b];
  EXPECT_NEAR(area, exact[0], 1e-14);
}

struct PatchResult {
  double plate_error = 0.0, block_error = 0.0, total_error = 0.0;
};

// The block's bottom (facing down, n1 x n1 facets over a unit square, turned by `angle` about its
// centre and moved by (ox, oy)) pressed d into the plate [-1, 2]^2 (n2 x n2, facing up).
PatchResult patch(int n1, int n2, double angle, double ox, double oy, bool one_way, int level) {
  const double pfac = 1e6, d = 1e-3, p = pfac * d;
  World w;
  const ContactSurface plate = add_plate(w, n2, n2, -1.0, -1.0, 3.0, 3.0, 0.0, true, pfac, 1.0);
  const auto first = static_cast<std::int32_t>(w.x.size());
  const ContactSurface block = add_plate(w, n1, n1, 0.0, 0.0, 1.0, 1.0, 1e-4, false, pfac, 1.0);
  const auto end = static_cast<std::int32_t>(w.x.size());
  const double c = std::cos(angle), s = std::sin(angle);
  auto place = [&](double x, double y) -> P2 {
    return {0.5 + c * (x - 0.5) - s * (y - 0.5) + ox, 0.5 + s * (x - 0.5) + c * (y - 0.5) + oy};
  };
  for (std::int32_t i = first; i < end; ++i) {
    const P2 q = place(w.x[i], w.y[i]);
    w.x[i] = q[0], w.y[i] = q[1];
  }
  ContactSettings settings;
  settings.damping = 0.0;
  settings.one_way = one_way;
  settings.accuracy_level = level;
  ContactInterface contact(settings, block, plate, w.mass, w.input());
  w.shift(first, end, 0.0, 0.0, -1e-4 - d);  // created open (no initial offset), now d deep
  ContactForces out = w.forces();
  contact.apply(w.input(0.0, 1e-6), out);
  PatchResult r;
  // Plate nodes: -p int_{footprint} N_i dA over the facets around each node.
  const std::vector<P2> footprint{place(0, 0), place(1, 0), place(1, 1), place(0, 1)};
  const double h = 3.0 / n2;
  double total = 0.0;
  for (int j = 0; j <= n2; ++j)
    for (int i = 0; i <= n2; ++i) {
      const double x = -1.0 + h * i, y = -1.0 + h * j;
      double share = 0.0;
      for (int a = -1; a <= 0; ++a)
        for (int b = -1; b <= 0; ++b) {
          if (i + a < 0 || i + a >= n2 || j + b < 0 || j + b >= n2) continue;
          const double xa = -1.0 + h * (i + a), ya = -1.0 + h * (j + b);
          share += nodal_share(footprint, xa, xa + h, ya, ya + h, x, y);
        }
      const std::size_t node = static_cast<std::size_t>(j * (n2 + 1) + i);
      r.plate_error = std::max(r.plate_error, std::abs(w.fz[node] + p * share) / (p / (n1 * n1)));
      total += w.fz[node];
    }
  // Block nodes: its whole bottom is covered, p h1^2 x (1, 1/2, 1/4) inside, on edges, at corners.
  const double h1 = 1.0 / n1;
  for (int j = 0; j <= n1; ++j)
    for (int i = 0; i <= n1; ++i) {
      const double share =
          h1 * h1 * ((i == 0 || i == n1) ? 0.5 : 1.0) * ((j == 0 || j == n1) ? 0.5 : 1.0);
      const std::size_t node = static_cast<std::size_t>(first + j * (n1 + 1) + i);
      r.block_error = std::max(r.block_error, std::abs(w.fz[node] - p * share) / (p * h1 * h1));
    }
  r.total_error = std::abs(-total - p) / p;
  return r;
}

TEST(Mortar, PatchTestNonMatchingRotatedMeshesLoadEveryNodeWithItsConsistentShare) {
  std::mt19937 random(27);
  std::uniform_real_distribution<double> fraction(0.0, 1.0);
  for (const auto& [n1, n2] : {std::pair{3, 5}, std::pair{4, 7}, std::pair{5, 4}})
    for (const bool one_way : {false, true})
      for (const int level : {1, 2, 3}) {
        const double angle = 0.6 * (fraction(random) - 0.5);  // within +-17 degrees
        const double ox = 0.3 * fraction(random), oy = 0.3 * fraction(random);
        const PatchResult r = patch(n1, n2, angle, ox, oy, one_way, level);
        std::cout << n1 << " on " << n2 << (one_way ? " one-way" : " symmetric") << " level "
                  << level << ": plate nodes " << r.plate_error << ", block nodes " << r.block_error
                  << ", total " << r.total_error << " of p A\n";
        EXPECT_LT(r.plate_error, 1e-6);
        EXPECT_LT(r.block_error, 1e-6);
        EXPECT_LT(r.total_error, 1e-6);
      }
}

}  // namespace
}  // namespace abut
