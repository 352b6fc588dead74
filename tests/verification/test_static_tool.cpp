// Analytic rigid tools in static steps (*CONTACT_TOOL, Metafor's rigid contact matrices, seed 002,
// in implicit use): node to surface against a plane and a cylinder that move.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>
#include <string>

#include "abut/io/deck.hpp"
#include "abut/solver/static_solver.hpp"
#include "ring_mesh.hpp"

namespace abut {
namespace {

// A block 10 x 10 x 10 mm (E = 2e5 MPa, nu = 0, 4 x 4 x 4, small strain) held at its top face
// stands on a rigid plane (pfac 1e4 MPa/mm, mu = 0.2). Step 1: the plane rises by
// u = int v_z dt = 0.01 x 0.99 + 0.01 x 0.01 / 2 = 9.95e-3 mm (its velocity curve: 0.01 mm/s to
// t = 0.99 s, to 0 at 1 s). Step 2: it slides 0.0995 mm along x under the block.
// Reference (closed form, the contact's spring and the block in series, uniform with nu = 0):
//   N = u / (1 / (pfac A) + h / (E A)) = 9.95e-3 / 1.5e-6 = 6633.333 N,
// and while the plane slides every node slips: the drag on the held face is mu N = 1326.667 N.
// The nodes on the block's bottom edges bear with the part of their area that faces the plane
// (their shares of the side faces would make the spring 1.5 times stiffer: N = 8354 N).
TEST(StaticTool, ARisingPlaneCompressesABlockAndDragsItWithFriction) {
  const std::string deck = R"(*UNIT_SYSTEM
MMTONS
*COMPONENT_BOX
"block"
1, 1, 4, 4, 4
0.0, 0.0, 0.0, 10.0, 10.0, 10.0
*MAT_ELASTIC
1, 7.85e-9, 200000.0, 0.0
*PART
"block"
1, 1
*PART_SOLID
1, FULL
*GEOMETRY_BOX
1
-1.0, -1.0, 9.999, 11.0, 11.0, 10.001
*BC_MOTION
G, 1, XYZ
*CURVE
1
0.0, 0.01
0.99, 0.01
1.0, 0.0
3.0, 0.0
*CURVE
2
0.0, 0.0
1.0, 0.0
1.01, 0.1
3.0, 0.1
*CONTACT_TOOL
1, PLANE, OUTSIDE
0.0, 0.0, 0.0, 0.0, 0.0, 1.0
2, 1.0, , , 1, 1.0
*CONTACT
"block on a plane tool"
1
P, 1, TOOL, 1, 0.2, 1.0e4
*STATIC
"press"
1.0, 0.25, , , 0
*STATIC
"drag"
2.0, 0.25, , , 0
*END
)";
  const Model m = read_deck_string(deck, "plane_tool.k");
  StaticControls controls;  // tight: the comparison is the solution's, not Newton's tolerance
  controls.force_tolerance = controls.displacement_tolerance = 1e-8;
  StaticSolver solver(m, controls);
  const double n_ref = 9.95e-3 / (1.0 / (1e4 * 100.0) + 10.0 / (2e5 * 100.0));
  int checked = 0;
  solver.run([&](const StaticIncrement& inc) {
    const Vec3 f = solver.contacts()[0].total_force();
    std::cout << "t = " << inc.total_time << ": normal " << f.z << " N, drag " << f.x << " N\n";
    if (inc.step == 0 && inc.step_end) {
      EXPECT_NEAR(f.z, n_ref, 1e-6 * n_ref);
      ++checked;
    }
    if (inc.step == 1) {
      // The tool's path is integrated by Simpson's rule across its curve's kinks (ToolMotion):
      // its rise holds to some 1e-6; the drag is Coulomb's to round-off.
      EXPECT_NEAR(f.z, n_ref, 1e-5 * n_ref);
      EXPECT_NEAR(f.x, 0.2 * f.z, 1e-9 * f.z);
      ++checked;
    }
  });
  EXPECT_GE(checked, 3);
}

// The shaft of test_static_smoothing.cpp (a ring 6 <= r <= 10 mm, 48 elements round, E = 2e7
// MPa, k = 100 MPa/mm, mu = 0.3, held in z) in an analytic bearing: a cylinder of radius 10 mm
// about z, the shaft INSIDE it. Step 1 lowers the shaft's inner nodes by delta = 5e-3 mm; step 2
// spins the bearing at pi/6 rad/s (from t = 1 s, reached at 1.01 s) while the shaft is held.
// Reference (closed form, a rigid shaft on a Winkler foundation): W = k delta R L pi / 2 = 7.854
// N, N = 2 k delta R L = 10 N, and the bearing's friction turns the shaft with T = mu R N =
// 30 N mm (its inner nodes' reaction). The nodes are the contact points, each with its facing
// area, chord L cos(h / 2) (h = 7.5 degrees), so the integrals become the sums over the nodes
// below 90 degrees (the trapezoidal rule of the integrals, -0.14% for N, exact for W), times
// the chords (-0.07%) and the facing (-0.21%): N and T 0.43% and W 0.29% below the integrals,
// computed here from the nodes' angles. Held to 1e-3 of them: the overlap's second order
// delta / (2 R) = 2.5e-4 and the shaft's compliance (1e-5) remain.
constexpr double kShaftR = 10.0, kDelta = 5e-3, kPenalty = 100.0, kMu = 0.3;
const verification::Ring kShaft{0, 48, 6.0, kShaftR};

// The held shaft's deck against a bearing tool whose line 2 is `bearing` (and line 3 `motion`),
// friction coefficient `mu`.
std::string shaft_in_bearing(const std::string& bearing, const std::string& motion,
                             double mu = kMu) {
  std::ostringstream nodes, hexes;
  nodes.precision(17);
  verification::write_ring(nodes, hexes, kShaft, 1, 0);
  // Each inner node: x held, y lowered by curve 1.
  std::ostringstream bc;
  for (int iz = 0; iz < 2; ++iz)
    for (int it = 0; it < kShaft.around; ++it)
      bc << "*BC_MOTION\nN, " << kShaft.id(0, it, iz) << ", X\nD, Y, 1, -1.0\n";
  return "*UNIT_SYSTEM\nMMTONS\n*NODE\n" + nodes.str() + "*ELEMENT_SOLID\n" + hexes.str() +
         R"(*MAT_ELASTIC
1, 7.85e-9, 2.0e7, 0.3
*PART
"shaft"
1, 1
*PART_SOLID
1, FULL
*BC_MOTION
P, 1, Z
)" + bc.str() +
         R"(*CURVE
1
0.0, 0.0
1.0, 5.0e-3
3.0, 5.0e-3
*CURVE
2
0.0, 0.0
1.0, 0.0
1.01, 0.5235987755982988
3.0, 0.5235987755982988
*CONTACT_TOOL
1, CYLINDER, INSIDE
)" + bearing +
         "\n" + motion + R"(*CONTACT
