// Contacts switched by sensors (*SENSOR, *CONTACT_SENSOR; Radioss /INTER/TYPE25 sens_ID, seed 004
// comment 10, and /SENSOR TIME, DIST, INTER).
//
// Model: a rigid steel block (0.1 x 0.1 x 0.02 m, 7800 kg/m^3: m = 1.56 kg, weight W = m g =
// 15.3036 N) above a fixed rigid plate, under gravity g = 9.81 m/s^2 along -z; contact penalty
// 1e9 Pa/m, critically damped (xi = 1) so that the block comes to rest on the plate without
// bouncing. References, chosen before running, from kinematics:
//  - DISTANCE sensor (switches the contact on): the block starts 2 mm above the plate; the sensor
//    watches a bottom corner of the block and the plate corner below it and triggers below 1 mm,
//    after the block has fallen h = 1 mm: t = sqrt(2 h / g) = 14.278 ms (within one step). At
//    rest on the plate (60 ms, 40 ms after landing, many times the critically damped spring's
//    time 1/omega = 0.4 ms) the contact's normal force is W (1e-6: the remaining motion).
//  - TIME sensor with a delay (switches the contact on): triggers at 5 ms, on from 10 ms; the
//    *CONTACT's own window t_beg = 40 ms is not used (seed 004, comment 10). The block starts on
//    the plate: free fall v_z = -g t exactly up to 10 ms, then the contact throws it back.
//  - CONTACT_FORCE sensor (switches the contact off): the block starts on the plate with the
//    contact on; the contact force grows as the block sinks; once it passes W/2 the contact goes
//    off for good: from then on no force and free fall, acceleration -g exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>

#include "run_to.hpp"

