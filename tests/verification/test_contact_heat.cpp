// Heat through contact in a whole explicit run (issue 11): the contact library's conduction and
// friction heat (src/contact/heat_exchange.cpp) feeding the heat solver on its own clock
// (Simulation::advance_heat).
//  - Two blocks of different conductivity in contact, the outer faces held at T_1 and T_2, the
//    sides insulated: at steady state the heat flow is the series resistance formula
//      q = (T_1 - T_2) / (L_1 / k_1 + 1 / h + L_2 / k_2)   [power / area]
//    and the interface temperature jumps by q / h (Incropera & DeWitt, Fundamentals of Heat and
//    Mass Transfer, section 3.1.4, thermal contact resistance), 0.1%.
//  - A block sliding to rest on a plane with friction (the model of
//    test_contact_sliding_block.cpp): the heat stored equals the friction work (1e-6 relative),
//    shared between block and plane as specified.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "abut/io/run.hpp"
#include "run_to.hpp"

namespace abut {
namespace {

// Sums C_a (T_a - T_0) over the nodes of a part: the heat the part has taken up.
double stored_heat(const Simulation& sim, std::int64_t part, double t0) {
  const Model& m = sim.model();
  std::vector<std::uint8_t> of_part(m.mesh.nodes.size(), 0);
  for (std::size_t h = 0; h < m.mesh.hex_count(); ++h)
    if (m.mesh.hex_part[h] == part)
      for (const std::int32_t i : m.mesh.hexes[h]) of_part[static_cast<std::size_t>(i)] = 1;
  double sum = 0.0;
  for (std::size_t i = 0; i < of_part.size(); ++i)
    if (of_part[i]) sum += sim.heat_capacity()[i] * (sim.temperature()[i] - t0);
  return sum;
}

ThermalProperties thermal(std::int64_t id, double k, double c) {
  ThermalProperties p;
  p.id = id;
  p.conductivity = k;
  p.specific_heat = c;
  return p;
}

// Block 1: x in [0, 0.05], 5 x 2 x 2 hexes, k_1 = 100; block 2: x in [0.05, 0.1], 4 x 3 x 3 hexes
// (non-matching at the interface), k_2 = 50; both 0.02 x 0.02 m, rho c = 1e4 J/(m^3 K), held in
// place. Contact conductance h = 2000 W/(m^2 K) while closed (the faces touch). Resistances
// L_1/k_1 = 5e-4, 1/h = 5e-4, L_2/k_2 = 1e-3 m^2 K/W: with T_1 - T_2 = 100 K, q = 5e4 W/m^2,
// 20 W through the 4e-4 m^2 interface, and a jump of 25 K. The whole heat capacity (0.4 J/K)
// times the whole resistance (5 K/W) is 2 s, which bounds the slowest decay time; the run
// lasts 30 s.
const char* kBlocks = R"(
*TIME
30.0
*COMPONENT_BOX
1, 1, 5, 2, 2
0.0, 0.0, 0.0, 0.05, 0.02, 0.02
*COMPONENT_BOX
2, 2, 4, 3, 3
0.05, 0.0, 0.0, 0.1, 0.02, 0.02
*MAT_ELASTIC
1, 1000.0, 100.0, 0.3
*MAT_ELASTIC
2, 1000.0, 100.0, 0.3
*PART
"hot block"
1, 1
"cold block"
2, 2
*BC_MOTION
P, 1, XYZ
*BC_MOTION
P, 2, XYZ
*CONTACT
"interface"
1
P, 1, P, 2, 0.0, 1.0e6
*END
)";

TEST(ContactHeat, SteadyFluxThroughAContactResistance) {
  Model model = read_deck_string(kBlocks, "hot_blocks.k");
  const double k1 = 100.0, k2 = 50.0, h = 2000.0, t1 = 100.0, t2 = 0.0;
  model.materials[0].thermal_id = 1;
  model.materials[1].thermal_id = 2;
  model.thermal.properties = {thermal(1, k1, 10.0), thermal(2, k2, 10.0)};
  model.thermal.initial_temperature = 50.0;
  std::vector<std::int32_t> cold, hot;
  const Nodes& n = model.mesh.nodes;
  for (std::size_t i = 0; i < n.size(); ++i) {
    if (std::abs(n.x[i]) < 1e-12) hot.push_back(static_cast<std::int32_t>(i));
    if (std::abs(n.x[i] - 0.1) < 1e-12) cold.push_back(static_cast<std::int32_t>(i));
  }
  model.thermal.prescribed.push_back({hot, {}, t1, {}});
  model.thermal.prescribed.push_back({cold, {}, t2, {}});
  ContactSpec::Conductance c;
  c.law = ContactSpec::Conductance::Law::OpenClosed;
  c.closed = h;
  model.contacts[0].conductance = c;

  Simulation sim(model);
  verification::run_to(sim, sim.end_time());
  const double area = 0.02 * 0.02;
  const double q = (t1 - t2) / (0.05 / k1 + 1.0 / h + 0.05 / k2);
  const double flow = sim.contact_reports().at(0).stats.heat_flow;
  // Interface temperatures: the mean over each block's nodes on x = 0.05.
  double sum1 = 0.0, sum2 = 0.0;
  int count1 = 0, count2 = 0;
  for (std::size_t e = 0; e < model.mesh.hex_count(); ++e)
    for (const std::int32_t i : model.mesh.hexes[e]) {
      if (std::abs(n.x[static_cast<std::size_t>(i)] - 0.05) > 1e-12) continue;
      const double t = sim.temperature()[static_cast<std::size_t>(i)];
      if (model.mesh.hex_part[e] == 1) {
        sum1 += t;
        ++count1;
      } else {
        sum2 += t;
        ++count2;
      }
    }
  const double jump = sum1 / count1 - sum2 / count2;
  std::cout << "heat flow " << flow << " W against q A = " << q * area << " W ("
            << 100.0 * (flow / (q * area) - 1.0) << "%); jump " << jump
            << " K against q/h = " << q / h << " K (" << 100.0 * (jump / (q / h) - 1.0) << "%); "
            << sim.cycle() << " mechanical and " << sim.thermal_steps() << " thermal steps\n";
  EXPECT_NEAR(flow, q * area, 1e-3 * q * area);
  EXPECT_NEAR(jump, q / h, 1e-3 * q / h);
  const HeatBalance b = sim.heat_balance();
  EXPECT_NEAR(b.error(), 0.0, 1e-9 * std::abs(b.prescribed));
}

// Metafor's pressure-dependent conductance h = h_c0 (p / H_v)^w (seed 002) in a run: the blocks of
// kBlocks overlapping by d (a linear penalty 1e9 Pa/m gives p = 1e9 d), at 100 and 0 degrees; the
// heat crossing at the first cycle is h A (T_1 - T_2), and doubling the overlap, hence the
// pressure, multiplies it by 2^w.
TEST(ContactHeat, DoublingThePressureMultipliesTheConductedHeatByTwoToTheW) {
  const double h0 = 1e4, hardness = 1e6, w = 0.7, area = 0.02 * 0.02;
  double flow[2] = {0.0, 0.0};
  for (const int k : {1, 2}) {
    const double d = 1e-4 * k;  // below delta0_max = 4% of the 10 mm element thickness
    Model model = read_deck_string(kBlocks, "pressed_blocks.k");
    std::vector<std::uint8_t> moved(model.mesh.nodes.size(), 0);  // block 2's nodes, once each
    for (std::size_t e = 0; e < model.mesh.hex_count(); ++e)
      if (model.mesh.hex_part[e] == 2)
        for (const std::int32_t i : model.mesh.hexes[e]) moved[static_cast<std::size_t>(i)] = 1;
    for (std::size_t i = 0; i < moved.size(); ++i)
      if (moved[i]) model.mesh.nodes.x[i] -= d;
    model.materials[0].thermal_id = model.materials[1].thermal_id = 1;
    model.thermal.properties = {thermal(1, 100.0, 10.0)};
    std::vector<std::int32_t> hot;
    for (std::size_t e = 0; e < model.mesh.hex_count(); ++e)
      if (model.mesh.hex_part[e] == 1)
        for (const std::int32_t i : model.mesh.hexes[e]) hot.push_back(i);
    model.thermal.initial_temperature = 0.0;
    model.thermal.initial.push_back({hot, 100.0, {}});
    model.contacts[0].penalty = 1e9;
    ContactSpec::Conductance c;
    c.law = ContactSpec::Conductance::Law::Pressure;
    c.nominal = h0;
    c.hardness = hardness;
    c.exponent = w;
    model.contacts[0].conductance = c;
    Simulation sim(model);
    sim.advance();
    flow[k - 1] = sim.contact_reports().at(0).stats.heat_flow;
    const double p = 1e9 * d;
    const double expected = h0 * std::pow(p / hardness, w) * area * 100.0;
    std::cout << "overlap " << d << " m: heat flow " << flow[k - 1]
              << " W, h_c0 (p/H_v)^w A dT = " << expected << " W\n";
    EXPECT_NEAR(flow[k - 1], expected, 0.01 * expected);
  }
  EXPECT_NEAR(flow[1] / flow[0], std::pow(2.0, w), 0.01 * std::pow(2.0, w));
}

// The block of test_contact_sliding_block.cpp (1 m/s, mu = 0.5, both bodies rigid steel) with
// fric_heat: 30% of the heat to the block (surface 1), 70% to the plane.
const char* kSliding = R"(
*UNIT_SYSTEM
SI
*TIME
0.3
*COMPONENT_BOX
1, 1, 2, 2, 1
0.0, -0.05, 0.0, 0.1, 0.05, 0.02
*COMPONENT_BOX
2, 2, 10, 4, 1
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
*INITIAL_VELOCITY
P, 1, 1.0, 0.0, 0.0
*BC_MOTION
P, 2, XYZ, XYZ
*CURVE
1
0.0, -9.81
1.0, -9.81
*LOAD_GRAVITY
Z, 1
*CONTACT
"block on plane"
1
P, 1, P, 2, 0.5, 6.2e9
*END
)";

