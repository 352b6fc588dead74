// Contact stiffness rules and penalty scaling (issue 7).
//
// 1. Radioss /INTER/TYPE25 Istf rules (seed 004, comment 2; decoded in seeds/README.md): for a
//    solid main segment K_m = Stfac B S^2 / V, for a secondary node of a solid K_s = Stfac B
//    V^(1/3), combined by Istf (1000: K_m; 2: mean; 3: max; 4: min; 5: series) and bounded by
//    [Stmin, Stmax] for Istf 2..5. The springs abut reports for a part pair must be these values
//    (round-off).
// 2. Abaqus/Explicit penalty scale factors (seed 001, table 29.3.6-1): with the default (here the
//    element-based) penalty scaled by s, the stable step with contact over the step without it
//    must not fall below 0.96, 0.34, 0.13, 0.04, 0.013 for s = 1, 10, 100, 1000, 10000; where
//    assignments overlap, the last one wins.
// 3. OptiStruct ADJUST (seed 003): secondary nodes within the depth are moved onto the main
//    surface before the run, without stress.
// 4. OptiStruct GPAD (seed 003, CONTPRM): a padding subtracted from the gap opening, so the
//    surfaces touch at that distance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>

#include "run_to.hpp"

namespace abut {
namespace {

constexpr double kE1 = 210e9, kNu1 = 0.3, kE2 = 70e9, kNu2 = 0.33;

// Block 1 (2 x 2 x 2 elements of 10 x 10 x 5 mm) under block 2 (4 x 4 x 1 elements of 5 x 5 x 20
// mm), `gap` apart. Block 1's nodes against block 2's facets, one-way.
std::string two_blocks(const std::string& keywords, double gap = 0.0001,
                       const std::string& pfac = "") {
  const std::string z0 = std::to_string(0.01 + gap), z1 = std::to_string(0.03 + gap);
  return R"(
*UNIT_SYSTEM
SI
*TIME
1.0e-5
*COMPONENT_BOX
1, 1, 2, 2, 2
0.0, 0.0, 0.0, 0.02, 0.02, 0.01
*COMPONENT_BOX
2, 2, 4, 4, 1
0.0, 0.0, )" +
         z0 + R"(, 0.02, 0.02, )" + z1 + R"(
*MAT_ELASTIC
1, 7800.0, 210.0e9, 0.3
*MAT_ELASTIC
2, 2700.0, 70.0e9, 0.33
*PART
"lower"
1, 1
"upper"
2, 2
*CONTACT
"blocks"
1
P, 1, P, 2, 0.0, )" +
         pfac + R"(
0, 0.1
, , , , 1
)" + keywords +
         "*END\n";
}

double bulk(double e, double nu) { return e / (3.0 * (1.0 - 2.0 * nu)); }

