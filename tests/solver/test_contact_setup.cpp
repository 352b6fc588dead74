// *CONTACT set-up in the solver: the automatic penalty needs a unit system (seed 000: "a value
// for the penalty stiffness or a unit system must be defined"); thermal options are refused
// until abut has a thermal solution; the automatic values follow the seed's formula.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "abut/io/deck.hpp"
#include "abut/solver/contact_surfaces.hpp"
#include "abut/solver/simulation.hpp"

namespace abut {
namespace {

std::string two_blocks(const std::string& units, const std::string& contact_lines) {
  return units + R"(*TIME
1.0e-4
*COMPONENT_BOX
1, 1, 2, 2, 1
0.0, 0.0, 0.0, 0.02, 0.02, 0.01
*COMPONENT_BOX
2, 2, 2, 2, 1
0.0, 0.0, 0.011, 0.02, 0.02, 0.021
*MAT_ELASTIC
1, 7800.0, 210.0e9, 0.3
*PART
1, 1
2, 1
*INITIAL_VELOCITY
P, 2, 0.0, 0.0, -50.0
*CONTACT
1
)" + contact_lines +
         "*END\n";
}

std::string message_of(const std::string& deck) {
  try {
    const Model model = read_deck_string(deck, "contact.k");
    Simulation sim(model);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ContactSetup, AutomaticPenaltyWithoutUnitSystemIsAnError) {
  const std::string message = message_of(two_blocks("", "P, 1, P, 2\n"));
  EXPECT_NE(message.find("*UNIT_SYSTEM"), std::string::npos) << message;
  EXPECT_NE(message.find("contact.k:"), std::string::npos) << message;
}

TEST(ContactSetup, GivenPenaltyNeedsNoUnitSystem) {
  EXPECT_EQ(message_of(two_blocks("", "P, 1, P, 2, 0.0, 1.0e13\n")), "");
}

// Thermal contact (fid_thermal, fric_heat) needs a temperature field: without thermal properties
// the run is refused at the *CONTACT, not run without heat.
TEST(ContactSetup, ThermalOptionsNeedThermalProperties) {
  const std::string units = "*UNIT_SYSTEM\nSI\n*FUNCTION\n5\n1.0\n";
  EXPECT_NE(message_of(two_blocks(units, "P, 1, P, 2\n0\n0, 0, 5\n")).find("thpid"),
            std::string::npos);
  EXPECT_NE(message_of(two_blocks(units, "P, 1, P, 2\n0\n0, 0, , 20.0, 0, 0, , 1\n"))
                .find("friction heat needs a temperature field"),
            std::string::npos);
}

TEST(ContactSetup, AutomaticPenaltyFollowsTheSeedFormula) {
  // K = E / (3 (1 - 2 nu)) = 175 GPa, L_min = (0.01^3)^(1/3) = 0.01 m, v_max = 50 m/s:
  // pfac = K / L_min * (1 + 0.5^2) (seed 000).
  const Model model =
      read_deck_string(two_blocks("*UNIT_SYSTEM\nSI\n", "P, 1, P, 2\n"), "contact.k");
  Simulation sim(model);
  const double expected = 175.0e9 / 0.01 * 1.25;
  const std::vector<ContactReport> reports = sim.contact_reports();
  for (const PartPenalty& p : reports[0].parts) EXPECT_NEAR(p.penalty, expected, 1e-9 * expected);
}

TEST(ContactSetup, AutomaticPenaltyOfAShellPartUsesItsElementVolume) {
  // A 2 x 2 plate of 0.01 m shells, h = 2 mm, on the 0.01 m cubes of part 1: L_min is the cube
  // root of the smallest element volume, A h for a shell (as for a hex, seed 000), so
  // pfac = K / (1e-4 * 2e-3)^(1/3) * (1 + 0.5^2).
  const std::string deck = R"(*UNIT_SYSTEM
SI
*TIME
1.0e-4
*COMPONENT_BOX
1, 1, 2, 2, 1
0.0, 0.0, 0.0, 0.02, 0.02, 0.01
*COMPONENT_SHELL_PLATE
2, 2, 2, 2
0.0, 0.0, 0.012, 0.02, 0.0, 0.012
0.0, 0.02, 0.012
*MAT_ELASTIC
1, 7800.0, 210.0e9, 0.3
*PART
1, 1
2, 1, , 0.002
*INITIAL_VELOCITY
P, 2, 0.0, 0.0, -50.0
*CONTACT
1
P, 1, P, 2
*END
)";
  const Model model = read_deck_string(deck, "shell_contact.k");
  Simulation sim(model);
  const std::vector<ContactReport> reports = sim.contact_reports();
  ASSERT_EQ(reports[0].parts.size(), 2u);
  const double shell = 175.0e9 / std::cbrt(1e-4 * 2e-3) * 1.25;
  EXPECT_NEAR(reports[0].parts[1].penalty, shell, 1e-9 * shell);
  EXPECT_EQ(reports[0].points, 16u * 4u + 2u * 4u * 4u);  // the block's 16 faces, both shell sides
}

TEST(ContactSetup, AutomaticPenaltyIsConvertedToTheUnitSystem) {
  // The same model in [mm, ton, s]: 50 m/s = 5e4 mm/s, E = 2.1e5 MPa, rho = 7.8e-9 t/mm^3;
  // pfac = 1.75e5 MPa / 10 mm * 1.25 = 2.1875e4 MPa/mm.
  const std::string deck = R"(*UNIT_SYSTEM
MMTONS
*TIME
1.0e-4
*COMPONENT_BOX
1, 1, 2, 2, 1
0.0, 0.0, 0.0, 20.0, 20.0, 10.0
*COMPONENT_BOX
2, 2, 2, 2, 1
0.0, 0.0, 11.0, 20.0, 20.0, 21.0
*MAT_ELASTIC
1, 7.8e-9, 2.1e5, 0.3
*PART
1, 1
2, 1
*INITIAL_VELOCITY
P, 2, 0.0, 0.0, -5.0e4
*CONTACT
1
P, 1, P, 2
*END
)";
  const Model model = read_deck_string(deck, "contact_mm.k");
  Simulation sim(model);
  const std::vector<ContactReport> reports = sim.contact_reports();
  for (const PartPenalty& p : reports[0].parts) EXPECT_NEAR(p.penalty, 2.1875e4, 1e-6 * 2.1875e4);
}

