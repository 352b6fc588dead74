// The heat and the mechanics on their own clocks (issue 29), from decks:
//  - Two blocks exchanging heat through a contact conductance h (each block a lump: Biot number
//    h L / k = 1e-3), at mechanical/thermal step ratios from 0.01 to 1000 (1000: the mechanical
//    step is 25 thermal time constants of a contact node). The temperature
//    difference of two lumps of capacities C_1, C_2 joined by a conductance G = h A decays as
//      dT(t) = dT(0) exp(-t / tau),  tau = 1 / (G (1/C_1 + 1/C_2))
//    (Incropera & DeWitt, Fundamentals of Heat and Mass Transfer, section 5.1, lumped
//    capacitance; two lumps: the same balance written for their difference). Every node stays
//    within the starting temperatures, and the block means follow the exponential within 1% of
//    dT(0) at every mechanical step; the heat balance closes.
//  - A free bar whose temperature is ramped 0 -> 100 over 1 ms on every node (*BC_TEMPERATURE
//    with a curve): it expands by alpha dT L (free thermal strain), followed within 1% from 1 ms
//    on, although its thermal step is far longer than the run.
//  - Friction heat: a block sliding to rest on a plane; at every mechanical step the heat stored
//    equals the friction work so far (1e-9).
//  - A heat flux that overflows stops the run as unstable (exit 3) with its last good state.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>

#include "abut/io/deck.hpp"
#include "abut/io/run.hpp"
#include "run_to.hpp"

