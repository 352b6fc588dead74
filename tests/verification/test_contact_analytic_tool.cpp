// Analytic rigid tools (*CONTACT_TOOL; Metafor's analytic rigid contact matrices, seed 002) as
// the main surface of a contact, against closed forms and against the same tool meshed as a
// *MAT_RIGID part (the reference issue 31 asks for). References, chosen before running:
//  - a rigid block resting under gravity on a PLANE: its nodes sink by m g / (pfac A) (the
//    spring of each node is pfac times its area facing the tool: the penalty law, laws/normal.hpp);
//  - the same block on a meshed rigid plate (node to surface, one-way, the same pfac; the plate
//    made 1e9 times denser than the block so that the reduced mass of the damping is the
//    block's): the same contact force at every cycle (same fixed step), to 1e-6 of m g;
//  - a rigid cube of side s resting in a spherical cup (SPHERE, INSIDE) and in a pipe
//    (CYLINDER, INSIDE) whose surface passes through its corners: by symmetry the four lower
//    corners carry the weight along the radial normals; corner vector area s^2/4 (-1, -1, -1)
//    projected on the normal, times the normal's vertical component, gives pfac s^2 / 4 per
//    corner in both cases (sphere: sqrt 3 / sqrt 3; pipe: sqrt 2 / sqrt 2), so the corners
//    penetrate by m g / (pfac s^2), to first order in the penetration over s (1e-5 here);
//  - Coulomb friction mu: a block sliding on a fixed PLANE feels F_t = mu N at every cycle to
//    round-off, and the impulse of friction mu (m g t - m v_z(t)) changes its velocity by
//    mu g t once it rests vertically (v_z = 0 to 1e-6 after the damped bounce); a PLANE
//    translating tangentially at constant speed drags a block at rest the same way: v_x = mu g t
//    (Coulomb's law with the tool's velocity as the partner's); two CYLINDER rollers spinning
//    under a held block push it along their surface velocity omega x r with mu N;
//  - the energy balance (the moving tool's work as external work) within 1e-3 at every cycle.
// Cells left out: symmetric and surface-to-surface (the tool has no points or facets: refused,
// tests/io/test_deck_contact_tool.cpp), static steps (refused), meshed curved tools (a chord's
// sagitta h^2 / 8R exceeds these penetrations by orders for any mesh that runs in seconds).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>

#include "run_to.hpp"

namespace abut {
namespace {

constexpr double kG = 9.81;

// A rigid block of density 7800 given by its box line, under gravity, for 0.05 s at a fixed
// step of 1e-5 s (below every contact spring's bound here), and `rest` (tool, contact).
std::string block_deck(const std::string& box, const std::string& rest) {
  return R"(*TIME
0.05, 0.9, 0, 1e-5
*COMPONENT_BOX
1, 1, 1, 1, 1
)" + box +
         R"(
*MAT_RIGID
1, 7800.0
*PART
"block"
1, 1
*CURVE
1
0.0, -9.81
1.0, -9.81
*LOAD_GRAVITY
Z, 1
)" + rest +
         "*END\n";
}

const std::string kSlab = "0.0, 0.0, 0.0, 0.1, 0.1, 0.02";  // m = 1.56 kg, bottom area 0.01
constexpr double kSlabMass = 7800.0 * 0.1 * 0.1 * 0.02, kSlabArea = 0.01;

const char* kPlaneTool = R"(*CONTACT_TOOL
7, PLANE
0, 0, 0, 0, 0, 1
*CONTACT
1
P, 1, TOOL, 7, 0.0, 1.0e9
, 0.5
)";

// The meshed reference: a fixed rigid plate whose top is the plane z = 0, the block's bottom
// nodes inside its facets.
const char* kMeshedPlate = R"(*COMPONENT_BOX
2, 2, 4, 4, 1
-0.1, -0.1, -0.02, 0.2, 0.2, 0.0
*MAT_RIGID
2, 7.8e12
*PART
"plate"
2, 2
*BC_MOTION
P, 2, XYZ, XYZ
*CONTACT
1
P, 1, P, 2, 0.0, 1.0e9
, 0.5
*CONTACT_DISCRETIZATION
1, N2S, 0
)";

struct ToolRun {
  std::vector<double> force_z;  // contact force on the block at every cycle
  double penetration = 0.0;     // at the end
  // The largest change of total - external work over the cycles, over the largest energy in play
  // during the run.
  double worst_energy = 0.0;
  double vx = 0.0, vz = 0.0;   // block velocity at the end
  double worst_coulomb = 0.0;  // max | |F_t| - mu N | over the cycles, / (mu m g)
  double tangential = 0.0, normal = 0.0, force_x = 0.0;  // contact at the end
};

