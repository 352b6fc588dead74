// S2S contact on non-matching meshes (issue 27, item 3): a rigid block on a rigid plane whose mesh
// lines do not line up with the block's edges (the plane 13 x 7 elements, the block turned about
// z and moved by random fractions of a plane element, fixed seed).
//
// Sources: mortar integration over the overlap of the two meshes transmits a uniform pressure
// exactly (Puso & Laursen 2004, CMAME 193:601; the contact patch test of Taylor & Papadopoulos
// 1991 and Crisfield 2000, IJNME 48:435), so every global response that only needs the true
// contact area A is exact:
//  - normal stiffness: a block of weight F = M g resting on the plane sinks d = F / (pfac A)
//    (the linear penalty law, seed 000: pressure = pfac d);
//  - Tresca friction (Metafor TrescaContactMaterial, seed 002): the slip limit tau A stops a block
//    sliding at v0 after v0^2 M / (2 tau A), as in tests/verification/test_friction_laws.cpp;
//  - adhesion (Radioss IVIS2 = -1, seed 004, comment 12): a block pressed on and pulled off
//    pulls at most SigMaxAdh A, at the adhesive zone's border, as in test_contact_ties.cpp.
// Before the cell-wise integration the plane's points, which straddle the block's border, saw
// 79-110% of the footprint (symmetric contact: d and the distance off by 5-10%).
// Model: the block and plane of test_friction_laws.cpp (steel block 0.1 x 0.1 x 0.02 m, 2 x 2 x 1
// elements, M = 1.56 kg, A = 0.01 m^2, pfac = 6.2e9 Pa/m), the block's rotations held.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <random>
#include <sstream>
#include <string>

#include "run_to.hpp"

namespace abut {
namespace {

constexpr double kG = 9.81, kMass = 7800.0 * 0.1 * 0.1 * 0.02, kArea = 0.01, kPfac = 6.2e9;

std::string num(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

// The rigid block (part 1) on the rigid plane (part 2); `time`: the *TIME line.
std::string block_and_plane(const std::string& time) {
  return "\n*UNIT_SYSTEM\nSI\n*TIME\n" + time + R"(
*COMPONENT_BOX
1, 1, 2, 2, 1
0.0, -0.05, 0.0, 0.1, 0.05, 0.02
*COMPONENT_BOX
2, 2, 13, 7, 1
-0.05, -0.1, -0.02, 0.45, 0.1, 0.0
*MAT_RIGID
1, 7800.0
*MAT_RIGID
2, 7800.0
*PART
"block"
1, 1
"plane"
2, 2
)";
}

// The same plane as a rigid shell plate 2 mm thick, its upper contact surface at z = 0 where the
// block stands (its mid-surface 1 mm below).
std::string block_and_shell_plane(const std::string& time) {
  return "\n*UNIT_SYSTEM\nSI\n*TIME\n" + time + R"(
*COMPONENT_BOX
1, 1, 2, 2, 1
0.0, -0.05, 0.0, 0.1, 0.05, 0.02
*COMPONENT_SHELL_PLATE
2, 2, 13, 7
-0.05, -0.1, -0.001, 0.45, -0.1, -0.001
-0.05, 0.1, -0.001
*MAT_RIGID
1, 7800.0
*MAT_RIGID
2, 7800.0
*PART
"block"
1, 1
"plane"
2, 2, , 0.002
)";
}

// A rigid shell sheet 0.1 x 0.1 m, 2 mm thick (4 x 4 shells), in the block's place: its lower
// contact surface at z = 0, on the shell plate above; its density makes it the block's mass M.
std::string sheet_and_shell_plane(const std::string& time) {
  return "\n*UNIT_SYSTEM\nSI\n*TIME\n" + time + R"(
*COMPONENT_SHELL_PLATE
1, 1, 4, 4
0.0, -0.05, 0.001, 0.1, -0.05, 0.001
0.0, 0.05, 0.001
*COMPONENT_SHELL_PLATE
2, 2, 13, 7
-0.05, -0.1, -0.001, 0.45, -0.1, -0.001
-0.05, 0.1, -0.001
*MAT_RIGID
1, 78000.0
*MAT_RIGID
2, 7800.0
*PART
"sheet"
1, 1, , 0.002
"plane"
2, 2, , 0.002
)";
}

enum class Plane { Solid, Shell, ShellUnderSheet };

// The block (part 1) on the plane (part 2), gravity -g z, initial speed v0 along x; `contact3`
// and `contact4`: the *CONTACT lines 3 and 4 (damping, one_way), `friction`: *CONTACT_FRICTION.
std::string deck(double end_time, double g, double v0, bool one_way, const std::string& friction,
                 Plane plane = Plane::Solid) {
  const std::string time = num(end_time);
  return (plane == Plane::Solid   ? block_and_plane(time)
          : plane == Plane::Shell ? block_and_shell_plane(time)
                                  : sheet_and_shell_plane(time)) +
         R"(*INITIAL_VELOCITY
P, 1, )" +
         num(v0) +
         R"(, 0.0, 0.0
