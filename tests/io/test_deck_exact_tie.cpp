// The exact tie of *CONTACT_FRICTION FREEZE (tie = EXACT): the *CONTACT becomes a Model::ties
// entry; options it would not use, and ties the solver cannot enforce, are errors at their lines.
#include <gmock/gmock.h>

#include <algorithm>
#include <string>

#include "abut/solver/simulation.hpp"
#include "abut/solver/static_solver.hpp"
#include "test_deck_helpers.hpp"

namespace abut {
namespace {

using testing::error_of;
using ::testing::HasSubstr;
using testing::model_of;

// Block 2 (1 x 1 x 1) stands on block 1 (2 x 2 x 1); *CONTACT 3 ties block 2's nodes (surface 1)
// to block 1's facets; the line after it is kLine + 1.
const std::string kBlocks = R"(*TIME
1.0e-3
*COMPONENT_BOX
1, 1, 2, 2, 1
0.0, 0.0, 0.0, 2.0, 2.0, 1.0
*COMPONENT_BOX
2, 2, 1, 1, 1
0.0, 0.0, 1.0, 1.0, 1.0, 2.0
*MAT_ELASTIC
1, 7800.0, 210.0e9, 0.3
*MAT_RIGID
2, 7800.0
*PART
1, 1
2, 1
)";
const std::string kTie = "*CONTACT\n3\nP, 2, P, 1\n*CONTACT_FRICTION\n3, FREEZE, , , , , , EXACT\n";

std::size_t lines_of(const std::string& s) {
  return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n'));
}

// The error raised when the deck's model is set up for an explicit run.
InputError run_error(const std::string& deck) {
  const Model m = model_of(deck);
  try {
    Simulation sim(m);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "expected an InputError for:\n" << deck;
  return InputError("no error");
}

TEST(DeckExactTie, BecomesATie) {
  const Model m = model_of(kBlocks + kTie);
  EXPECT_TRUE(m.contacts.empty());
  ASSERT_EQ(m.ties.size(), 1u);
  const TieSpec& t = m.ties[0];
  EXPECT_EQ(t.id, 3);
  EXPECT_EQ(t.surface1.id, 2);
  EXPECT_EQ(t.surface2.id, 1);
  const SourceLocation exact = m.sources.of(SourceEntity::Tie, t.id, "exact");
  EXPECT_EQ(exact.line, lines_of(kBlocks) + 5);
  EXPECT_EQ(exact.field, "tie");
  // PENALTY (or nothing) keeps the penalty FREEZE contact.
  const Model p = model_of(kBlocks +
                           "*CONTACT\n3\nP, 2, P, 1\n*CONTACT_FRICTION\n3, FREEZE, , , , "
                           ", , PENALTY\n");
  EXPECT_TRUE(p.ties.empty());
  ASSERT_EQ(p.contacts.size(), 1u);
  EXPECT_FALSE(p.contacts[0].exact_tie);
  // The tie binds block 2's four bottom nodes and runs.
  Simulation sim(m);
  sim.advance();
  EXPECT_FALSE(sim.has_contact());
}

TEST(DeckExactTie, FieldErrors) {
  const std::string c = kBlocks + "*CONTACT\n3\nP, 2, P, 1\n";
  const std::size_t line = lines_of(c) + 2;
  InputError e = error_of(c + "*CONTACT_FRICTION\n3, COULOMB, 0.1, , , , , EXACT\n");
  EXPECT_EQ(e.where().line, line);
  EXPECT_EQ(e.where().field, "tie");
  EXPECT_THAT(e.message(), HasSubstr("option of law FREEZE"));
  e = error_of(c + "*CONTACT_FRICTION\n3, FREEZE, , , , , , RIGID\n");
  EXPECT_EQ(e.where().field, "tie");
  EXPECT_THAT(e.message(), HasSubstr("PENALTY (springs) or EXACT"));
  e = error_of(c + "*CONTACT_FRICTION\n3, FREEZE, , , 1e9, , , EXACT\n");
  EXPECT_EQ(e.where().field, "pen_t");
  EXPECT_THAT(e.message(), HasSubstr("no springs"));
}

TEST(DeckExactTie, OptionsATieDoesNotUse) {
  // pfac on *CONTACT, a sense on *CONTACT_NORMAL, a Radioss stiffness rule, a sensor.
  InputError e = error_of(kBlocks + "*CONTACT\n3\nP, 2, P, 1, , 1e12\n" +
                          "*CONTACT_FRICTION\n3, FREEZE, , , , , , EXACT\n");
  EXPECT_EQ(e.where().field, "pfac");
  EXPECT_THAT(e.message(), HasSubstr("with an exact tie"));
  e = error_of(kBlocks + kTie + "*CONTACT_NORMAL\n3, , , BILATERAL\n");
  EXPECT_EQ(e.where().line, lines_of(kBlocks + kTie) + 2);
  EXPECT_THAT(e.message(), HasSubstr("detection depth only"));
  e = error_of(kBlocks + kTie + "*CONTACT_STIFFNESS\n3, MAX\n");
  EXPECT_EQ(e.where().line, lines_of(kBlocks + kTie) + 2);
  EXPECT_THAT(e.message(), HasSubstr("no springs"));
  e = error_of(kBlocks + kTie + "*CONTACT_SMOOTHING\n3, BOTH\n");
  EXPECT_EQ(e.where().line, lines_of(kBlocks + kTie) + 2);
  EXPECT_THAT(e.message(), HasSubstr("binds nodes where they are"));
  e = error_of(kBlocks +
               "*CONTACT\n3\nP, 1, P, 1\n*CONTACT_FRICTION\n3, FREEZE, , , , , , EXACT\n");
  EXPECT_THAT(e.message(), HasSubstr("tied to itself"));
}

TEST(DeckExactTie, TiesTheSolverCannotEnforce) {
  const std::size_t tie_line = lines_of(kBlocks) + 5;
  // A boundary condition on a tied node.
  InputError e = run_error(kBlocks + kTie + "*BC_MOTION\nP, 2, XYZ\n");
  EXPECT_EQ(e.where().line, tie_line);
  EXPECT_EQ(e.where().field, "tie");
  EXPECT_THAT(e.message(), HasSubstr("has a boundary condition"));
  // A tied node starting faster than its facet.
  e = run_error(kBlocks + kTie + "*INITIAL_VELOCITY\nP, 2, 1.0\n");
  EXPECT_THAT(e.message(), HasSubstr("starts with a velocity other than its facet point's"));
  // Facets of a rigid part.
  std::string rigid = kBlocks;
  rigid.replace(rigid.find("*PART\n1, 1"), 10, "*PART\n1, 2");
  e = run_error(rigid + kTie);
  EXPECT_THAT(e.message(), HasSubstr("rigid part"));
  // The same nodes tied twice (first at line tie_line), and a chain (block 1's top nodes tied
  // to block 2 while block 2's nodes follow them).
  const std::string twice = kBlocks + kTie +
                            "*CONTACT\n4\nP, 2, P, 1\n*CONTACT_FRICTION\n4, FREEZE, , , , , , "
                            "EXACT\n";
  e = run_error(twice);
  EXPECT_EQ(e.where().line, lines_of(twice));
  EXPECT_THAT(e.message(), HasSubstr("is tied by exact tie 3 already"));
  const std::string chain = kBlocks + kTie +
                            "*CONTACT\n4\nP, 1, P, 2\n*CONTACT_FRICTION\n4, FREEZE, , , , , , "
                            "EXACT\n";
  e = run_error(chain);
  EXPECT_THAT(e.message(), HasSubstr("chains of ties are not supported"));
  // A tie that finds no node within the detection depth.
  const std::string far =
      kBlocks + "*COMPONENT_BOX\n3, 3, 1, 1, 1\n5, 5, 5, 6, 6, 6\n*PART\n3, 1\n" +
      "*CONTACT\n3\nP, 3, P, 1\n*CONTACT_FRICTION\n3, FREEZE, , , , , , EXACT\n";
  e = run_error(far);
  EXPECT_EQ(e.where().line, lines_of(far));
  EXPECT_THAT(e.message(), HasSubstr("binds no node"));
}

TEST(DeckExactTie, StaticBoundaryConditionOnATiedNode) {
  Model m = model_of(kBlocks + kTie);
  m.materials[1].params = m.materials[0].params;  // no rigid material in static steps
  // Block 2's node at (0, 0, 1) (its nodes follow block 1's 18) is tied; prescribe it in step 1.
  std::int32_t tied = -1;
  for (std::size_t i = 18; i < m.mesh.nodes.size(); ++i)
    if (m.mesh.nodes.x[i] == 0.0 && m.mesh.nodes.y[i] == 0.0 && m.mesh.nodes.z[i] == 1.0)
      tied = static_cast<std::int32_t>(i);
  ASSERT_GE(tied, 0);
  StaticStep step;
  step.displacements.push_back({tied, 2, 0.0, {}, {}});
  m.static_steps.push_back(step);
  StaticSolver solver(m);
  try {
    solver.run();
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, lines_of(kBlocks) + 5);
    EXPECT_EQ(e.where().field, "tie");
    EXPECT_THAT(e.message(), HasSubstr("has a boundary condition in direction z in step 1"));
  }
}

// Radioss Irem_i2 (*CONTACT_DISCRETIZATION tied_nodes, seed 004): a contact 4 between the tied
// blocks keeps the tied nodes as secondary points (KEEP, Irem_i2 = 3) or drops them (REMOVE,
// Irem_i2 = 1). Block 2's bottom nodes (4 of its 8) are tied: N2S 8 points -> 4; S2S 6 facets of
// 4 points -> 5 facets (its bottom facet's nodes are all tied), explicit and static alike.
TEST(DeckExactTie, AContactMayDropTheTiedNodes) {
  for (const std::string method : {"N2S", "S2S"})
    for (const bool remove : {false, true}) {
      const std::string deck = kBlocks + kTie + "*CONTACT\n4\nP, 2, P, 1, 0.0, 1.0e12\n" +
                               "*CONTACT_DISCRETIZATION\n4, " + method + ", 0, , " +
                               (remove ? "REMOVE" : "KEEP") + "\n";
      const std::size_t expected = method == "N2S" ? (remove ? 4u : 8u) : (remove ? 20u : 24u);
      Model m = model_of(deck);
      ASSERT_EQ(m.contacts.size(), 1u);
      EXPECT_EQ(m.contacts[0].remove_tied_nodes, remove);
      {
        const Simulation sim(m);
        EXPECT_EQ(sim.contact_reports().at(0).points, expected) << method << " " << remove;
        // The tie holds the 4 bottom nodes of block 2 on block 1.
        const std::string discretisation =
            method == "N2S" ? "node-to-surface" : "surface-to-surface (accuracy level 2)";
        EXPECT_EQ(sim.contact_reports().at(0).laws.discretisation,
                  discretisation + ", one-way" + (remove ? ", 4 tied nodes removed" : ""));
      }
      m.materials[1].params = m.materials[0].params;  // no rigid material in static steps
      m.static_steps.push_back(StaticStep{});
      const StaticSolver solver(m);
      ASSERT_EQ(solver.contacts().size(), 1u);
      EXPECT_EQ(solver.contacts()[0].points().size(), expected) << method << " " << remove;
    }
}

}  // namespace
}  // namespace abut
