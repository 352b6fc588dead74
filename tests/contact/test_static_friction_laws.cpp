// Tangential laws in static steps (issue 31): the static contact takes the explicit interface's
// laws (laws/tangential.hpp) with their consistent tangents. A node pressed into a square facet
// (the fixture of test_static_contact_initial.cpp) and moved sideways:
//   - Coulomb with mu_s > mu_d: a point that stuck at the last converged state holds up to
//     mu_s p, then slides at mu_d p (Metafor's CoulombContactMaterial, seed 002);
//   - Tresca: slides at m_d k whatever the pressure (Metafor's TrescaContactMaterial, seed 002);
//   - a pressure-dependent mu (Radioss Ifric 1 with C1 only: mu = Fric + C1 p, seed 004) slides at
//     mu(p) p.
// The tangent C = -d tau / d u of the point's traction tau = p n + t must be the derivative of
// the traction (Wriggers, Computational Contact Mechanics, 2006, section 10.3.2): checked against
// central differences of the evaluated traction, sticking and sliding, so that Newton's method
// converges quadratically.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <type_traits>
#include <variant>
#include <vector>

#include "abut/contact/static_contact.hpp"

namespace abut {
namespace {

constexpr double kPenalty = 1000.0, kDepth = 0.02;  // p = 20

// Nodes 0-3: the main facet [-1, 1]^2 at z = 0 (normal +z). Node 4: the secondary node, with
// nodes 5-7 its facet (0.2 x 0.2, facing -z) for its tributary area.
struct PressedNode {
  std::vector<double> x{-1, 1, 1, -1, 0, 0, 0.2, 0.2}, y{-1, -1, 1, 1, 0, 0.2, 0.2, 0},
      z{0, 0, 0, 0, 0, 0, 0, 0};
  StaticContact contact;

