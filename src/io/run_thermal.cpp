// Thermal output of an explicit run: see run_thermal.hpp.
#include "run_thermal.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace abut::thermal_output {
namespace {

// Mechanical cycles per thermal step over the run (0 before the first thermal step).
double steps_per_thermal_step(const Simulation& sim, std::int64_t cycles) {
  return sim.thermal_steps() > 0
             ? static_cast<double>(cycles) / static_cast<double>(sim.thermal_steps())
             : 0.0;
}

}  // namespace

std::vector<std::string> energy_columns() {
  return {"thermal_work",    "heat_stored",  "heat_boundary",
          "heat_prescribed", "heat_sources", "heat_balance_error"};
}

void append_energy_values(const Simulation& sim, std::vector<CsvHistory::Value>& values) {
  const HeatBalance b = sim.heat_balance();
  values.emplace_back(sim.energies().thermal_work);
  for (const double v : {b.stored, b.boundary, b.prescribed, b.sources, b.error()})
    values.emplace_back(v);
}

void write_summary(JsonWriter& json, const Simulation& sim, std::int64_t cycles) {
  const HeatBalance b = sim.heat_balance();
  json.key("thermal").begin_object();
  json.member("thermal_steps", sim.thermal_steps());
  json.member("thermal_stable_step", sim.thermal_stable_step());
  json.member("mechanical_steps_per_thermal_step", steps_per_thermal_step(sim, cycles));
  json.key("heat_balance").begin_object();
  json.member("stored", b.stored).member("boundary", b.boundary);
  json.member("prescribed", b.prescribed).member("sources", b.sources);
  json.member("error", b.error());
  json.member("largest", b.largest).member("relative_error", b.relative_error());
  json.end_object();
  json.end_object();
}

// Simulation plans thermal steps of at most 0.9 of the elements' thermal stable step, shorter where
// a contact conducts fast (Simulation::Impl::thermal_step_limit); the temperatures advance with
// every mechanical step.
std::string start_line(const Simulation& sim) {
  const double thermal = sim.thermal_stable_step();
  const double mechanical = sim.initial_time_step();
  const std::string ratio = thermal >= mechanical
                                ? fmt::format("one thermal step per {:.0f} mechanical steps or so",
                                              std::floor(0.9 * thermal / mechanical))
                                : fmt::format("{:.0f} thermal steps per mechanical step or so",
                                              std::ceil(mechanical / (0.9 * thermal)));
  return fmt::format(
      "abut: heat: thermal stable step of the elements {:.4g} = {:.3g} x the mechanical step; the "
      "heat is sub-cycled: {} (shorter thermal steps where a contact conducts fast); the "
      "temperatures advance with "
      "every mechanical step\n",
      thermal, thermal / mechanical, ratio);
}

std::string end_line(const Simulation& sim, std::int64_t cycles) {
  const HeatBalance b = sim.heat_balance();
  return fmt::format(
      "abut: heat: {} thermal steps ({:.3g} mechanical steps per thermal step), heat stored "
      "{:.6g}, heat balance error {:.3g} ({:.3f}%)\n",
      sim.thermal_steps(), steps_per_thermal_step(sim, cycles), b.stored, b.error(),
      100.0 * b.relative_error());
}

}  // namespace abut::thermal_output
