// Metafor's parameter dependencies (seed 002; laws/dependency.hpp): a parameter times a function
// of the time (TM) or of the penetration (GD).
//   - Coulomb and Tresca limits at a time t are the coefficients times their factors at t;
//   - a normal law scaled by f is the law with pfac f (LinearPenalty);
//   - in a static step a gap-dependent tangential penalty k_t(d) = k g(d) gives the stick
//     traction k_t(d) s, and its tangent C = -d tau / d u carries the -(dk_t/dd) s (x) n term
//     (static_contact.hpp): checked against central differences of the evaluated traction, as
//     test_static_friction_laws.cpp does, sticking and sliding.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <iostream>
#include <optional>
#include <vector>

#include "abut/contact/laws/dependency.hpp"
#include "abut/contact/laws/normal.hpp"
#include "abut/contact/laws/tangential.hpp"
#include "abut/contact/static_contact.hpp"

namespace abut {
namespace {

TEST(LawDependency, CoulombLimitsFollowTheirTimeFactors) {
  Coulomb c{
      0.6, 0.4, {}, {}, {[](double t) { return 1.0 - t; }}, {[](double t) { return 2.0 * t; }}};
  const SlipState at{100.0, 1.0, 0.0, 0.25, {}};  // N = 100 at t = 0.25
  const SlipLimits l = c.limits(at);
  EXPECT_DOUBLE_EQ(l.stick, 0.6 * 0.75 * 100.0);
  EXPECT_DOUBLE_EQ(l.slide, 0.4 * 0.5 * 100.0);
  EXPECT_DOUBLE_EQ(c.slide_slope(at), 0.4 * 0.5);
  // At t = 0.5, mu_d(t) = 0.4 > mu_s(t) = 0.3: the static coefficient is both.
  const SlipLimits late = c.limits({100.0, 1.0, 0.0, 0.5, {}});
  EXPECT_DOUBLE_EQ(late.stick, 30.0);
  EXPECT_DOUBLE_EQ(late.slide, 30.0);
}

TEST(LawDependency, TrescaLimitsFollowTheirTimeFactors) {
  Tresca t{
      0.8, 0.5, 100.0, {[](double s) { return 1.0 + s; }}, {}, {[](double s) { return 0.5 * s; }}};
  const SlipLimits l = t.limits({0.0, 2.0, 0.0, 1.0, {}});  // area 2 at t = 1
  EXPECT_DOUBLE_EQ(l.stick, 0.8 * 2.0 * 100.0 * 0.5 * 2.0);
  EXPECT_DOUBLE_EQ(l.slide, 0.5 * 100.0 * 0.5 * 2.0);
}

TEST(LawDependency, ScaledLinearPenaltyIsThePenaltyTimesTheFactor) {
  const NormalResponse a = scaled(evaluate(LinearPenalty{}, 0.01, 1000.0), 2.5);
  const NormalResponse b = evaluate(LinearPenalty{}, 0.01, 2500.0);
  EXPECT_DOUBLE_EQ(a.pressure, b.pressure);
  EXPECT_DOUBLE_EQ(a.stiffness, b.stiffness);
  EXPECT_DOUBLE_EQ(a.energy, b.energy);
}

TEST(LawDependency, TangentialPenaltySlopeIsTheDerivativeOfItsFactor) {
  // g(d) = 1 + 50 d + 1000 d^2, f(t) = 3: slope 3 (50 + 2000 d).
  TangentialPenalty k{[](double d) { return 1.0 + 50.0 * d + 1000.0 * d * d; },
                      {[](double) { return 3.0; }}};
  for (const double d : {0.0, 0.01, 0.02}) {
    EXPECT_DOUBLE_EQ(k.factor(d, 0.0), 3.0 * (1.0 + 50.0 * d + 1000.0 * d * d));
    EXPECT_NEAR(k.slope(d, 0.0), 3.0 * (50.0 + 2000.0 * d), 1e-6);
  }
}

constexpr double kPenalty = 1000.0, kDepth = 0.02;

// A node pressed kDepth into the facet [-1, 1]^2 at z = 0 (test_static_friction_laws.cpp), with
// k_t(d) = kPenalty g(d) and the normal law times f(t).
struct PressedNode {
  std::vector<double> x{-1, 1, 1, -1, 0, 0, 0.2, 0.2}, y{-1, -1, 1, 1, 0, 0.2, 0.2, 0},
      z{0, 0, 0, 0, 0, 0, 0, 0};
  std::optional<StaticContact> contact;
  double time = 0.0;

