// nodes.csv: the histories of chosen nodes (*OUTPUT_NODE_HISTORY; OutputRequests::history_nodes),
// in explicit and static runs. References: a rigid translation (x = X + v t, exact in central
// differences), Hooke's law for the static block, and the contact's own total force.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "abut/io/deck.hpp"
#include "abut/io/run.hpp"
#include "test_deck_helpers.hpp"
#include "test_files.hpp"

namespace abut {
namespace {

using testing::Csv;
using testing::error_of;
using testing::file_text;
using testing::fresh_dir;
using testing::kBoxModel;
using testing::model_of;
using testing::read_csv;

// A free cube moving at v = (3, -2, 1) m/s: every node follows x = X + v t.
TEST(NodeHistory, ExplicitRunFollowsTheChosenNodes) {
  const std::string deck = R"(*UNIT_SYSTEM
SI
*TIME
1.0e-4
*OUTPUT
, 1.0e-5
*COMPONENT_BOX
1, 1, 1, 1, 1
0.0, 0.0, 0.0, 0.01, 0.01, 0.01
*MAT_ELASTIC
1, 7800.0, 210.0e9, 0.3
*PART
1, 1
*INITIAL_VELOCITY
P, 1, 3.0, -2.0, 1.0
*OUTPUT_NODE_HISTORY
N, 1
P, 1
)";
  const std::filesystem::path dir = fresh_dir("abut_test_node_history");
  const Model model = model_of(deck);
  std::ostringstream log;
  ASSERT_TRUE(run_simulation(model, RunOptions{dir, 1, false}, log).stable);
  const Csv nodes = read_csv(dir / "nodes.csv");
  const Csv energy = read_csv(dir / "energy.csv");
  EXPECT_EQ(nodes.columns, (std::vector<std::string>{"time", "node", "x", "y", "z", "ux", "uy",
                                                     "uz", "vx", "vy", "vz", "contact_force_x",
                                                     "contact_force_y", "contact_force_z"}));
  // Node 1 asked twice is followed once: the cube's 8 nodes at every history output.
  ASSERT_EQ(nodes.rows.size(), 8 * energy.rows.size());
  ASSERT_GE(energy.rows.size(), 11u);
  std::set<double> ids;
  const double v[3] = {3.0, -2.0, 1.0};
  for (std::size_t r = 0; r < nodes.rows.size(); ++r) {
    const std::vector<double>& row = nodes.rows[r];
    const double t = row[0];
    EXPECT_EQ(t, energy.rows[r / 8][0]);
    ids.insert(row[1]);
    for (int d = 0; d < 3; ++d) {
      EXPECT_NEAR(row[5 + d], v[d] * t, 1e-12) << "row " << r;
      // The cube's corners: 0 or 0.01 m, to the CSV's 10 significant digits of x (1e-9 of it).
      const double reference = row[2 + d] - row[5 + d];
      EXPECT_NEAR(std::min(std::abs(reference), std::abs(reference - 0.01)), 0.0,
                  1e-9 * std::abs(row[2 + d]));
      EXPECT_NEAR(row[8 + d], v[d], 1e-9);
      EXPECT_EQ(row[11 + d], 0.0);
    }
  }
  EXPECT_EQ(ids, (std::set<double>{1, 2, 3, 4, 5, 6, 7, 8}));
  std::filesystem::remove_all(dir);
}

// A block pressed onto a plate: the contact forces on the followed block nodes add up to the
// contact's total force on surface 1 (contact.csv) at every output.
TEST(NodeHistory, ContactForcesAddUpToTheContactsTotal) {
  const std::string deck = R"(*UNIT_SYSTEM
SI
*TIME
2.0e-5
*OUTPUT
, 2.0e-6
*COMPONENT_BOX
1, 1, 2, 2, 1
0.0, 0.0, 0.0, 0.02, 0.02, 0.01
*COMPONENT_BOX
2, 2, 1, 1, 1
0.005, 0.005, 0.01, 0.015, 0.015, 0.02
*MAT_ELASTIC
1, 7800.0, 210.0e9, 0.3
*PART
1, 1
2, 1
*INITIAL_VELOCITY
P, 2, 0.0, 0.0, -5.0
*CONTACT
1
P, 2, P, 1
*OUTPUT_NODE_HISTORY
P, 2
)";
  const std::filesystem::path dir = fresh_dir("abut_test_node_history_contact");
  const Model model = model_of(deck);
  std::ostringstream log;
  ASSERT_TRUE(run_simulation(model, RunOptions{dir, 1, false}, log).stable);
  const Csv nodes = read_csv(dir / "nodes.csv");
  const Csv contact = read_csv(dir / "contact.csv");
  ASSERT_EQ(nodes.rows.size(), 8 * contact.rows.size());
  double peak = 0.0;
  // contact.csv: time, contact, fx, fy, fz, ...
  for (const std::vector<double>& row : contact.rows) peak = std::max(peak, std::abs(row[4]));
  ASSERT_GT(peak, 0.0) << "the block never touched the plate";
  for (std::size_t c = 0; c < contact.rows.size(); ++c) {
    double sum[3] = {0.0, 0.0, 0.0};
    for (std::size_t k = 0; k < 8; ++k)
      for (int d = 0; d < 3; ++d) sum[d] += nodes.rows[8 * c + k][11 + d];
    for (int d = 0; d < 3; ++d)
      EXPECT_NEAR(sum[d], contact.rows[c][2 + d], 1e-8 * peak) << "output " << c << " axis " << d;
  }
  std::filesystem::remove_all(dir);
}

