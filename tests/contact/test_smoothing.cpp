// Contact surface smoothing with Nagata patches (smoothing.hpp; OptiStruct SMOOTH, seed 003).
// References from the patch's definition (T. Nagata, CAGD 22 (2005) 327-347): on a circle of
// radius R cut into chords of angle 2 phi, with the nodal normals radial, the edge curve is
// x(t) = x_a (1 - t) + x_b t - c t (1 - t), c = -2 R sin^2(phi) / cos(phi) along the chord's
// normal, whose mid-point lies at R (cos phi + sin^2 phi / (2 cos phi)) from the centre, the
// farthest point of the curve (R (1 + 3.136e-3) for phi = pi / 8, where the chord's own mid-point
// lies 7.6% of R inside).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "abut/contact/smoothing.hpp"

namespace abut {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Surface {
  std::vector<double> x, y, z;
  std::vector<std::array<std::int32_t, 4>> facets;
  std::int32_t node(double px, double py, double pz) {
    x.push_back(px), y.push_back(py), z.push_back(pz);
    return static_cast<std::int32_t>(x.size()) - 1;
  }
};

// A closed cylinder of radius r about z, `around` facets round and 2 along, outward normals.
Surface cylinder(double r, int around) {
  Surface s;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < around; ++i) {
      const double a = 2.0 * kPi * i / around;
      s.node(r * std::cos(a), r * std::sin(a), j * 0.5);
    }
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < around; ++i) {
      const int k = (i + 1) % around;
      s.facets.push_back(
          {j * around + i, j * around + k, (j + 1) * around + k, (j + 1) * around + i});
    }
  return s;
}

// The positions of the host nodes and the dependent nodes after an update.
struct Placed {
  std::vector<double> x, y, z;
};
Placed place(const Surface& s, NagataSmoothing& smoothing, DependentNodes& d) {
  smoothing.update(s.x, s.y, s.z, d);
  Placed p;
  d.extend(s.x, s.y, s.z, p.x, p.y, p.z);
  return p;
}

TEST(NagataSmoothing, ACoarseCylinderBecomesNagatasCurves) {
  const double r = 2.0;
  const Surface s = cylinder(r, 8);  // chords of 45 degrees: below the crease angle
  DependentNodes d;
  d.first = static_cast<std::int32_t>(s.x.size());
  NagataSmoothing smoothing;
  const NagataSmoothing::Facets out = smoothing.smooth(s.facets, d, 4);
  ASSERT_EQ(out.facets.size(), 16u * 16u);
  const Placed p = place(s, smoothing, d);
  const double phi = kPi / 8.0;
  const double farthest =
      r * (std::cos(phi) + std::sin(phi) * std::sin(phi) / (2.0 * std::cos(phi)));
  double lo = 1e300, hi = 0.0;
  for (std::size_t k = static_cast<std::size_t>(d.first); k < p.x.size(); ++k) {
    const double radius = std::hypot(p.x[k], p.y[k]);
    lo = std::min(lo, radius), hi = std::max(hi, radius);
  }
  EXPECT_NEAR(hi, farthest, 1e-12 * r);  // the edges' mid-points (n = 4 has points there)
  EXPECT_GE(lo, r * (1.0 - 1e-12));      // no point inside the circle
  // Each facet's patch gives its corners: the parent's shape at the corners' coordinates.
  for (std::size_t f = 0; f < out.facets.size(); f += 37) {
    const FacetParent& parent = out.parents[f];
    for (int a = 0; a < 4; ++a) {
      double n[FacetParent::kMaxNodes];
      parent.shape(parent.corner_xi[a].data(), n);
      double px = 0.0;
      for (int b = 0; b < parent.count; ++b) px += n[b] * p.x[parent.nodes[b]];
      EXPECT_NEAR(px, p.x[out.facets[f][a]], 1e-12 * r) << f << " " << a;
    }
  }
}

// A short cylinder (one facet along its axis) closed by flat ends: its rims fold by 90 degrees,
// creases, yet each rim edge is the same Nagata curve as without the end (its tangents are normal
// to the normals of both sides: the side's radial one and the end's axial one), and the ends stay
// flat, so the two sides share it.
TEST(NagataSmoothing, ACreaseFollowsTheCurveOfBothItsSides) {
  const double r = 2.0;
  Surface s = cylinder(r, 8);
  s.facets.resize(8);  // one facet along the axis: nodes 0-7 at z = 0, 8-15 at z = 0.5
  const std::int32_t bottom = s.node(0.0, 0.0, 0.0), top = s.node(0.0, 0.0, 0.5);
  for (int i = 0; i < 8; ++i) {
    const int k = (i + 1) % 8;
    s.facets.push_back({k, i, bottom, bottom});    // normal -z
    s.facets.push_back({8 + i, 8 + k, top, top});  // normal +z
  }
  DependentNodes d;
  d.first = static_cast<std::int32_t>(s.x.size());
  NagataSmoothing smoothing;
  smoothing.smooth(s.facets, d, 4);
  const Placed p = place(s, smoothing, d);
  const double phi = kPi / 8.0;
  const double farthest =
      r * (std::cos(phi) + std::sin(phi) * std::sin(phi) / (2.0 * std::cos(phi)));
  double hi = 0.0;
  for (std::size_t k = static_cast<std::size_t>(d.first); k < p.x.size(); ++k) {
    const bool on_end = std::abs(p.z[k]) < 1e-9 || std::abs(p.z[k] - 0.5) < 1e-9;
    const bool on_side = std::abs(std::hypot(p.x[k], p.y[k]) - r) < 0.1 * r;
    EXPECT_TRUE(on_end || on_side) << k;
    if (on_end) {
      EXPECT_NEAR(p.z[k], std::round(2.0 * p.z[k]) / 2.0, 1e-14) << k;  // flat ends
    }
    hi = std::max(hi, std::hypot(p.x[k], p.y[k]));
  }
  EXPECT_NEAR(hi, farthest, 1e-12 * r);  // the rims' mid-points bulge as the side's curves
}