*BC_MOTION
P, 2, XYZ, XYZ
*BC_MOTION
P, 1, 0, XYZ
*CURVE
1
0.0, )" + num(-g) +
         "\n1.0, " + num(-g) + R"(
*LOAD_GRAVITY
Z, 1
*CONTACT
"block on plane"
1
P, 1, P, 2, , )" +
         num(kPfac) + "\n0, 0.1\n, , , , " + (one_way ? "1" : "0") + "\n" +
         (friction.empty() ? "" : "*CONTACT_FRICTION\n" + friction + "\n") + "*END\n";
}

// The block (or sheet) turned by `angle` about its centre's vertical and moved by (dx, dy).
Model placed(const std::string& text, double angle, double dx, double dy) {
  Model m = read_deck_string(text, "nonmatching.k");
  std::vector<std::uint8_t> block(m.mesh.nodes.size(), 0);
  for (std::size_t h = 0; h < m.mesh.hex_count(); ++h)
    if (m.mesh.hex_part[h] == 1)
      for (const std::int32_t a : m.mesh.hexes[h]) block[a] = 1;
  for (std::size_t e = 0; e < m.mesh.shell_count(); ++e)
    if (m.mesh.shell_part[e] == 1)
      for (const std::int32_t a : m.mesh.shells[e]) block[a] = 1;
  const double c = std::cos(angle), s = std::sin(angle);
  for (std::size_t i = 0; i < block.size(); ++i) {
    if (!block[i]) continue;
    const double x = m.mesh.nodes.x[i] - 0.05, y = m.mesh.nodes.y[i];
    m.mesh.nodes.x[i] = 0.05 + c * x - s * y + dx;
    m.mesh.nodes.y[i] = s * x + c * y + dy;
  }
  return m;
}

struct Placement {
  double angle, dx, dy;
};
Placement random_placement(std::mt19937& random) {
  std::uniform_real_distribution<double> fraction(0.0, 1.0);
  // Up to 17 degrees, up to one plane element (0.5/13 by 0.2/7 m).
  return {0.6 * (fraction(random) - 0.5), fraction(random) * 0.5 / 13, fraction(random) * 0.2 / 7};
}

// Rests the block (or sheet) on `plane` at two random placements (fixed `seed`), symmetric and
// one-way, and expects each to sink F / (pfac A) within 1%.
void expect_sinks_weight_over_penalty_times_true_area(std::uint32_t seed, Plane plane,
                                                      const char* what) {
  std::mt19937 random(seed);
  const double expected = kMass * kG / (kPfac * kArea);
  for (const bool one_way : {false, true})
    for (int trial = 0; trial < 2; ++trial) {
      const Placement at = random_placement(random);
      const Model model = placed(deck(0.04, kG, 0.0, one_way, "", plane), at.angle, at.dx, at.dy);
      Simulation sim(model);
      const double z0 = sim.part_states()[0].centre_of_mass.z;
      verification::run_to(sim, sim.end_time());
      const double sink = z0 - sim.part_states()[0].centre_of_mass.z;
      std::cout << what << ", " << (one_way ? "one-way" : "symmetric") << ", turned " << at.angle
                << " rad, moved " << at.dx << ", " << at.dy << ": sinks " << sink
                << " m, F / (pfac A) = " << expected << " m, error "
                << 100.0 * (sink - expected) / expected << "%, " << sim.cycle() << " cycles\n";
      EXPECT_NEAR(sink, expected, 0.01 * expected) << what << (one_way ? ", one-way" : "");
    }
}

TEST(NonMatchingContact, RestingBlockSinksWeightOverPenaltyTimesTrueArea) {
  expect_sinks_weight_over_penalty_times_true_area(2704, Plane::Solid, "block");
}

// The plane as a shell plate (issue 27: the plate's points, on a shell, integrated point-wise
// until 2026-12-02 and saw 90-115% of the footprint in symmetric contact: a 4 x 4 block on
// shells of 7 to 13 per 0.2 m). The block's points lie inside the plate's border: each of its
// cells is wholly over the plate.
TEST(NonMatchingContact, BlockOnAShellPlaneSinksWeightOverPenaltyTimesTrueArea) {
  expect_sinks_weight_over_penalty_times_true_area(2712, Plane::Shell, "block on shells");
}