namespace abut {
namespace {

// Two 0.01 m cubes of one hexahedron each, side by side along x, held in place; rho c = 1e6
// J/(m^3 K), k = 1e6 W/(m K), h = 1e5 W/(m^2 K) while closed: C = 1 J/K each, G = 10 W/K,
// tau = 0.05 s, Biot h L / k = 1e-3. The elements' thermal step is 0.9 x 3.75e-5 s; the density
// (c_p = 1e6 / rho keeps rho c) and Young's modulus set the mechanical step, about
// 0.0059 sqrt(rho / E), hence the ratio.
std::string two_blocks(double density, double young, double end) {
  return "*TIME\n" + std::to_string(end) +
         "\n*COMPONENT_BOX\n1, 1, 1, 1, 1\n0.0, 0.0, 0.0, 0.01, 0.01, 0.01\n"
         "*COMPONENT_BOX\n2, 2, 1, 1, 1\n0.01, 0.0, 0.0, 0.02, 0.01, 0.01\n"
         "*MAT_ELASTIC\n1, " +
         std::to_string(density) + ", " + std::to_string(young) + ", 0.3, , 1\n*PROP_THERMAL\n1, " +
         std::to_string(1e6 / density) + ", 1.0e6\n" +
         R"(*PART
"hot"
1, 1
"cold"
2, 1
*BC_MOTION
P, 1, XYZ
*BC_MOTION
P, 2, XYZ
*INITIAL_TEMPERATURE
P, 1, 100.0
P, 2, 0.0
*CONTACT
"interface"
1
P, 1, P, 2, 0.0, 1.0e6
*CONTACT_THERMAL
1, OPEN_CLOSED, 1.0e5
*END
)";
}

// The heat capacity of a part's nodes (those of its hexahedra and shells), sum C_a, and their
// capacity-weighted mean temperature.
struct PartHeat {
  double mean = 0.0, capacity = 0.0;
};
PartHeat part_heat(const Simulation& sim, std::int64_t part) {
  const Mesh& mesh = sim.model().mesh;
  std::vector<std::uint8_t> of(mesh.nodes.size(), 0);
  for (std::size_t h = 0; h < mesh.hex_count(); ++h)
    if (mesh.hex_part[h] == part)
      for (const std::int32_t i : mesh.hexes[h]) of[static_cast<std::size_t>(i)] = 1;
  for (std::size_t e = 0; e < mesh.shell_count(); ++e)
    if (mesh.shell_part[e] == part)
      for (const std::int32_t i : mesh.shells[e]) of[static_cast<std::size_t>(i)] = 1;
  double heat = 0.0, capacity = 0.0;
  for (std::size_t i = 0; i < of.size(); ++i)
    if (of[i]) {
      heat += sim.heat_capacity()[i] * sim.temperature()[i];
      capacity += sim.heat_capacity()[i];
    }
  return {heat / capacity, capacity};
}

struct RatioCase {
  double density, young;  // set the mechanical step
  double ratio;           // the mechanical / thermal step ratio it was chosen for
};

class TwoLumps : public ::testing::TestWithParam<RatioCase> {};

TEST_P(TwoLumps, FollowTheExponentialAtAnyStepRatio) {
  const double tau = 0.05;
  // One time constant: the error of forward Euler and of the lumps is largest around it.
  const Model model =
      read_deck_string(two_blocks(GetParam().density, GetParam().young, tau), "two_blocks.k");
  Simulation sim(model);
  double worst = 0.0, low = 100.0, high = 0.0;
  const double thermal = 0.9 * sim.thermal_stable_step();
  const double ratio = sim.time_step() / thermal;
  verification::run_to(sim, sim.end_time(), [&](const Simulation& s) {
    const double exact = 100.0 * std::exp(-s.time() / tau);
    worst = std::max(worst, std::abs(part_heat(s, 1).mean - part_heat(s, 2).mean - exact));
    for (const double t : s.temperature()) {
      low = std::min(low, t);
      high = std::max(high, t);
    }
  });
  const HeatBalance b = sim.heat_balance();
  std::cout << "mechanical/thermal step " << ratio << ": largest error " << worst
            << " K of 100 K; temperatures within [" << low << ", " << high << "]; heat balance "
            << b.relative_error() << "; " << sim.cycle() << " mechanical and "
            << sim.thermal_steps() << " thermal steps\n";
  EXPECT_GT(ratio, 0.3 * GetParam().ratio);  // the case is the one the table names
  EXPECT_LT(ratio, 3.0 * GetParam().ratio);
  EXPECT_LT(worst, 1.0);  // 1% of the starting difference
  EXPECT_GE(low, -1e-9);
  EXPECT_LE(high, 100.0 + 1e-9);
  EXPECT_LT(std::abs(b.relative_error()), 1e-12);
}

// rho / E = (0.0059 x 3.375e-5 r / 0.0059^2 ...): (ratio x 5.7e-3)^2 from the estimate above.
INSTANTIATE_TEST_SUITE_P(StepRatios, TwoLumps,
                         ::testing::Values(RatioCase{1e3, 3e11, 0.01}, RatioCase{1e3, 3e9, 0.1},
                                           RatioCase{1e3, 3e7, 1.0}, RatioCase{1e5, 3e7, 10.0},
                                           RatioCase{1e7, 3e7, 100.0},
                                           RatioCase{1e9, 3e7, 1000.0}));

// A free steel bar, 0.05 x 0.01 x 0.01 m, 10 x 2 x 2 hexahedra of 5 mm (E = 2.1e11, rho = 7850,
// c = 460, k = 50, alpha = 1.2e-5), every node held at T(t) = 100 min(t / 1 ms, 1): the bar
// lengthens by alpha dT L = 6e-5 m (free thermal strain). Its thermal step, about
// rho c (5 mm)^2 / (6 k) = 0.3 s, is 150 times the 2 ms run: the held temperatures follow their
// curve at every mechanical step all the same. The ramp is 50 periods of the bar's first
// longitudinal mode (2 L / c = 19 us), so it leaves a vibration of at most 1/(pi 50) = 0.6% of
// the lengthening.
TEST(HeatClock, HeldTemperaturesFollowTheirCurveAndTheBarExpands) {
  const Model model = read_deck_string(R"(*TIME
0.002
*COMPONENT_BOX
1, 1, 10, 2, 2
0.0, 0.0, 0.0, 0.05, 0.01, 0.01
*MAT_ELASTIC
1, 7850.0, 2.1e11, 0.3, , 1
*PROP_THERMAL
1, 460.0, 50.0, 1.2e-5, 0.0
*PART
"bar"
1, 1
*CURVE
7
0.0, 0.0
0.001, 100.0
0.002, 100.0
*BC_TEMPERATURE
ALL, 0, 7, 1.0
*END
)",
                                       "ramped_bar.k");
  Simulation sim(model);
  const Nodes& n = model.mesh.nodes;
  const auto length = [&] {
    double left = 0.0, right = 0.0;
    int count_left = 0, count_right = 0;
    for (std::size_t i = 0; i < n.size(); ++i) {
      if (std::abs(n.x[i]) < 1e-12) left += sim.x()[i], ++count_left;
      if (std::abs(n.x[i] - 0.05) < 1e-12) right += sim.x()[i], ++count_right;
    }
    return right / count_right - left / count_left;
  };
  const double lengthening = 1.2e-5 * 100.0 * 0.05;
  double worst = 0.0, worst_temperature = 0.0;
  verification::run_to(sim, sim.end_time(), [&](const Simulation& s) {
    const double held = 100.0 * std::min(s.time() / 0.001, 1.0);
    for (const double t : s.temperature())
      worst_temperature = std::max(worst_temperature, std::abs(t - held));
    if (s.time() >= 0.001) worst = std::max(worst, std::abs(length() - 0.05 - lengthening));
  });
  std::cout << "held temperatures off their curve by at most " << worst_temperature
            << " K; lengthening from 1 ms off alpha dT L by at most " << worst / lengthening
            << " of it; " << sim.thermal_steps() << " thermal steps\n";
  EXPECT_LT(worst_temperature, 1e-9);
  EXPECT_LT(worst, 0.01 * lengthening);
}