TEST(NagataSmoothing, FacetsThatShareAnEdgeShareItsPoints) {
  Surface s;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) s.node(i, j, 0.0);
  s.facets = {{0, 1, 4, 3}, {1, 2, 5, 4}};
  DependentNodes d;
  d.first = 6;
  NagataSmoothing smoothing;
  smoothing.smooth(s.facets, d, 4);
  // 25 grid points a facet less its 4 nodes, less the 3 inner points of the shared edge (the
  // edges' mid-points among them).
  EXPECT_EQ(d.size(), 2u * 21u - 3u);
  const Placed p = place(s, smoothing, d);
  for (std::size_t k = 6; k < p.z.size(); ++k) EXPECT_EQ(p.z[k], 0.0);  // a plane stays a plane
}

// A cube's faces, 2 x 2 facets each: its edges and corners fold by 90 degrees, beyond the crease
// angle, so every edge that touches them stays straight and the smoothed cube is the cube.
TEST(NagataSmoothing, ABoxKeepsItsEdges) {
  Surface s;
  const auto id = [](int i, int j, int k) { return i + 3 * j + 9 * k; };
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) s.node(i - 1.0, j - 1.0, k - 1.0);
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      s.facets.push_back({id(a, b, 0), id(a, b + 1, 0), id(a + 1, b + 1, 0), id(a + 1, b, 0)});
      s.facets.push_back({id(a, b, 2), id(a + 1, b, 2), id(a + 1, b + 1, 2), id(a, b + 1, 2)});
      s.facets.push_back({id(a, 0, b), id(a + 1, 0, b), id(a + 1, 0, b + 1), id(a, 0, b + 1)});
      s.facets.push_back({id(a, 2, b), id(a, 2, b + 1), id(a + 1, 2, b + 1), id(a + 1, 2, b)});
      s.facets.push_back({id(0, a, b), id(0, a, b + 1), id(0, a + 1, b + 1), id(0, a + 1, b)});
      s.facets.push_back({id(2, a, b), id(2, a + 1, b), id(2, a + 1, b + 1), id(2, a, b + 1)});
    }
  DependentNodes d;
  d.first = 27;
  NagataSmoothing smoothing;  // 60 degrees
  smoothing.smooth(s.facets, d, 4);
  const Placed p = place(s, smoothing, d);
  for (std::size_t k = 27; k < p.x.size(); ++k) {
    const double m = std::max({std::abs(p.x[k]), std::abs(p.y[k]), std::abs(p.z[k])});
    EXPECT_NEAR(m, 1.0, 1e-14) << k;  // on a face of the cube
  }
}

TEST(NagataSmoothing, TrianglesOfASphereBulgeTowardsIt) {
  // An octahedron's 8 triangles on the unit sphere: nodal normals radial, edges of 90 degrees,
  // each face 54.7 degrees from its corners' normals. With a crease angle of 120 degrees, the
  // edges' mid-points lie at cos(phi) + sin^2(phi) / (2 cos(phi)) = 1.0607 from the centre (phi =
  // 45 degrees), where the chords' lie at 0.7071.
  Surface s;
  s.node(1, 0, 0), s.node(0, 1, 0), s.node(-1, 0, 0), s.node(0, -1, 0), s.node(0, 0, 1),
      s.node(0, 0, -1);
  for (int i = 0; i < 4; ++i) {
    s.facets.push_back({i, (i + 1) % 4, 4, 4});
    s.facets.push_back({(i + 1) % 4, i, 5, 5});
  }
  DependentNodes d;
  d.first = 6;
  NagataSmoothing smoothing(120.0);
  smoothing.smooth(s.facets, d, 2);  // n = 2: the corners are the edges' mid-points
  ASSERT_EQ(d.size(), 12u);
  const Placed p = place(s, smoothing, d);
  const double phi = kPi / 4.0;
  for (std::size_t k = 6; k < p.x.size(); ++k)
    EXPECT_NEAR(std::hypot(p.x[k], p.y[k], p.z[k]),
                std::cos(phi) + std::sin(phi) * std::sin(phi) / (2.0 * std::cos(phi)), 1e-12);
}

}  // namespace
}  // namespace abut
