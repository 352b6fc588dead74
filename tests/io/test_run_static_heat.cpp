// What a static thermal run writes about its heat (static_thermal_output.hpp), read back from its
// files and checked against closed forms. A steel bar 0.1 m long, 0.01 x 0.01 m (A = 1e-4 m^2),
// k = 50 W/(m K), 10 x 2 x 2 hexahedra, clamped at x = 0, in one static step; steady 1D
// conduction (Incropera & DeWitt, Fundamentals of Heat and Mass Transfer, section 3.1) with the
// end x = 0 held at T_1 = 100 C and at x = L:
//  - held at T_2 = 20 C: the heat through the bar is Q = k A (T_1 - T_2) / L = 4 W;
//  - convecting to T_inf = 20 C with h = 500 W/(m^2 K): the resistances L / (k A) and 1 / (h A)
//    in series, Q = A (T_1 - T_inf) / (L / k + 1 / h) = 2 W, T(L) = T_inf + Q / (h A) = 60 C;
//  - a flux q(t) = 3e4 t W/m^2 into the end face: Q = q A (1.5 W at t = 0.5, 3 W at t = 1), all
//    of it leaving through the held end, T(L) = T_1 + q L / k (130 and 160 C).
// The temperature is linear along the bar, which trilinear hexahedra hold exactly, so the written
// flows match to round-off (1e-10 of Q; energy.csv to its 10 digits): energy.csv's heat_flow_*
// columns, the VTU field heat_flow (the heat flowing into each node by conduction: at the two end
// faces minus what enters there, zero inside) and summary.json's balance, whose error is that of
// the linear solve (1e-12 of Q; measured 1e-15 to 7e-14).
// Then the two blocks of tests/verification/test_static_contact_heat.cpp: the heat the held face
// puts in crosses the contact (its contact.csv heat_flow, 20 W by the series resistances) and
// leaves through the other held face.
#include <gmock/gmock.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "../verification/two_blocks_model.hpp"
#include "abut/io/run.hpp"
#include "test_deck_helpers.hpp"
#include "test_files.hpp"
#include "vtu_arrays.hpp"

namespace abut {
namespace {

using testing::Csv;
using testing::data_array;
using testing::file_text;
using ::testing::HasSubstr;
using testing::model_of;
using testing::read_csv;

constexpr double kLength = 0.1, kArea = 1.0e-4, kK = 50.0;

const std::string kBar = R"(*UNIT_SYSTEM
SI, C
*COMPONENT_BOX
1, 1, 10, 2, 2
0.0, 0.0, 0.0, 0.1, 0.01, 0.01
*MAT_ELASTIC
1, 7800.0, 2.0e11, 0.3, 0, 1
*PROP_THERMAL
1, 460.0, 50.0
*PART
"bar"
1, 1
*GEOMETRY_BOX
1
-0.001, -1.0, -1.0, 0.001, 1.0, 1.0
*GEOMETRY_BOX
2
0.099, -1.0, -1.0, 0.101, 1.0, 1.0
*BC_MOTION
G, 1, XYZ
*BC_TEMPERATURE
G, 1, 0, 100.0
)";

// The number after "key": in a JSON text (the first such key).
double json_number(const std::string& json, const std::string& key) {
  const auto at = json.find("\"" + key + "\":");
  if (at == std::string::npos) throw std::runtime_error("no " + key);
  return std::stod(json.substr(at + key.size() + 3));
}

std::filesystem::path state_file(std::size_t index) {
  char name[32];
  std::snprintf(name, sizeof name, "state_%04zu.vtu", index);
  return std::filesystem::path("states") / name;
}

// What a run wrote: energy.csv, contact.csv, summary.json and its last VTU state's fields.
struct Written {
  Csv energy, contact;
  std::string summary, log;
  std::vector<double> points, temperature, heat_flow;  // of the last state
  std::vector<double> first_heat_flow;                 // of the reference state

