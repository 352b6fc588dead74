// The shipped examples parse into the model they describe. rubber_sphere.k is the example deck
// of the IMPETUS *CONTACT page (seed 000) exactly as printed there.
#include <gmock/gmock.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "abut/solver/static_heat.hpp"
#include "abut/solver/static_solver.hpp"
#include "test_deck_helpers.hpp"

namespace abut {
namespace {

std::string example(const std::string& name) {
  return std::string(ABUT_SOURCE_DIR) + "/examples/" + name;
}

TEST(DeckExamples, SeedRubberSphereOnSteelBlock) {
  const DeckResult r = read_deck_with_notes(example("rubber_sphere.k"));
  const Model& m = r.model;
  EXPECT_EQ(m.units, UnitSystem::SI);
  EXPECT_DOUBLE_EQ(m.time.end_time, 0.001);

  ASSERT_EQ(m.parts.size(), 2u);
  EXPECT_EQ(m.parts[0].id, 1);
  EXPECT_EQ(m.parts[0].title, "rubber");
  EXPECT_EQ(m.parts[0].material_id, 1);
  EXPECT_EQ(m.parts[1].id, 2);
  EXPECT_EQ(m.parts[1].title, "steel");
  EXPECT_EQ(m.parts[1].material_id, 2);

  // Seed: "1, 1500.0, 3.0e9 / 1.0e6, 0, 1.0e2" and "2, 7800.0, 210.0e9, 0.3".
  const auto& rubber = std::get<MooneyRivlinParams>(m.material_of_part(1));
  EXPECT_DOUBLE_EQ(rubber.density, 1500.0);
  EXPECT_DOUBLE_EQ(rubber.bulk, 3.0e9);
  EXPECT_DOUBLE_EQ(rubber.c1, 1.0e6);
  EXPECT_DOUBLE_EQ(rubber.c2, 0.0);
  EXPECT_DOUBLE_EQ(rubber.alpha[0], 100.0);
  EXPECT_DOUBLE_EQ(rubber.beta[0], 0.0);
  const auto& steel = std::get<ElasticParams>(m.material_of_part(2));
  EXPECT_DOUBLE_EQ(steel.density, 7800.0);
  EXPECT_DOUBLE_EQ(steel.young, 210.0e9);
  EXPECT_DOUBLE_EQ(steel.poisson, 0.3);

  // The block: 2 x 2 x 1 elements, 3 x 3 x 2 nodes.
  EXPECT_EQ(m.nodes_of({EntityType::Part, 2, {}}).size(), 18u);
  EXPECT_EQ(std::count(m.mesh.hex_part.begin(), m.mesh.hex_part.end(), 2), 4);
  EXPECT_GT(std::count(m.mesh.hex_part.begin(), m.mesh.hex_part.end(), 1), 0);

  // "P, 1, 0.0, 0.0, -100.0": part 1 only.
  const auto sphere_nodes = m.nodes_of({EntityType::Part, 1, {}});
  for (std::size_t i = 0; i < m.mesh.nodes.size(); ++i) {
    const bool on_sphere =
        std::binary_search(sphere_nodes.begin(), sphere_nodes.end(), static_cast<std::int32_t>(i));
    EXPECT_DOUBLE_EQ(m.vz0[i], on_sphere ? -100.0 : 0.0);
    EXPECT_DOUBLE_EQ(m.vx0[i], 0.0);
    EXPECT_DOUBLE_EQ(m.vy0[i], 0.0);
  }

  // "rubber to steel" / "1" / "P, 1, P, 2, 0.1".
  ASSERT_EQ(m.contacts.size(), 1u);
  const ContactSpec& c = m.contacts[0];
  EXPECT_EQ(c.id, 1);
  EXPECT_EQ(c.title, "rubber to steel");
  EXPECT_EQ(c.surface1.type, EntityType::Part);
  EXPECT_EQ(c.surface1.id, 1);
  EXPECT_EQ(c.surface2.type, EntityType::Part);
  EXPECT_EQ(c.surface2.id, 2);
  EXPECT_DOUBLE_EQ(c.friction, 0.1);
  EXPECT_FALSE(c.friction_function.valid());
  EXPECT_FALSE(c.penalty.has_value());  // automatic
  EXPECT_DOUBLE_EQ(c.damping, 0.1);

  // *CHANGE_P-ORDER and *SMOOTH_MESH tell the user what they did.
  EXPECT_GE(r.notes.size(), 2u);
}

TEST(DeckExamples, BarImpact) {
  const Model m = read_deck(example("bar_impact.k"));
  EXPECT_EQ(m.title, "Steel bar, 50 m/s, one end held fixed");
  EXPECT_EQ(m.mesh.hex_count(), 160u);  // 40 x 2 x 2
  for (std::size_t i = 0; i < m.mesh.nodes.size(); ++i) EXPECT_DOUBLE_EQ(m.vx0[i], -50.0);
  ASSERT_EQ(m.motions.size(), 1u);
  EXPECT_EQ(m.motions[0].id, 1);
  EXPECT_EQ(m.motions[0].fixed_translation, kFixX);
  const auto end_face = m.nodes_of(m.motions[0].entity);
  EXPECT_EQ(end_face.size(), 9u);  // 3 x 3 nodes at x = 0
  for (const auto i : end_face) EXPECT_DOUBLE_EQ(m.mesh.nodes.x[i], 0.0);
}

// A static deck (*STATIC): the punch pressed into the base and half released. It runs in well under
// a second, so it is run here: the punch is in equilibrium (the contact force balances the
// reaction on its top face) and the force halves with the travel (linear elastic).
TEST(DeckExamples, StaticBlockPress) {
  const Model m = read_deck(example("static_block_press.k"));
  ASSERT_EQ(m.static_steps.size(), 2u);
  EXPECT_EQ(m.static_steps[0].title, "press");
  EXPECT_DOUBLE_EQ(m.static_steps[0].period, 1.0);
  EXPECT_DOUBLE_EQ(m.static_steps[1].period, 1.0);
  EXPECT_DOUBLE_EQ(m.time.end_time, 2.0);
  for (const Part& p : m.parts) EXPECT_EQ(p.solid_integration, Part::SolidIntegration::Full);
  ASSERT_EQ(m.contacts.size(), 1u);
  EXPECT_TRUE(m.motions.empty());
  // Base bottom: 9 x 9 nodes, 3 dofs; punch top: 5 x 5 nodes, 3 dofs.
  EXPECT_EQ(m.static_steps[0].displacements.size(), 3u * 81u + 3u * 25u);

  StaticSolver solver(m);
  std::vector<double> force;  // of the base on the punch, at the end of each step
  solver.run([&](const StaticIncrement& inc) {
    if (!inc.step_end) return;
    double top = 0.0;  // reaction on the punch's top face
    for (std::size_t i = 0; i < m.mesh.nodes.size(); ++i)
      if (m.mesh.nodes.z[i] == 20.0) top += solver.reaction()[3 * i + 2];
    double contact = 0.0;  // force on surface 1 (the punch), both passes
    const auto passes = solver.contacts();
    for (std::size_t k = 0; k < passes.size(); ++k)
      contact += (k == 0 ? 1.0 : -1.0) * passes[k].total_force().z;
    EXPECT_NEAR(contact + top, 0.0, 1e-4 * std::abs(top));
    force.push_back(contact);
  });
  ASSERT_EQ(force.size(), 2u);
  EXPECT_NEAR(force[0], 18.07e3, 0.01e3);
  EXPECT_NEAR(force[1] / force[0], 0.5, 0.005);
}

// The .inp example (tools/make_punch_inp.py): a steel punch pressed 1 mm into a soft block,
// face to face with Coulomb friction, NLGEOM. The reference is CalculiX 2.20 on the same deck, the
// punch force at full travel (the example's header: 283.74 N, quarter model), within 0.5%. It
// stopped at its first increment until static cells integrated their normal law point by point
// (docs/contact.md); no test ran it then.
TEST(DeckExamples, PunchInpAgainstCalculiX) {
  const Model m = read_deck(example("punch.inp"));
  double top_z = -1e300;
  for (std::size_t i = 0; i < m.mesh.nodes.size(); ++i) top_z = std::max(top_z, m.mesh.nodes.z[i]);
  StaticSolver solver(m);
  double force = 0.0;
  solver.run([&](const StaticIncrement& inc) {
    if (!inc.step_end) return;
    force = 0.0;  // minus the sum of RF_z over the top face (the .dat files print -283.74)
    for (std::size_t i = 0; i < m.mesh.nodes.size(); ++i)
      if (m.mesh.nodes.z[i] == top_z) force -= solver.reaction()[3 * i + 2];
  });
  std::cout << "punch force at 1 mm: " << force << " N (ccx 283.74 N)\n";
  EXPECT_NEAR(force, 283.74, 0.005 * 283.74);
}

// The thermal contact example: each state's heat flow through the die-plate contact rises with
// the press force and stays below the bound of the die's own resistance L/(kA) = 0.5 K/W in series
// with the contact's at the mean pressure p: h(p) = h_c0 (p/H_v)^w is concave, so the points'
// conductance sums to at most h(p) A, and the plate's resistance can only add (Incropera & DeWitt,
// section 3.1: resistances in series). Each state's heat balance: all the heat the die's held face
// puts in crosses the contact and leaves through the plate's held face.
TEST(DeckExamples, HotDiePress) {
  const Model m = read_deck(example("hot_die_press.k"));
  ASSERT_EQ(m.static_steps.size(), 2u);
  StaticSolver solver(m);
  StaticHeat heat(m);
  ASSERT_TRUE(heat.active());
  std::vector<double> flow, force;
  solver.run([&](const StaticIncrement& inc) {
    heat.solve(solver, inc.total_time);
    double f = 0.0;  // of the plate on the die, both passes
    const auto passes = solver.contacts();
    for (std::size_t k = 0; k < passes.size(); ++k)
      f += (k == 0 ? 1.0 : -1.0) * passes[k].total_force().z;
    force.push_back(f);
    flow.push_back(heat.contact_heat_flow()[0]);
    const SteadyHeatBalance& b = heat.balance();
    EXPECT_NEAR(b.prescribed_in, flow.back(), 1e-9 * flow.back());
    EXPECT_NEAR(b.prescribed_out, -flow.back(), 1e-9 * flow.back());
    EXPECT_EQ(b.boundary_in, 0.0);
    EXPECT_EQ(b.boundary_out, 0.0);
    EXPECT_LT(std::abs(b.relative_error()), 1e-12);
  });
  ASSERT_EQ(flow.size(), 4u);
  const double area = 0.02 * 0.02, die = 0.01 / (50.0 * area);
  for (std::size_t i = 0; i < flow.size(); ++i) {
    const double h = 1.0e5 * std::pow(force[i] / area / 1.0e9, 0.95);
    EXPECT_GT(flow[i], 0.0);
    EXPECT_LT(flow[i], 280.0 / (die + 1.0 / (h * area)));
    if (i > 0) {
      EXPECT_GT(flow[i], flow[i - 1]);
    }
  }
}

// examples/gmsh/can_drop.k: the can of can.geo, meshed by Gmsh at read time with 6 mm
// tetrahedra, is part 1 over the generated plate (10 x 10 x 2 hexahedra).
TEST(DeckExamples, GmshCanDrop) {
  const DeckResult r = read_deck_with_notes(example("gmsh/can_drop.k"));
  const Model& m = r.model;
  ASSERT_EQ(m.mesh.cells.size(), 1u);
  EXPECT_EQ(m.mesh.cells[0].type, CellType::tet4);
  EXPECT_GT(m.mesh.cells[0].size(), 1000u);
  EXPECT_EQ(std::count(m.mesh.hex_part.begin(), m.mesh.hex_part.end(), 2), 200);
  // The lowest point of the can is 0.5 mm above the plate (can.geo).
  double lowest = 1e9;
  for (const std::int32_t n : m.nodes_of({EntityType::Part, 1, {}}))
    lowest = std::min(lowest, m.mesh.nodes.z[static_cast<std::size_t>(n)]);
  EXPECT_NEAR(lowest, 0.5, 1e-9);
}

}  // namespace
}  // namespace abut
