// The .inp reader, steps: *STEP/*STATIC, OP=NEW/MOD of *BOUNDARY, *CLOAD and *DLOAD resolved
// over the steps (model-level boundary conditions included), amplitudes, equations, print
// requests (CalculiX manual: *BOUNDARY, *CLOAD, *DLOAD, *AMPLITUDE, *STEP, *NODE PRINT).
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <tuple>

#include "abut/io/deck.hpp"

namespace abut {
namespace {

// Two unit cubes side by side along x: node id = 1 + i + 3 j + 6 k at (i, j, k).
const std::string kModel = R"(*NODE, NSET=NALL
1, 0., 0., 0.
2, 1., 0., 0.
3, 2., 0., 0.
4, 0., 1., 0.
5, 1., 1., 0.
6, 2., 1., 0.
7, 0., 0., 1.
8, 1., 0., 1.
9, 2., 0., 1.
10, 0., 1., 1.
11, 1., 1., 1.
12, 2., 1., 1.
*ELEMENT, TYPE=C3D8, ELSET=EALL
1, 1, 2, 5, 4, 7, 8, 11, 10
2, 2, 3, 6, 5, 8, 9, 12, 11
*MATERIAL, NAME=STEEL
*ELASTIC
210000., 0.3
*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL
*NSET, NSET=LEFT
1, 4, 7, 10
)";

Model model_of(const std::string& text) { return read_inp_string_with_notes(text, "t.inp").model; }

// (user node id, dof) -> value, of a step's list.
template <class List>
std::map<std::pair<std::int64_t, int>, double> by_node(const Model& m, const List& list) {
  std::map<std::pair<std::int64_t, int>, double> out;
  for (const auto& e : list)
    out[{m.mesh.nodes.id[static_cast<std::size_t>(e.node)], e.dof}] = e.value;
  return out;
}

// (user element id, face) -> pressure.
std::map<std::pair<std::int64_t, int>, double> by_face(const Model& m,
                                                       const std::vector<StepPressure>& list) {
  std::map<std::pair<std::int64_t, int>, double> out;
  for (const StepPressure& p : list)
    out[{m.mesh.hex_id[static_cast<std::size_t>(p.face.solid)], p.face.face}] = p.value;
  return out;
}

TEST(InpSteps, OpNewAndModOverThreeSteps) {
  const Model m = model_of(kModel + R"(*BOUNDARY
LEFT, 1, 1
1, 2, 3
*STEP
*STATIC
*BOUNDARY
3, 1, 1, 0.5
*CLOAD
12, 3, 10.
*CLOAD
12, 3, 5.
*DLOAD
2, P4, 1.
*END STEP
*STEP
*STATIC
*BOUNDARY
3, 1, 1, 0.7
*CLOAD, OP=NEW
9, 3, 2.
*DLOAD
1, P2, 3.
*END STEP
*STEP
*STATIC
*BOUNDARY, OP=NEW
6, 2, 2
*BOUNDARY
6, 3, 3, -0.1
*CLOAD
9, 3, 4.
*DLOAD, OP=NEW
2, P4, 2.
*END STEP
)");
  ASSERT_EQ(m.static_steps.size(), 3u);
  using Key = std::map<std::pair<std::int64_t, int>, double>;
  // Step 1: the model-level conditions (LEFT in x, node 1 in y and z) and node 3 in x; the two
  // *CLOADs on one dof in one step add up.
  EXPECT_EQ(by_node(m, m.static_steps[0].displacements), (Key{{{1, 0}, 0.0},
                                                              {{4, 0}, 0.0},
                                                              {{7, 0}, 0.0},
                                                              {{10, 0}, 0.0},
                                                              {{1, 1}, 0.0},
                                                              {{1, 2}, 0.0},
                                                              {{3, 0}, 0.5}}));
  EXPECT_EQ(by_node(m, m.static_steps[0].forces), (Key{{{12, 2}, 15.0}}));
  EXPECT_EQ(by_face(m, m.static_steps[0].pressures), (Key{{{2, 3}, 1.0}}));
  // Step 2: OP=MOD replaces node 3's value; OP=NEW removes the force on node 12; the pressure
  // of step 1 stays next to the new one.
  EXPECT_EQ(by_node(m, m.static_steps[1].displacements), (Key{{{1, 0}, 0.0},
                                                              {{4, 0}, 0.0},
                                                              {{7, 0}, 0.0},
                                                              {{10, 0}, 0.0},
                                                              {{1, 1}, 0.0},
                                                              {{1, 2}, 0.0},
                                                              {{3, 0}, 0.7}}));
  EXPECT_EQ(by_node(m, m.static_steps[1].forces), (Key{{{9, 2}, 2.0}}));
  EXPECT_EQ(by_face(m, m.static_steps[1].pressures), (Key{{{2, 3}, 1.0}, {{1, 1}, 3.0}}));
  // Step 3: OP=NEW drops every earlier condition, model-level ones included, but not the
  // second card of the step; a force from an earlier step is replaced, not added to.
  EXPECT_EQ(by_node(m, m.static_steps[2].displacements), (Key{{{6, 1}, 0.0}, {{6, 2}, -0.1}}));
  EXPECT_EQ(by_node(m, m.static_steps[2].forces), (Key{{{9, 2}, 4.0}}));
  EXPECT_EQ(by_face(m, m.static_steps[2].pressures), (Key{{{2, 3}, 2.0}}));
  // Where each comes from: the data line.
  EXPECT_EQ(m.static_steps[2].forces[0].where.line, 53u);
  EXPECT_EQ(m.static_steps[2].forces[0].where.keyword, "*CLOAD");
}

TEST(InpSteps, AbaqusBoundaryTypes) {
  const Model m = model_of(kModel + R"(*BOUNDARY
1, ENCASTRE
2, XSYMM
3, YASYMM
*STEP
*STATIC
*END STEP
)");
  using Key = std::map<std::pair<std::int64_t, int>, double>;
  EXPECT_EQ(by_node(m, m.static_steps[0].displacements), (Key{{{1, 0}, 0.0},
                                                              {{1, 1}, 0.0},
                                                              {{1, 2}, 0.0},
                                                              {{2, 0}, 0.0},
                                                              {{3, 0}, 0.0},
                                                              {{3, 2}, 0.0}}));
}

TEST(InpSteps, AmplitudesBecomeCurvesAndLapseAtTheEndOfTheirStep) {
  const Model m = model_of(kModel + R"(*AMPLITUDE, NAME=RISE
0., 0., 2., 1.
*AMPLITUDE, NAME=ALWAYS, TIME=TOTAL TIME
0., 0., 1., 1., 10., 1.
*STEP
*STATIC
0.5, 1.
*CLOAD, AMPLITUDE=rise
12, 3, 10.
*CLOAD, AMPLITUDE=ALWAYS
9, 1, 3.
*END STEP
*STEP
*STATIC
*END STEP
)");
  ASSERT_EQ(m.static_steps.size(), 2u);
  const StaticStep& s1 = m.static_steps[0];
  ASSERT_EQ(s1.forces.size(), 2u);
  const StepForce& rise = s1.forces[0].node == 11 ? s1.forces[0] : s1.forces[1];
  const StepForce& always = s1.forces[0].node == 11 ? s1.forces[1] : s1.forces[0];
  ASSERT_TRUE(rise.amplitude.curve.valid());
  EXPECT_FALSE(rise.amplitude.total_time);
  EXPECT_EQ(m.functions.value(rise.amplitude.curve, 1.0, Variables{}), 0.5);
  EXPECT_TRUE(always.amplitude.total_time);
  EXPECT_NE(rise.amplitude.curve.index, always.amplitude.curve.index);
  // Step 2: RISE (step time) has lapsed: its force stays at 10 x RISE(1) = 5 without a curve;
  // ALWAYS (total time) keeps its curve and reference value.
  const auto forces = by_node(m, m.static_steps[1].forces);
  EXPECT_EQ(forces.at({12, 2}), 5.0);
  EXPECT_EQ(forces.at({9, 0}), 3.0);
  for (const StepForce& f : m.static_steps[1].forces)
    EXPECT_EQ(f.amplitude.curve.valid(), f.node == 8);
}

TEST(InpSteps, StaticDataNlgeomAndTime) {
  const Model m = model_of(kModel + R"(*STEP, INC=50
*STATIC
0.1, 2., 0.01, 0.5
*END STEP
*STEP, NLGEOM
*STATIC, DIRECT
0.25, 1.
*END STEP
*STEP, NAME=Third
*STATIC
*END STEP
)");
  ASSERT_EQ(m.static_steps.size(), 3u);
  const StaticStep& a = m.static_steps[0];
  EXPECT_FALSE(a.nonlinear_geometry);
  EXPECT_EQ(a.max_increments, 50);
  EXPECT_EQ(a.initial_increment, 0.1);
  EXPECT_EQ(a.period, 2.0);
  EXPECT_EQ(a.min_increment, 0.01);
  EXPECT_EQ(a.max_increment, 0.5);
  EXPECT_FALSE(a.fixed_increments);
  EXPECT_EQ(a.title, "Step 1");
  const StaticStep& b = m.static_steps[1];
  EXPECT_TRUE(b.nonlinear_geometry);
  EXPECT_TRUE(b.fixed_increments);
  EXPECT_EQ(b.max_increments, 100);
  // CalculiX defaults: minimum min(initial, 1e-5 period); maximum (1e30) capped at the period.
  EXPECT_EQ(b.min_increment, 1e-5);
  EXPECT_EQ(b.max_increment, 1.0);
  const StaticStep& c = m.static_steps[2];
  EXPECT_TRUE(c.nonlinear_geometry);  // NLGEOM stays on
  EXPECT_EQ(c.title, "Third");
  EXPECT_EQ(c.initial_increment, 1.0);
  EXPECT_EQ(c.period, 1.0);
  EXPECT_EQ(m.time.end_time, 4.0);
}

TEST(InpSteps, EquationsFirstTermDependent) {
  const Model m = model_of(kModel + R"(*EQUATION
2
3, 3, 1., 9, 3, -1.
5
1, 1, 1., 2, 1, 2., 3, 1, 3., 4, 1, 4.,
5, 2, -0.5
*STEP
*STATIC
*END STEP
)");
  ASSERT_EQ(m.equations.size(), 2u);
  const LinearConstraint& a = m.equations[0];
  ASSERT_EQ(a.terms.size(), 2u);
  EXPECT_EQ(m.mesh.nodes.id[static_cast<std::size_t>(a.terms[0].node)], 3);
  EXPECT_EQ(a.terms[0].dof, 2);
  EXPECT_EQ(a.terms[1].coefficient, -1.0);
  ASSERT_EQ(m.equations[1].terms.size(), 5u);
  EXPECT_EQ(m.equations[1].terms[4].dof, 1);
  EXPECT_EQ(m.equations[1].terms[4].coefficient, -0.5);
  EXPECT_EQ(m.equations[1].where.line, 26u);
}

TEST(InpSteps, PrintRequestsCarryOverUntilReplaced) {
  const Model m = model_of(kModel + R"(*STEP
*STATIC
*NODE PRINT, NSET=LEFT, FREQUENCY=5, TOTALS=YES
U, RF
*EL PRINT
S, E, ELSE
*CONTACT PRINT
CDISP, CSTRESS, CELS
*END STEP
*STEP
*STATIC
*NODE PRINT
U
*END STEP
)");
  const auto& p1 = m.static_steps.at(0).prints;
  ASSERT_EQ(p1.size(), 3u);
  EXPECT_EQ(p1[0].kind, PrintRequest::Kind::Node);
  EXPECT_EQ(p1[0].quantities, (std::vector<std::string>{"U", "RF"}));
  EXPECT_EQ(p1[0].set_name, "LEFT");
  EXPECT_EQ(p1[0].members, (std::vector<std::int32_t>{0, 3, 6, 9}));
  EXPECT_EQ(p1[0].frequency, 5);
  EXPECT_TRUE(p1[0].totals);
  EXPECT_FALSE(p1[0].totals_only);
  EXPECT_EQ(p1[1].kind, PrintRequest::Kind::Element);
  EXPECT_EQ(p1[1].members, (std::vector<std::int32_t>{0, 1}));  // no ELSET: every element
  EXPECT_EQ(p1[2].kind, PrintRequest::Kind::Contact);
  EXPECT_EQ(p1[2].quantities, (std::vector<std::string>{"CDIS", "CSTR", "CELS"}));
  EXPECT_TRUE(p1[2].members.empty());
  // Step 2 replaces the node request, keeps the element and contact ones.
  const auto& p2 = m.static_steps.at(1).prints;
  ASSERT_EQ(p2.size(), 3u);
  EXPECT_EQ(p2[0].quantities, (std::vector<std::string>{"U"}));
  EXPECT_EQ(p2[0].members.size(), 12u);
  EXPECT_EQ(p2[0].frequency, 1);
  EXPECT_EQ(p2[1].kind, PrintRequest::Kind::Element);
  EXPECT_EQ(p2[2].kind, PrintRequest::Kind::Contact);
}

TEST(InpSteps, PrintKeysOfFieldsAbutDoesNotComputeAreLeftOutWithANote) {
  const DeckResult r = read_inp_string_with_notes(kModel + R"(*STEP
*STATIC
*NODE PRINT, NSET=LEFT
NT, U
*EL PRINT
S
*END STEP
*STEP
*STATIC
*EL PRINT
SDV
*END STEP
)",
                                                  "t.inp");
  const auto& first = r.model.static_steps.at(0).prints;
  ASSERT_EQ(first.size(), 2u);
  EXPECT_EQ(first[0].quantities, (std::vector<std::string>{"U"}));
  // Step 2's *EL PRINT has nothing abut computes, but it still replaces step 1's.
  const auto& second = r.model.static_steps.at(1).prints;
  ASSERT_EQ(second.size(), 1u);
  EXPECT_EQ(second[0].kind, PrintRequest::Kind::Node);
  ASSERT_EQ(r.notes.size(), 2u);
  EXPECT_EQ(r.notes[0].rfind("t.inp:25: *NODE PRINT: NT left out", 0), 0u) << r.notes[0];
  EXPECT_EQ(r.notes[1].rfind("t.inp:32: *EL PRINT: SDV left out", 0), 0u) << r.notes[1];
}