// *TIME dt_max bounds the thermal step too: the two lumps of two_blocks (thermal step 3.4e-5 s
// from the elements) with the mechanical step held at or below 1e-5 s still plan at least one
// thermal step per 1e-5 s, and follow the exponential.
TEST(HeatClock, DtMaxBoundsTheThermalStep) {
  std::string text = two_blocks(1e3, 3e11, 0.005);
  text.replace(text.find("0.005000\n"), 9, "0.005000, 0.9, 0.0, 1.0e-5\n");
  const Model model = read_deck_string(text, "dt_max.k");
  Simulation sim(model);
  verification::run_to(sim, sim.end_time());
  const double exact = 100.0 * std::exp(-0.005 / 0.05);
  std::cout << sim.thermal_steps() << " thermal steps in 0.005 s with dt_max 1e-5 s; difference "
            << part_heat(sim, 1).mean - part_heat(sim, 2).mean << " K (exact " << exact << ")\n";
  EXPECT_GE(sim.thermal_steps(), 500);
  EXPECT_NEAR(part_heat(sim, 1).mean - part_heat(sim, 2).mean, exact, 1.0);
}

// A heat flux that grows without bound (q = 1e300 exp(1e4 t) W/m^2 on one face) drives the
// temperature past every finite value: the run stops as unstable (exit 3), naming the node.
TEST(HeatClock, ATemperatureThatDivergesStopsTheRun) {
  const Model model = read_deck_string(R"(*TIME
0.01
*COMPONENT_BOX
1, 1, 2, 1, 1
0.0, 0.0, 0.0, 0.02, 0.01, 0.01
*MAT_ELASTIC
1, 7850.0, 2.1e11, 0.3, , 1
*PROP_THERMAL
1, 460.0, 50.0
*PART
"bar"
1, 1
*FUNCTION
9
1.0e300 * exp(1.0e4 * t)
*LOAD_THERMAL_SURFACE
1, P, 1, 9, 1.0
*END
)",
                                       "diverging_flux.k");
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "abut_heat_diverges";
  std::filesystem::remove_all(dir);
  RunOptions options;
  options.output_dir = dir;
  std::ostringstream log;
  options.progress = false;
  const RunReport report = run_simulation(model, options, log);
  std::cout << report.message << "\n";
  EXPECT_FALSE(report.stable);
  EXPECT_NE(report.message.find("temperature"), std::string::npos);
  EXPECT_LT(report.end_time, 0.01);
  std::filesystem::remove_all(dir);
}