ToolRun run(const std::string& deck, double mass, double mu = 0.0) {
  const Model model = read_deck_string(deck, "tool.k");
  Simulation sim(model);
  ToolRun r;
  const Energies e0 = sim.energies();  // at t = 0
  const double start = e0.total() - e0.external_work;
  double imbalance = 0.0, in_play = std::abs(e0.total());
  verification::run_to(sim, sim.end_time(), [&](const Simulation& s) {
    const ContactStats& stats = s.contact_reports()[0].stats;
    r.force_z.push_back(stats.force.z);
    const Energies e = s.energies();
    imbalance = std::max(imbalance, std::abs(e.total() - e.external_work - start));
    in_play = std::max({in_play, std::abs(e.total()), std::abs(e.external_work)});
    if (mu > 0.0)
      r.worst_coulomb =
          std::max(r.worst_coulomb,
                   std::abs(stats.tangential_force - mu * stats.normal_force) / (mu * mass * kG));
  });
  r.worst_energy = imbalance / in_play;
  const ContactStats& stats = sim.contact_reports()[0].stats;
  r.penetration = stats.max_penetration;
  r.tangential = stats.tangential_force;
  r.normal = stats.normal_force;
  r.force_x = stats.force.x;
  r.vx = sim.part_states()[0].velocity.x;
  r.vz = sim.part_states()[0].velocity.z;
  return r;
}

TEST(ContactAnalyticTool, BlockRestsOnPlaneAsOnAMeshedRigidPlate) {
  const ToolRun tool = run(block_deck(kSlab, kPlaneTool), kSlabMass);
  const ToolRun mesh = run(block_deck(kSlab, kMeshedPlate), kSlabMass);
  const double sink = kSlabMass * kG / (1.0e9 * kSlabArea);
  ASSERT_EQ(tool.force_z.size(), mesh.force_z.size());
  double worst = 0.0;
  for (std::size_t k = 0; k < tool.force_z.size(); ++k)
    worst = std::max(worst, std::abs(tool.force_z[k] - mesh.force_z[k]) / (kSlabMass * kG));
  std::cout << "PLANE: sink " << tool.penetration << " (closed form " << sink << ", error "
            << tool.penetration / sink - 1.0 << "); meshed plate " << mesh.penetration
            << "; force history vs meshed plate: worst " << worst << " of m g over "
            << tool.force_z.size() << " cycles; energy balance " << tool.worst_energy << " (meshed "
            << mesh.worst_energy << ")\n";
  EXPECT_NEAR(tool.penetration, sink, 1e-4 * sink);
  EXPECT_LT(worst, 1e-6);
  EXPECT_LT(tool.worst_energy, 1e-3);
  EXPECT_NEAR(tool.force_z.back(), kSlabMass * kG, 1e-4 * kSlabMass * kG);
}

// A cube of side 0.1 centred on the tool's centre or axis (corners on its surface), pfac 1e10.
void cube_in(const std::string& tool_lines, const char* name) {
  const std::string deck = block_deck(
      "-0.05, -0.05, -0.05, 0.05, 0.05, 0.05",
      "*CONTACT_TOOL\n" + tool_lines + "*CONTACT\n1\nP, 1, TOOL, 8, 0.0, 1.0e10\n, 0.5\n");
  const double mass = 7800.0 * 1e-3, s = 0.1;
  const ToolRun r = run(deck, mass);
  const double depth = mass * kG / (1.0e10 * s * s);
  std::cout << name << ": corner penetration " << r.penetration << " (closed form " << depth
            << ", error " << r.penetration / depth - 1.0 << "); force " << r.force_z.back()
            << " (m g " << mass * kG << "); energy balance " << r.worst_energy << "\n";
  EXPECT_NEAR(r.penetration, depth, 1e-4 * depth) << name;
  EXPECT_NEAR(r.force_z.back(), mass * kG, 1e-4 * mass * kG) << name;
  EXPECT_LT(r.worst_energy, 1e-3) << name;
}

TEST(ContactAnalyticTool, CubeRestsInSphericalCup) {
  cube_in("8, SPHERE, INSIDE\n0, 0, 0, , , , 0.08660254037844387\n", "SPHERE");
}

TEST(ContactAnalyticTool, CubeRestsInPipe) {
  cube_in("8, CYLINDER, INSIDE\n-1, 0, 0, 1, 0, 0, 0.07071067811865476\n", "CYLINDER");
}

constexpr double kMu = 0.3;