// A shell sheet on the shell plate: in symmetric contact the plate's cells straddling the sheet's
// border meet a shell's facets, whose contact surface lies half the thickness off them (issue 27:
// point-wise, -2.2% and -0.8% before 2026-12-03; the cells now meet a shell's facets by cell
// where they reach its free border, cell_cover.cpp).
TEST(NonMatchingContact, ShellSheetOnAShellPlaneSinksWeightOverPenaltyTimesTrueArea) {
  expect_sinks_weight_over_penalty_times_true_area(2713, Plane::ShellUnderSheet, "sheet on shells");
}

// Tresca: m_s = 1, m_d = 0.8, k = 1000 Pa: tau A = 8 N stops the block from 1 m/s after 0.0975 m.
TEST(NonMatchingContact, TrescaStoppingDistanceIsExactOnAnyMeshAlignment) {
  std::mt19937 random(2705);
  const double v0 = 1.0, tau = 0.8 * 1000.0;
  const double expected = v0 * v0 * kMass / (2.0 * tau * kArea);
  // The block on the solid plane, and the shell sheet on the shell plate (issue 27).
  for (const Plane plane : {Plane::Solid, Plane::ShellUnderSheet})
    for (const bool one_way : {false, true}) {
      const Placement at = random_placement(random);
      const Model model = placed(deck(0.25, kG, v0, one_way, "1, TRESCA, 1.0, 0.8\n1000.0", plane),
                                 at.angle, at.dx, at.dy);
      Simulation sim(model);  // the simulation refers to the model
      const double x0 = sim.part_states()[0].centre_of_mass.x;
      verification::run_to(sim, sim.end_time());
      const PartState block = sim.part_states()[0];
      const double distance = block.centre_of_mass.x - x0;
      std::cout << (plane == Plane::Solid ? "block, " : "shell sheet, ")
                << (one_way ? "one-way" : "symmetric") << ", turned " << at.angle << " rad: slides "
                << distance << " m, v0^2 M / (2 tau A) = " << expected << " m, error "
                << 100.0 * (distance - expected) / expected << "%, final speed " << block.velocity.x
                << " m/s, " << sim.cycle() << " cycles\n";
      EXPECT_NEAR(distance, expected, 0.01 * expected);
      EXPECT_LT(std::abs(block.velocity.x), 1e-3 * v0);
    }
}

// The block of deck() without gravity, moved by *BC_MOTION as in test_contact_ties.cpp: pressed
// 10 um into the plane (0.01 m/s for 1 ms), then pulled off at 0.01 m/s, so that its face crosses
// the adhesive zone (Gap / 2 = 0.1 mm) in 10 ms; no contact damping (it would add to the pull),
// dt_max = 1e-5 s (the opening grows by 1e-3 of the zone per step).
std::string adhesion_deck(bool one_way, Plane plane) {
  const std::string time = "0.014, 0.9, 0.0, 1.0e-5";
  return (plane == Plane::Solid ? block_and_plane(time) : sheet_and_shell_plane(time)) +
         R"(*BC_MOTION
P, 2, XYZ, XYZ
*CURVE
3
0.0, -0.01
0.001, -0.01
0.001000001, 0.01
1.0, 0.01
*BC_MOTION
P, 1, XY, XYZ
V, Z, 3
*CONTACT
1
P, 1, P, 2, , )" +
         num(kPfac) + "\n0, 0.0\n, , , , " + (one_way ? "1" : "0") +
         "\n*CONTACT_ADHESION\n1, 2.0e-4, 1.0e4\n*END\n";
}

// SigMaxAdh = 1e4 Pa: the largest pull is SigMaxAdh A = 100 N whatever the meshes.
TEST(NonMatchingContact, AdhesivePullOffIsSigMaxTimesTrueArea) {
  std::mt19937 random(2706);
  const double expected = 1.0e4 * kArea;
  // The block on the solid plane, two placements each, and the shell sheet on the shell plate
  // (issue 27), one placement each.
  for (const Plane plane : {Plane::Solid, Plane::ShellUnderSheet})
    for (const bool one_way : {false, true})
      for (int trial = 0; trial < (plane == Plane::Solid ? 2 : 1); ++trial) {
        const Placement at = random_placement(random);
        const Model model = placed(adhesion_deck(one_way, plane), at.angle, at.dx, at.dy);
        Simulation sim(model);
        double largest_pull = 0.0;
        verification::run_to(sim, sim.end_time(), [&](const Simulation& s) {
          largest_pull = std::max(largest_pull, -s.contact_reports()[0].stats.force.z);
        });
        std::cout << (plane == Plane::Solid ? "block, " : "shell sheet, ")
                  << (one_way ? "one-way" : "symmetric") << ", turned " << at.angle
                  << " rad, moved " << at.dx << ", " << at.dy << ": largest pull " << largest_pull
                  << " N, SigMaxAdh A = " << expected << " N, error "
                  << 100.0 * (largest_pull - expected) / expected << "%\n";
        EXPECT_NEAR(largest_pull, expected, 0.01 * expected);
      }
}

}  // namespace
}  // namespace abut