"shaft in an analytic bearing"
1
P, 1, TOOL, 1, )" +
         std::to_string(mu) + R"(, 100.0
*STATIC
"lower"
1.0, 0.25, , , 1
*STATIC
"spin"
2.0, 0.1, , 0.1, 1
*END
)";
}

// The facing area of a shaft node (chord L cos(h / 2), h the angle between nodes).
double facing_area() {
  const double h = 2.0 * verification::kRingPi / kShaft.around;
  return 2.0 * kShaftR * std::sin(h / 2.0) * std::cos(h / 2.0) * verification::kRingLength;
}

TEST(StaticTool, ASpinningBearingTurnsAHeldShaftWithTheFrictionOfItsCircle) {
  using verification::kRingLength;
  using verification::kRingPi;
  constexpr double kR = kShaftR;
  const verification::Ring& shaft = kShaft;
  const Model m = read_deck_string(
      shaft_in_bearing("0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 10.0", ", , , , , , 2, 1.0\n"),
      "bearing_tool.k");
  StaticSolver solver(m);
  // The nodes' sums: sum over the nodes below the axis of k delta cos(theta) (and its vertical
  // part, cos^2) times their facing areas.
  const double facing = facing_area();
  double sum_cos = 0.0, sum_cos2 = 0.0;
  for (int it = 0; it < shaft.around; ++it) {
    const double c = std::max(0.0, -std::sin(shaft.angle(it)));  // cos of the angle from below
    sum_cos += c, sum_cos2 += c * c;
  }
  const double w_ref = kPenalty * kDelta * facing * sum_cos2;
  const double n_ref = kPenalty * kDelta * facing * sum_cos;
  const double t_ref = kMu * kR * n_ref;
  std::cout << "nodes' sums against the integrals: W "
            << w_ref / (kPenalty * kDelta * kR * kRingLength * kRingPi / 2.0) << ", N "
            << n_ref / (2.0 * kPenalty * kDelta * kR * kRingLength) << "\n";
  double worst_w = 0.0, worst_n = 0.0, worst_t = 0.0;
  int increments = 0;
  solver.run([&](const StaticIncrement& inc) {
    if (inc.step != 1) return;
    const verification::DriveReaction drive =
        verification::drive_reaction(m.mesh.nodes, solver.displacement(), solver.reaction(), 6.5);
    const double w = drive.vertical, torque = drive.torque;
    const double normal = verification::normal_force(solver.contacts());
    std::cout << "t = " << inc.total_time << ": W " << w << " N, N " << normal << " N, T " << torque
              << " N mm\n";
    worst_w = std::max(worst_w, std::abs(std::abs(w) - w_ref) / w_ref);
    worst_n = std::max(worst_n, std::abs(normal - n_ref) / n_ref);
    // The first increment of the spin may still stick in part (elastic slip mu p / k_t).
    if (inc.increment > 1) worst_t = std::max(worst_t, std::abs(std::abs(torque) - t_ref) / t_ref);
    ++increments;
  });
  std::cout << "worst errors: W " << worst_w << ", N " << worst_n << ", T " << worst_t << "\n";
  EXPECT_GE(increments, 10);
  EXPECT_LT(worst_w, 1e-3);
  EXPECT_LT(worst_n, 1e-3);
  EXPECT_LT(worst_t, 1e-3);
}

