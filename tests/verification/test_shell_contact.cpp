// Shells as contact surfaces (issue 9): both sides of a shell touch, each at half the thickness
// from the mid-surface (Radioss /INTER/TYPE25, seed 004, comment 1: "two contact segments
// shifted by half thickness with opposite normal directions"; comment 3: g = g_s + g_m with
// g = t/2 on shells, 0 on solids).
//
// A rigid block rests under gravity on a fixed rigid shell plate 10 mm thick (mid-surface z = 0),
// from above, or from below with gravity reversed. At rest the linear penalty carries the weight
// over the block's face, pfac A d = m g, so the block's face lies at h/2 - d from the mid-surface
// with d = m g / (pfac A): an equilibrium that the offset surface must reproduce to round-off
// (compared at 1e-6 of d, once the contact damping has let the start transient die out).
// Without the offset the face would sit at -d. The same with the roles swapped: a rigid shell
// plate rests on (or hangs below) a fixed block, its nodes the contact points (g_s = h/2).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>

#include "run_to.hpp"

namespace abut {
namespace {

constexpr double kThickness = 0.01;
constexpr double kPenalty = 1e9;                          // pfac [Pa/m]
constexpr double kBlockMass = 7800.0 * 0.1 * 0.1 * 0.02;  // rho V of the 0.1 x 0.1 x 0.02 block
constexpr double kPlateMass = 7800.0 * 0.1 * 0.1 * kThickness;
double sink(double mass) { return mass * 9.81 / (kPenalty * 0.1 * 0.1); }  // d = m g / (pfac A)
const double kSink = sink(kBlockMass);

struct Case {
  bool from_below = false;              // the block below the plate
  bool plate_moves = false;             // the plate (0.1 x 0.1) on a fixed block (0.2 x 0.2)
  std::string method = "S2S";           // *CONTACT_DISCRETIZATION method
  std::string surfaces = "P, 1, P, 2";  // block, plate
  std::string symmetric = "";
  double start = 0.5 * kThickness;  // the block's face from the mid-surface at t = 0
  std::string keywords = "";        // more keywords
};

// The block's face next to the plate starts on the plate's contact surface (z = +-h/2).
std::string deck(const Case& c) {
  const double s = c.from_below ? -1.0 : 1.0;  // the block above (+1) or below (-1) the plate
  const double g = c.plate_moves ? 9.81 * s : -9.81 * s;  // presses the moving part on the other
  const double near = s * c.start, far = s * (c.start + 0.02);
  const double block = c.plate_moves ? 0.1 : 0.05, plate = c.plate_moves ? 0.05 : 0.1;
  const std::string b = std::to_string(block), p = std::to_string(plate);
  const int nb = c.plate_moves ? 8 : 4, np = c.plate_moves ? 4 : 8;
  return R"(
*UNIT_SYSTEM
SI
*TIME
0.04
*COMPONENT_BOX
1, 1, )" +
         std::to_string(nb) + ", " + std::to_string(nb) + ", 1\n-" + b + ", -" + b + ", " +
         std::to_string(std::min(near, far)) + ", " + b + ", " + b + ", " +
         std::to_string(std::max(near, far)) + "\n*COMPONENT_SHELL_PLATE\n2, 2, " +
         std::to_string(np) + ", " + std::to_string(np) + "\n-" + p + ", -" + p + ", 0.0, " + p +
         ", -" + p + ", 0.0\n-" + p + ", " + p + R"(, 0.0
*MAT_RIGID
1, 7800.0
*PART
"block"
1, 1
"plate"
2, 1, , 0.01
*BC_MOTION
P, )" + std::string(c.plate_moves ? "1" : "2") +
         R"(, XYZ, XYZ
*CURVE
1
0.0, )" + std::to_string(g) +
         "\n1.0, " + std::to_string(g) + R"(
*LOAD_GRAVITY
Z, 1
*CONTACT
1
)" + c.surfaces +
         ", 0.0, " + std::to_string(kPenalty) + R"(
0, 1.0
*CONTACT_DISCRETIZATION
1, )" + c.method +
         ", " + c.symmetric + "\n" + c.keywords + "*END\n";
}

// Distance of the block's face from the plate's mid-surface at rest.
double face_height(const Case& c) {
  const Model model = read_deck_string(deck(c), "block_on_shell_plate.k");
  Simulation sim(model);
  verification::run_to(sim, model.time.end_time);
  const double block = sim.part_states().at(0).centre_of_mass.z;
  const double plate = sim.part_states().at(1).centre_of_mass.z;
  std::cout << "penetration reported " << sim.contact_reports()[0].stats.max_penetration << " m\n";
  return c.from_below ? -(block + 0.01 - plate) : block - 0.01 - plate;
}