TEST(InpSteps, ControlsAreNotedAndFileOutputChoosesTheStates) {
  const DeckResult r = read_inp_string_with_notes(kModel + R"(*STEP
*STATIC
*CONTROLS, PARAMETERS=LINE SEARCH
,1.,1.,
*NODE FILE, FREQUENCY=2
U
*END STEP
)",
                                                  "t.inp");
  ASSERT_EQ(r.notes.size(), 1u);
  EXPECT_EQ(r.notes[0].rfind("t.inp:25: *CONTROLS skipped", 0), 0u) << r.notes[0];
  EXPECT_TRUE(r.model.static_steps.at(0).prints.empty());
  // *NODE FILE chooses the states' fields and frequency (OutputRequests).
  EXPECT_EQ(r.model.output.state_frequency, 2);
  ASSERT_TRUE(r.model.output.state_fields.has_value());
  EXPECT_EQ(*r.model.output.state_fields, (std::vector<std::string>{"displacement"}));
}

// *CONTROLS, PARAMETERS=FIELD sets R_n and C_n of the displacement field for this step and the
// next ones until RESET (CalculiX User's Manual, *CONTROLS).
TEST(InpSteps, FieldControlsSetTheNewtonTolerancesUntilReset) {
  const DeckResult r = read_inp_string_with_notes(kModel + R"(*CONTROLS, PARAMETERS=FIELD
1e-9, 2e-9
*STEP
*STATIC
*END STEP
*STEP
*STATIC
*CONTROLS, PARAMETERS=FIELD, FIELD=DISPLACEMENT
, 1e-6
*END STEP
*STEP
*STATIC
*CONTROLS, RESET
*END STEP
)",
                                                  "t.inp");
  const auto& steps = r.model.static_steps;
  ASSERT_EQ(steps.size(), 3u);
  EXPECT_EQ(steps[0].force_tolerance, 1e-9);
  EXPECT_EQ(steps[0].displacement_tolerance, 2e-9);
  EXPECT_EQ(steps[1].force_tolerance, 1e-9);
  EXPECT_EQ(steps[1].displacement_tolerance, 1e-6);
  EXPECT_FALSE(steps[2].force_tolerance.has_value());
  EXPECT_FALSE(steps[2].displacement_tolerance.has_value());
  EXPECT_TRUE(r.notes.empty());
}

}  // namespace
}  // namespace abut