  static StaticContact make(const TangentialLaw& law, PressedNode& self,
                            std::optional<Adhesion> adhesion) {
    ContactSurface main, secondary;
    main.add({0, 1, 2, 3}, 1, 0.0, 1.0);
    secondary.add({4, 5, 6, 7}, 2, 0.0, 1.0);
    StaticContactSettings s;
    s.node_to_surface = true;
    s.penalty = kPenalty;
    s.depth = 0.5;
    s.search_distance = 0.5;
    s.tangential_law = law;
    s.adhesion = adhesion;
    const std::vector<std::int32_t> nodes{4};
    return StaticContact(s, secondary, main, nodes, {self.x, self.y, self.z, {}, {}, {}, 0, 0, {}});
  }
  explicit PressedNode(const TangentialLaw& law, std::optional<Adhesion> adhesion = {})
      : contact(make(law, *this, adhesion)) {
    for (int n = 4; n < 8; ++n) z[n] = -kDepth;
    evaluate({0, 0, -kDepth});
    contact.commit();  // pressed, sticking, no tangential traction yet
  }
  double dt = 0.0;  // the increment: the sliding speed is the slip over it
  // The node at u (its facet follows in z only); the point's whole traction p n + t.
  Vec3 evaluate(const Vec3& u) {
    x[4] = u.x, y[4] = u.y, z[4] = u.z;
    contact.evaluate({x, y, z, {}, {}, {}, 0, dt, {}});
    return contact.elements().empty() ? Vec3{} : contact.elements()[0].traction;
  }
  const StaticContactPoint& point() const { return contact.points()[0]; }
};

// |C_ij + d tau_i / d u_j| over |C|, by central differences of step h.
double tangent_error(PressedNode& c, const Vec3& u) {
  c.evaluate(u);
  const std::array<double, 9> C = c.contact.elements()[0].tangent;
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

TEST(StaticFrictionLaws, StaticCoulombHoldsUpToMuSThenSlidesAtMuD) {
  const double mu_s = 0.5, mu_d = 0.3, p = kPenalty * kDepth;
  PressedNode c(Coulomb{mu_s, mu_d, {}, {}, {}, {}});
  // Beyond mu_d p but within mu_s p: t = k_t slip (k_t = the penalty), sticking.
  const double hold = 0.45 * p / kPenalty;
  c.evaluate({hold, 0.0, -kDepth});
  EXPECT_FALSE(c.point().slipping);
  EXPECT_NEAR(c.point().traction.x, -0.45 * p, 1e-12 * p);
  EXPECT_LT(tangent_error(c, {hold, 0.0, -kDepth}), 1e-6);
  // Past mu_s p: slides at mu_d p, along the slip.
  const double past = 0.6 * p / kPenalty;
  c.evaluate({past, 0.0, -kDepth});
  EXPECT_TRUE(c.point().slipping);
  EXPECT_NEAR(c.point().traction.x, -mu_d * p, 1e-12 * p);
  EXPECT_LT(tangent_error(c, {past, 0.2 * past, -kDepth}), 1e-6);
  // Once it slid (committed), it holds only mu_d p: a trial of 0.4 p, within mu_s p, slides.
  c.evaluate({past, 0.0, -kDepth});
  c.contact.commit();
  c.evaluate({past + 0.1 * p / kPenalty, 0.0, -kDepth});
  EXPECT_TRUE(c.point().slipping);
  EXPECT_NEAR(c.point().traction.x, -mu_d * p, 1e-12 * p);
}

TEST(StaticFrictionLaws, TrescaSlidesAtMdKWhateverThePressure) {
  const double m_s = 0.6, m_d = 0.5, k = 4.0;  // m_d k = 2 < mu p for any mu > 0.1
  for (const double deeper : {0.0, 0.01}) {
    PressedNode c(Tresca{m_s, m_d, k, {}, {}, {}});
    const Vec3 u{0.1, 0.05, -kDepth - deeper};
    c.evaluate(u);
    EXPECT_TRUE(c.point().slipping);
    EXPECT_NEAR(norm(c.point().traction), m_d * k, 1e-12 * m_d * k) << "deeper " << deeper;
    EXPECT_LT(tangent_error(c, u), 1e-6);
  }
}

TEST(StaticFrictionLaws, PressureDependentMuSlidesAtMuOfPTimesP) {
  const double fric = 0.1, c1 = 0.01, p = kPenalty * kDepth;  // mu(20) = 0.3
  ViscousFriction law;
  law.fric = fric;
  law.c[0] = c1;
  PressedNode c(Coulomb{0.0, 0.0, {}, law, {}, {}});
  const Vec3 u{0.1, 0.0, -kDepth};
  c.evaluate(u);
  EXPECT_TRUE(c.point().slipping);
  EXPECT_NEAR(c.point().traction.x, -(fric + c1 * p) * p, 1e-12 * p);
  // The slope d(mu p)/dp = mu + p dmu/dp = 0.3 + 0.2 enters the tangent.
  EXPECT_LT(tangent_error(c, {0.1, 0.03, -kDepth}), 1e-6);
}

// Laws of the sliding speed V (Radioss Ifric 1 with its V and p V terms, Ifric 3), V the slip
// over the increment dt = 0.5: mu(p, V) p at V = |slip| / dt, and the tangent with dL/dV.
TEST(StaticFrictionLaws, SpeedDependentMuSlidesAtMuOfVAndTakesItsSlopeInTheTangent) {
  const double p = kPenalty * kDepth;
  ViscousFriction viscous;
  viscous.fric = 0.2;
  viscous.c[1] = 0.5;   // C2 V
  viscous.c[2] = 0.01;  // C3 p V
  RenardFriction renard;
  renard.c = {0.2, 0.3, 0.5, 0.25, 0.1, 0.3};  // mu_s, mu_d, mu_max, mu_min, Vcr1, Vcr2
  for (const FrictionModel& model : {FrictionModel{viscous}, FrictionModel{renard}}) {
    for (const double slip : {0.02, 0.1, 0.4}) {  // V = 0.04, 0.2, 0.8 (Renard: each branch)
      PressedNode c(Coulomb{0.0, 0.0, {}, model, {}, {}});
      c.dt = 0.5;
      const Vec3 u{slip, 0.3 * slip, -kDepth};
      c.evaluate(u);
      const double v = norm(Vec3{slip, 0.3 * slip, 0.0}) / c.dt;
      const double mu = std::visit(
          [&](const auto& m) {
            if constexpr (std::is_same_v<std::decay_t<decltype(m)>, std::monostate>)
              return 0.0;
            else
              return m.mu(p, v);
          },
          model);
      EXPECT_TRUE(c.point().slipping);
      EXPECT_NEAR(norm(c.point().traction), mu * p, 1e-12 * p) << "slip " << slip;
      EXPECT_LT(tangent_error(c, u), 1e-6) << "slip " << slip;
    }
  }
}

// Adhesion (Radioss IVIS2 = -1, seed 004): a node that touched, now open by s = 0.005 within the
// zone Gap/2 = 0.01 and moved sideways over an increment dt = 0.5, is pulled back by
// SigMaxAdh s / (Gap/2) and resisted sideways by ViscAdhFact ViscFluid / (Gap/2) slip / dt.
TEST(StaticFrictionLaws, AdhesionPullsBackAndItsViscosityResistsTheSlip) {
  const Adhesion bond{0.02, 50.0, 3.0, 2.0};  // Gap, SigMaxAdh, ViscFluid, ViscAdhFact
  PressedNode c(Coulomb{0.3, 0.3, {}, {}, {}, {}}, bond);
  c.dt = 0.5;
  const Vec3 u{0.004, -0.002, 0.005};
  c.evaluate(u);
  EXPECT_TRUE(c.point().active);
  EXPECT_NEAR(c.point().pressure, -50.0 * 0.005 / 0.01, 1e-9);
  const Vec3 expected = Vec3{0.004, -0.002, 0.0} * (-2.0 * 3.0 / 0.01 / 0.5);
  EXPECT_NEAR(norm(c.point().traction - expected), 0.0, 1e-9);
  EXPECT_LT(tangent_error(c, u), 1e-6);
  // Its work over the increment, t . slip on the point's area, is dissipated as friction work
  // (as in explicit steps): area 1200 |slip|^2.
  const double area = c.point().area;
  c.contact.commit();
  EXPECT_GT(area, 0.0);
  EXPECT_NEAR(c.contact.friction_work(), area * 1200.0 * (0.004 * 0.004 + 0.002 * 0.002), 1e-12);
  // Beyond the zone the bond breaks.
  c.evaluate({0.0, 0.0, 0.011});
  EXPECT_FALSE(c.point().active);
}

}  // namespace
}  // namespace abut