TEST(ContactHeat, FrictionHeatEqualsTheFrictionWorkSharedAsSpecified) {
  Model model = read_deck_string(kSliding, "sliding_block_heat.k");
  const double t0 = 20.0, share = 0.3;
  for (Material& m : model.materials) m.thermal_id = 1;
  model.thermal.properties = {thermal(1, 45.0, 460.0)};
  model.thermal.initial_temperature = t0;
  model.contacts[0].friction_heat = true;
  model.contacts[0].friction_heat_to_surface1 = share;
  Simulation sim(model);
  const double mass = sim.part_states().at(0).mass;
  // The heat is in the temperatures at every mechanical step, however long the thermal step
  // (issue 29: a state at 0.4 s used to show none of 0.83 J).
  double worst = 0.0;
  verification::run_to(sim, sim.end_time(), [&](const Simulation& s) {
    const double heat = s.contact_reports().at(0).stats.friction_heat;
    worst = std::max(worst, std::abs(s.heat_balance().stored - heat) / (0.5 * mass));
  });
  std::cout << "stored heat off the friction heat so far by at most " << worst
            << " of 1/2 m v0^2 over the steps\n";
  EXPECT_LT(worst, 1e-9);
  const double work = sim.contact_reports().at(0).stats.friction_energy;
  const double block = stored_heat(sim, 1, t0), plane = stored_heat(sim, 2, t0);
  std::cout << "friction work " << work << " J (1/2 m v0^2 = " << 0.5 * mass << " J); heat in "
            << "block " << block << " J, plane " << plane << " J; relative error of the sum "
            << (block + plane) / work - 1.0 << "\n";
  EXPECT_NEAR(work, 0.5 * mass * 1.0, 0.01 * 0.5 * mass);  // the block's kinetic energy
  EXPECT_NEAR(block + plane, work, 1e-6 * work);
  EXPECT_NEAR(block, share * work, 1e-6 * work);
  EXPECT_NEAR(plane, (1.0 - share) * work, 1e-6 * work);
  EXPECT_NEAR(sim.contact_reports().at(0).stats.friction_heat, work, 1e-12 * work);
}

