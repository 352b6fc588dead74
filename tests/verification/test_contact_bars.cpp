// Two identical elastic bars colliding head-on, each at v toward the other. Elementary 1D wave
// theory (Graff, "Wave Motion in Elastic Solids", 1975, ch. 2; Goldsmith, "Impact", 1960,
// ch. 4): at first touch a compressive front (stress rho c v, c = sqrt(E/rho)) runs into each
// bar while the interface stays at rest; the fronts reflect at the free ends as release waves
// that reach the interface at 2L/c, when both bars are stress-free and moving apart at v. So
// the contact lasts 2L/c and each bar's centre-of-mass velocity reverses (the velocities swap).
//
// Model: steel bars 0.2 m long of 200 cubic elements (1 mm), Poisson's ratio 0 (no lateral
// coupling: exactly 1D), v = 10 m/s (strain v/c = 0.2%), initial gap 0.1 mm. pfac = E/h, the
// axial stiffness of one element per unit area: the interface spring then delays the stress
// build-up only by rho c / (2 pfac) = h / (2c), half an element transit. The remaining velocity
// deficit comes from the release front, which the solver's linear bulk viscosity has spread
// over a width ~ sqrt(h L); it shrinks as the mesh is refined (1.9%, 1.4%, 1.0% at 80, 160,
// 320 elements).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>

#include "run_to.hpp"
#include "two_bars.hpp"

namespace abut {
namespace {

constexpr double kRho = 7800.0, kE = 210e9, kV = 10.0, kL = 0.2;

// Bars of n elements along x with a square cross-section of side b; pfac = E/h.
std::string bars_deck(int n, double b, const std::string& extra = "") {
  return verification::two_bars_deck({kL, n, b, kV, 1.2e-4, kE * n / kL, extra});
}

struct Impact : verification::ContactSpans {
  double v_left = 0.0, v_right = 0.0;
};

Impact collide(int n, double b, const std::string& extra = "") {
  const Model model = read_deck_string(bars_deck(n, b, extra), "bars.k");
  Simulation sim(model);
  Impact r;
  r.start(sim);
  verification::run_to(sim, sim.end_time(), [&](const Simulation& s) { r.record(s); });
  const auto parts = sim.part_states();
  r.v_left = parts.at(0).velocity.x;
  r.v_right = parts.at(1).velocity.x;
  return r;
}

TEST(ContactBars, ContactLastsTwoLOverCAndTheVelocitiesSwap) {
  const Impact r = collide(200, 0.001);  // cubic 1 mm elements
  const double c = std::sqrt(kE / kRho);
  const double expected = 2.0 * kL / c;
  const double duration = r.end - r.begin;
  std::cout << "contact duration " << duration << " s, 2L/c = " << expected << " s, error "
            << 100.0 * (duration - expected) / expected << "%\n"
            << "velocities after: left " << r.v_left << " m/s, right " << r.v_right
            << " m/s (before: +" << kV << ", -" << kV << "), errors "
            << 100.0 * (r.v_left + kV) / kV << "%, " << 100.0 * (kV - r.v_right) / kV << "%\n";
  EXPECT_EQ(r.periods, 1);  // one uninterrupted contact
  ASSERT_GT(r.begin, 0.0);
  ASSERT_GT(r.end, r.begin);
  EXPECT_NEAR(duration, expected, 0.02 * expected);
  EXPECT_NEAR(r.v_left, -kV, 0.02 * kV);
  EXPECT_NEAR(r.v_right, kV, 0.02 * kV);
}

// Slender elements (1.25 mm long, 5 mm across): a side facet is then shorter than its detection
// depth (half the 5 mm thickness), so a point on one bar's end face lies within reach of side
// facets of the other bar beyond their smooth edges. Contact must still begin only when the
// ends meet (after gap / 2v = 5 us) and last 2L/c. (The velocity deficit is larger here: the
// bulk viscosity's length scale is the cube root of the element volume, 3.1 mm.)
TEST(ContactBars, SlenderElementsTouchOnlyWhenTheEndsMeet) {
  const Impact r = collide(160, 0.005);
  const double c = std::sqrt(kE / kRho);
  const double expected = 2.0 * kL / c;
  std::cout << "slender elements: contact from " << r.begin << " s (ends meet at 5e-06 s) for "
            << r.end - r.begin << " s, error " << 100.0 * (r.end - r.begin - expected) / expected
            << "%\n";
  EXPECT_EQ(r.periods, 1);
  EXPECT_NEAR(r.begin, 5e-6, 2e-7);
  EXPECT_NEAR(r.end - r.begin, expected, 0.02 * expected);
}

// The same impact with node-to-surface contact (Radioss TYPE25, OptiStruct N2S), symmetric: each
// bar's end nodes against the other bar's end facet, each node's spring pfac times its tributary
// area, so the interface is as stiff as with integration points.
TEST(ContactBars, NodeToSurfaceContactLastsTwoLOverC) {
  const Impact r = collide(200, 0.001, "*CONTACT_DISCRETIZATION\n1, N2S\n");
  const double c = std::sqrt(kE / kRho);
  const double expected = 2.0 * kL / c;
  const double duration = r.end - r.begin;
  std::cout << "node-to-surface: contact duration " << duration << " s, error "
            << 100.0 * (duration - expected) / expected << "%; velocities after " << r.v_left
            << ", " << r.v_right << " m/s\n";
  EXPECT_EQ(r.periods, 1);
  EXPECT_NEAR(duration, expected, 0.02 * expected);
  EXPECT_NEAR(r.v_left, -kV, 0.02 * kV);
  EXPECT_NEAR(r.v_right, kV, 0.02 * kV);
}

}  // namespace
}  // namespace abut