TEST(ContactStiffnessRules, EachIstfGivesTheSeedsFormula) {
  const double stfac = 2.0;
  // Secondary nodes (block 1): every element 10 x 10 x 5 mm.
  const double ks = stfac * bulk(kE1, kNu1) * std::cbrt(0.01 * 0.01 * 0.005);
  // Main segments (block 2, elements 5 x 5 x 20 mm): end faces S = 25 mm^2, sides S = 100 mm^2.
  const double v2 = 0.005 * 0.005 * 0.02, b2 = bulk(kE2, kNu2);
  const double km_end = stfac * b2 * std::pow(0.005 * 0.005, 2) / v2;
  const double km_side = stfac * b2 * std::pow(0.005 * 0.02, 2) / v2;
  const double km_lo = std::min(km_end, km_side), km_hi = std::max(km_end, km_side);
  struct Case {
    const char* rule;
    double lo, hi;
  };
  const Case cases[] = {
      {"MAIN", km_lo, km_hi},
      {"MEAN", 0.5 * (km_lo + ks), 0.5 * (km_hi + ks)},
      {"MAX", std::max(km_lo, ks), std::max(km_hi, ks)},
      {"MIN", std::min(km_lo, ks), std::min(km_hi, ks)},
      {"SERIES", km_lo * ks / (km_lo + ks), km_hi * ks / (km_hi + ks)},
      {"1000", km_lo, km_hi},
      {"2", 0.5 * (km_lo + ks), 0.5 * (km_hi + ks)},
  };
  for (const Case& c : cases) {
    const std::string keyword = "*CONTACT_STIFFNESS\n1, " + std::string(c.rule) +
                                ", 2.0\n*CONTACT_DISCRETIZATION\n1, N2S\n";
    const Model model = read_deck_string(two_blocks(keyword), "istf.k");
    Simulation sim(model);
    const auto& pairs = sim.contact_reports().at(0).pairs;
    ASSERT_EQ(pairs.size(), 1u) << c.rule;
    EXPECT_EQ(pairs[0].part1, 1);
    EXPECT_EQ(pairs[0].part2, 2);
    EXPECT_NEAR(pairs[0].penalty_min, c.lo, 1e-12 * c.lo) << c.rule;
    EXPECT_NEAR(pairs[0].penalty_max, c.hi, 1e-12 * c.hi) << c.rule;
  }
  // Stmin / Stmax bound Istf 2..5: chosen inside each rule's range so that both act.
  for (const std::string rule : {"MEAN", "SERIES"}) {
    const double lo = rule == "MEAN" ? 0.5 * (km_lo + ks) : km_lo * ks / (km_lo + ks);
    const double hi = rule == "MEAN" ? 0.5 * (km_hi + ks) : km_hi * ks / (km_hi + ks);
    char bounds[96];
    std::snprintf(bounds, sizeof bounds, "%.17g, %.17g", 1.2 * lo, 0.9 * hi);
    const std::string keyword = "*CONTACT_STIFFNESS\n1, " + rule + ", 2.0, " + bounds +
                                "\n*CONTACT_DISCRETIZATION\n1, N2S\n";
    const Model model = read_deck_string(two_blocks(keyword), "istf_bounds.k");
    Simulation sim(model);
    const auto& pair = sim.contact_reports().at(0).pairs.at(0);
    EXPECT_NEAR(pair.penalty_min, 1.2 * lo, 1e-12 * hi) << rule;
    EXPECT_NEAR(pair.penalty_max, 0.9 * hi, 1e-12 * hi) << rule;
  }
}

// Table 29.3.6-1 of seed 001 with the element-based automatic penalty (rule ELEMENT).
TEST(ContactPenaltyScale, StepRatioRespectsTheAbaqusTable) {
  std::string without = two_blocks("");
  without.erase(without.find("*CONTACT\n"), without.find("*END") - without.find("*CONTACT\n"));
  const Model model_without = read_deck_string(without, "no_contact.k");
  const double step_without = Simulation(model_without).initial_time_step();
  const struct {
    double scale, bound;
  } table[] = {{1.0, 0.96}, {10.0, 0.34}, {100.0, 0.13}, {1000.0, 0.04}, {10000.0, 0.013}};
  for (const auto& row : table) {
    const std::string keywords =
        "*CONTACT_STIFFNESS\n1, ELEMENT\n*CONTACT_SCALE_PENALTY\n1\n, , , , " +
        std::to_string(row.scale) + "\n";
    const Model model = read_deck_string(two_blocks(keywords), "scaled.k");
    Simulation sim(model);
    const double ratio = sim.initial_time_step() / step_without;
    std::cout << "scale " << row.scale << ": step ratio " << ratio << " (Abaqus lower bound "
              << row.bound << "); pair scale " << sim.contact_reports()[0].pairs.at(0).scale
              << "\n";
    EXPECT_EQ(sim.contact_reports()[0].pairs.at(0).scale, row.scale);
    EXPECT_GE(ratio, row.bound);
    EXPECT_LE(ratio, 1.0 + 1e-12);
  }
}

TEST(ContactPenaltyScale, TheLastAssignmentWinsWhereTheyOverlap) {
  const std::string all_then_pair = "*CONTACT_SCALE_PENALTY\n1\n, , , , 10.0\nP, 1, P, 2, 100.0\n";
  const std::string pair_then_all = "*CONTACT_SCALE_PENALTY\n1\nP, 1, P, 2, 100.0\n, , , , 10.0\n";
  const std::string other_pair =
      "*CONTACT_SCALE_PENALTY\n1\nP, 2, P, 2, 100.0\n";  // upper with itself
  double base = 0.0;
  {
    const Model model = read_deck_string(two_blocks("", 0.0001, "1.0e12"), "base.k");
    Simulation sim(model);
    base = sim.contact_reports()[0].pairs.at(0).penalty_max;
    EXPECT_DOUBLE_EQ(base, 1e12);
  }
  for (const auto& [keywords, scale] :
       {std::pair{all_then_pair, 100.0}, {pair_then_all, 10.0}, {other_pair, 1.0}}) {
    const Model model = read_deck_string(two_blocks(keywords, 0.0001, "1.0e12"), "overlap.k");
    Simulation sim(model);
    const auto& pair = sim.contact_reports()[0].pairs.at(0);
    EXPECT_EQ(pair.scale, scale);
    EXPECT_DOUBLE_EQ(pair.penalty_max, scale * base);
  }
}

