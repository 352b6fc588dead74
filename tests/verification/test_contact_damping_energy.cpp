// Contact damping at a step set by the contact springs (issue 27, item 5): a rigid block held on
// a fixed rigid plate by a bilateral contact (a linear spring k = pfac A in tension and
// compression, so the only nonlinearity left is the damping) is launched off the plate at 1 m/s
// and rings down. Nothing but the springs limits the step.
//
// - Step: central differences with a viscous force taken at the half step before are stable up
//   to omega dt = 2 (sqrt(1 + xi^2) - xi) (Belytschko, Liu & Moran, "Nonlinear Finite Elements
//   for Continua and Structures", 2000, section 6.2), omega^2 = k / M here; the step must stay
//   within sf_dt = 0.9 times it.
// - Energy: the books stay closed from the first cycle on: the balance error does not move by
//   more than round-off, with the damping's work booked as the product form of the kinetic
//   energy sees it, 1/2 (F_d^n + F_d^(n+1)) . (x^(n+1) - x^n) (ContactStats::damping_energy),
//   exact for a linear spring at a constant step. Booked as F_d^n . v^(n-1/2) dt, the balance
//   drifted by about (omega dt)^2 / 8 of the energy dissipated. Two offsets are left out as they
//   are not the contact's: the first cycle, where a damping force acting at t = 0 works over the
//   start's half kick (here 3.5e-4 at xi = 0.1), and the last two, where the step shortened to
//   meet the end time breaks the product form's identity by O((omega dt)^2) of the spring's
//   energy whatever the force (0.4% here).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>

#include "run_to.hpp"

namespace abut {
namespace {

constexpr double kPfac = 1.0e9;            // [Pa/m]
constexpr double kArea = 0.01;             // block face 0.1 x 0.1 m
constexpr double kMass = 7800.0 * 0.0002;  // steel block 0.1 x 0.1 x 0.02 m: 1.56 kg

std::string num(double v) {
  std::ostringstream s;
  s << std::setprecision(17) << v;
  return s.str();
}

// dt_max of *TIME: 0 for none.
std::string ringing_block(double xi, double t_end, double dt_max) {
  return "*TIME\n" + num(t_end) + ", 0.9, 0.0, " + (dt_max > 0.0 ? num(dt_max) : "") + R"(
*COMPONENT_BOX
1, 1, 2, 2, 1
0.0, 0.0, 0.0, 0.1, 0.1, 0.02
*COMPONENT_BOX
2, 2, 4, 4, 1
-0.05, -0.05, -0.02, 0.15, 0.15, 0.0
*MAT_RIGID
1, 7800.0
*PART
"block"
1, 1
"plate"
2, 1
*BC_MOTION
P, 2, XYZ, XYZ
*INITIAL_VELOCITY
P, 1, 0.0, 0.0, 1.0
*CONTACT
1
P, 1, P, 2, 0.0, )" +
         num(kPfac) + "\n0, " + num(xi) + R"(
, , , , 1
*CONTACT_NORMAL
1, LINEAR, , BILATERAL
*END
)";
}

TEST(ContactDampingEnergy, RingingBlockAtTheSpringStepKeepsItsBooks) {
  const double omega = std::sqrt(kPfac * kArea / kMass);
  const double period = 2.0 * std::acos(-1.0) / omega;
  for (const double xi : {0.0, 0.1, 0.3}) {
    // At the step the springs allow.
    {
      const Model model = read_deck_string(ringing_block(xi, 5.0 * period, 0.0), "ringing.k");
      Simulation sim(model);
      double step = 0.0;
      verification::run_to(sim, sim.end_time(),
                           [&](const Simulation& s) { step = std::max(step, s.time_step()); });
      const double bound = 0.9 * 2.0 / omega * (std::sqrt(1.0 + xi * xi) - xi);
      std::cout << "xi " << xi << ": largest omega dt " << omega * step << " (bound "
                << omega * bound << ")\n";
      EXPECT_LE(step, bound) << "xi " << xi;
      // Stable: the block stays within its undamped swing v0 / omega either side of contact.
      EXPECT_LT(std::abs(sim.part_states().at(0).centre_of_mass.z - 0.01), 1.001 / omega)
          << "xi " << xi;
    }
    // At a constant step, 20 per period (omega dt = 0.31), for 5 periods: the springs' own bound
    // changes as the block moves, and a change of step breaks the product form's identity
    // whatever the force.
    const double dt = period / 20.0;
    const Model model = read_deck_string(ringing_block(xi, 100.0 * dt, dt), "ringing.k");
    Simulation sim(model);
    double first = 0.0, drift = 0.0;
    int cycle = 0;
    verification::run_to(sim, sim.end_time(), [&](const Simulation& s) {
      if (s.time() + 2.0 * s.time_step() > s.end_time()) return;  // the shortened last step
      if (++cycle == 1) first = s.energy_balance_error();
      drift = std::max(drift, std::abs(s.energy_balance_error() - first));
    });
    const Energies e = sim.energies();
    std::cout << "  constant step: balance " << first << " after the first cycle, moving by "
              << drift << "; kinetic at the end " << e.kinetic << ", contact column " << e.contact
              << " of " << 0.5 * kMass << " J\n";
    EXPECT_LT(drift, 1e-9) << "xi " << xi;
  }
}

}  // namespace
}  // namespace abut