TEST(ShellContact, BlockRestsOnTheTopSurfaceOfAShellPlate) {
  EXPECT_NEAR(face_height({}), 0.5 * kThickness - kSink, 1e-6 * kSink);
}

TEST(ShellContact, BlockRestsAgainstTheBottomSurfaceOfAShellPlate) {
  Case c;
  c.from_below = true;
  EXPECT_NEAR(face_height(c), 0.5 * kThickness - kSink, 1e-6 * kSink);
}

TEST(ShellContact, BlockNodesOnBothSidesOfAShellPlate) {
  for (const bool below : {false, true}) {
    Case c;
    c.from_below = below;
    c.method = "N2S";
    c.symmetric = "0";
    EXPECT_NEAR(face_height(c), 0.5 * kThickness - kSink, 1e-6 * kSink) << "below " << below;
  }
}

TEST(ShellContact, ShellNodesRestOnBothSidesOfABlock) {
  for (const bool below : {false, true}) {
    Case c;
    c.from_below = below;
    c.plate_moves = true;
    c.method = "N2S";
    c.symmetric = "0";
    c.surfaces = "P, 2, P, 1";  // the plate's nodes against the block
    EXPECT_NEAR(face_height(c), 0.5 * kThickness - sink(kPlateMass), 1e-6 * sink(kPlateMass))
        << "below " << below;
  }
}

TEST(ShellContact, ShellAgainstBlockBothWaysSurfaceToSurface) {
  for (const bool below : {false, true}) {
    Case c;
    c.from_below = below;
    c.plate_moves = true;
    EXPECT_NEAR(face_height(c), 0.5 * kThickness - sink(kPlateMass), 1e-6 * sink(kPlateMass))
        << "below " << below;
  }
}

// OptiStruct MORIENT NORM / REVNORM (seed 003: "contact force is oriented along the vector
// normal to the master surface" / "opposite to" it), *CONTACT_GAP shell_side: the plate acts with
// one side only, on its mid-surface (no shell gap), and pushes every point out to that side. The
// plate's normal is +z. A block resting on the side the normal points to settles with its face
// kSink past the mid-surface (pfac A d = m g, as above but without the h/2 offset); a block pressed
// against the other side from the mid-surface is not held: it falls through at least as far as
// free fall takes it in the run, g T^2 / 2 (the surface can only push it further that way).
// Node-to-surface and surface-to-surface.
TEST(ShellContact, OneSidedShellPushesEverythingToItsSide) {
  for (const std::string method : {"S2S", "N2S"})
    for (const bool below : {false, true})
      for (const std::string side : {"NORM", "REVNORM"}) {
        Case c;
        c.from_below = below;
        c.method = method;
        c.symmetric = "0";
        c.start = 0.0;
        c.keywords = "*CONTACT_GAP\n1, , , , , , , , " + side + "\n";
        const bool rests = (side == "NORM") != below;  // the block on the side of the push
        const double face = face_height(c);
        std::cout << method << (below ? " below, " : " above, ") << side << ": face " << face
                  << " m from the mid-surface\n";
        if (rests) {
          EXPECT_NEAR(face, -kSink, 1e-6 * kSink) << method << " " << side << " " << below;
        } else {
          const double fall = 0.5 * 9.81 * 0.04 * 0.04;  // T = 0.04 s, *TIME of deck()
          EXPECT_LT(face, -fall * (1.0 - 1e-9)) << method << " " << side << " " << below;
        }
      }
}

// OptiStruct MORIENT OVERLAP (seed 003: "Slave and master bodies overlap"; the user guide: the
// contact then pushes the bodies apart, as for a fitted bolt), *CONTACT_GAP shell_side OVERLAP:
// the block starts with its face through the plate's mid-surface by kSink / 2, from above (gravity
// down) or from below (gravity up). Each facet pushes back to the side the block came from, on
// the mid-surface as NORM / REVNORM do, so the block rests with its face kSink through it
// (pfac A d = m g). With the plate's normal +z, that is NORM from above and REVNORM from below;
// OPENGAP (two-sided) would push it on through. Node-to-surface and surface-to-surface.
TEST(ShellContact, OverlappingBlockIsPushedBackTheWayItCame) {
  for (const std::string method : {"S2S", "N2S"})
    for (const bool below : {false, true}) {
      Case c;
      c.from_below = below;
      c.method = method;
      c.symmetric = "0";
      c.start = -0.5 * kSink;
      c.keywords = "*CONTACT_GAP\n1, , , , , , , , OVERLAP\n";
      const double face = face_height(c);
      std::cout << method << (below ? " below" : " above") << ", OVERLAP: face " << face
                << " m from the mid-surface\n";
      EXPECT_NEAR(face, -kSink, 1e-6 * kSink) << method << " " << below;
    }
}

