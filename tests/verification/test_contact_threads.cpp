// A contact run is bitwise identical for any number of threads (issue 4): contact points are
// evaluated in parallel into per-point slots and their forces, energies and statistics are
// summed serially in point order (docs/contact.md, "Determinism and cost").
//
// Model: a spinning elastic sphere thrown obliquely onto an elastic plate with friction
// (mu = 0.3), default damping, symmetric contact, automatic penalties; 160 cycles, most of them
// in contact (sliding, sticking, damping and the broad-phase rebuilds all run).
#include <gtest/gtest.h>
#include <omp.h>

#include <vector>

#include "run_to.hpp"

namespace abut {
namespace {

const char* kDeck = R"(
*UNIT_SYSTEM
SI
*TIME
1.0
*COMPONENT_SPHERE
1, 1, 4
0.0, 0.0, 0.01002, 0.01
*COMPONENT_BOX
2, 2, 6, 6, 2
-0.03, -0.03, -0.01, 0.03, 0.03, 0.0
*MAT_ELASTIC
1, 7800.0, 210.0e9, 0.3
*PART
"sphere"
1, 1
"plate"
2, 1
*INITIAL_VELOCITY
P, 1, 20.0, 5.0, -100.0, 0.0, 3000.0, 0.0
0.0, 0.0, 0.01002
*BC_MOTION
P, 2, XYZ
*CONTACT
"thrown sphere"
1
P, 1, P, 2, 0.3
*END
)";

struct ContactRun {
  std::vector<double> state;  // positions, velocities, energies and contact statistics
  std::size_t active_cycles = 0;
  double friction_energy = 0.0;
};

ContactRun run(int threads, int cycles) {
  omp_set_num_threads(threads);
  const Model model = read_deck_string(kDeck, "contact_threads.k");
  Simulation sim(model);
  ContactRun r;
  for (int i = 0; i < cycles; ++i) {
    sim.advance();
    if (sim.contact_reports()[0].stats.active_points > 0) ++r.active_cycles;
  }
  for (const auto* v : {&sim.x(), &sim.y(), &sim.z(), &sim.vx(), &sim.vy(), &sim.vz()})
    r.state.insert(r.state.end(), v->begin(), v->end());
  const Energies e = sim.energies();
  const ContactStats c = sim.contact_reports()[0].stats;
  r.state.insert(r.state.end(),
                 {e.internal, e.hourglass, e.contact, e.friction, c.force.x, c.force.y, c.force.z,
                  c.tangential_force, c.friction_energy, c.damping_energy, c.max_penetration});
  r.friction_energy = c.friction_energy;
  return r;
}

TEST(ContactThreads, OneAndTwoThreadsGiveBitwiseIdenticalContactRuns) {
  const int saved = omp_get_max_threads();
  const ContactRun one = run(1, 160);
  const ContactRun two = run(2, 160);
  omp_set_num_threads(saved);
  EXPECT_GT(one.active_cycles, 120u);  // the contact lasts from cycle 19 to about 155
  EXPECT_GT(one.friction_energy, 0.0);
  EXPECT_EQ(one.active_cycles, two.active_cycles);
  ASSERT_EQ(one.state.size(), two.state.size());
  for (std::size_t i = 0; i < one.state.size(); ++i)
    ASSERT_EQ(one.state[i], two.state[i]) << "entry " << i;
}

}  // namespace
}  // namespace abut
