// Restart with sensors and released boundary conditions (simulation_restart.cpp, sensors.cpp): a
// state saved after a sensor switched a contact off, or after a contact released the constraints
// of the nodes it touched, continues bitwise identically. Without their state in the file the
// continued run would differ: the contact, whose force is 0 once it is off, would switch back on
// (the sensor would not trigger again), and the released nodes would be held again.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "abut/core/state_archive.hpp"
#include "abut/io/deck.hpp"
#include "abut/solver/simulation.hpp"

namespace abut {
namespace {

// A rigid block resting on a rigid plate under gravity; a CONTACT_FORCE sensor switches the
// contact off once it carries half the block's weight (7.65 N).
const char* const kForceSensor = R"(*TIME
0.01
*COMPONENT_BOX
1, 1, 1, 1, 1
0.0, 0.0, 0.0, 0.1, 0.1, 0.02
*COMPONENT_BOX
2, 2, 1, 1, 1
0.0, 0.0, -0.02, 0.1, 0.1, 0.0
*MAT_RIGID
1, 7800.0
*PART
1, 1
2, 1
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
P, 1, P, 2, 0.0, 1.0e9
0, 1.0
*SENSOR
3, CONTACT_FORCE, 7.65, ABOVE, , 1
*CONTACT_SENSOR
1, 3, OFF
*END
)";

// An elastic block whose bottom nodes are held in z; a rigid plate rises into it at 1 m/s and the
// nodes it touches are released in z. The plate spans half the block: the other half stays held.
const char* const kRelease = R"(*TIME
0.004
*COMPONENT_BOX
1, 1, 4, 4, 2
0.0, 0.0, 0.0, 0.04, 0.04, 0.02
*COMPONENT_BOX
2, 2, 1, 1, 1
-0.01, -0.01, -0.011, 0.019, 0.05, -0.001
*MAT_ELASTIC
1, 1000.0, 1.0e7, 0.3
*MAT_RIGID
2, 7800.0
*PART
1, 1
2, 2
*BC_MOTION
G, 1, Z
*GEOMETRY_BOX
1
-1.0, -1.0, -0.001, 1.0, 1.0, 0.001
*BC_MOTION
P, 2, XY, XYZ
V, Z, 1
*CURVE
1
0.0, 1.0
1.0, 1.0
*CONTACT
1
P, 1, P, 2, 0.0, 1.0e11
*CONTACT_RELEASE_BC
1, 0, 0, 1
*END
)";

bool same(const std::vector<double>& u, const std::vector<double>& v) {
  return u.size() == v.size() &&
         (u.empty() || std::memcmp(u.data(), v.data(), u.size() * sizeof(double)) == 0);
}

// Runs `deck` to t_save, saves, runs `after` cycles more; a second simulation loads the state and
// runs as many cycles: both must end bitwise alike. `check` sees the first one at the save.
void expect_restart_identical(const char* deck, double t_save, int after,
                              const std::function<void(Simulation&)>& check) {
  const Model model = read_deck_string(deck, "t.k");
  Simulation first(model);
  while (first.time() < t_save) first.advance();
  check(first);
  StateArchive saved = StateArchive::for_saving();
  first.archive(saved);
  for (int i = 0; i < after; ++i) first.advance();

  Simulation second(model);
  StateArchive loading = StateArchive::for_loading(saved.bytes());
  second.archive(loading);
  EXPECT_TRUE(loading.exhausted());
  EXPECT_TRUE(second.take_messages().empty());  // the set-up's log lines are the first run's
  for (int i = 0; i < after; ++i) second.advance();
  EXPECT_EQ(first.time(), second.time());
  EXPECT_EQ(first.sensor_trigger_time(3), second.sensor_trigger_time(3));
  for (const auto field : {&Simulation::x, &Simulation::y, &Simulation::z, &Simulation::vx,
                           &Simulation::vy, &Simulation::vz})
    EXPECT_TRUE(same((first.*field)(), (second.*field)()));
  const Energies ea = first.energies(), eb = second.energies();
  EXPECT_EQ(std::memcmp(&ea, &eb, sizeof ea), 0);
}

TEST(RestartSensors, ASensorThatSwitchedAContactOffKeepsItOff) {
  expect_restart_identical(kForceSensor, 0.002, 50, [](Simulation& s) {
    EXPECT_TRUE(std::isfinite(s.sensor_trigger_time(3)));  // triggered before the save
    EXPECT_EQ(s.contact_reports()[0].stats.normal_force, 0.0);
  });
}

TEST(RestartSensors, ReleasedBoundaryConditionsStayReleased) {
  expect_restart_identical(kRelease, 0.002, 100, [](Simulation& s) {
    bool released = false;  // the log line of the release came before the save
    for (const std::string& line : s.take_messages())
      released = released || line.find("released the z boundary conditions") != std::string::npos;
    EXPECT_TRUE(released);
  });
}

}  // namespace
}  // namespace abut