// Issue 13: the skin of a hex turned inside out after reading (the deck reader refuses one in
// the deck) is an error at the contact surface's field, not one without a location.
TEST(ContactSetup, InvertedHexOfASurfaceIsAtTheSurfaceField) {
  Model model = read_deck_string(two_blocks("*UNIT_SYSTEM\nSI\n", "P, 1, P, 2\n"), "contact.k");
  Hex8& hex = model.mesh.hexes[0];
  std::swap_ranges(hex.begin(), hex.begin() + 4, hex.begin() + 4);  // top below bottom
  try {
    contact_faces(model, model.contacts[0].surface1, false, false);
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, "contact.k");
    EXPECT_EQ(e.where().line, 20u);  // the surface row of *CONTACT
    EXPECT_NE(std::string(e.what()).find("element 1 has a non-positive volume"), std::string::npos)
        << e.what();
  }
}

// Start-up check (issue 13): two steel blocks, one meshed 20 times finer than the other. Each
// part's automatic penalty follows its smallest element (seed 000) and the pair runs with the
// smaller one, so the fine block is held by the coarse block's soft springs: a warning naming both
// parts, once per pair (both passes of the symmetric contact). Equal meshes: no warning.
TEST(ContactSetup, PairGovernedByTheOtherSidesLargerElementsIsAWarning) {
  const auto reports_of = [](int fine) {
    const std::string n = std::to_string(fine), nz = std::to_string(fine / 2);
    const std::string deck =
        "*UNIT_SYSTEM\nSI\n*TIME\n1.0e-4\n*COMPONENT_BOX\n1, 1, 2, 2, 1\n"
        "0.0, 0.0, 0.0, 0.02, 0.02, 0.01\n*COMPONENT_BOX\n2, 2, " +
        n + ", " + n + ", " + nz +
        "\n0.0, 0.0, 0.011, 0.02, 0.02, 0.021\n*MAT_ELASTIC\n1, 7800.0, "
        "210.0e9, 0.3\n*PART\n1, 1\n2, 1\n*CONTACT\n1\nP, 1, P, 2\n*END\n";
    const Model model = read_deck_string(deck, "contact.k");
    const Simulation sim(model);
    return sim.contact_reports();
  };
  const std::vector<ContactReport> equal = reports_of(2);
  EXPECT_TRUE(equal[0].warnings.empty());
  const std::vector<ContactReport> fine = reports_of(40);
  ASSERT_EQ(fine[0].warnings.size(), 1u);
  const std::string& w = fine[0].warnings[0];
  double coarse_penalty = 0.0, fine_penalty = 0.0;
  for (const PartPenalty& p : fine[0].parts)
    (p.part_id == 1 ? coarse_penalty : fine_penalty) = p.penalty;
  EXPECT_GE(fine_penalty / coarse_penalty, 10.0);
  EXPECT_NE(w.find("contact 1: parts 1 and 2 touch with part 1's automatic penalty"),
            std::string::npos)
      << w;
  EXPECT_NE(w.find("let part 2 penetrate deeper"), std::string::npos) << w;
}

// Start-up check (issue 13): block 2 (two element layers of 5 mm) starts overlapping block 1 (the
// same) by 3.5 mm, deeper than the detection depth of half an element (2.5 mm, seed 000): the
// search never finds its bottom points, so they would stay inside unseen. The warning names both
// parts and the depths; at 1 mm of overlap the search sees them (they are offset or released by
// the initial-penetration rules) and nothing is said.
TEST(ContactSetup, InitialPenetrationDeeperThanTheDetectionDepthIsAWarning) {
  const auto warnings_of = [](double overlap) {
    const std::string z0 = std::to_string(0.01 - overlap), z1 = std::to_string(0.02 - overlap);
    const std::string deck =
        "*UNIT_SYSTEM\nSI\n*TIME\n1.0e-4\n*COMPONENT_BOX\n1, 1, 2, 2, 2\n"
        "0.0, 0.0, 0.0, 0.02, 0.02, 0.01\n*COMPONENT_BOX\n2, 2, 2, 2, 2\n"
        "0.0, 0.0, " +
        z0 + ", 0.02, 0.02, " + z1 +
        "\n*MAT_ELASTIC\n1, 7800.0, 210.0e9, 0.3\n*PART\n1, 1\n2, 1\n"
        "*CONTACT\n1\nP, 2, P, 1\n*END\n";
    const Model model = read_deck_string(deck, "contact.k");
    const Simulation sim(model);
    return sim.contact_reports()[0].warnings;
  };
  EXPECT_TRUE(warnings_of(0.001).empty());
  const std::vector<std::string> deep = warnings_of(0.0035);
  ASSERT_EQ(deep.size(), 2u);  // both passes of the symmetric contact: each side inside the other
  EXPECT_NE(deep[0].find("contact 1: "), std::string::npos) << deep[0];
  EXPECT_NE(deep[0].find("start inside part"), std::string::npos) << deep[0];
  EXPECT_NE(deep[0].find("up to 0.0035 deep, below the detection depth 0.0025"), std::string::npos)
      << deep[0];
}

}  // namespace
}  // namespace abut