// Uniaxial compression (Hooke's law, as DeckStatic.UniaxialCompressionMatchesHookeAndTheInpModel):
// the top nodes move down by delta t / T, and their forces add up to E A eps(t).
TEST(NodeHistory, StaticRunFollowsTheChosenNodes) {
  constexpr double kE = 1000.0, kL = 2.0, kArea = 1.5, kDelta = 0.002;
  const std::string deck = R"(*COMPONENT_BOX
1, 1, 2, 3, 4
0.0, 0.0, 0.0, 1.0, 1.5, 2.0
*MAT_ELASTIC
1, 7800.0, 1000.0, 0.3
*PART
1, 1
*PART_SOLID
1, FULL
*CURVE
1
0.0, 0.0
1.0, 1.0
*GEOMETRY_BOX
1
-0.01, -1.0, -1.0, 0.01, 2.0, 3.0
*GEOMETRY_BOX
2
-1.0, -0.01, -1.0, 2.0, 0.01, 3.0
*GEOMETRY_BOX
3
-1.0, -1.0, -0.01, 2.0, 2.0, 0.01
*GEOMETRY_BOX
4
-1.0, -1.0, 1.99, 2.0, 2.0, 2.01
*BC_MOTION
G, 1, X
G, 2, Y
G, 3, Z
G, 4
D, Z, 1, -0.002
*STATIC
"press"
1.0, 0.5, , , 0
*OUTPUT_NODE_HISTORY
G, 4
)";
  const std::filesystem::path dir = fresh_dir("abut_test_node_history_static");
  const Model model = model_of(deck);
  std::ostringstream log;
  ASSERT_TRUE(run_static_analysis(model, RunOptions{dir, 1, false}, log).stable);
  const Csv nodes = read_csv(dir / "nodes.csv");
  EXPECT_EQ(nodes.columns, (std::vector<std::string>{"time", "node", "x", "y", "z", "ux", "uy",
                                                     "uz", "force_x", "force_y", "force_z"}));
  // The top face has (2 + 1) x (3 + 1) nodes; states at t = 0, 0.5 and 1.
  constexpr std::size_t kTop = 12;
  ASSERT_EQ(nodes.rows.size(), 3 * kTop);
  for (std::size_t s = 0; s < 3; ++s) {
    double force = 0.0;
    const double t = nodes.rows[s * kTop][0];
    EXPECT_DOUBLE_EQ(t, 0.5 * static_cast<double>(s));
    for (std::size_t k = 0; k < kTop; ++k) {
      const std::vector<double>& row = nodes.rows[s * kTop + k];
      EXPECT_NEAR(row[7], -kDelta * t, 1e-9 * kDelta);
      EXPECT_NEAR(row[4], kL - kDelta * t, 1e-9 * kDelta);
      force += row[10];
    }
    const double hooke = kE * kArea * kDelta * t / kL;
    EXPECT_NEAR(force, -hooke, 1e-6 * kE * kArea * kDelta / kL) << "t = " << t;
  }
  std::filesystem::remove_all(dir);
}

TEST(NodeHistory, UnknownEntitiesAreLocatedErrors) {
  const std::string model = std::string(kBoxModel);
  InputError e = error_of(model + "*OUTPUT_NODE_HISTORY\nNS, 99\n");
  EXPECT_NE(std::string(e.what()).find("node set 99 does not exist"), std::string::npos)
      << e.what();
  EXPECT_EQ(e.where().keyword, "*OUTPUT_NODE_HISTORY");
  // IMPETUS's own keyword (its card is not in the seeds) points at abut's.
  e = error_of(model + "*OUTPUT_NODE\n1\n");
  EXPECT_NE(std::string(e.what()).find("*OUTPUT_NODE_HISTORY"), std::string::npos) << e.what();
  e = error_of(model + "*OUTPUT_NODE_HISTORY\nES, 1\n");
  EXPECT_NE(std::string(e.what()).find("not supported yet"), std::string::npos) << e.what();
  EXPECT_EQ(e.where().field, "entype");
}

}  // namespace
}  // namespace abut