// Seed 001: an assignment covers the pairs between its two surfaces whichever side each part is
// on, and one whose surfaces fall outside the contact is ignored.
TEST(ContactPenaltyScale, EitherWayRoundAndPartsOutsideTheContactIgnored) {
  const std::string far_part =
      "*COMPONENT_BOX\n3, 3, 1, 1, 1\n0.1, 0.1, 0.1, 0.11, 0.11, 0.11\n*PART\n\"far\"\n3, 1\n"
      "*SET_PART\n5\n2, 3\n";
  for (const auto& [keywords, scale] : {
           std::pair{std::string("*CONTACT_SCALE_PENALTY\n1\nP, 2, P, 1, 100.0\n"), 100.0},
           {far_part + "*CONTACT_SCALE_PENALTY\n1\nP, 1, PS, 5, 100.0\n", 100.0},
           {far_part + "*CONTACT_SCALE_PENALTY\n1\nP, 3, , , 100.0\nP, 1, P, 3, 10.0\n", 1.0},
       }) {
    const Model model = read_deck_string(two_blocks(keywords, 0.0001, "1.0e12"), "sides.k");
    Simulation sim(model);
    const auto& pairs = sim.contact_reports()[0].pairs;
    ASSERT_EQ(pairs.size(), 1u) << keywords;
    EXPECT_EQ(pairs[0].scale, scale) << keywords;
    EXPECT_DOUBLE_EQ(pairs[0].penalty_max, scale * 1e12) << keywords;
  }
}

// ADJUST: block 1's top nodes start 0.1 mm below block 2; with a depth of 0.5 mm they are moved
// onto it in the reference configuration: no stress and no contact force at the start.
TEST(ContactAdjust, MovesSecondaryNodesOntoTheMainSurfaceWithoutStress) {
  for (const std::string adjust : {"0.0005", "AUTO"}) {
    const Model model =
        read_deck_string(two_blocks("*CONTACT_INITIAL\n1, OFFSET, " + adjust + "\n"), "adjust.k");
    int moved = 0, kept = 0;
    for (std::size_t i = 0; i < model.mesh.nodes.size(); ++i) {
      if (model.mesh.hex_part.empty()) break;
      const double z = model.mesh.nodes.z[i];
      if (std::abs(z - 0.0101) < 1e-12) ++moved;  // block 1's top layer, now on block 2's bottom
      if (std::abs(z - 0.01) < 1e-12) ++kept;
    }
    // AUTO: 5% of block 2's mean edge ((5 + 5 + 20) / 3 mm on its faces) = 0.44 mm > 0.1 mm.
    EXPECT_EQ(moved, 9 + 25) << adjust;  // block 1's 3 x 3 top nodes, block 2's 5 x 5 bottom nodes
    EXPECT_EQ(kept, 0) << adjust;
    Simulation sim(model);
    sim.advance();
    EXPECT_LT(sim.contact_reports()[0].stats.normal_force, 1e-6)
        << adjust;  // round-off of a zero gap
    EXPECT_LT(sim.energies().internal, 1e-12) << adjust;
  }
  // A depth below the gap moves nothing.
  const Model model =
      read_deck_string(two_blocks("*CONTACT_INITIAL\n1, OFFSET, 0.00005\n"), "no_adjust.k");
  int kept = 0;
  for (std::size_t i = 0; i < model.mesh.nodes.size(); ++i)
    kept += std::abs(model.mesh.nodes.z[i] - 0.01) < 1e-12;
  EXPECT_EQ(kept, 9);
}

