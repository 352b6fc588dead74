// The stable step and contact (issue 12; ContactStats::approach_step): two blocks approaching
// each other run at their elements' step until they are within the search margin, and
// Simulation::contact_step_loss (summary.json time_step_lost_to_contact) says how much the
// contact springs shortened the step.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

#include "abut/io/deck.hpp"
#include "abut/solver/simulation.hpp"

namespace abut {
namespace {

// Two steel blocks of 1 mm hexahedra, 2 mm apart, closing at 20 m/s: they touch at t = 0.1 ms.
// Undamped contact (xi = 0): damping at xi lowers the springs' stable step by the factor
// sqrt(1 + xi^2) - xi (0.905 at the default 0.1; ContactInterface::spring_step).
std::string approaching_blocks(const std::string& end_time, const std::string& xi = "0.0") {
  return R"(*UNIT_SYSTEM
SI
*TIME
)" + end_time +
         R"(
*COMPONENT_BOX
1, 1, 10, 10, 4
0.0, 0.0, 0.0, 0.01, 0.01, 0.004
*COMPONENT_BOX
2, 2, 10, 10, 4
0.0, 0.0, 0.006, 0.01, 0.01, 0.01
*MAT_ELASTIC
1, 7800.0, 210.0e9, 0.3
*PART
1, 1
2, 1
*INITIAL_VELOCITY
P, 1, 0.0, 0.0, 10.0
P, 2, 0.0, 0.0, -10.0
*CONTACT
1
P, 1, P, 2
0, )" + xi +
         R"(
*END
)";
}

TEST(ContactStep, ApproachingBlocksRunAtTheElementStepUntilNear) {
  const Model model = read_deck_string(approaching_blocks("5.0e-5"), "t.k");
  Simulation sim(model);
  EXPECT_EQ(sim.time_step_limit().rfind("elements of part", 0), 0u) << sim.time_step_limit();
  while (!sim.finished()) sim.advance();
  EXPECT_EQ(sim.contact_step_loss(), 0.0);
  EXPECT_EQ(sim.contact_reports()[0].stats.active_points, 0u);
}

TEST(ContactStep, TheLossIsReportedOnceTheSpringsLimitTheStep) {
  const Model model = read_deck_string(approaching_blocks("2.0e-4"), "t.k");
  Simulation sim(model);
  bool contact_limited = false, touched = false;
  while (!sim.finished()) {
    sim.advance();
    contact_limited = contact_limited || sim.time_step_limit().rfind("contact", 0) == 0;
    touched = touched || sim.contact_reports()[0].stats.active_points > 0;
  }
  EXPECT_TRUE(touched);
  EXPECT_TRUE(contact_limited);
  // The springs hold the step while the blocks touch and while they may touch in the next step,
  // not all the time they are within the search margin: at most 4%, the bound Abaqus/Explicit
  // gives for its default penalty (seed 001, table 29.3.6-1: the increment with contact is at
  // least 0.96 of that without; issue 12). It was 4.2% with the bound on every point near a
  // facet. The blocks meet face to face, every point in the same step: the kink's bound
  // (ContactStats::kink_step, an accuracy bound of issue 27 that Abaqus's table does not count)
  // takes its own share, reported apart.
  const double kink = sim.contact_kink_step_loss();
  std::cout << "step lost to contact " << sim.contact_step_loss() << ", of which to the kink "
            << kink << "\n";
  EXPECT_GT(sim.contact_step_loss() - kink, 0.0);
  EXPECT_LT(sim.contact_step_loss() - kink, 0.04);
  EXPECT_GE(kink, 0.0);
}

// The default damping, xi = 0.1, shortens the springs' bound by 9.5%, and so the steps they hold.
TEST(ContactStep, DampedSpringsHoldAShorterStep) {
  auto least_contact_step = [](const std::string& xi) {
    const Model model = read_deck_string(approaching_blocks("2.0e-4", xi), "t.k");
    Simulation sim(model);
    double least = sim.time_step();
    while (!sim.finished()) {
      sim.advance();
      const std::string limit = sim.time_step_limit();  // the springs' bound, not the kink's
      if (!sim.finished() && limit.rfind("contact", 0) == 0 &&
          limit.find("together") == std::string::npos)  // (the last step only reaches the end)
        least = std::min(least, sim.time_step());
    }
    return least;
  };
  const double xi = 0.1;
  EXPECT_NEAR(least_contact_step("0.1") / least_contact_step("0.0"), std::sqrt(1.0 + xi * xi) - xi,
              0.01);
}

}  // namespace
}  // namespace abut