TEST(ContactAnalyticTool, CoulombFrictionOnPlane) {
  // Sliding at 1 m/s on the fixed plane; pfac 1e10 (bounce damped out well before the end).
  const std::string deck =
      block_deck(kSlab,
                 "*INITIAL_VELOCITY\nP, 1, 1.0, 0.0, 0.0\n*CONTACT_TOOL\n7, PLANE\n"
                 "0, 0, 0, 0, 0, 1\n*CONTACT\n1\nP, 1, TOOL, 7, 0.3, 1.0e10\n");
  const ToolRun r = run(deck, kSlabMass, kMu);
  const double t = 0.05, dv = kMu * kG * t;
  std::cout << "friction on a fixed plane: worst |F_t - mu N| " << r.worst_coulomb
            << " of mu m g; v_x " << r.vx << " (1 - mu g t = " << 1.0 - dv << ", error of the "
            << "change " << (1.0 - r.vx) / dv - 1.0 << "); v_z " << r.vz << "; energy balance "
            << r.worst_energy << "\n";
  EXPECT_LT(r.worst_coulomb, 1e-12);
  EXPECT_NEAR(1.0 - r.vx, dv, 1e-4 * dv);
  EXPECT_LT(r.worst_energy, 1e-3);
}

TEST(ContactAnalyticTool, MovingPlaneDragsBlockByFriction) {
  // The plane moves along x at 1 m/s from the start; the block starts at rest.
  const std::string deck = block_deck(
      kSlab,
      "*CURVE\n2\n0.0, 1.0\n1.0, 1.0\n*CONTACT_TOOL\n7, PLANE\n0, 0, 0, 0, 0, 1\n2, 1.0\n"
      "*CONTACT\n1\nP, 1, TOOL, 7, 0.3, 1.0e10\n");
  const ToolRun r = run(deck, kSlabMass, kMu);
  const double t = 0.05, v = kMu * kG * t;
  std::cout << "moving plane: v_x " << r.vx << " (mu g t = " << v << ", error " << r.vx / v - 1.0
            << "); worst |F_t - mu N| " << r.worst_coulomb << " of mu m g; tool reaction x "
            << -r.force_x << " (-mu N = " << -kMu * r.normal << "); energy balance "
            << r.worst_energy << "\n";
  EXPECT_NEAR(r.vx, v, 1e-4 * v);
  EXPECT_LT(r.worst_coulomb, 1e-12);
  EXPECT_NEAR(r.force_x, kMu * r.normal, 1e-12 * kSlabMass * kG);
  EXPECT_LT(r.worst_energy, 1e-3);
}

TEST(ContactAnalyticTool, SpinningRollersRubAHeldBlock) {
  // Two rollers (CYLINDER, axes along y under the block's bottom edges x = 0 and x = 0.1, tops
  // at z = 0) spinning at 20 rad/s: their tops move along x at omega R = 1 m/s and rub the block,
  // held in x and y and against turning (a free block would ride off the rollers' crowns). Each
  // roller pushes its nodes along x with mu N (Coulomb, the surface velocity omega x r as the
  // partner's); at rest the two carry m g: mu m g along x. All the spin's work is dissipated by
  // friction: the balance checks the tool work booked for a spinning tool.
  const std::string roller = "0, -1, -0.05, 0, 1, 0, 0.05\n, , , , , , 2, 20.0\n";
  const std::string deck = block_deck(
      kSlab,
      "*BC_MOTION\nP, 1, XY, XYZ\n*CURVE\n2\n0.0, 1.0\n1.0, 1.0\n*CONTACT_TOOL\n7, "
      "CYLINDER\n" +
          roller + "*CONTACT_TOOL\n8, CYLINDER\n" + std::string("0.1") + roller.substr(1) +
          "*CONTACT\n1\nP, 1, TOOL, 7, 0.3, 1.0e10\n, 0.5\n*CONTACT\n2\nP, 1, TOOL, 8, "
          "0.3, 1.0e10\n, 0.5\n");
  const Model model = read_deck_string(deck, "rollers.k");
  Simulation sim(model);
  double worst = 0.0;
  verification::run_to(sim, sim.end_time(), [&](const Simulation& s) {
    for (const ContactReport& c : s.contact_reports())
      worst = std::max(
          worst, std::abs(c.stats.force.x - kMu * c.stats.normal_force) / (kMu * kSlabMass * kG));
  });
  double fx = 0.0, tool_work = 0.0;
  for (const ContactReport& c : sim.contact_reports()) {
    fx += c.stats.force.x;
    tool_work += c.stats.tool_work;
  }
  const Energies e = sim.energies();
  const double friction = kMu * kSlabMass * kG;
  std::cout << "spinning rollers: worst |F_x - mu N| " << worst << " of mu m g; F_x at rest " << fx
            << " (mu m g = " << friction << "); spin work " << tool_work << ", friction energy "
            << e.friction << "; energy balance " << sim.energy_balance_error() << "\n";
  EXPECT_LT(worst, 1e-12);
  EXPECT_NEAR(fx, friction, 1e-4 * friction);
  EXPECT_GT(tool_work, 0.0);
  EXPECT_LT(std::abs(sim.energy_balance_error()), 1e-3);
}

}  // namespace
}  // namespace abut
