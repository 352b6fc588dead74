// Edge-to-edge contact (issue 9; Radioss /INTER/TYPE25 Iedge, seed 004): two rigid shell plates
// meet edge to edge at 90 degrees, the lower edge of one (along x, in the plane y = 0) crossing
// the upper edge of the other (along y, in the plane x = 0), approaching at 2 x 5 m/s. No node
// of either plate lies on the other's plane, so no point or node ever meets a facet: without edge
// contact (*CONTACT_EDGE NONE) the plates pass through each other with their velocities intact;
// with Iedge 1 (shell borders) the edges, capsules of radius h/2, collide and the plates bounce.
// References: momentum conservation (the plates' total momentum stays zero to round-off) and the
// pass-through velocity (unchanged to round-off).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <string>

#include "run_to.hpp"

namespace abut {
namespace {

std::string crossing_plates(const std::string& iedge, double xi = 0.0) {
  return R"(
*UNIT_SYSTEM
SI
*TIME
0.004
*COMPONENT_SHELL_PLATE
1, 1, 5, 2
-0.025, 0.0, 0.002, 0.025, 0.0, 0.002
-0.025, 0.0, 0.022
*COMPONENT_SHELL_PLATE
2, 2, 5, 2
0.0, -0.025, -0.002, 0.0, 0.025, -0.002
0.0, -0.025, -0.022
*MAT_RIGID
1, 7800.0
*PART
"upper plate"
1, 1, , 0.002
"lower plate"
2, 1, , 0.002
*INITIAL_VELOCITY
P, 1, 0.0, 0.0, -5.0
*INITIAL_VELOCITY
P, 2, 0.0, 0.0, 5.0
*CONTACT
1
P, 1, P, 2, 0.0, 1.0e11
0, )" + std::to_string(xi) +
         R"(
*CONTACT_EDGE
1, )" + iedge +
         "\n*END\n";
}

struct Outcome {
  double v_upper = 0.0, v_lower = 0.0, momentum = 0.0, balance = 0.0;
};

Outcome cross(const std::string& iedge) {
  const Model model = read_deck_string(crossing_plates(iedge), "crossing_plates.k");
  Simulation sim(model);
  verification::run_to(sim, model.time.end_time);
  const auto parts = sim.part_states();
  Outcome o;
  o.v_upper = parts[0].velocity.z;
  o.v_lower = parts[1].velocity.z;
  o.momentum = parts[0].mass * o.v_upper + parts[1].mass * o.v_lower;
  o.balance = sim.energy_balance_error();
  std::cout << "iedge " << iedge << ": upper plate " << o.v_upper << " m/s, lower " << o.v_lower
            << " m/s, energy balance " << o.balance << "\n";
  return o;
}

TEST(EdgeContact, CrossingShellEdgesPassThroughWithoutEdgeContact) {
  const Outcome o = cross("NONE");
  EXPECT_NEAR(o.v_upper, -5.0, 1e-9);
  EXPECT_NEAR(o.v_lower, 5.0, 1e-9);
}

TEST(EdgeContact, CrossingShellEdgesBounceWithEdgeContact) {
  const Outcome o = cross("BORDERS");
  // Undamped (xi = 0) elastic impact of equal masses: the velocities reverse.
  EXPECT_NEAR(o.v_upper, 5.0, 0.05);
  EXPECT_NEAR(o.v_lower, -5.0, 0.05);
  EXPECT_NEAR(o.momentum, 0.0, 1e-9);
  EXPECT_LT(std::abs(o.balance), 1e-2);
}

// Damped edge springs (xi = 0.3; issue 27: the balance within 1% at every output): their damping
// work is booked as the points' is, 1/2 (F_d^n + F_d^(n+1)) . (x^(n+1) - x^n)
// (test_contact_damping_energy.cpp). The plates part with equal and opposite momenta, slower.
// Booked as F_d^n . v^(n-1/2) dt, the worst balance over the cycles was 1.24%; now 0.63%, of which
// 0.27% is there without damping (the spring's onset and release within a step).
TEST(EdgeContact, DampedEdgeSpringsKeepTheEnergyBooks) {
  const Model model = read_deck_string(crossing_plates("BORDERS", 0.3), "crossing_plates.k");
  Simulation sim(model);
  const double worst = verification::worst_energy_balance(sim, 0.5 * 2.0 * 25.0 * 0.0078);
  const auto parts = sim.part_states();
  std::cout << "damped edge springs: upper plate " << parts[0].velocity.z << " m/s; worst energy "
            << "balance " << worst << "\n";
  EXPECT_GT(parts[0].velocity.z, 0.0);
  EXPECT_LT(parts[0].velocity.z, 5.0);
  EXPECT_NEAR(parts[0].mass * parts[0].velocity.z + parts[1].mass * parts[1].velocity.z, 0.0, 1e-9);
  EXPECT_LT(worst, 1e-2);
}