// A rigid part 1 (rotations held) resting under gravity, node to surface, on a held rigid part 2
// (the deck's components and parts are `bodies`; `more`: the contact's further keywords): its
// sink d from where it starts, and the worst energy balance over the cycles once the energies
// exceed 1e-3 of m g d_ref, gravity's work at rest (before that it is a ratio of round-off). Until
// 2026-12-03 the first cycles read up to 35%: the external work at t^n was booked with the kick's
// mid velocity, F^n . a^n dt^2/4 off the trapezoidal work central differences conserve
// (simulation.cpp, kick).
struct Settled {
  double sink = 0.0, worst_balance = 0.0;
};
Settled settle(const std::string& bodies, const std::string& contact_line3,
               const std::string& more, double mass, double d_ref) {
  const std::string deck = "*UNIT_SYSTEM\nSI\n*TIME\n0.04\n" + bodies + R"(*BC_MOTION
P, 1, 0, XYZ
*BC_MOTION
P, 2, XYZ, XYZ
*CURVE
1
0.0, -9.81
1.0, -9.81
*LOAD_GRAVITY
Z, 1
*CONTACT
1
P, 1, P, 2, 0.0, )" + std::to_string(kPenalty) +
                           "\n" + contact_line3 + "\n*CONTACT_DISCRETIZATION\n1, N2S, 0\n" + more +
                           "*END\n";
  const Model model = read_deck_string(deck, "resting_on_part_2.k");
  Simulation sim(model);
  const double z0 = sim.part_states().at(0).centre_of_mass.z;
  Settled out;
  verification::run_to(sim, sim.end_time(), [&](const Simulation& s) {
    const Energies e = s.energies();
    if (std::max(std::abs(e.total()), std::abs(e.external_work)) <= 1e-3 * mass * 9.81 * d_ref)
      return;
    out.worst_balance = std::max(out.worst_balance, std::abs(s.energy_balance_error()));
  });
  out.sink = z0 - sim.part_states().at(0).centre_of_mass.z;
  return out;
}

// A rigid shell sheet 0.1 x 0.1 m (4 x 4), 10 mm thick, 10 mm above a rigid shell plate 10 mm
// thick (8 x 8, x from -0.1 m to `plate_end`, y within 0.1 m).
std::string sheet_on_plate(double plate_end) {
  return R"(*COMPONENT_SHELL_PLATE
1, 1, 4, 4
-0.05, -0.05, 0.01, 0.05, -0.05, 0.01
-0.05, 0.05, 0.01
*COMPONENT_SHELL_PLATE
2, 2, 8, 8
-0.1, -0.1, 0.0, )" + std::to_string(plate_end) +
         R"(, -0.1, 0.0
-0.1, 0.1, 0.0
*MAT_RIGID
1, 7800.0
*PART
"sheet"
1, 1, , 0.01
"plate"
2, 1, , 0.01
)";
}

// The sink of `settle` against m g / (pfac A), and the energy balance, for the case `name`.
void expect_sink(const Settled& r, double expected, const std::string& name) {
  std::cout << name << ": sink " << r.sink << " m, m g / (pfac A) = " << expected << " m, error "
            << (r.sink - expected) / expected << "; worst energy balance " << r.worst_balance
            << "\n";
  EXPECT_NEAR(r.sink, expected, 1e-5 * expected) << name;
  EXPECT_LT(r.worst_balance, 0.01) << name;
}