namespace abut {
namespace {

constexpr double kG = 9.81, kMass = 0.1 * 0.1 * 0.02 * 7800.0, kWeight = kMass * kG;

// The block (part 1) at height `gap` above the plate (part 2), then `extra` (sensors, contact).
std::string deck(double end, double gap, const std::string& contact_row, const std::string& extra) {
  const std::string z0 = std::to_string(gap), z1 = std::to_string(gap + 0.02);
  return "*TIME\n" + std::to_string(end) + "\n*COMPONENT_BOX\n1, 1, 1, 1, 1\n0.0, 0.0, " + z0 +
         ", 0.1, 0.1, " + z1 +
         "\n*COMPONENT_BOX\n2, 2, 1, 1, 1\n0.0, 0.0, -0.02, 0.1, 0.1, 0.0\n"
         "*MAT_RIGID\n1, 7800.0\n*PART\n\"block\"\n1, 1\n\"plate\"\n2, 1\n"
         "*BC_MOTION\nP, 2, XYZ, XYZ\n*CURVE\n1\n0.0, -9.81\n1.0, -9.81\n*LOAD_GRAVITY\nZ, 1\n"
         "*CONTACT\n\"switched\"\n1\n" +
         contact_row + "\n0, 1.0\n" + extra + "*END\n";
}

// The node of a model at a position (the generator numbers the nodes itself).
std::int64_t node_at(const Model& m, double x, double y, double z) {
  const auto& n = m.mesh.nodes;
  for (std::size_t i = 0; i < n.size(); ++i)
    if (std::abs(n.x[i] - x) < 1e-9 && std::abs(n.y[i] - y) < 1e-9 && std::abs(n.z[i] - z) < 1e-9)
      return n.id[i];
  return -1;
}

TEST(ContactSensors, DistanceSensorSwitchesOnAtFallenHeightAndBlockRestsWithItsWeight) {
  // Node ids first from a deck without the sensor; the sensor's deck has the same mesh.
  const std::string row = "P, 1, P, 2, 0.0, 1.0e9";
  const Model probe = read_deck_string(deck(0.06, 0.002, row, ""), "probe.k");
  const std::int64_t a = node_at(probe, 0.0, 0.0, 0.002), b = node_at(probe, 0.0, 0.0, 0.0);
  ASSERT_GT(a, 0);
  ASSERT_GT(b, 0);
  const std::string sensor = "*SENSOR\n1, DISTANCE, 0.001, BELOW, , " + std::to_string(a) + ", " +
                             std::to_string(b) + "\n*CONTACT_SENSOR\n1, 1, ON\n";
  const Model model = read_deck_string(deck(0.06, 0.002, row, sensor), "distance_sensor.k");
  Simulation sim(model);
  double max_step = 0.0;
  verification::run_to(sim, sim.end_time(),
                       [&](const Simulation& s) { max_step = std::max(max_step, s.time_step()); });
  const double expected = std::sqrt(2.0 * 0.001 / kG);
  const double triggered = sim.sensor_trigger_time(1);
  const double force = sim.contact_reports()[0].stats.normal_force;
  std::cout << "distance sensor triggered at t = " << triggered << " s (sqrt(2h/g) = " << expected
            << " s, largest step " << max_step << " s); normal force at rest " << force
            << " N, weight " << kWeight << " N, relative error "
            << std::abs(force - kWeight) / kWeight << "\n";
  EXPECT_GE(triggered, expected);
  EXPECT_LE(triggered, expected + max_step);
  EXPECT_NEAR(force, kWeight, 1e-6 * kWeight);
  EXPECT_NEAR(sim.part_states()[0].velocity.z, 0.0, 1e-6);
}

TEST(ContactSensors, TimeSensorWithDelayReplacesTheContactWindow) {
  // t_beg = 40 ms on the *CONTACT row must not count: the sensor decides.
  const std::string row = "P, 1, P, 2, 0.0, 1.0e9, 0.04";
  const std::string sensor = "*SENSOR\n7, TIME, 0.005, , 0.005\n*CONTACT_SENSOR\n1, 7\n";
  const Model model = read_deck_string(deck(0.03, 0.0, row, sensor), "time_sensor.k");
  Simulation sim(model);
  double worst_free_fall = 0.0, first_force = -1.0, max_step = 0.0;
  int forces_before = 0;
  verification::run_to(sim, sim.end_time(), [&](const Simulation& s) {
    const double t = s.time(), vz = s.part_states()[0].velocity.z;
    max_step = std::max(max_step, s.time_step());
    const bool force = s.contact_reports()[0].stats.active_points > 0;
    if (t < 0.01) {
      if (force) ++forces_before;
      worst_free_fall = std::max(worst_free_fall, std::abs(vz + kG * t) / (kG * t));
    } else if (force && first_force < 0.0) {
      first_force = t;
    }
  });
  std::cout << "time sensor: triggered at " << sim.sensor_trigger_time(7)
            << " s; cycles with contact force before 10 ms: " << forces_before
            << "; worst relative free-fall error " << worst_free_fall
            << "; first contact force at t = " << first_force << " s (largest step " << max_step
            << " s); v_z at the end " << sim.part_states()[0].velocity.z << " m/s\n";
  EXPECT_GE(sim.sensor_trigger_time(7), 0.005);
  EXPECT_EQ(forces_before, 0);
  EXPECT_LT(worst_free_fall, 1e-9);
  EXPECT_GE(first_force, 0.01);
  EXPECT_LE(first_force, 0.01 + max_step);            // at the first cycle at or after 10 ms
  EXPECT_GT(sim.part_states()[0].velocity.z, -1e-3);  // stopped, not falling through at -g t
}

TEST(ContactSensors, ContactForceSensorSwitchesTheContactOff) {
  const std::string row = "P, 1, P, 2, 0.0, 1.0e9";
  const std::string sensor = "*SENSOR\n3, CONTACT_FORCE, " + std::to_string(0.5 * kWeight) +
                             ", ABOVE, , 1\n*CONTACT_SENSOR\n1, 3, OFF\n";
  const Model model = read_deck_string(deck(0.02, 0.0, row, sensor), "force_sensor.k");
  Simulation sim(model);
  double force_at_trigger = 0.0, t_off = -1.0, v_off = 0.0, previous_force = 0.0;
  int forces_after = 0;
  verification::run_to(sim, sim.end_time(), [&](const Simulation& s) {
    const double f = s.contact_reports()[0].stats.normal_force;
    const double trigger = s.sensor_trigger_time(3);
    if (std::isfinite(trigger)) {
      if (t_off < 0.0) {
        t_off = s.time();
        v_off = s.part_states()[0].velocity.z;
        force_at_trigger = previous_force;  // the force the sensor read (the cycle before)
      }
      if (f != 0.0 || s.contact_reports()[0].stats.active_points > 0) ++forces_after;
    }
    previous_force = f;
  });
  ASSERT_GT(t_off, 0.0);
  const double a = (sim.part_states()[0].velocity.z - v_off) / (sim.time() - t_off);
  std::cout << "force sensor: off at t = " << t_off << " s, having read " << force_at_trigger
            << " N (threshold " << 0.5 * kWeight << " N); cycles with force after: " << forces_after
            << "; acceleration after " << a << " m/s^2\n";
  EXPECT_GT(force_at_trigger, 0.5 * kWeight);
  EXPECT_EQ(forces_after, 0);
  EXPECT_NEAR(a, -kG, 1e-9 * kG);
}

}  // namespace
}  // namespace abut