// Metafor's matrix segments: the bearing as arcs (*CONTACT_TOOL dx, dy, dz, span). The lower
// half, from -x through -y, carries what the whole cylinder does (the upper half opens as the
// shaft goes down): the same nodes at the same depths, to round-off. The arc from -x to just
// past -y (93.75 degrees: its end half-way between two nodes; a node on an end is on it or not
// by round-off) carries the nodes at 180 to 270 degrees and pushes the shaft up and to the right: F
// = -sum k delta cos(theta) A (cos a, sin a) over those nodes (a their angle, theta the angle from
// the bottom), held to 1e-3 as above. Frictionless: while the shaft goes down its nodes slide along
// the bearing, and friction would add its share.
TEST(StaticTool, ArcsOfABearingCarryTheirShareOfTheShaft) {
  const auto lowered = [](const std::string& bearing) {
    const Model m = read_deck_string(shaft_in_bearing(bearing, "", 0.0), "arc_tool.k");
    StaticSolver solver(m);
    Vec3 force;
    solver.run([&](const StaticIncrement& inc) {
      if (inc.step == 0 && inc.step_end) force = solver.contacts()[0].total_force();
    });
    return force;
  };
  const Vec3 whole = lowered("0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 10.0");
  const Vec3 half = lowered("0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 10.0, , -1.0, 0.0, 0.0, 180.0");
  const Vec3 quarter = lowered("0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 10.0, , -1.0, 0.0, 0.0, 93.75");
  std::cout << "whole " << whole.x << " " << whole.y << ", half " << half.x << " " << half.y
            << ", quarter " << quarter.x << " " << quarter.y << " N\n";
  EXPECT_NEAR(half.y, whole.y, 1e-10 * whole.y);  // round-off of the two solves
  EXPECT_NEAR(half.x, whole.x, 1e-10 * whole.y);
  Vec3 expected;
  for (int it = 0; it < kShaft.around; ++it) {
    const double a = kShaft.angle(it);
    if (a < verification::kRingPi - 1e-12 || a > 1.5 * verification::kRingPi + 1e-12) continue;
    const double c = std::max(0.0, -std::sin(a));
    expected =
        expected - Vec3{std::cos(a), std::sin(a), 0.0} * (kPenalty * kDelta * c * facing_area());
  }
  EXPECT_NEAR(quarter.x, expected.x, 1e-3 * std::abs(expected.x));
  EXPECT_NEAR(quarter.y, expected.y, 1e-3 * std::abs(expected.y));
}

// A tool is met by nodes: smoothing, which is for surface-to-surface contact, is refused at its
// line rather than ignored.
TEST(StaticTool, SmoothingIsRefusedWithATool) {
  std::string deck = shaft_in_bearing("0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 10.0", "");
  const std::size_t at = deck.find("*STATIC\n\"lower\"");
  deck.insert(at, "*CONTACT_SMOOTHING\n1, BOTH\n");
  const auto line = static_cast<std::size_t>(std::count(deck.begin(), deck.begin() + at, '\n')) + 2;
  const Model m = read_deck_string(deck, "bearing_tool.k");
  try {
    StaticSolver solver(m);
    solver.run();
    ADD_FAILURE() << "a tool contact took smoothing";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, line) << e.what();
    EXPECT_NE(std::string(e.what()).find("surface-to-surface"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace abut