  // The sum of `field` over the nodes at x (the bar is clamped and unloaded: it does not move).
  double sum_at_x(const std::vector<double>& field, double x) const {
    double sum = 0.0;
    for (std::size_t i = 0; i < field.size(); ++i)
      if (std::abs(points[3 * i] - x) < 1e-9) sum += field[i];
    return sum;
  }
  // The largest |heat_flow| at the nodes strictly between x = 0 and x = L.
  double largest_inside() const {
    double largest = 0.0;
    for (std::size_t i = 0; i < heat_flow.size(); ++i)
      if (points[3 * i] > 1e-9 && points[3 * i] < kLength - 1e-9)
        largest = std::max(largest, std::abs(heat_flow[i]));
    return largest;
  }
};

Written run(const std::string& deck, const std::string& name) {
  const Model model = model_of(deck);
  const std::filesystem::path dir = testing::fresh_dir(name);
  std::ostringstream log;
  const RunReport report = run_simulation(model, {dir, 1, false}, log);
  EXPECT_TRUE(report.stable) << log.str();
  Written w;
  w.log = log.str();
  w.energy = read_csv(dir / "energy.csv");
  if (std::filesystem::exists(dir / "contact.csv")) w.contact = read_csv(dir / "contact.csv");
  w.summary = file_text(dir / "summary.json");
  std::size_t last = 0;
  while (std::filesystem::exists(dir / state_file(last + 1))) ++last;
  const std::string vtu = file_text(dir / state_file(last));
  w.points = data_array<double>(vtu, "Points");
  w.temperature = data_array<double>(vtu, "temperature");
  w.heat_flow = data_array<double>(vtu, "heat_flow");
  w.first_heat_flow = data_array<double>(file_text(dir / state_file(0)), "heat_flow");
  std::filesystem::remove_all(dir);
  return w;
}

// The balance of energy.csv's row `row`: the four flows, to the 10 significant digits that the
// CSV files hold, and the error (computed before it is written) relative to the largest.
void expect_balance(const Written& w, std::size_t row, double boundary_in, double boundary_out,
                    double prescribed_in, double prescribed_out, const char* what) {
  const double q = std::max({boundary_in, -boundary_out, prescribed_in, -prescribed_out});
  EXPECT_NEAR(w.energy.at(row, "heat_flow_boundary_in"), boundary_in, 1e-9 * q) << what;
  EXPECT_NEAR(w.energy.at(row, "heat_flow_boundary_out"), boundary_out, 1e-9 * q) << what;
  EXPECT_NEAR(w.energy.at(row, "heat_flow_prescribed_in"), prescribed_in, 1e-9 * q) << what;
  EXPECT_NEAR(w.energy.at(row, "heat_flow_prescribed_out"), prescribed_out, 1e-9 * q) << what;
  const double error = w.energy.at(row, "heat_flow_balance_error");
  EXPECT_NEAR(error, 0.0, 1e-12 * q) << what;
  std::cout << what << ": balance error " << error << " W = " << error / q
            << " of the largest flow\n";
}

TEST(RunStaticHeat, BarBetweenHeldTemperatures) {
  const Written w = run(kBar + R"(*BC_TEMPERATURE
G, 2, 0, 20.0
*STATIC
1.0
)",
                        "abut_static_heat_held");
  const double q = kK * kArea * 80.0 / kLength;  // 4 W
  EXPECT_EQ(w.energy.columns,
            (std::vector<std::string>{"time", "internal", "contact", "friction", "external_work",
                                      "balance_error", "heat_flow_boundary_in",
                                      "heat_flow_boundary_out", "heat_flow_prescribed_in",
                                      "heat_flow_prescribed_out", "heat_flow_balance_error"}));
  ASSERT_EQ(w.energy.rows.size(), 1u);
  expect_balance(w, 0, 0.0, 0.0, q, -q, "held ends");
  // Conduction draws Q out of the hot end's nodes and brings it to the cold end's.
  EXPECT_NEAR(w.sum_at_x(w.heat_flow, 0.0), -q, 1e-10 * q);
  EXPECT_NEAR(w.sum_at_x(w.heat_flow, kLength), q, 1e-10 * q);
  EXPECT_LT(w.largest_inside(), 1e-10 * q);
  // summary.json: the balance of the last state.
  EXPECT_THAT(w.summary, HasSubstr("\"thermal\""));
  EXPECT_THAT(w.summary, HasSubstr("\"steady_state\": true"));
  EXPECT_NEAR(json_number(w.summary, "prescribed_in"), q, 1e-10 * q);
  EXPECT_NEAR(json_number(w.summary, "prescribed_out"), -q, 1e-10 * q);
  EXPECT_NEAR(json_number(w.summary, "relative_error"), 0.0, 1e-12);
  EXPECT_THAT(w.log, HasSubstr("steady heat flow at t = 1"));
}

// One hexahedron along the bar: every node is held, there is nothing to solve, and the flows are
// still those of the held temperatures.
TEST(RunStaticHeat, EveryNodeHeld) {
  std::string deck = kBar;
  deck.replace(deck.find("1, 1, 10, 2, 2"), 14, "1, 1, 1, 2, 2");
  const Written w = run(deck + R"(*BC_TEMPERATURE
G, 2, 0, 20.0
*STATIC
1.0
)",
                        "abut_static_heat_all_held");
  const double q = kK * kArea * 80.0 / kLength;
  expect_balance(w, 0, 0.0, 0.0, q, -q, "every node held");
  EXPECT_NEAR(w.sum_at_x(w.heat_flow, 0.0), -q, 1e-10 * q);
}