// Radioss Ishape (seed 004, comment 4; *CONTACT_GAP ishape): a rigid shell sheet 0.1 x 0.1 m,
// 10 mm thick (g_s = 5 mm), its rotations held, rests under gravity on a held rigid shell plate
// 10 mm thick (g_m = 5 mm) whose free border lies 2 mm short of the sheet's last row of nodes
// (x = 0.05 m; the plate ends at x = 0.048 m). Node to surface, one way, the sheet's nodes against
// the plate. At rest pfac A d = m g with A the area of the nodes that bear:
//  - SQUARE: the last row's gap reaches 2 mm < g_s beyond the border, so every node bears,
//    A = 0.01 m^2;
//  - CUT: the last row (two corner and three edge nodes of a 4 x 4 mesh: 2 elements' area,
//    1.25e-3 m^2) finds no partner, A = 8.75e-3 m^2;
//  - ROUND: that row lies sqrt(2^2 + 5^2) mm = 5.39 mm > g_s from the slab's edge: open, as CUT.
// The sheet's mid-surface then lies at g - d = 10 mm - d above the plate's (d = 0.765 um and
// 0.874 um). Energy balance (the contact damping's work included) within 1% at every cycle.
TEST(ShellContact, BorderShapeDecidesWhetherNodesBeyondAFreeBorderBear) {
  const double mass = 7800.0 * 0.1 * 0.1 * kThickness;
  const struct {
    const char* shape;
    double area;
  } cases[] = {{"SQUARE", 0.01}, {"CUT", 0.00875}, {"ROUND", 0.00875}};
  for (const auto& c : cases) {
    const double expected = mass * 9.81 / (kPenalty * c.area);
    expect_sink(settle(sheet_on_plate(0.048), "0, 1.0",
                       std::string("*CONTACT_GAP\n1, , , , , , , , , ") + c.shape + "\n", mass,
                       expected),
                expected, c.shape);
  }
}

// IMPETUS delta_edge (*CONTACT line 3; seed 000: "a point may be this far beyond a sharp edge of
// the facet it slides on and still be held by it"): a rigid block 0.1 x 0.1 x 0.02 m (4 x 4 x 1)
// rests under gravity, node to surface, on a held rigid slab whose top ends 2 mm short of the
// block's last row of nodes (x = 0.05 m; the slab ends at 0.048 m, a sharp edge). With
// delta_edge 0 or 1 mm that row (5 nodes, 2 elements' area) is not held, A = 8.75e-3 m^2; with
// 3 mm it is, A = 0.01 m^2: pfac A d = m g, d = 1.749 and 1.530 um, energy balance within 1% at
// every cycle.
TEST(ShellContact, DeltaEdgeHoldsNodesJustBeyondASharpEdge) {
  const double mass = 7800.0 * 0.1 * 0.1 * 0.02;
  const std::string bodies = R"(*COMPONENT_BOX
1, 1, 4, 4, 1
-0.05, -0.05, 0.0, 0.05, 0.05, 0.02
*COMPONENT_BOX
2, 2, 8, 8, 1
-0.1, -0.1, -0.02, 0.048, 0.1, 0.0
*MAT_RIGID
1, 7800.0
*PART
"block"
1, 1
"slab"
2, 1
)";
  const struct {
    const char* delta_edge;
    double area;
  } cases[] = {{"0.0", 0.00875}, {"0.001", 0.00875}, {"0.003", 0.01}};
  for (const auto& c : cases) {
    const double expected = mass * 9.81 / (kPenalty * c.area);
    expect_sink(settle(bodies, std::string("0, 1.0, , , , , ") + c.delta_edge, "", mass, expected),
                expected, std::string("delta_edge ") + c.delta_edge);
  }
}

// Radioss Igap0 = 1 (*CONTACT_GAP igap0; seed 004, comment 3): a node-to-surface point on a
// shell's free border has no gap of its own, g_s = 0. The sheet of the test above rests on a held
// plate that reaches beyond it on every side (x, y within 0.1 m), its mid-surface starting at
// g_s + g_m = 10 mm above the plate's. With igap0 0 every node bears, A = 0.01 m^2; with igap0 1
// the 16 nodes of the sheet's border touch only at g_m = 5 mm and stay open, so the 9 inner nodes
// (each 0.025^2 m^2) carry the weight, A = 5.625e-3 m^2: pfac A d = m g, d = 0.765 and 1.360 um.
// Energy balance within 1% at every cycle, as above.
TEST(ShellContact, Igap0LeavesTheFreeBorderNodesWithoutAGapOfTheirOwn) {
  const double mass = 7800.0 * 0.1 * 0.1 * kThickness;
  const struct {
    const char* igap0;
    double area;
  } cases[] = {{"0", 0.01}, {"1", 9 * 0.025 * 0.025}};
  for (const auto& c : cases) {
    const double expected = mass * 9.81 / (kPenalty * c.area);
    expect_sink(settle(sheet_on_plate(0.1), "0, 1.0",
                       std::string("*CONTACT_GAP\n1, , , , , , ") + c.igap0 + "\n", mass,
                       expected),
                expected, std::string("igap0 ") + c.igap0);
  }
}

}  // namespace
}  // namespace abut
