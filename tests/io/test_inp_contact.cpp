// The .inp reader, contact: *CONTACT PAIR with each *SURFACE BEHAVIOR pressure-overclosure law,
// *FRICTION, and *CHANGE FRICTION in a step (CalculiX manual: *CONTACT PAIR, *SURFACE BEHAVIOR,
// *FRICTION, *CHANGE FRICTION).
#include <gtest/gtest.h>

#include <string>
#include <utility>

#include "abut/io/deck.hpp"
#include "abut/solver/static_solver.hpp"

namespace abut {
namespace {

// Two unit cubes stacked along z, 0.01 apart: element 1 below, element 2 above.
const std::string kModel = R"(*NODE, NSET=NALL
1, 0., 0., 0.
2, 1., 0., 0.
3, 1., 1., 0.
4, 0., 1., 0.
5, 0., 0., 1.
6, 1., 0., 1.
7, 1., 1., 1.
8, 0., 1., 1.
11, 0., 0., 1.01
12, 1., 0., 1.01
13, 1., 1., 1.01
14, 0., 1., 1.01
15, 0., 0., 2.01
16, 1., 0., 2.01
17, 1., 1., 2.01
18, 0., 1., 2.01
*ELEMENT, TYPE=C3D8, ELSET=EALL
1, 1, 2, 3, 4, 5, 6, 7, 8
2, 11, 12, 13, 14, 15, 16, 17, 18
*MATERIAL, NAME=STEEL
*ELASTIC
210000., 0.3
*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL
*ELSET, ELSET=UPPER
2
*NSET, NSET=BOTTOM_OF_UPPER
11, 12, 13, 14
*SURFACE, NAME=TOP
1, S2
*SURFACE, NAME=UNDER
UPPER, S1
*SURFACE, NAME=UNDER_NODES, TYPE=NODE
BOTTOM_OF_UPPER
)";
const std::string kStep = "*STEP\n*STATIC\n*END STEP\n";

DeckResult read(const std::string& text) { return read_inp_string_with_notes(text, "t.inp"); }

TEST(InpContact, LinearNodeToSurfaceWithFriction) {
  const DeckResult r = read(
      kModel + R"(*CONTACT PAIR, INTERACTION=SI1, TYPE=NODE TO SURFACE, ADJUST=0.02, SMALL SLIDING
UNDER_NODES, TOP
*SURFACE INTERACTION, NAME=SI1
*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR
1.e7, 3., 1.e-3
*FRICTION
0.2, 5000.
)" + kStep);
  const Model& m = r.model;
  ASSERT_EQ(m.contacts.size(), 1u);
  const ContactSpec& c = m.contacts[0];
  EXPECT_EQ(c.id, 1);
  EXPECT_EQ(c.title, "UNDER_NODES/TOP");
  EXPECT_EQ(c.surface1.type, EntityType::NodeSet);
  EXPECT_EQ(m.nodes_of(c.surface1).size(), 4u);
  EXPECT_EQ(c.surface2.type, EntityType::FaceSet);
  EXPECT_EQ(m.face_set(c.surface2).name, "TOP");
  EXPECT_EQ(c.discretisation, Discretisation::NodeToSurface);
  EXPECT_TRUE(c.one_way);
  EXPECT_EQ(c.symmetric, false);
  EXPECT_EQ(c.damping, 0.0);
  EXPECT_EQ(c.penalty, 1e7);
  EXPECT_FALSE(c.exponential);
  EXPECT_FALSE(c.penalty_curve.valid());
  EXPECT_EQ(c.adjust_depth, 0.02);
  EXPECT_TRUE(c.small_sliding);
  EXPECT_EQ(c.friction_law, ContactSpec::FrictionLaw::Coulomb);
  EXPECT_EQ(c.mu_static, 0.2);
  EXPECT_EQ(c.mu_dynamic, 0.2);
  EXPECT_EQ(c.tangential_penalty, 5000.0);
  // ADJUST moved the slave nodes (0.01 above the master face) onto it.
  EXPECT_DOUBLE_EQ(m.mesh.nodes.z[8], 1.0);
  bool sigma_note = false;
  for (const std::string& n : r.notes)
    sigma_note = sigma_note ||
                 (n.rfind("t.inp:39:", 0) == 0 && n.find("sigma_inf and c0") != std::string::npos);
  EXPECT_TRUE(sigma_note) << "the note names the line of K, sigma_inf, c0";
}

TEST(InpContact, ExponentialSurfaceToSurfaceWithoutFriction) {
  const Model m = read(kModel + R"(*SURFACE INTERACTION, NAME=Soft
*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=EXPONENTIAL
1.e-3, 0.1
*CONTACT PAIR, INTERACTION=SOFT, TYPE=SURFACE TO SURFACE
UNDER, TOP
)" + kStep)
                      .model;
  const ContactSpec& c = m.contacts.at(0);
  EXPECT_EQ(c.discretisation, Discretisation::SurfaceToSurface);
  EXPECT_EQ(c.surface1.type, EntityType::FaceSet);
  EXPECT_EQ(m.face_set(c.surface1).name, "UNDER");
  ASSERT_TRUE(c.exponential);
  EXPECT_EQ(c.exponential->c0, 1e-3);
  EXPECT_EQ(c.exponential->p0, 0.1);
  EXPECT_FALSE(c.penalty);
  EXPECT_EQ(c.friction_law, ContactSpec::FrictionLaw::None);
  EXPECT_FALSE(c.small_sliding);
  EXPECT_FALSE(c.adjust_depth);
}

TEST(InpContact, TabularLawIsAPenaltyCurve) {
  const Model m = read(kModel + R"(*SURFACE INTERACTION, NAME=T
*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=TABULAR
0., 0.
100., 1.e-3
1000., 2.e-3
*CONTACT PAIR, INTERACTION=T, TYPE=SURFACE TO SURFACE
UNDER, TOP
TOP, UNDER
)" + kStep)
                      .model;
  ASSERT_EQ(m.contacts.size(), 2u);
  const ContactSpec& c = m.contacts[0];
  ASSERT_TRUE(c.penalty_curve.valid());
  EXPECT_DOUBLE_EQ(m.functions.value(c.penalty_curve, 1.5e-3, Variables{}), 550.0);
  EXPECT_DOUBLE_EQ(m.functions.value(c.penalty_curve, 1.0, Variables{}), 1000.0);
  EXPECT_EQ(m.contacts[1].penalty_curve.index, c.penalty_curve.index);  // one curve per law
  EXPECT_EQ(m.contacts[1].id, 2);
  EXPECT_EQ(m.contacts[1].title, "TOP/UNDER");
}

TEST(InpContact, TiedFreezesWithTheStickSlope) {
  const Model m = read(kModel + R"(*CONTACT PAIR, INTERACTION=GLUE, TYPE=SURFACE TO SURFACE
UNDER, TOP
*SURFACE INTERACTION, NAME=GLUE
*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=TIED
1.e9
*FRICTION
0.0001, 1.e3
)" + kStep)
                      .model;
  const ContactSpec& c = m.contacts.at(0);
  EXPECT_EQ(c.friction_law, ContactSpec::FrictionLaw::Freeze);
  EXPECT_EQ(c.penalty, 1e9);
  EXPECT_EQ(c.tangential_penalty, 1e3);
}

TEST(InpContact, ChangeFrictionChangesEveryContactOfTheInteraction) {
  const Model m = read(kModel + R"(*SURFACE INTERACTION, NAME=SI1
*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR
1.e7
*FRICTION
0.2, 80.
*SURFACE INTERACTION, NAME=SI2
*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR
1.e7
*CONTACT PAIR, INTERACTION=SI1, TYPE=NODE TO SURFACE
UNDER, TOP
*CONTACT PAIR, INTERACTION=SI2, TYPE=NODE TO SURFACE
UNDER_NODES, TOP
*CONTACT PAIR, INTERACTION=si1, TYPE=SURFACE TO SURFACE
TOP, UNDER
*STEP
*STATIC
*END STEP
*STEP
*STATIC
*CHANGE FRICTION, INTERACTION=SI1
*FRICTION
0.1, 40.
*END STEP
*STEP
*STATIC
*END STEP
)")
                      .model;
  ASSERT_EQ(m.static_steps.size(), 3u);
  EXPECT_TRUE(m.static_steps[0].contact_changes.empty());
  const auto& changes = m.static_steps[1].contact_changes;
  ASSERT_EQ(changes.size(), 2u);
  EXPECT_EQ(changes[0].contact, 0u);
  EXPECT_EQ(changes[1].contact, 2u);
  EXPECT_EQ(changes[1].friction, 0.1);
  EXPECT_EQ(changes[1].stick_slope, 40.0);
  EXPECT_TRUE(m.static_steps[2].contact_changes.empty());  // "from this step on"
  EXPECT_EQ(m.contacts[1].friction_law, ContactSpec::FrictionLaw::None);
}

// *CHANGE SURFACE BEHAVIOR (CalculiX manual): the new law for every pair of the interaction; a
// TIED pair becomes a sliding one with the interaction's *FRICTION.
TEST(InpContact, ChangeSurfaceBehaviorUntiesWithTheInteractionsFriction) {
  const Model m = read(kModel + R"(*SURFACE INTERACTION, NAME=SI1
*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=TIED
1.e9
*FRICTION
0.3, 1.e3
*CONTACT PAIR, INTERACTION=SI1, TYPE=SURFACE TO SURFACE
TOP, UNDER
*STEP
*STATIC
*END STEP
*STEP
*STATIC
*CHANGE SURFACE BEHAVIOR, INTERACTION=SI1
*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=EXPONENTIAL
0.01, 5.
*END STEP
)")
                      .model;
  EXPECT_EQ(m.contacts[0].friction_law, ContactSpec::FrictionLaw::Freeze);
  const auto& changes = m.static_steps.at(1).contact_changes;
  ASSERT_EQ(changes.size(), 1u);
  ASSERT_TRUE(changes[0].overclosure.has_value());
  EXPECT_EQ(changes[0].overclosure->c0, 0.01);
  EXPECT_EQ(changes[0].overclosure->p0, 5.0);
  EXPECT_FALSE(changes[0].overclosure->slope.has_value());
  EXPECT_EQ(changes[0].friction, 0.3);
  EXPECT_EQ(changes[0].stick_slope, 1.e3);
}

// *TIE (CalculiX) is abut's exact tie: the slave nodes follow the master faces at their initial
// gap. The upper cube, tied 0.01 above the lower one, moves with it under a shear load.
TEST(InpContact, TieBindsTheSlaveNodesToTheMasterFaces) {
  const std::string tie = "*TIE, NAME=GLUE, POSITION TOLERANCE=0.05, ADJUST=NO\nUNDER_NODES, TOP\n";
  const std::string step =
      "*STEP\n*STATIC\n*BOUNDARY\n1, 1, 3\n2, 1, 3\n3, 1, 3\n4, 1, 3\n*CLOAD\n15, 1, 1000.\n"
      "16, 1, 1000.\n*END STEP\n";
  const DeckResult r = read(kModel + tie + step);
  const Model& m = r.model;
  EXPECT_TRUE(m.contacts.empty());
  ASSERT_EQ(m.ties.size(), 1u);
  EXPECT_EQ(m.ties[0].title, "GLUE");
  EXPECT_EQ(m.ties[0].detection_depth, 0.05);
  EXPECT_EQ(m.ties[0].surface1.type, EntityType::NodeSet);
  StaticSolver solver(m);
  solver.run();
  const auto u = solver.displacement();
  const auto index = [&m](std::int64_t id) {
    for (std::size_t i = 0; i < m.mesh.nodes.size(); ++i)
      if (m.mesh.nodes.id[i] == id) return i;
    return std::size_t(0);
  };
  EXPECT_GT(u[3 * index(15)], 1e-6);  // it moves
  for (const auto& [tied, main] : {std::pair{11, 5}, {12, 6}, {13, 7}, {14, 8}})
    for (int d = 0; d < 3; ++d)
      EXPECT_NEAR(u[3 * index(tied) + d], u[3 * index(main) + d], 1e-12 * u[3 * index(15)]);

  // ADJUST=YES (the default) is not supported; the master must be made of faces.
  try {
    read(kModel + "*TIE, NAME=GLUE\nUNDER_NODES, TOP\n" + step);
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().field, "ADJUST");
    EXPECT_NE(std::string(e.what()).find("give ADJUST=NO"), std::string::npos);
  }
  try {
    read(kModel + "*TIE, NAME=GLUE, ADJUST=NO\nTOP, UNDER_NODES\n" + step);
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().field, "master");
    EXPECT_NE(std::string(e.what()).find("is made of nodes"), std::string::npos);
  }
}

}  // namespace
}  // namespace abut