// contact.csv of a thermal contact carries heat_flow, conducted_heat and friction_heat; at the end
// the friction heat equals the friction energy of the same row.
TEST(ContactHeat, ContactHistoryHasTheHeatColumns) {
  Model model = read_deck_string(kSliding, "sliding_block_heat.k");
  for (Material& m : model.materials) m.thermal_id = 1;
  model.thermal.properties = {thermal(1, 45.0, 460.0)};
  model.contacts[0].friction_heat = true;
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "abut_test_contact_heat_history";
  std::filesystem::remove_all(dir);
  std::ostringstream log;
  run_simulation(model, {dir, 1, false}, log);
  std::ifstream csv(dir / "contact.csv");
  std::string header, line, last;
  std::getline(csv, header);
  EXPECT_EQ(header,
            "time,contact,fx,fy,fz,normal_force,tangential_force,energy,friction_energy,"
            "max_penetration,active_points,heat_flow,conducted_heat,friction_heat");
  while (std::getline(csv, line)) last = line;
  std::vector<double> values;
  std::stringstream row(last);
  for (std::string cell; std::getline(row, cell, ',');) values.push_back(std::stod(cell));
  ASSERT_EQ(values.size(), 14u);
  EXPECT_GT(values[8], 0.7);  // friction energy [J]
  EXPECT_NEAR(values[13], values[8], 1e-9 * values[8]);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace abut