// A shell plate on a block (issue 29's second case): a 20 x 20 mm plate of 2 x 2 shells, 1 mm
// thick, at 100 degrees, lying on a 20 x 20 x 10 mm block of 2 x 2 x 1 hexahedra at 0, both
// held, rho c = 1e6 J/(m^3 K); h = 1e5 W/(m^2 K) across. The plate is a lump through its
// thickness (shells conduct in their plane only) and uniform in its plane; the block is a lump
// (k = 1e6 W/(m K), Biot 1e-3). Capacities per area 1e3 and 1e4 J/(m^2 K): tau = 1 / (h (1e-3 +
// 1e-4)) = 9.09 ms, run to 3 tau. The density (c_p = 1e6 / rho keeps rho c) sets the mechanical
// step: rho = 1000, far below the contact's time constants; rho = 1e12, longer than tau (the
// issue's plate cooled 3% too fast).
std::string plate_on_block(double density) {
  const std::string rho = std::to_string(density), c = std::to_string(1e6 / density);
  return "*TIME\n0.0273\n*COMPONENT_BOX\n1, 1, 2, 2, 1\n0.0, 0.0, -0.01, 0.02, 0.02, 0.0\n"
         "*COMPONENT_SHELL_PLATE\n2, 2, 2, 2\n0.0, 0.0, 0.0005, 0.02, 0.0, 0.0005\n"
         "0.0, 0.02, 0.0005\n*MAT_ELASTIC\n1, " +
         rho + ", 1.0e11, 0.3, , 1\n*MAT_ELASTIC\n2, " + rho +
         ", 1.0e11, 0.3, , 2\n*PROP_THERMAL\n1, " + c + ", 1.0e6\n*PROP_THERMAL\n2, " + c +
         R"(, 50.0
*PART
"block"
1, 1
"plate"
2, 2, , 0.001
*BC_MOTION
P, 1, XYZ
*BC_MOTION
P, 2, XYZ, XYZ
*INITIAL_TEMPERATURE
P, 1, 0.0
P, 2, 100.0
*CONTACT
"plate on block"
1
P, 2, P, 1, 0.0, 1.0e6
*CONTACT_THERMAL
1, OPEN_CLOSED, 1.0e5
*END
)";
}

class PlateOnBlock : public ::testing::TestWithParam<double> {};

TEST_P(PlateOnBlock, FollowsTheTwoLumpExponential) {
  const Model model = read_deck_string(plate_on_block(GetParam()), "plate_on_block.k");
  Simulation sim(model);
  const double c_block = part_heat(sim, 1).capacity, c_plate = part_heat(sim, 2).capacity;
  const double step = sim.time_step();
  const double tau = 1.0 / (1e5 * 4e-4 * (1.0 / c_block + 1.0 / c_plate));
  double worst = 0.0;
  verification::run_to(sim, sim.end_time(), [&](const Simulation&) {
    const double exact = 100.0 * std::exp(-sim.time() / tau);
    worst = std::max(worst, std::abs(part_heat(sim, 2).mean - part_heat(sim, 1).mean - exact));
  });
  std::cout << "plate on block (rho = " << GetParam() << "): mechanical step " << step << " s, tau "
            << tau << " s (capacities " << c_plate << " and " << c_block << " J/K); largest error "
            << worst << " K of 100 K; " << sim.cycle() << " mechanical and " << sim.thermal_steps()
            << " thermal steps\n";
  EXPECT_NEAR(tau, 1.0 / (1e5 * (1e-3 + 1e-4)), 1e-9);  // the capacities are those of the page
  EXPECT_LT(worst, 1.0);
}

INSTANTIATE_TEST_SUITE_P(StepRatios, PlateOnBlock, ::testing::Values(1e3, 1e12));

}  // namespace
}  // namespace abut
