// A thermal deck end to end: a bar of hexahedra, one end held at T_s by *BC_TEMPERATURE, the rest
// insulated, read from .k text and run by the explicit solver. Early on the bar is a semi-infinite
// body, whose temperature is T(x, t) = T_s + (T_0 - T_s) erf(x / (2 sqrt(a t))), a = k / (rho c)
// (Carslaw & Jaeger, Conduction of Heat in Solids, 2nd ed., 1959, section 2.4). The run's output
// carries the temperature in the VTU states, the heat balance in energy.csv and summary.json.
#include <gmock/gmock.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "abut/io/run.hpp"
#include "abut/solver/simulation.hpp"
#include "test_deck_helpers.hpp"
#include "test_files.hpp"

namespace abut {
namespace {

using testing::file_text;

using ::testing::HasSubstr;
using testing::model_of;
using ::testing::Not;

// Steel's thermal properties in a bar 100 mm long of 2 mm hexahedra; a very soft E so that the
// mechanical step is long (the mechanics play no part: nothing loads the bar). At t = 10 s,
// 2 sqrt(a t) = 22 mm << 100 mm: the far end has not felt the heat yet.
const char* kBar = R"(*UNIT_SYSTEM
SI, C
*TIME
10.0
*OUTPUT
5.0, 1.0
*COMPONENT_BOX
1, 1, 50, 1, 1
0.0, 0.0, 0.0, 0.1, 0.002, 0.002
*MAT_ELASTIC
1, 7800.0, 2.1e5, 0.3, 0, 1
*PROP_THERMAL
"steel"
1, 460.0, 45.0
*PART
"bar"
1, 1
*GEOMETRY_BOX
1
-1.0e-4, -1.0, -1.0, 1.0e-4, 1.0, 1.0
*INITIAL_TEMPERATURE
ALL, 0, 20.0
*BC_TEMPERATURE
G, 1, , 120.0
)";

TEST(DeckThermalRun, HeldEndFollowsTheErfSolution) {
  const Model m = model_of(kBar);
  const double t0 = 20.0, ts = 120.0, end = 10.0;
  const double a = 45.0 / (7800.0 * 460.0);
  Simulation sim(m);
  while (!sim.finished()) sim.advance();
  ASSERT_NEAR(sim.temperature_time(), end, 1e-9 * end);
  EXPECT_GT(sim.cycle(), 10 * sim.thermal_steps());  // sub-cycled: many mechanical steps each
  for (const double x : {0.002, 0.004, 0.008, 0.012, 0.02}) {
    double sum = 0.0;
    int count = 0;
    for (std::size_t i = 0; i < m.mesh.nodes.size(); ++i)
      if (std::abs(m.mesh.nodes.x[i] - x) < 1e-9) {
        sum += sim.temperature()[i];
        ++count;
      }
    ASSERT_EQ(count, 4);
    const double exact = ts + (t0 - ts) * std::erf(x / (2.0 * std::sqrt(a * end)));
    EXPECT_NEAR(sum / count, exact, 0.01 * (ts - t0)) << "x = " << x;
  }
  const HeatBalance b = sim.heat_balance();
  EXPECT_GT(b.stored, 0.0);
  EXPECT_NEAR(b.error(), 0.0, 1e-9 * b.stored);
}

TEST(DeckThermalRun, OutputCarriesTheHeat) {
  const auto dir = std::filesystem::temp_directory_path() / "abut_deck_thermal_run";
  std::filesystem::remove_all(dir);
  Model m = model_of(kBar);
  RunOptions options;
  options.output_dir = dir;
  options.progress = false;
  std::ostringstream log;
  const RunReport report = run_simulation(m, options, log);
  ASSERT_TRUE(report.stable) << report.message;
  EXPECT_THAT(log.str(), HasSubstr("the heat is sub-cycled"));
  EXPECT_THAT(log.str(), HasSubstr("thermal steps"));
  const std::string state = file_text(dir / "states" / "state_0002.vtu");
  EXPECT_THAT(state, HasSubstr("Name=\"temperature\""));
  EXPECT_THAT(state, HasSubstr("Name=\"heat_flow\""));
  const std::string energy = file_text(dir / "energy.csv");
  EXPECT_THAT(
      energy.substr(0, energy.find('\n')),
      HasSubstr(
          ",balance_error,thermal_work,heat_stored,heat_boundary,heat_prescribed,heat_sources,"
          "heat_balance_error"));
  const std::string summary = file_text(dir / "summary.json");
  EXPECT_THAT(summary, HasSubstr("\"thermal\""));
  EXPECT_THAT(summary, HasSubstr("\"mechanical_steps_per_thermal_step\""));
  EXPECT_THAT(summary, HasSubstr("\"heat_balance\""));
  std::filesystem::remove_all(dir);

  // A model without heat keeps the columns and fields it always had.
  const Model plain = model_of(testing::kBoxModel);
  options.output_dir = dir;
  run_simulation(plain, options, log);
  const std::string plain_energy = file_text(dir / "energy.csv");
  EXPECT_EQ(plain_energy.substr(0, plain_energy.find('\n')),
            "time,kinetic,internal,hourglass,contact,friction,eroded,contact_released,"
            "external_work,total,balance_error");
  EXPECT_THAT(file_text(dir / "summary.json"), Not(HasSubstr("\"thermal\"")));
  EXPECT_THAT(file_text(dir / "states" / "state_0000.vtu"), Not(HasSubstr("temperature")));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace abut
