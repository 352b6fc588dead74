// Surface-to-surface cells of the static contact integrated point by point (mortar.hpp,
// CellSample): a unit square facet pressed by a tilted plane, so that the penetration varies
// linearly over the one cell of the facet (accuracy level 1), d(x) = d0 + s x. The reference is
// the integral of the linear penalty over the facet with its bilinear shape functions, by hand:
//   f_a = K int d N_a dA = K (d0/4 + s/12) on the two nodes at x = 0, K (d0/4 + s/6) at x = 1,
//   S_ab = K int N_a N_b dA = K/9 (a = b), K/18 (a, b along an edge), K/36 (across),
// along the plane's normal scaled to a unit z part (the cell's push, mortar.hpp). The cell's mean
// gap alone would give K (d0/4 + s/8) to every node: off by s/24. CalculiX's contact4 (a C3D20
// cube pressed into another's face) moved from U 5.0e-4 to 9.8e-6 of the largest displacement
// with the samples (test_ccx_conformance.py).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <iostream>
#include <vector>

#include "abut/contact/static_contact.hpp"

namespace abut {
namespace {

constexpr double kPenalty = 1000.0, kDepth = 0.01, kSlope = 0.004;

// Nodes 0-3: the secondary facet, the unit square at z = 0 facing -z. Nodes 4-7: the main facet,
// a larger square under it facing +z, raised to z = kDepth + kSlope x into it.
struct TiltedPress {
  std::vector<double> x{0, 0, 1, 1, -1, 2, 2, -1}, y{0, 1, 1, 0, -1, -1, 2, 2};
  std::vector<double> z{0, 0, 0, 0, 0, 0, 0, 0};
  TiltedPress() {
    for (int n = 4; n < 8; ++n) z[n] = kDepth + kSlope * x[n];
  }
  StaticContact contact() const {
    ContactSurface secondary, main;
    secondary.add({0, 1, 2, 3}, 1, 0.0, 1.0);
    main.add({4, 5, 6, 7}, 2, 0.0, 1.0);
    StaticContactSettings s;
    s.penalty = kPenalty;
    s.accuracy_level = 1;  // one cell: the facet
    s.depth = 0.5;
    s.search_distance = 0.5;
    return StaticContact(s, secondary, main, {}, {x, y, z, {}, {}, {}, 0, 0, {}});
  }
};

// The nodal forces (3 per node, the element's node order) of a contact element.
std::vector<double> forces(const StaticContactElement& e) {
  std::vector<double> f(3 * static_cast<std::size_t>(e.count), 0.0);
  e.add_forces(f.data());
  return f;
}

TEST(StaticCellSamples, LinearPenetrationLoadsTheNodesWithItsIntegral) {
  const TiltedPress press;
  StaticContact contact = press.contact();
  contact.evaluate({press.x, press.y, press.z, {}, {}, {}, 0, 0, {}});
  ASSERT_EQ(contact.elements().size(), 1u);
  const StaticContactElement& e = contact.elements()[0];
  const std::vector<double> f = forces(e);
  std::vector<double> k(9 * static_cast<std::size_t>(e.count * e.count));
  e.stiffness(k.data());
  const double fz_at_0 = kPenalty * (kDepth / 4 + kSlope / 12);
  const double fz_at_1 = kPenalty * (kDepth / 4 + kSlope / 6);
  double total_z = 0.0;
  int seen = 0;
  for (int a = 0; a < e.count; ++a) {
    const auto n = static_cast<std::size_t>(e.nodes[static_cast<std::size_t>(a)]);
    const double fz = f[3 * static_cast<std::size_t>(a) + 2];
    total_z += fz;
    if (n >= 4) continue;  // the main facet's nodes: their share balances, checked in total
    ++seen;
    // The secondary is pushed off the main surface under it (+z), along the push (-s, 0, 1).
    const double expected = press.x[n] == 0.0 ? fz_at_0 : fz_at_1;
    EXPECT_NEAR(fz, expected, 1e-12 * expected) << "node " << n;
    EXPECT_NEAR(f[3 * static_cast<std::size_t>(a)], -kSlope * fz, 1e-12 * expected);
    for (int b = 0; b < e.count; ++b) {
      const auto m = static_cast<std::size_t>(e.nodes[static_cast<std::size_t>(b)]);
      if (m >= 4) continue;
      const bool same = n == m;
      const bool across = press.x[n] != press.x[m] && press.y[n] != press.y[m];
      const double s_ab = kPenalty * (same ? 1.0 / 9 : across ? 1.0 / 36 : 1.0 / 18);
      const std::size_t row = 3 * static_cast<std::size_t>(a) + 2;
      const std::size_t col = 3 * static_cast<std::size_t>(b) + 2;
      EXPECT_NEAR(k[row * 3 * static_cast<std::size_t>(e.count) + col], s_ab, 1e-12 * kPenalty);
    }
  }
  EXPECT_EQ(seen, 4);
  EXPECT_NEAR(total_z, 0.0, 1e-12 * kPenalty * kDepth);  // action and reaction
  // The point's pressure is the mean over the cell, K (d0 + s/2).
  EXPECT_NEAR(contact.points()[0].pressure, kPenalty * (kDepth + kSlope / 2), 1e-12 * kPenalty);
}

// A cell half open: d(x) = s (x - 1/2) closes on x > 1/2, and only that half pushes. The samples
// see the law's kink only through their places (it is no edge of the overlap), so the reference,
// the total force K s / 8 (the integral of d over the closed half), holds within the rule's error
// there, stated as 10% (measured -5.5%); the cell's mean gap finds it exactly touching, with no
// force at all.
TEST(StaticCellSamples, APartlyOpenCellPushesWithItsClosedPart) {
  TiltedPress press;
  for (int n = 4; n < 8; ++n) press.z[n] = kSlope * (press.x[n] - 0.5);
  StaticContact contact = press.contact();
  contact.evaluate({press.x, press.y, press.z, {}, {}, {}, 0, 0, {}});
  ASSERT_EQ(contact.elements().size(), 1u);
  const StaticContactElement& e = contact.elements()[0];
  const std::vector<double> f = forces(e);
  double pushed = 0.0;
  for (int a = 0; a < e.count; ++a)
    if (e.nodes[static_cast<std::size_t>(a)] < 4) pushed += f[3 * static_cast<std::size_t>(a) + 2];
  const double exact = kPenalty * kSlope / 8;
  std::cout << "partly open cell: force " << pushed << " of " << exact << "\n";
  EXPECT_NEAR(pushed, exact, 0.1 * exact);
}

// The tangent of a cell whose push m turns from its normal n: sliding the secondary facet rigidly
// by dx changes every sample's penetration by m . dx (the main plane is z = d0 + s x, the gap is
// measured along n = z, and the samples keep their places on the facet), so the secondary's forces
// F_a m change by exactly S_ab m (m . dx): the tangent is S_ab m (x) m. A slide along the surface,
// dx = e_x, changes the forces by -s S_ab m, which a tangent S_ab n (x) n misses altogether; it
// made Newton converge linearly on CalculiX's beamcontact with its penalty x 100, where the push of
// a beam bent against a plate turned by a slope of 0.035 (docs/contact.md). Reference: central
// differences of the forces, exact to round-off here (linear law, every sample closed).
TEST(StaticCellSamples, TheTangentIsTheForcesDerivativeUnderARigidSlide) {
  TiltedPress press;
  constexpr double kSteepSlope = 0.03;
  for (int n = 4; n < 8; ++n) press.z[n] = kDepth + kSteepSlope * press.x[n];
  StaticContact contact = press.contact();
  // The secondary's nodal forces, summed per direction, with the facet moved by h along axis.
  auto secondary_force = [&](int axis, double h) {
    TiltedPress moved = press;
    std::vector<double>* coordinate[3] = {&moved.x, &moved.y, &moved.z};
    for (int n = 0; n < 4; ++n) (*coordinate[axis])[static_cast<std::size_t>(n)] += h;
    contact.evaluate({moved.x, moved.y, moved.z, {}, {}, {}, 0, 0, {}});
    EXPECT_EQ(contact.elements().size(), 1u);
    const StaticContactElement& e = contact.elements()[0];
    const std::vector<double> f = forces(e);
    std::array<double, 3> sum{};
    for (int a = 0; a < e.count; ++a)
      if (e.nodes[static_cast<std::size_t>(a)] < 4)
        for (int i = 0; i < 3; ++i)
          sum[static_cast<std::size_t>(i)] +=
              f[3 * static_cast<std::size_t>(a) + static_cast<std::size_t>(i)];
    return sum;
  };
  contact.evaluate({press.x, press.y, press.z, {}, {}, {}, 0, 0, {}});
  const StaticContactElement e = contact.elements()[0];
  const auto m = static_cast<std::size_t>(3 * e.count);
  std::vector<double> k(m * m);
  e.stiffness(k.data());
  constexpr double h = 1e-6;
  for (int axis = 0; axis < 3; ++axis) {
    const std::array<double, 3> plus = secondary_force(axis, h), minus = secondary_force(axis, -h);
    for (int i = 0; i < 3; ++i) {
      // -d f_i / d u_axis of the secondary's nodes, summed over the slid nodes (columns) too.
      double tangent = 0.0;
      for (int a = 0; a < e.count; ++a)
        for (int b = 0; b < e.count; ++b)
          if (e.nodes[static_cast<std::size_t>(a)] < 4 && e.nodes[static_cast<std::size_t>(b)] < 4)
            tangent += k[(3 * static_cast<std::size_t>(a) + static_cast<std::size_t>(i)) * m +
                         3 * static_cast<std::size_t>(b) + static_cast<std::size_t>(axis)];
      const double derivative =
          -(plus[static_cast<std::size_t>(i)] - minus[static_cast<std::size_t>(i)]) / (2 * h);
      EXPECT_NEAR(tangent, derivative, 1e-6 * kPenalty * kSteepSlope)
          << "force "
          << "xyz"[i] << " under a slide along "
          << "xyz"[axis];
    }
  }
}

}  // namespace
}  // namespace abut