// Solid edges (Iedge 11, 13, 22 and Edge_angle): the same crossing with two rigid bars of square
// section standing on an edge, a diamond: the lower bar along x with its ridge on top at z = 0,
// the upper bar along y with its ridge below at z = 2 mm, each 50 mm long, the diamond's
// half-diagonal 5 mm, one hexahedron each (equal masses), approaching at 2 x 5 m/s. Their faces'
// points lie beyond the other bar (the 2 x 2 Gauss points at 14 mm from the crossing, the bars 5
// mm wide there), so only the ridges meet: a 90-degree solid edge each. Without edge contact, or
// with SHARP and an edge_angle below 90 degrees (the ridge is then not sharp), they pass through
// with their velocities; with SHARP (edge_angle 135, the default), SHARP_ALL_SHELLS or ALL the
// ridges collide and the bars bounce: undamped, equal masses, the velocities reverse (1%, as the
// plates above) and the momentum stays zero to round-off. The energy balance is printed, not held:
// the ridges' impact gains 1.2% (the bars part at 5.03 m/s; 1.4% and 1.0% with the penalty / 10
// and / 100), where the shell plates' capsules above gain 0.07%: an open finding of edge springs
// of radius 0.
std::string crossing_bars(const std::string& edge_line) {
  constexpr double s = 0.005, half = 0.025, gap = 0.002;
  // A hexahedron from a base diamond at one end and the extrusion to the other, the base ordered
  // so that its normal points along the extrusion (positive volume).
  std::string nodes, hexes;
  int id = 0;
  const auto bar = [&](int element, int part, const std::array<Vec3, 4>& base, const Vec3& along) {
    std::array<Vec3, 4> b = base;
    if (dot(cross(b[1] - b[0], b[3] - b[0]), along) < 0.0) std::swap(b[1], b[3]);
    std::string row = std::to_string(element) + ", " + std::to_string(part);
    for (const Vec3& shift : {Vec3{}, along})
      for (const Vec3& c : b) {
        const Vec3 x = c + shift;
        nodes += std::to_string(++id) + ", " + std::to_string(x.x) + ", " + std::to_string(x.y) +
                 ", " + std::to_string(x.z) + "\n";
        row += ", " + std::to_string(id);
      }
    hexes += row + "\n";
  };
  bar(1, 1, {Vec3{-half, 0.0, 0.0}, {-half, s, -s}, {-half, 0.0, -2 * s}, {-half, -s, -s}},
      {2 * half, 0.0, 0.0});
  bar(2, 2,
      {Vec3{0.0, -half, gap}, {s, -half, gap + s}, {0.0, -half, gap + 2 * s}, {-s, -half, gap + s}},
      {0.0, 2 * half, 0.0});
  return "*UNIT_SYSTEM\nSI\n*TIME\n0.004\n*NODE\n" + nodes + "*ELEMENT_SOLID\n" + hexes +
         R"(*MAT_RIGID
1, 7800.0
*PART
"lower bar"
1, 1
"upper bar"
2, 1
*INITIAL_VELOCITY
P, 1, 0.0, 0.0, 5.0
*INITIAL_VELOCITY
P, 2, 0.0, 0.0, -5.0
*CONTACT
1
P, 1, P, 2, 0.0, 1.0e11
0, 0.0
*CONTACT_EDGE
1, )" + edge_line +
         "\n*END\n";
}

TEST(EdgeContact, CrossingSolidRidgesBounceWhenTheirEdgesAreSelected) {
  struct Cell {
    const char* edges;
    bool bounce;
  };
  for (const Cell& cell : {Cell{"NONE", false}, Cell{"SHARP", true}, Cell{"SHARP, 60", false},
                           Cell{"SHARP_ALL_SHELLS", true}, Cell{"ALL", true}}) {
    const Model model = read_deck_string(crossing_bars(cell.edges), "crossing_bars.k");
    Simulation sim(model);
    double worst = 0.0;
    verification::run_to(sim, model.time.end_time, [&](const Simulation& s) {
      worst = std::max(worst, std::abs(s.energy_balance_error()));
    });
    const auto parts = sim.part_states();
    const double lower = parts[0].velocity.z, upper = parts[1].velocity.z;
    std::cout << "bars, iedge " << cell.edges << ": lower " << lower << " m/s, upper " << upper
              << " m/s, worst energy balance " << worst << "\n";
    const double sign = cell.bounce ? -1.0 : 1.0;
    EXPECT_NEAR(lower, sign * 5.0, cell.bounce ? 0.05 : 1e-9) << cell.edges;
    EXPECT_NEAR(upper, -sign * 5.0, cell.bounce ? 0.05 : 1e-9) << cell.edges;
    EXPECT_NEAR(parts[0].mass * lower + parts[1].mass * upper, 0.0, 1e-9) << cell.edges;
    if (!cell.bounce) {
      EXPECT_LT(worst, 1e-9) << cell.edges;  // nothing touches
    }
  }
}

}  // namespace
}  // namespace abut