TEST(RunStaticHeat, BarCoolingByConvection) {
  const Written w = run(kBar + R"(*LOAD_THERMAL_CONVECTION
1, G, 2, 500.0, 20.0
*STATIC
1.0
)",
                        "abut_static_heat_convection");
  const double h = 500.0, q = kArea * 80.0 / (kLength / kK + 1.0 / h);  // 2 W
  ASSERT_EQ(w.energy.rows.size(), 1u);
  expect_balance(w, 0, 0.0, -q, q, 0.0, "convecting end");
  EXPECT_NEAR(w.sum_at_x(w.temperature, kLength) / 9.0, 20.0 + q / (h * kArea), 1e-10 * 100.0);
  EXPECT_NEAR(w.sum_at_x(w.heat_flow, 0.0), -q, 1e-10 * q);
  EXPECT_NEAR(w.sum_at_x(w.heat_flow, kLength), q, 1e-10 * q);
  EXPECT_LT(w.largest_inside(), 1e-10 * q);
}

// The flux follows its curve: each state has the flux of its own time.
TEST(RunStaticHeat, BarHeatedByARampedFlux) {
  const Written w = run(kBar + R"(*CURVE
1
0.0, 0.0
1.0, 1.0
*LOAD_THERMAL_SURFACE
1, G, 2, 1, 3.0e4
*STATIC
1.0, 0.5
)",
                        "abut_static_heat_flux");
  ASSERT_EQ(w.energy.rows.size(), 2u);
  for (std::size_t row = 0; row < 2; ++row) {
    const double t = w.energy.rows[row][0], q = 3.0e4 * t * kArea;
    expect_balance(w, row, q, 0.0, 0.0, -q, row == 0 ? "flux at t = 0.5" : "flux at t = 1");
  }
  const double q = 3.0e4 * kArea;  // the last state, t = 1
  EXPECT_NEAR(w.sum_at_x(w.temperature, kLength) / 9.0, 100.0 + 3.0e4 * kLength / kK,
              1e-10 * 100.0);
  // The heat flows from the heated end to the held one.
  EXPECT_NEAR(w.sum_at_x(w.heat_flow, kLength), -q, 1e-10 * q);
  EXPECT_NEAR(w.sum_at_x(w.heat_flow, 0.0), q, 1e-10 * q);
  EXPECT_NEAR(json_number(w.summary, "boundary_in"), q, 1e-10 * q);
}

// Two blocks, k = 100 and 50 W/(m K), 50 mm each, 0.02 x 0.02 m, non-matching meshes, clamped,
// in contact with a conductance h = 2000 W/(m^2 K).
const std::string kBlocks = std::string(verification::kTwoBlocksModel) + R"(*BC_MOTION
G, 1, XYZ
G, 2, XYZ
*CONTACT
"interface"
1
P, 1, P, 2, 0.0, 1.0e13
*CONTACT_THERMAL
1, OPEN_CLOSED, 2000.0
*STATIC
1.0, , , , 0
)";

// The blocks' outer faces held at 100 and 0 C: the series resistances
// give q = 100 / (L_1 / k_1 + 1 / h + L_2 / k_2) = 5e4 W/m^2, 20 W (Incropera & DeWitt, section
// 3.1.4). The contact carries what the hot face puts in to round-off, so the balance closes; the
// flow itself is 20 W within the non-matching interface's quadrature (-8.6e-6, see
// test_static_contact_heat.cpp).
TEST(RunStaticHeat, HeatCrossingAContact) {
  const Written w = run(kBlocks + R"(*BC_TEMPERATURE
G, 1, 0, 100.0
G, 2, 0, 0.0
)",
                        "abut_static_heat_contact");
  ASSERT_EQ(w.energy.rows.size(), 1u);
  ASSERT_EQ(w.contact.rows.size(), 1u);
  const double through = w.contact.at(0, "heat_flow");
  EXPECT_NEAR(through / 20.0, 1.0, 1e-3);
  expect_balance(w, 0, 0.0, 0.0, through, -through, "across a contact");
}

// Only the hot block's face held: the reference state has no contact yet, so the cold block has
// no steady temperature there (it keeps its initial one and no heat flows: the field is zero); once
// the contact conducts, both blocks are at 100 C and no heat flows. The flows are then round-off,
// and so would be the largest of them: the balance says that nothing flows rather than dividing
// round-off by round-off.
TEST(RunStaticHeat, NoHeatFlowIsNoError) {
  const Written w = run(kBlocks + R"(*BC_TEMPERATURE
G, 1, 0, 100.0
)",
                        "abut_static_heat_none");
  EXPECT_THAT(w.log, HasSubstr("the first state keeps the initial temperature"));
  for (const double f : w.first_heat_flow) EXPECT_EQ(f, 0.0);
  for (const double t : w.temperature) EXPECT_NEAR(t, 100.0, 1e-9);
  EXPECT_THAT(w.summary, HasSubstr("\"heat_flows\": false"));
  EXPECT_EQ(json_number(w.summary, "relative_error"), 0.0);
  EXPECT_LT(std::abs(json_number(w.summary, "error")), 1e-9);
  EXPECT_THAT(w.log, HasSubstr("no heat flows at t = 1"));
}

}  // namespace
}  // namespace abut
