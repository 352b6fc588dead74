// The description of a contact's settings in the library's words (contact/describe.hpp), which the
// log and summary.json carry whatever the input language: each law and rule by its type and
// members, no deck field (pfac, Istf, Igap, Iedge) and no dialect keyword (COULOMB, BILATERAL).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "abut/contact/describe.hpp"

namespace abut {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

TEST(ContactDescription, DefaultSettings) {
  const ContactDescription d = describe(ContactSettings{});
  EXPECT_EQ(d.discretisation, "surface-to-surface (accuracy level 2), symmetric");
  EXPECT_EQ(d.normal_law, "linear penalty, positive side");
  EXPECT_EQ(d.tangential_law, "frictionless");
  EXPECT_EQ(d.stiffness_rule, "facet penalty");
  EXPECT_EQ(d.gap_rule, "shell gaps x 1");
  EXPECT_EQ(d.edge_rule, "none");
  EXPECT_EQ(d.erosion_rule, "eroded facets removed, free nodes kept");
}

TEST(ContactDescription, EachLawByItsMembers) {
  ContactSettings s;
  s.discretisation = Discretisation::NodeToSurface;
  s.one_way = true;
  s.removed_nodes = RemovedNodes({4, 7, 4});
  s.sense = ContactSense::Bilateral;
  s.normal_law = ExponentialOverclosure{0.001, 2e6};
  s.normal_in_time = TimeFactor{[](double t) { return t; }};
  s.tangential_law = Coulomb{0.3, 0.2, {}, {}, {}, TimeFactor{[](double) { return 1.0; }}};
  s.stick_stress = 5e6;
  s.stiffness = {StiffnessRule::Mean, 2.0, 1e3, 1e9};
  s.gaps.mesh_fraction = 0.4;
  s.gaps.border = GapSettings::Border::Round;
  s.edges = {EdgeSelection::SharpSolidEdges, 120.0};
  s.erosion = {false, false};
  const ContactDescription d = describe(s);
  EXPECT_EQ(d.discretisation, "node-to-surface, one-way, 2 tied nodes removed");
  EXPECT_EQ(d.normal_law, "exponential overclosure, c0 = 0.001, p0 = 2e+06 x f(t), bilateral");
  EXPECT_EQ(d.tangential_law,
            "Coulomb, mu_static = 0.3, mu_dynamic = 0.2 x f(t), sticking until 5e+06");
  EXPECT_EQ(d.stiffness_rule, "mean of both sides, scale = 2, minimum = 1000, maximum = 1e+09");
  EXPECT_EQ(d.gap_rule, "shell gaps x 1, at most 0.4 of the mesh size, round border");
  EXPECT_EQ(d.edge_rule, "sharp solid edges and shell borders (edge angle 120)");
  EXPECT_EQ(d.erosion_rule, "eroded facets kept, free nodes removed");
}

TEST(ContactDescription, TangentialLaws) {
  EXPECT_EQ(describe(TangentialLaw{Sticking{}}), "sticking");
  EXPECT_EQ(describe(TangentialLaw{Tresca{0.6, 0.5, 100.0, {}, {}, {}}}),
            "Tresca, factor_static = 0.6, factor_dynamic = 0.5, shear_yield = 100");
  Coulomb viscous;
  viscous.model = ViscousFriction{0.1, {}};
  EXPECT_EQ(describe(TangentialLaw{viscous}), "Coulomb, mu(p, V) viscous law, fric = 0.1");
  Coulomb renard;
  renard.model = RenardFriction{{0.2, 0.1, 0.4, 0.05, 1.0, 2.0}};
  EXPECT_EQ(describe(TangentialLaw{renard}),
            "Coulomb, mu(V) Renard law, mu_static = 0.2, mu_dynamic = 0.1");
  Coulomb of_state;
  of_state.function = [](double, double, double, double, double, double) { return 0.1; };
  EXPECT_EQ(describe(TangentialLaw{of_state}), "Coulomb, mu = function of the contact state");
  ContactSettings frozen;
  frozen.freeze = true;
  EXPECT_THAT(describe(frozen).tangential_law, HasSubstr("frozen"));
  EXPECT_THAT(describe(frozen).tangential_law, Not(HasSubstr("frictionless")));
}

}  // namespace
}  // namespace abut