  PressedNode(const TangentialLaw& law, TangentialPenalty kt, TimeFactor normal) {
    ContactSurface main, secondary;
    main.add({0, 1, 2, 3}, 1, 0.0, 1.0);
    secondary.add({4, 5, 6, 7}, 2, 0.0, 1.0);
    StaticContactSettings s;
    s.node_to_surface = true;
    s.penalty = kPenalty;
    s.depth = 0.5;
    s.search_distance = 0.5;
    s.tangential_law = law;
    s.stick_slope_factor = std::move(kt);
    s.normal_in_time = std::move(normal);
    const std::vector<std::int32_t> nodes{4};
    contact.emplace(s, secondary, main, nodes, ContactInput{x, y, z, {}, {}, {}, 0, 0, {}});
    for (int n = 4; n < 8; ++n) z[n] = -kDepth;
    evaluate({0, 0, -kDepth});
    contact->commit();
  }
  Vec3 evaluate(const Vec3& u) {
    x[4] = u.x, y[4] = u.y, z[4] = u.z;
    contact->evaluate({x, y, z, {}, {}, {}, time, 0.0, {}});
    return contact->elements().empty() ? Vec3{} : contact->elements()[0].traction;
  }
  const StaticContactPoint& point() const { return contact->points()[0]; }
};

double tangent_error(PressedNode& c, const Vec3& u) {
  c.evaluate(u);
  const std::array<double, 9> C = c.contact->elements()[0].tangent;
  double worst = 0.0, scale = 0.0;
  for (const double v : C) scale = std::max(scale, std::abs(v));
  const double h = 1e-7;
  for (int j = 0; j < 3; ++j) {
    Vec3 du{};
    du[j] = h;
    const Vec3 plus = c.evaluate(u + du), minus = c.evaluate(u - du);
    for (int i = 0; i < 3; ++i)
      worst = std::max(worst, std::abs(C[3 * i + j] + (plus[i] - minus[i]) / (2.0 * h)));
  }
  c.evaluate(u);
  return worst / scale;
}

TEST(LawDependency, StaticGapDependentTangentialPenaltyHasItsConsistentTangent) {
  const auto g = [](double d) { return 1.0 + 50.0 * d + 1000.0 * d * d; };  // 2.4 at d = 0.02
  const double p = kPenalty * kDepth, kt = kPenalty * g(kDepth);
  PressedNode c(Coulomb{0.5, 0.3, {}, {}, {}, {}}, {g, {}}, {});
  // Sticking: t = -k_t(d) u (u = 0.3 mu_s p / k_t: well within mu_s p).
  const double hold = 0.3 * 0.5 * p / kt;
  c.evaluate({hold, 0.0, -kDepth});
  EXPECT_FALSE(c.point().slipping);
  EXPECT_NEAR(c.point().traction.x, -kt * hold, 1e-12 * p);
  const double stick_error = tangent_error(c, {hold, 0.3 * hold, -kDepth});
  // Sliding: beyond mu_s p, at mu_d p.
  const double past = 2.0 * 0.5 * p / kt;
  c.evaluate({past, 0.0, -kDepth});
  EXPECT_TRUE(c.point().slipping);
  EXPECT_NEAR(c.point().traction.x, -0.3 * p, 1e-12 * p);
  const double slip_error = tangent_error(c, {past, 0.4 * past, -kDepth});
  std::cout << "k_t(d) tangent vs central differences: stick " << stick_error << ", slip "
            << slip_error << "\n";
  EXPECT_LT(stick_error, 1e-6);
  EXPECT_LT(slip_error, 1e-6);
}

TEST(LawDependency, StaticTimeDependentPenaltyScalesPressureNotTheTangent) {
  // pfac f(t), f(t) = 1 + t, and k_t = pen f(t) (PEN_T TIME) evaluated at t = 1.5: p = 2.5 pfac d.
  const auto f = [](double t) { return 1.0 + t; };
  PressedNode c(Coulomb{0.5, 0.5, {}, {}, {}, {}}, {{}, {f}}, {f});
  c.time = 1.5;
  const double u = 1e-4;
  c.evaluate({u, 0.0, -kDepth});
  EXPECT_NEAR(c.point().pressure, 2.5 * kPenalty * kDepth, 1e-12 * kPenalty);
  EXPECT_NEAR(c.point().traction.x, -2.5 * kPenalty * u, 1e-12 * kPenalty);
  EXPECT_LT(tangent_error(c, {u, 0.2 * u, -kDepth}), 1e-6);
}

}  // namespace
}  // namespace abut
