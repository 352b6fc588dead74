// The *CONTACT_* keywords that choose a contact's laws: each parses into the ContactSpec of the
// *CONTACT it names (before or after it in the deck), and each error names file, line and field.
#include <gmock/gmock.h>

#include <algorithm>
#include <limits>
#include <string>

#include "abut/solver/simulation.hpp"
#include "test_deck_helpers.hpp"

namespace abut {
namespace {

using testing::error_of;
using ::testing::HasSubstr;
using testing::model_of;

// Two elastic blocks, one on the other, and node set 5; no *CONTACT yet.
const std::string kTwoBlocks = R"(*UNIT_SYSTEM
SI
*TIME
1.0e-3
*COMPONENT_BOX
1, 1, 2, 2, 1
0.0, 0.0, 0.0, 2.0, 2.0, 1.0
*COMPONENT_BOX
2, 2, 1, 1, 1
0.0, 0.0, 1.0, 1.0, 1.0, 2.0
*MAT_ELASTIC
1, 7800.0, 210.0e9, 0.3
*PART
1, 1
2, 1
*SET_NODE
5
1, 2
*SET_PART
7
1, 2
*CURVE
9
0.0, 0.0
1.0, 1.0e9
)";
// ... with *CONTACT 3 between parts 1 and 2; the keyword under test starts on line kLine.
const std::string kContact = kTwoBlocks + "*CONTACT\n3\nP, 1, P, 2\n";

std::size_t lines_of(const std::string& s) {
  return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n'));
}
const std::size_t kLine = lines_of(kContact) + 1;

// The one contact of `extra` appended to the two blocks with *CONTACT 3.
ContactSpec contact_of(const std::string& extra) {
  const Model m = model_of(kContact + extra);
  EXPECT_EQ(m.contacts.size(), 1u);
  return m.contacts.at(0);
}

// Where the deck with `extra` gives `setting` of contact 3 (Sources; empty: not given).
SourceLocation place_of(const std::string& extra, std::string_view setting) {
  return model_of(kContact + extra).sources.of(SourceEntity::Contact, 3, setting);
}

// The error of `extra` appended to the two blocks with *CONTACT 3: its message, checked to be at
// line kLine + row_offset (the keyword's first row is kLine + 1) and in field `field`.
std::string error_at(const std::string& extra, std::size_t line, const std::string& field) {
  const InputError e = error_of(kContact + extra);
  EXPECT_EQ(e.where().file, "t.k") << e.what();
  EXPECT_EQ(e.where().line, line) << e.what();
  EXPECT_EQ(e.where().field, field) << e.what();
  return e.message();
}

TEST(DeckContactDiscretization, NodeToSurfaceAndSymmetry) {
  const ContactSpec c = contact_of("*CONTACT_DISCRETIZATION\n3, N2S, 0\n");
  EXPECT_EQ(c.discretisation, Discretisation::NodeToSurface);
  EXPECT_EQ(c.symmetric, false);
  const SourceLocation method = place_of("*CONTACT_DISCRETIZATION\n3, N2S, 0\n", "discretisation");
  EXPECT_EQ(method.line, kLine + 1);
  EXPECT_EQ(method.keyword, "*CONTACT_DISCRETIZATION");
  EXPECT_EQ(method.field, "method");

  const ContactSpec d = contact_of("*CONTACT_DISCRETIZATION\n3\n");
  EXPECT_EQ(d.discretisation, Discretisation::SurfaceToSurface);
  EXPECT_FALSE(d.symmetric.has_value());
  EXPECT_EQ(place_of("*CONTACT_DISCRETIZATION\n3\n", "symmetric").field, "symmetric");
  EXPECT_EQ(contact_of("*CONTACT_DISCRETIZATION\n3, s2s, 1\n").symmetric, true);
  EXPECT_FALSE(d.small_sliding);  // OptiStruct TRACK: FINITE by default in abut
  EXPECT_TRUE(contact_of("*CONTACT_DISCRETIZATION\n3, S2S, , small\n").small_sliding);
  EXPECT_THAT(error_at("*CONTACT_DISCRETIZATION\n3, S2S, , tiny\n", kLine + 1, "sliding"),
              HasSubstr("FINITE"));

  // Without the keyword: seed 000's surface to surface, symmetric by default.
  const ContactSpec e = contact_of("");
  EXPECT_EQ(e.discretisation, Discretisation::SurfaceToSurface);
  EXPECT_FALSE(e.symmetric.has_value());
  EXPECT_TRUE(place_of("", "discretisation").file.empty());
}

TEST(DeckContactDiscretization, NodeSetIsSurfaceOneOfNodeToSurfaceOnly) {
  // The keyword before its *CONTACT.
  const Model m =
      model_of(kTwoBlocks + "*CONTACT_DISCRETIZATION\n3, N2S\n*CONTACT\n3\nNS, 5, P, 2\n");
  const ContactSpec& c = m.contacts.at(0);
  EXPECT_EQ(c.surface1.type, EntityType::NodeSet);
  EXPECT_EQ(c.surface1.id, 5);
  EXPECT_EQ(c.discretisation, Discretisation::NodeToSurface);

  const std::size_t contact_line = lines_of(kTwoBlocks) + 3;
  const InputError no_n2s = error_of(kTwoBlocks + "*CONTACT\n3\nNS, 5, P, 2\n");
  EXPECT_EQ(no_n2s.where().line, contact_line);
  EXPECT_EQ(no_n2s.where().field, "enid_1");
  EXPECT_THAT(no_n2s.message(),
              HasSubstr("a node set is a surface only for node-to-surface contact: add "
                        "*CONTACT_DISCRETIZATION with N2S"));
  const std::string with_ns = kTwoBlocks + "*CONTACT\n3\nNS, 5, P, 2\n";
  const std::size_t line = lines_of(with_ns) + 2;
  auto error_in = [&](const std::string& extra) { return error_of(with_ns + extra); };
  InputError e = error_in("*CONTACT_DISCRETIZATION\n3, S2S\n");
  EXPECT_EQ(e.where().line, line);
  EXPECT_EQ(e.where().field, "method");
  EXPECT_THAT(e.message(), HasSubstr("expected N2S"));
  e = error_in("*CONTACT_DISCRETIZATION\n3, N2S, 1\n");
  EXPECT_EQ(e.where().line, line);
  EXPECT_EQ(e.where().field, "symmetric");
  EXPECT_THAT(e.message(), HasSubstr("node set"));
  // Surface 2 stays P, PS or ALL; a missing node set is reported.
  EXPECT_THAT(error_of(kTwoBlocks + "*CONTACT\n3\nP, 1, NS, 5\n").message(),
              HasSubstr("not supported yet"));
  EXPECT_THAT(error_of(kTwoBlocks + "*CONTACT_DISCRETIZATION\n3, N2S\n*CONTACT\n3\nNS, 6, P, 2\n")
                  .message(),
              HasSubstr("node set 6 does not exist"));
}

TEST(DeckContactDiscretization, Errors) {
  EXPECT_THAT(error_at("*CONTACT_DISCRETIZATION\n3, E2E\n", kLine + 1, "method"),
              HasSubstr("expected S2S (surface to surface) or N2S (node to surface), got 'E2E'"));
  EXPECT_THAT(error_at("*CONTACT_DISCRETIZATION\n3, N2S, 2\n", kLine + 1, "symmetric"),
              HasSubstr("expected 0 or 1"));
  const std::string one_way = kTwoBlocks + "*CONTACT\n3\nP, 1, P, 2\n0\n0, 0, 0, 20, 1\n";
  const InputError e = error_of(one_way + "*CONTACT_DISCRETIZATION\n3, N2S, 1\n");
  EXPECT_EQ(e.where().line, lines_of(one_way) + 2);
  EXPECT_THAT(e.message(), HasSubstr("contradicts one_way = 1"));
}

TEST(DeckContactKeywords, MissingContactAndRepeatedKeyword) {
  EXPECT_THAT(error_at("*CONTACT_NORMAL\n4\n", kLine + 1, "coid"),
              HasSubstr("contact 4 does not exist: coid must be the ctid of a *CONTACT (defined "
                        "contacts: 3)"));
  EXPECT_THAT(error_at("*CONTACT_NORMAL\n3\n*CONTACT_NORMAL\n3, LINEAR\n", kLine + 3, "coid"),
              HasSubstr("*CONTACT_NORMAL is given twice for contact 3 (first at t.k:" +
                        std::to_string(kLine + 1) + ")"));
  EXPECT_THAT(error_at("*CONTACT_FRICTION\n", kLine, ""), HasSubstr("missing data line"));
}

TEST(DeckContactKeywords, OptionsThatWouldDoNothingTogether) {
  // Clearance replaces the initial gap; FREEZE ties at the initial distance; BILATERAL holds from
  // the start: the initial-penetration options would be ignored, so they are errors.
  const std::size_t l = kLine + 1;
  EXPECT_THAT(
      error_at("*CONTACT_NORMAL\n3, , , , , 0.001\n*CONTACT_INITIAL\n3, SHIFT\n", l, "clearance"),
      HasSubstr("the clearance replaces the initial gap of every point"));
  EXPECT_THAT(
      error_at("*CONTACT_NORMAL\n3, , , BILATERAL\n*CONTACT_INITIAL\n3, FORCE\n", l, "sense"),
      HasSubstr("BILATERAL"));
  EXPECT_THAT(
      error_at("*CONTACT_NORMAL\n3, , , , , 0\n*CONTACT_FRICTION\n3, FREEZE\n", l + 2, "law"),
      HasSubstr("the clearance of *CONTACT_NORMAL would do nothing"));
  const std::string offset = kTwoBlocks + "*CONTACT\n3\nP, 1, P, 2\n0, 0.1, , , 1e-4\n";
  const InputError e = error_of(offset + "*CONTACT_FRICTION\n3, FREEZE\n");
  EXPECT_EQ(e.where().line, lines_of(offset) + 2);
  EXPECT_THAT(e.message(), HasSubstr("delta0_offset"));
  // Each on its own is fine.
  EXPECT_EQ(contact_of("*CONTACT_NORMAL\n3, , , BILATERAL, , 0.001\n").clearance, 0.001);
}

TEST(DeckContactNormal, CurveSenseDepthClearance) {
  const Model m = model_of(kContact + "*CONTACT_NORMAL\n3, CURVE, 9, BILATERAL, 0.05, -0.001\n");
  const ContactSpec& c = m.contacts.at(0);
  ASSERT_TRUE(c.penalty_curve.valid());
  EXPECT_DOUBLE_EQ(m.functions.value(c.penalty_curve, 0.5, {}), 0.5e9);
  EXPECT_EQ(c.sense, ContactSense::Bilateral);
  EXPECT_EQ(c.detection_depth, 0.05);
  EXPECT_EQ(c.clearance, -0.001);
  const SourceLocation depth = m.sources.of(SourceEntity::Contact, 3, "detection_depth");
  EXPECT_EQ(depth.line, kLine + 1);
  EXPECT_EQ(depth.field, "depth");

  const ContactSpec d = contact_of("*CONTACT_NORMAL\n3\n");
  EXPECT_FALSE(d.penalty_curve.valid());
  EXPECT_EQ(d.sense, ContactSense::Positive);
  EXPECT_FALSE(d.detection_depth.has_value());
  EXPECT_FALSE(d.clearance.has_value());
  EXPECT_EQ(contact_of("*CONTACT_NORMAL\n3, linear, , negative\n").sense, ContactSense::Negative);
}

TEST(DeckContactNormal, Errors) {
  const std::size_t l = kLine + 1;
  EXPECT_THAT(error_at("*CONTACT_NORMAL\n3, CURVE\n", l, "fid"), HasSubstr("law CURVE needs"));
  EXPECT_THAT(error_at("*CONTACT_NORMAL\n3, LINEAR, 9\n", l, "fid"),
              HasSubstr("used only with law CURVE"));
  EXPECT_THAT(error_at("*CONTACT_NORMAL\n3, CURVE, 8\n", l, "fid"), HasSubstr("8"));
  EXPECT_THAT(error_at("*CONTACT_NORMAL\n3, QUADRATIC\n", l, "law"),
              HasSubstr("expected LINEAR (pressure = pfac x penetration) or CURVE"));
  EXPECT_THAT(error_at("*CONTACT_NORMAL\n3, , , UP\n", l, "sense"),
              HasSubstr("expected POSITIVE (stay outside), NEGATIVE"));
  EXPECT_THAT(error_at("*CONTACT_NORMAL\n3, , , , 0\n", l, "depth"),
              HasSubstr("expected a detection depth > 0"));
  EXPECT_THAT(error_at("*CONTACT_NORMAL\n3, , , , , big\n", l, "clearance"),
              HasSubstr("expected a number"));
  const std::string sticky = kTwoBlocks + "*CONTACT\n3\nP, 1, P, 2\n0\n0, 0, 0, 20, 0, 0, 1.0e6\n";
  const InputError e = error_of(sticky + "*CONTACT_NORMAL\n3, , , BILATERAL\n");
  EXPECT_EQ(e.where().line, lines_of(sticky) + 2);
  EXPECT_EQ(e.where().field, "sense");
  EXPECT_THAT(e.message(), HasSubstr("sigma_stick"));
}

TEST(DeckContactFriction, CoulombTrescaAndFilter) {
  ContactSpec c = contact_of("*CONTACT_FRICTION\n3, COULOMB, 0.3, 0.2, 1.0e12, 1, 0.5\n");
  EXPECT_EQ(c.friction_law, ContactSpec::FrictionLaw::Coulomb);
  EXPECT_DOUBLE_EQ(c.mu_static, 0.3);
  EXPECT_DOUBLE_EQ(c.mu_dynamic, 0.2);
  EXPECT_EQ(c.tangential_penalty, 1.0e12);
  EXPECT_EQ(c.friction_filter.kind, FrictionFilter::Kind::Simple);
  EXPECT_DOUBLE_EQ(c.friction_filter.xfreq, 0.5);
  EXPECT_EQ(place_of("*CONTACT_FRICTION\n3, coulomb, 0.3\n", "tangential_law").line, kLine + 1);

  c = contact_of("*CONTACT_FRICTION\n3, coulomb, 0.3\n");
  EXPECT_DOUBLE_EQ(c.mu_dynamic, 0.3);
  EXPECT_FALSE(c.tangential_penalty.has_value());
  EXPECT_EQ(c.friction_filter.kind, FrictionFilter::Kind::None);

  c = contact_of("*CONTACT_FRICTION\n3, TRESCA, 0.8, 0.6, , 3, 100\n2.0e8\n");
  EXPECT_EQ(c.friction_law, ContactSpec::FrictionLaw::Tresca);
  EXPECT_EQ(c.friction_c, (std::array<double, 6>{0.8, 0.6, 2.0e8, 0, 0, 0}));
  EXPECT_EQ(c.friction_filter.kind, FrictionFilter::Kind::Frequency);
  EXPECT_DOUBLE_EQ(c.friction_filter.xfreq, 100.0);
  c = contact_of("*CONTACT_FRICTION\n3, TRESCA, 0.8\n2.0e8\n");
  EXPECT_EQ(c.friction_c, (std::array<double, 6>{0.8, 0.8, 2.0e8, 0, 0, 0}));

  EXPECT_EQ(contact_of("*CONTACT_FRICTION\n3, NONE\n").friction_law,
            ContactSpec::FrictionLaw::None);
  EXPECT_EQ(contact_of("*CONTACT_FRICTION\n3, STICK, , , 1e10\n").friction_law,
            ContactSpec::FrictionLaw::Stick);
  EXPECT_EQ(contact_of("*CONTACT_FRICTION\n3, FREEZE\n").friction_law,
            ContactSpec::FrictionLaw::Freeze);
  EXPECT_EQ(contact_of("").friction_law, ContactSpec::FrictionLaw::Impetus);
}

TEST(DeckContactFriction, RadiossLaws) {
  ContactSpec c = contact_of("*CONTACT_FRICTION\n3, VISCOUS, 0.1\n1e-9, 0.01, 0, 0, 1e-4\n");
  EXPECT_EQ(c.friction_law, ContactSpec::FrictionLaw::Viscous);
  EXPECT_DOUBLE_EQ(c.mu_static, 0.1);
  EXPECT_EQ(c.friction_c, (std::array<double, 6>{1e-9, 0.01, 0, 0, 1e-4, 0}));
  c = contact_of("*CONTACT_FRICTION\n3, 2\n1, 2, 3, 4, 5, 6\n");
  EXPECT_EQ(c.friction_law, ContactSpec::FrictionLaw::Darmstad);
  EXPECT_DOUBLE_EQ(c.mu_static, 0.0);
  EXPECT_EQ(c.friction_c, (std::array<double, 6>{1, 2, 3, 4, 5, 6}));
  c = contact_of("*CONTACT_FRICTION\n3, 1.0, 0.2\n");
  EXPECT_EQ(c.friction_law, ContactSpec::FrictionLaw::Viscous);
  EXPECT_EQ(c.friction_c, (std::array<double, 6>{}));
  c = contact_of("*CONTACT_FRICTION\n3, RENARD, , , , 2, 0.001\n0.2, 0.15, 0.3, 0.1, 0.5, 2.0\n");
  EXPECT_EQ(c.friction_law, ContactSpec::FrictionLaw::Renard);
  EXPECT_EQ(c.friction_c, (std::array<double, 6>{0.2, 0.15, 0.3, 0.1, 0.5, 2.0}));
  EXPECT_EQ(c.friction_filter.kind, FrictionFilter::Kind::Period);
  EXPECT_EQ(contact_of("*CONTACT_FRICTION\n3, 3\n0.2, 0.15, 0.3, 0.1, 0.5, 2.0\n").friction_law,
            ContactSpec::FrictionLaw::Renard);
}

TEST(DeckContactFriction, Errors) {
  const std::size_t l = kLine + 1;
  const std::string f = "*CONTACT_FRICTION\n3, ";
  EXPECT_THAT(error_at(f + "\n", l, "law"), HasSubstr("expected a friction law: NONE, COULOMB"));
  EXPECT_THAT(error_at(f + "AMONTONS\n", l, "law"), HasSubstr("got 'AMONTONS'"));
  EXPECT_THAT(error_at(f + "4\n", l, "law"), HasSubstr("Radioss Ifric 1, 2, 3"));
  EXPECT_THAT(error_at(f + "COULOMB\n", l, "mu_s"), HasSubstr("missing value"));
  EXPECT_THAT(error_at(f + "COULOMB, -0.1\n", l, "mu_s"), HasSubstr(">= 0"));
  EXPECT_THAT(error_at(f + "COULOMB, 0.2, 0.3\n", l, "mu_d"), HasSubstr("[0, mu_s]"));
  EXPECT_THAT(error_at(f + "COULOMB, 0.2\n1\n", l + 1, "c1"), HasSubstr("does not use c1"));
  EXPECT_THAT(error_at(f + "NONE, 0.2\n", l, "mu_s"),
              HasSubstr("law NONE does not use mu_s: leave it empty"));
  EXPECT_THAT(error_at(f + "NONE, , , 1e9\n", l, "pen_t"), HasSubstr("law NONE"));
  EXPECT_THAT(error_at(f + "TRESCA, 0.5\n", l, "c1"),
              HasSubstr("Tresca friction needs the shear yield stress k in c1"));
  EXPECT_THAT(error_at(f + "TRESCA, 0.5\n0\n", l + 1, "c1"), HasSubstr("k > 0"));
  EXPECT_THAT(error_at(f + "TRESCA, 0.5, 0.6\n1e8\n", l, "mu_d"), HasSubstr("[0, m_s]"));
  EXPECT_THAT(error_at(f + "TRESCA, 0.5\n1e8, 1\n", l + 1, "c2"), HasSubstr("does not use c2"));
  EXPECT_THAT(error_at(f + "VISCOUS, 0.1, 0.1\n", l, "mu_d"), HasSubstr("Fric"));
  EXPECT_THAT(error_at(f + "VISCOUS\n0, 0, 0, 0, 0, 1\n", l + 1, "c6"), HasSubstr("C1..C5"));
  EXPECT_THAT(error_at(f + "RENARD\n", l, "c1"), HasSubstr("Renard friction needs line 2"));
  EXPECT_THAT(error_at(f + "RENARD, 0.2\n0.2, 0.15, 0.3, 0.1, 0.5, 2\n", l, "mu_s"),
              HasSubstr("c1 is mu_s"));
  EXPECT_THAT(error_at(f + "RENARD\n0.2, 0.15, 0.3, 0.1, 0.5\n", l + 1, "c6"),
              HasSubstr("missing value"));
  EXPECT_THAT(error_at(f + "RENARD\n0.4, 0.15, 0.3, 0.1, 0.5, 2\n", l + 1, "c1"),
              HasSubstr("mu_s between mu_min (c4) and mu_max (c3)"));
  EXPECT_THAT(error_at(f + "RENARD\n0.2, 0.05, 0.3, 0.1, 0.5, 2\n", l + 1, "c2"),
              HasSubstr("mu_d between"));
  EXPECT_THAT(error_at(f + "RENARD\n0.2, 0.15, 0.3, 0.1, 0, 2\n", l + 1, "c5"),
              HasSubstr("Vcr1 > 0"));
  EXPECT_THAT(error_at(f + "RENARD\n0.2, 0.15, 0.3, 0.1, 0.5, 0.5\n", l + 1, "c6"),
              HasSubstr("Vcr2 > Vcr1"));
  EXPECT_THAT(error_at(f + "STICK, , , 0\n", l, "pen_t"), HasSubstr("tangential penalty > 0"));
  EXPECT_THAT(error_at(f + "STICK, , , , 4\n", l, "filter"),
              HasSubstr("expected a friction filter"));
  EXPECT_THAT(error_at(f + "STICK, , , , 1, 1.5\n", l, "xfreq"), HasSubstr("(0, 1]"));
  EXPECT_THAT(error_at(f + "STICK, , , , 2, 0\n", l, "xfreq"), HasSubstr("> 0"));
  EXPECT_THAT(error_at(f + "STICK, , , , , 0.5\n", l, "xfreq"),
              HasSubstr("only with a friction filter"));

  // Friction on *CONTACT and *CONTACT_FRICTION together; FREEZE with sigma_stick.
  const std::string mu = kTwoBlocks + "*CONTACT\n3\nP, 1, P, 2, 0.1\n";
  InputError e = error_of(mu + "*CONTACT_FRICTION\n3, COULOMB, 0.2\n");
  EXPECT_EQ(e.where().line, lines_of(mu) + 2);
  EXPECT_EQ(e.where().field, "law");
  EXPECT_THAT(e.message(), HasSubstr("give friction either as mu on *CONTACT or with "
                                     "*CONTACT_FRICTION, not both"));
  const std::string mu_fcn =
      kTwoBlocks +
      "*FUNCTION\n4\n0.1\n*CONTACT_FRICTION\n3, NONE\n*CONTACT\n3\nP, 1, P, 2, fcn(4)\n";
  EXPECT_THAT(error_of(mu_fcn).message(), HasSubstr("not both"));
  const std::string sticky = kTwoBlocks + "*CONTACT\n3\nP, 1, P, 2\n0\n0, 0, 0, 20, 0, 0, 1.0e6\n";
  e = error_of(sticky + "*CONTACT_FRICTION\n3, FREEZE\n");
  EXPECT_EQ(e.where().line, lines_of(sticky) + 2);
  EXPECT_THAT(e.message(), HasSubstr("sigma_stick"));
}

TEST(DeckContactAdhesion, FieldsAndErrors) {
  const ContactSpec c = contact_of("*CONTACT_ADHESION\n3, 0.002, 1.0e6, 0.5, 2.0\n");
  ASSERT_TRUE(c.adhesion.has_value());
  EXPECT_DOUBLE_EQ(c.adhesion->gap, 0.002);
  EXPECT_DOUBLE_EQ(c.adhesion->max_stress, 1.0e6);
  EXPECT_DOUBLE_EQ(c.adhesion->fluid_viscosity, 0.5);
  EXPECT_DOUBLE_EQ(c.adhesion->viscous_factor, 2.0);
  const ContactSpec d = contact_of("*CONTACT_ADHESION\n3, 0.002, 0\n");
  EXPECT_DOUBLE_EQ(d.adhesion->fluid_viscosity, 0.0);
  EXPECT_DOUBLE_EQ(d.adhesion->viscous_factor, 1.0);
  EXPECT_FALSE(contact_of("").adhesion.has_value());

  const std::size_t l = kLine + 1;
  EXPECT_THAT(error_at("*CONTACT_ADHESION\n3\n", l, "gap"), HasSubstr("missing value"));
  EXPECT_THAT(error_at("*CONTACT_ADHESION\n3, 0, 1e6\n", l, "gap"), HasSubstr("gap/2 wide"));
  EXPECT_THAT(error_at("*CONTACT_ADHESION\n3, 0.002\n", l, "sig_max"), HasSubstr("missing value"));
  EXPECT_THAT(error_at("*CONTACT_ADHESION\n3, 0.002, -1\n", l, "sig_max"), HasSubstr(">= 0"));
  EXPECT_THAT(error_at("*CONTACT_ADHESION\n3, 0.002, 1, -1\n", l, "visc_fluid"), HasSubstr(">= 0"));
  EXPECT_THAT(error_at("*CONTACT_ADHESION\n3, 0.002, 1, 0, -1\n", l, "visc_fact"),
              HasSubstr(">= 0"));
}

TEST(DeckContactStiffness, RulesAndBounds) {
  ContactSpec c = contact_of("*CONTACT_STIFFNESS\n3, SERIES, 2.0, 1.0e3, 1.0e9\n");
  EXPECT_EQ(c.stiffness.rule, StiffnessRule::Series);
  EXPECT_DOUBLE_EQ(c.stiffness.scale, 2.0);
  EXPECT_DOUBLE_EQ(c.stiffness.minimum, 1.0e3);
  EXPECT_DOUBLE_EQ(c.stiffness.maximum, 1.0e9);
  EXPECT_FALSE(c.element_penalty);
  EXPECT_EQ(place_of("*CONTACT_STIFFNESS\n3, 1000\n", "stiffness").field, "rule");
  c = contact_of("*CONTACT_STIFFNESS\n3, 1000\n");
  EXPECT_EQ(c.stiffness.rule, StiffnessRule::Main);
  EXPECT_DOUBLE_EQ(c.stiffness.scale, 1.0);
  EXPECT_DOUBLE_EQ(c.stiffness.minimum, 0.0);
  EXPECT_EQ(c.stiffness.maximum, std::numeric_limits<double>::infinity());  // no bound
  const StiffnessRule rules[] = {StiffnessRule::Mean, StiffnessRule::Maximum,
                                 StiffnessRule::Minimum, StiffnessRule::Series};
  for (int istf = 2; istf <= 5; ++istf) {
    EXPECT_EQ(contact_of("*CONTACT_STIFFNESS\n3, " + std::to_string(istf) + "\n").stiffness.rule,
              rules[istf - 2]);
  }
  EXPECT_EQ(contact_of("*CONTACT_STIFFNESS\n3, mean\n").stiffness.rule, StiffnessRule::Mean);
  EXPECT_EQ(contact_of("*CONTACT_STIFFNESS\n3, MAX\n").stiffness.rule, StiffnessRule::Maximum);
  EXPECT_EQ(contact_of("*CONTACT_STIFFNESS\n3, MIN\n").stiffness.rule, StiffnessRule::Minimum);
  c = contact_of("*CONTACT_STIFFNESS\n3, ELEMENT\n");
  EXPECT_TRUE(c.element_penalty);
  EXPECT_EQ(c.stiffness.rule, StiffnessRule::FacetPenalty);
  c = contact_of("*CONTACT_STIFFNESS\n3\n");
  EXPECT_FALSE(c.element_penalty);
  EXPECT_EQ(c.stiffness.rule, StiffnessRule::FacetPenalty);
}

TEST(DeckContactStiffness, Errors) {
  const std::size_t l = kLine + 1;
  EXPECT_THAT(error_at("*CONTACT_STIFFNESS\n3, HARMONIC\n", l, "rule"),
              HasSubstr("expected PFAC, ELEMENT, MAIN, MEAN, MAX, MIN or SERIES"));
  EXPECT_THAT(error_at("*CONTACT_STIFFNESS\n3, PFAC, 2\n", l, "stfac"),
              HasSubstr("belongs to the Radioss rules"));
  EXPECT_THAT(error_at("*CONTACT_STIFFNESS\n3, ELEMENT, , , 1e9\n", l, "st_max"),
              HasSubstr("leave it empty with rule ELEMENT"));
  EXPECT_THAT(error_at("*CONTACT_STIFFNESS\n3, MAIN, , 1\n", l, "st_min"),
              HasSubstr("Istf 2 to 5"));
  EXPECT_THAT(error_at("*CONTACT_STIFFNESS\n3, MEAN, 0\n", l, "stfac"), HasSubstr("> 0"));
  EXPECT_THAT(error_at("*CONTACT_STIFFNESS\n3, MEAN, 1, -1\n", l, "st_min"), HasSubstr(">= 0"));
  EXPECT_THAT(error_at("*CONTACT_STIFFNESS\n3, MEAN, 1, 10, 10\n", l, "st_max"),
              HasSubstr("> st_min"));
  const std::string pfac = kTwoBlocks + "*CONTACT\n3\nP, 1, P, 2, 0, 1e12\n";
  const InputError e = error_of(pfac + "*CONTACT_STIFFNESS\n3, ELEMENT\n");
  EXPECT_EQ(e.where().line, lines_of(pfac) + 2);
  EXPECT_EQ(e.where().field, "rule");
  EXPECT_THAT(e.message(), HasSubstr("replaces the penalty pfac"));
  EXPECT_EQ(model_of(pfac + "*CONTACT_STIFFNESS\n3, PFAC\n").contacts.at(0).penalty, 1e12);
}

TEST(DeckContactScalePenalty, AssignmentsInDeckOrder) {
  const Model m = model_of(kTwoBlocks + R"(*CONTACT_SCALE_PENALTY
3
P, 1, P, 2, 10
, , , , 0.5
*CONTACT
3
ALL, , ALL
*CONTACT_SCALE_PENALTY
3
PS, 7, , , 2
ALL, , P, 1, 3
)");
  const auto& s = m.contacts.at(0).pair_scales;
  ASSERT_EQ(s.size(), 4u);
  EXPECT_EQ(s[0].set1->type, EntityType::Part);
  EXPECT_EQ(s[0].set1->id, 1);
  EXPECT_EQ(s[0].set2->id, 2);
  EXPECT_DOUBLE_EQ(s[0].scale, 10.0);
  EXPECT_FALSE(s[1].set1.has_value());
  EXPECT_FALSE(s[1].set2.has_value());
  EXPECT_DOUBLE_EQ(s[1].scale, 0.5);
  EXPECT_EQ(s[2].set1->type, EntityType::PartSet);
  EXPECT_EQ(s[2].set1->id, 7);
  EXPECT_FALSE(s[2].set2.has_value());
  EXPECT_EQ(s[3].set1->type, EntityType::All);
  EXPECT_EQ(s[3].set2->id, 1);
  EXPECT_DOUBLE_EQ(s[3].scale, 3.0);
  EXPECT_EQ(s[3].where.line, lines_of(kTwoBlocks) + 11);
}

TEST(DeckContactScalePenalty, Errors) {
  const std::size_t l = kLine + 2;
  EXPECT_THAT(error_at("*CONTACT_SCALE_PENALTY\n3\n", kLine, ""),
              HasSubstr("missing data line: expected entype_1, enid_1, entype_2, enid_2, scale"));
  EXPECT_THAT(error_at("*CONTACT_SCALE_PENALTY\n3\nP, 1, P, 2\n", l, "scale"),
              HasSubstr("missing value"));
  EXPECT_THAT(error_at("*CONTACT_SCALE_PENALTY\n3\nP, 1, P, 2, 0\n", l, "scale"),
              HasSubstr("expected a penalty scale factor > 0"));
  EXPECT_THAT(
      error_at("*CONTACT_SCALE_PENALTY\n3\nP, 1, P, 2, 2\nP, 1, P, 9, 2\n", l + 1, "enid_2"),
      HasSubstr("part 9 does not exist"));
  EXPECT_THAT(error_at("*CONTACT_SCALE_PENALTY\n3\n, 1, , , 2\n", l, "entype_1"),
              HasSubstr("expected an entity type P, PS or ALL"));
  EXPECT_THAT(error_at("*CONTACT_SCALE_PENALTY\n3\nNS, 5, , , 2\n", l, "entype_1"),
              HasSubstr("not supported yet"));
  EXPECT_THAT(error_at("*CONTACT_SCALE_PENALTY\n3\nPS, 8, , , 2\n", l, "enid_1"),
              HasSubstr("part set 8 does not exist"));
}

// *CONTACT_FRICTION_PAIR (Radioss fric_ID): a law per part pair, in deck order, with the law
// line of *CONTACT_FRICTION less coid and pen_t.
TEST(DeckContactFrictionPair, PairsInDeckOrder) {
  const ContactSpec c = contact_of(
      "*CONTACT_FRICTION_PAIR\n3, P, 1, P, 2\nCOULOMB, 0.5, 0.3, 1, 0.2\n"
      "*CONTACT_FRICTION_PAIR\n3, PS, 7\nTRESCA, 0.8, 0.6\n2.0e8\n"
      "*CONTACT_FRICTION_PAIR\n3\n3\n0.1, 0.2, 0.3, 0.05, 1.0, 2.0\n");
  ASSERT_EQ(c.friction_pairs.size(), 3u);
  const auto& p = c.friction_pairs;
  EXPECT_EQ(p[0].set1->type, EntityType::Part);
  EXPECT_EQ(p[0].set1->id, 1);
  EXPECT_EQ(p[0].set2->id, 2);
  EXPECT_EQ(p[0].law, ContactSpec::FrictionLaw::Coulomb);
  EXPECT_DOUBLE_EQ(p[0].mu_static, 0.5);
  EXPECT_DOUBLE_EQ(p[0].mu_dynamic, 0.3);
  EXPECT_EQ(p[0].filter.kind, FrictionFilter::Kind::Simple);
  EXPECT_DOUBLE_EQ(p[0].filter.xfreq, 0.2);
  EXPECT_EQ(p[0].where.line, kLine + 2);
  EXPECT_EQ(p[1].set1->type, EntityType::PartSet);
  EXPECT_FALSE(p[1].set2.has_value());
  EXPECT_EQ(p[1].law, ContactSpec::FrictionLaw::Tresca);
  EXPECT_DOUBLE_EQ(p[1].c[2], 2.0e8);
  EXPECT_FALSE(p[2].set1.has_value());
  EXPECT_EQ(p[2].law, ContactSpec::FrictionLaw::Renard);
  EXPECT_DOUBLE_EQ(p[2].c[5], 2.0);
  // The contact's own law is untouched.
  EXPECT_EQ(c.friction_law, ContactSpec::FrictionLaw::Impetus);
}

TEST(DeckContactFrictionPair, Errors) {
  const std::size_t l = kLine + 1;
  EXPECT_THAT(error_at("*CONTACT_FRICTION_PAIR\n3, P, 1, P, 2\n", kLine, ""),
              HasSubstr("missing data line: expected law"));
  EXPECT_THAT(error_at("*CONTACT_FRICTION_PAIR\n3, P, 1, P, 2\nSTICK\n", l + 1, "law"),
              HasSubstr("give it with *CONTACT_FRICTION"));
  EXPECT_THAT(error_at("*CONTACT_FRICTION_PAIR\n3, P, 1, P, 2\nFRICTIONAL\n", l + 1, "law"),
              HasSubstr("expected a friction law: NONE, COULOMB, TRESCA, VISCOUS"));
  EXPECT_THAT(error_at("*CONTACT_FRICTION_PAIR\n3, P, 1, P, 2\nCOULOMB, 0.2, 0.3\n", l + 1, "mu_d"),
              HasSubstr("expected a dynamic friction coefficient in [0, mu_s]"));
  EXPECT_THAT(error_at("*CONTACT_FRICTION_PAIR\n3, , 1\nCOULOMB, 0.2\n", l, "entype_1"),
              HasSubstr("expected an entity type P, PS or ALL"));
  EXPECT_THAT(error_at("*CONTACT_FRICTION_PAIR\n3, P, 1, P, 9\nCOULOMB, 0.2\n", l, "enid_2"),
              HasSubstr("part 9 does not exist"));
  EXPECT_THAT(error_at("*CONTACT_FRICTION_PAIR\n3, P, 1\nCOULOMB, 0.2, , 0, 0.5\n", l + 1, "xfreq"),
              HasSubstr("xfreq is used only with a friction filter"));
  EXPECT_THAT(error_at("*CONTACT_FRICTION_PAIR\n4, P, 1\nCOULOMB, 0.2\n", l, "coid"),
              HasSubstr("contact 4 does not exist"));
  // A tied contact has no friction to replace, whichever keyword comes first.
  for (const std::string& deck :
       {std::string("*CONTACT_FRICTION_PAIR\n3, P, 1\nCOULOMB, 0.2\n*CONTACT_FRICTION\n3, "
                    "FREEZE\n"),
        std::string("*CONTACT_FRICTION\n3, STICK\n*CONTACT_FRICTION_PAIR\n3, P, 1\nCOULOMB, "
                    "0.2\n")}) {
    const InputError e = error_of(kContact + deck);
    EXPECT_THAT(e.what(), HasSubstr("would do nothing"));
    EXPECT_EQ(e.where().field, "law");
  }
}

TEST(DeckContactInitial, PenetrationAndAdjust) {
  ContactSpec c = contact_of("*CONTACT_INITIAL\n3, SHIFT, 0.001\n");
  EXPECT_EQ(c.initial_penetration, InitialPenetration::Shift);
  EXPECT_EQ(c.adjust_depth, 0.001);
  EXPECT_EQ(place_of("*CONTACT_INITIAL\n3, -1, auto\n", "adjust").line, kLine + 1);
  c = contact_of("*CONTACT_INITIAL\n3, -1, auto\n");
  EXPECT_EQ(c.initial_penetration, InitialPenetration::Force);
  EXPECT_EQ(c.adjust_depth, -1.0);
  c = contact_of("*CONTACT_INITIAL\n3, 5, NO\n");
  EXPECT_EQ(c.initial_penetration, InitialPenetration::Shift);
  EXPECT_FALSE(c.adjust_depth.has_value());
  c = contact_of("*CONTACT_INITIAL\n3\n");
  EXPECT_EQ(c.initial_penetration, InitialPenetration::Offset);
  EXPECT_FALSE(c.adjust_depth.has_value());
  EXPECT_FALSE(c.adjust_nodes.has_value());
  const std::string offset = kTwoBlocks + "*CONTACT\n3\nP, 1, P, 2\n0, 0.1, , , 1e-4\n";
  EXPECT_EQ(model_of(offset + "*CONTACT_INITIAL\n3, OFFSET\n").contacts.at(0).initial_offset, 1e-4);
}

TEST(DeckContactInitial, Errors) {
  const std::size_t l = kLine + 1;
  EXPECT_THAT(error_at("*CONTACT_INITIAL\n3, IGNORE\n", l, "penetration"),
              HasSubstr("expected OFFSET, SHIFT or FORCE (or Radioss Inacti 5, -1)"));
  EXPECT_THAT(error_at("*CONTACT_INITIAL\n3, , 0\n", l, "adjust"),
              HasSubstr("expected NO, AUTO or an adjustment depth > 0, got 0"));
  EXPECT_THAT(error_at("*CONTACT_INITIAL\n3, , YES\n", l, "adjust"), HasSubstr("got YES"));
  EXPECT_THAT(error_at("*CONTACT_INITIAL\n3, , NO, 4\n", l, "adjust_nsid"),
              HasSubstr("but adjust is NO"));
  EXPECT_THAT(error_at("*CONTACT_INITIAL\n3, , , 0\n", l, "adjust_nsid"),
              HasSubstr("expected the id of a *SET_NODE (> 0)"));
  for (const char* contact_line3 : {"0, 0.1, , , 1e-4\n", "0, 0.1, , , , 1e-3\n"}) {
    const std::string deck = kTwoBlocks + "*CONTACT\n3\nP, 1, P, 2\n" + contact_line3;
    const InputError e = error_of(deck + "*CONTACT_INITIAL\n3, FORCE\n");
    EXPECT_EQ(e.where().line, lines_of(deck) + 2);
    EXPECT_EQ(e.where().field, "penetration");
    EXPECT_THAT(e.message(), HasSubstr("replaces delta0_offset and delta0_max"));
  }
}

// Where each setting of a contact is (Sources): the field of the deck reference for every setting
// the contact library or the solvers may report, so that their errors point at it.
TEST(DeckContactSources, EverySettingIsAtItsField) {
  const std::string deck = kTwoBlocks +
                           "*CONTACT\n3, 2\nP, 1, P, 2, 0.0, , 0.0, 1.0\n0, 0.1, , , 0.0, , 0.0\n"
                           ", , , 20.0, 0, 0, , 0\n"
                           "*CONTACT_NORMAL\n3, LINEAR, , POSITIVE, 0.05\n"
                           "*CONTACT_FRICTION\n3, COULOMB, 0.3, 0.2, 1e9\n"
                           "*CONTACT_DISCRETIZATION\n3, S2S, 1\n"
                           "*CONTACT_GAP\n3\n"
                           "*CONTACT_EDGE\n3, SHARP_ALL_SHELLS\n"
                           "*CONTACT_EROSION\n3, KEEP\n"
                           "*CONTACT_ADHESION\n3, 0.001, 1e5\n"
                           "*CONTACT_STIFFNESS\n3, 1000\n"
                           "*CONTACT_INITIAL\n3, -1\n";
  const Model m = model_of(deck);
  struct Expected {
    const char *setting, *keyword, *field;
    std::size_t line;  // after the line of *CONTACT
  };
  // The fields of docs/deck-reference.md, chosen before the run.
  const Expected expected[] = {
      {"accuracy_level", "*CONTACT", "accuracy_level", 1},
      {"surface1", "*CONTACT", "enid_1", 2},
      {"surface2", "*CONTACT", "enid_2", 2},
      {"penalty", "*CONTACT", "pfac", 2},
      {"begin_time", "*CONTACT", "t_beg", 2},
      {"end_time", "*CONTACT", "t_end", 2},
      {"damping", "*CONTACT", "xi", 3},
      {"regions", "*CONTACT", "gid_0", 3},
      {"initial_offset", "*CONTACT", "delta0_offset", 3},
      {"initial_max", "*CONTACT", "delta0_max", 3},
      {"edge_tolerance", "*CONTACT", "delta_edge", 3},
      {"thermal", "*CONTACT", "fid_thermal", 4},
      {"edge_angle", "*CONTACT", "alpha_edge", 4},
      {"one_way", "*CONTACT", "one_way", 4},
      {"stick_stress", "*CONTACT", "sigma_stick", 4},
      {"friction_heat", "*CONTACT", "fric_heat", 4},
      {"normal_law", "*CONTACT_NORMAL", "law", 6},
      {"sense", "*CONTACT_NORMAL", "sense", 6},
      {"detection_depth", "*CONTACT_NORMAL", "depth", 6},
      {"clearance", "*CONTACT_NORMAL", "clearance", 6},
      {"tangential_law", "*CONTACT_FRICTION", "law", 8},
      {"tangential_penalty", "*CONTACT_FRICTION", "pen_t", 8},
      {"friction_filter", "*CONTACT_FRICTION", "filter", 8},
      {"discretisation", "*CONTACT_DISCRETIZATION", "method", 10},
      {"symmetric", "*CONTACT_DISCRETIZATION", "symmetric", 10},
      {"small_sliding", "*CONTACT_DISCRETIZATION", "sliding", 10},
      {"gaps", "*CONTACT_GAP", "igap", 12},
      {"shell_sides", "*CONTACT_GAP", "shell_side", 12},
      {"edges", "*CONTACT_EDGE", "iedge", 14},
      {"erosion", "*CONTACT_EROSION", "facets", 16},
      {"adhesion", "*CONTACT_ADHESION", "gap", 18},
      {"stiffness", "*CONTACT_STIFFNESS", "rule", 20},
      {"initial_penetration", "*CONTACT_INITIAL", "penetration", 22},
      {"adjust", "*CONTACT_INITIAL", "adjust", 22},
  };
  for (const Expected& e : expected) {
    const SourceLocation at = m.sources.of(SourceEntity::Contact, 3, e.setting);
    EXPECT_EQ(at.file, "t.k") << e.setting;
    EXPECT_EQ(at.keyword, e.keyword) << e.setting;
    EXPECT_EQ(at.field, e.field) << e.setting;
    EXPECT_EQ(at.line, lines_of(kTwoBlocks) + 1 + e.line) << e.setting;
  }
}

// A solver's error about a setting is at that setting's field, and asks for what to give in the
// dialect's words: here the automatic penalty, which needs units (seed 000) or pfac.
TEST(DeckContactSources, TheSolverAsksInTheDecksWords) {
  std::string deck = kTwoBlocks + "*CONTACT\n3\nP, 1, P, 2\n";
  deck.erase(0, std::string("*UNIT_SYSTEM\nSI\n").size());
  const Model m = model_of(deck);
  try {
    const Simulation sim(m);
    ADD_FAILURE() << "expected an error for the missing penalty";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().field, "pfac") << e.what();
    EXPECT_EQ(e.where().line, lines_of(deck)) << e.what();  // the row of the surfaces and pfac
    EXPECT_THAT(e.what(), HasSubstr("neither pfac of *CONTACT nor *UNIT_SYSTEM is given"));
  }
}

}  // namespace
}  // namespace abut
