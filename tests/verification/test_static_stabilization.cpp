// Contact stabilization in static steps (*CONTACT_STABILIZATION, OptiStruct CNTSTB; laws/
// stabilization.hpp). A steel block 10 x 10 x 10 mm floats 0.01 mm above an aluminium base of the
// same footprint (meshes 3 x 3 and 4 x 4, not matching), pressed by 100 MPa on its top face: on
// rollers at x = 0 and y = 0 (a quarter of a block twice as wide), the base held at its bottom in
// z only, frictionless contact with pfac = 1e6 MPa/mm, small displacements. Until the contact
// closes nothing holds the block along z, and the static solver stops on a singular matrix; the
// stabilization's damping carries it across the gap and fades to nothing at the step's end
// (S1 = 0), so the end state is the undamped one.
// Reference (closed form): two bars in series under uniform stress p (rollers, frictionless
// contact, nu = 0 so that the contact area keeps its size: with nu = 0.3 and 0.33 the faces widen
// by nu p / E, and the travel moved by 3e-6 of itself): the contact force p A = 1e4 N and the top
// face's travel
//   w = g0 + p / pfac + p h / E_steel + p h / E_alu
//     = 0.01 + 1e-4 + 4.7619e-3 + 1.42857e-2 = 2.914762e-2 mm,
// which the uniform contact pressure gives exactly on non-matching meshes (the static patch test,
// docs/verification.md).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>

#include "abut/io/deck.hpp"
#include "abut/solver/static_solver.hpp"

namespace abut {
namespace {

constexpr double kPressure = 100.0, kGap = 0.01, kPfac = 1e6, kH = 10.0;
constexpr double kSteel = 210000.0, kAluminium = 70000.0;

std::string floating_block(const std::string& stabilization) {
  return std::string(R"(*UNIT_SYSTEM
MMTONS
*COMPONENT_BOX
"base"
1, 1, 4, 4, 4
0.0, 0.0, 0.0, 10.0, 10.0, 10.0
*COMPONENT_BOX
"block"
2, 2, 3, 3, 3
0.0, 0.0, 10.01, 10.0, 10.0, 20.01
*MAT_ELASTIC
1, 2.7e-9, 70000.0, 0.0
*MAT_ELASTIC
2, 7.85e-9, 210000.0, 0.0
*PART
"base"
1, 1
"block"
2, 2
*PART_SOLID
1, FULL
2, FULL
*GEOMETRY_BOX
1
-1.0, -1.0, -0.001, 11.0, 11.0, 0.001
*GEOMETRY_BOX
2
-0.001, -1.0, -1.0, 0.001, 11.0, 21.0
*GEOMETRY_BOX
3
-1.0, -0.001, -1.0, 11.0, 0.001, 21.0
*GEOMETRY_BOX
4
-1.0, -1.0, 20.009, 11.0, 11.0, 20.011
*BC_MOTION
1
G, 1, Z
2
G, 2, X
3
G, 3, Y
*CURVE
1
0.0, 0.0
1.0, 1.0
*LOAD_PRESSURE
G, 4, 1, 100.0
*CONTACT
"block on base"
1
P, 2, P, 1, 0.0, 1.0e6
)") + stabilization +
         R"(*STATIC
"press"
1.0, 0.25, , , 0
*END
)";
}

TEST(StaticStabilization, CarriesAFloatingBlockAcrossItsGapAndFadesAway) {
  // Without stabilization the block floats: every increment is singular until the smallest.
  {
    const Model m = read_deck_string(floating_block(""), "floating.k");
    StaticSolver solver(m);
    EXPECT_THROW(solver.run(), StaticConvergenceError);
  }
  // Each discretisation: S2S symmetric (the default) and one-way hold the patch test to
  // round-off, and the travel is held to the closed form. N2S one-way does not hold it (its
  // pressures are off by up to 14.4% on these meshes, docs/verification.md), and here its nodes on
  // the base's border (flush with it, nu = 0) open and close: with the default Newton tolerances it
  // converges, its force is statics and exact, but its travel ends 24% long (0.0362 mm; the block's
  // border sinks into the base), an open finding of node-to-surface contact on a surface's border
  // (the issue's note), so the travel is printed, not held, for N2S.
  struct Cell {
    const char* discretisation;
    bool surface_to_surface;
  };
  for (const Cell& cell : {Cell{"", true}, Cell{"*CONTACT_DISCRETIZATION\n1, S2S, 0\n", true},
                           Cell{"*CONTACT_DISCRETIZATION\n1, N2S, 0\n", false}}) {
    const Model m = read_deck_string(
        floating_block(std::string(cell.discretisation) + "*CONTACT_STABILIZATION\n1\n"),
        "floating.k");
    StaticControls controls;  // tight: the comparison is the solution's, not Newton's tolerance
    if (cell.surface_to_surface) controls.force_tolerance = controls.displacement_tolerance = 1e-8;
    StaticSolver solver(m, controls);
    ASSERT_NO_THROW(solver.run()) << cell.discretisation;
    const Nodes& x = m.mesh.nodes;
    double travel = 0.0;
    int top = 0;
    for (std::size_t i = 0; i < x.size(); ++i)
      if (std::abs(x.z[i] - (kGap + 2 * kH)) < 1e-9)
        travel -= solver.displacement()[3 * i + 2], ++top;
    travel /= top;
    const double expected =
        kGap + kPressure / kPfac + kPressure * kH / kSteel + kPressure * kH / kAluminium;
    double force = 0.0, work = 0.0;
    const auto passes = solver.contacts();  // symmetric: the second pass acts on the base
    for (std::size_t k = 0; k < passes.size(); ++k) {
      force += (k == 0 ? 1.0 : -1.0) * passes[k].total_force().z;
      work += passes[k].stabilization_work();
    }
    std::cout << "floating block " << cell.discretisation << ": travel " << travel
              << " mm (closed form " << expected << "), contact force " << force
              << " N, stabilization work " << work << " N mm\n";
    if (cell.surface_to_surface) {
      EXPECT_NEAR(travel, expected, 1e-6 * expected) << cell.discretisation;
    }
    EXPECT_NEAR(force, kPressure * kH * kH, 1e-6 * kPressure * kH * kH) << cell.discretisation;
    EXPECT_GT(work, 0.0) << cell.discretisation;  // it did act
  }
}

}  // namespace
}  // namespace abut