// ADJUST = SET of GRID (seed 003): "only the nodes on the slave entity which also belong to this
// SET will be selected for adjustment". The set holds the 3 top nodes of block 1 on x = 0 and a
// node of block 2 (not on surface 1, so not adjusted). Without a depth, the contact's search
// depth bounds the move (here half of block 2's 20 mm: the 0.1 mm gap is within it): exactly those
// 3 nodes move onto block 2, the other 6 top nodes stay.
TEST(ContactAdjust, MovesOnlyTheNodesOfTheGivenSet) {
  const Model plain = read_deck_string(two_blocks(""), "plain.k");
  const Nodes& n = plain.mesh.nodes;
  std::string members;
  for (std::size_t i = 0; i < n.size(); ++i) {
    const bool top_edge = std::abs(n.z[i] - 0.01) < 1e-12 && std::abs(n.x[i]) < 1e-12;
    const bool upper =
        std::abs(n.z[i] - 0.0301) < 1e-12 && std::abs(n.x[i]) < 1e-12 && std::abs(n.y[i]) < 1e-12;
    if (top_edge || upper) members += (members.empty() ? "" : ", ") + std::to_string(n.id[i]);
  }
  for (const std::string adjust : {"", "0.0005"}) {
    const Model model =
        read_deck_string(two_blocks("*SET_NODE\n7\n" + members + "\n*CONTACT_INITIAL\n1, OFFSET, " +
                                    adjust + ", 7\n"),
                         "adjust_set.k");
    int moved = 0, kept = 0;
    for (std::size_t i = 0; i < model.mesh.nodes.size(); ++i) {
      const double z = model.mesh.nodes.z[i], x = model.mesh.nodes.x[i];
      if (std::abs(z - 0.0101) < 1e-12 && std::abs(x) < 1e-12) ++moved;
      if (std::abs(z - 0.01) < 1e-12) ++kept;
    }
    EXPECT_EQ(moved, 3 + 5) << adjust;  // and block 2's 5 bottom nodes on x = 0, already there
    EXPECT_EQ(kept, 6) << adjust;
    Simulation sim(model);
    sim.advance();
    EXPECT_LT(sim.energies().internal, 1e-12) << adjust;
  }
  // A set with no node on surface 1 is an error at its field.
  std::string upper_only;
  for (std::size_t i = 0; i < n.size(); ++i)
    if (std::abs(n.z[i] - 0.0301) < 1e-12) upper_only = std::to_string(n.id[i]);
  try {
    read_deck_string(
        two_blocks("*SET_NODE\n7\n" + upper_only + "\n*CONTACT_INITIAL\n1, OFFSET, , 7\n"),
        "adjust_none.k");
    ADD_FAILURE() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().field, "adjust_nsid");
    EXPECT_NE(std::string(e.what()).find("has no node on surface 1"), std::string::npos);
  }
}

// GPAD: the blocks start 0.1 mm apart. Padded by 0.2 mm, they overlap the padding by 0.1 mm: with
// every initial penetration pushing (FORCE), the contact force at t = 0 is pfac 0.1 mm times
// block 1's top, 20 x 20 mm (no damping force at rest), for node-to-surface and surface-to-surface
// points alike. Padded by 0.05 mm they stay open.
TEST(ContactPadding, SurfacesTouchAtThePaddingDistance) {
  const double pfac = 1e12, expected = pfac * 1e-4 * 0.02 * 0.02;
  for (const std::string method : {"N2S", "S2S"})
    for (const std::string gpad : {"0.0002", "0.00005"}) {
      const Model model = read_deck_string(
          two_blocks("*CONTACT_DISCRETIZATION\n1, " + method + "\n*CONTACT_INITIAL\n1, FORCE\n" +
                         "*CONTACT_GAP\n1, , , , , , , " + gpad + "\n",
                     0.0001, "1e12"),
          "gpad.k");
      Simulation sim(model);  // its reports hold the forces of t = 0
      const double force = sim.contact_reports().at(0).stats.normal_force;
      std::cout << method << " gpad " << gpad << ": normal force " << force << " N\n";
      if (gpad == "0.0002") {
        EXPECT_NEAR(force, expected, 1e-9 * expected) << method;
      } else {
        EXPECT_EQ(force, 0.0) << method;
      }
    }
}

}  // namespace
}  // namespace abut
