#pragma once
// The thermal output of an explicit run (issue 11), for run.cpp: the extra energy.csv columns,
// the `thermal` object of summary.json and the log lines. Only for thermal models, so the files
// of the other runs keep their columns.
#include <cstdint>
#include <string>
#include <vector>

#include "abut/io/csv_history.hpp"
#include "abut/io/json_writer.hpp"
#include "abut/solver/simulation.hpp"

namespace abut::thermal_output {

// The run has a temperature field (some hexahedra have thermal properties).
inline bool active(const Simulation& sim) { return !sim.temperature().empty(); }

// thermal_work (the thermal expansion's work on the mechanics, Energies::thermal_work), then
// heat_stored, heat_boundary, heat_prescribed, heat_sources, heat_balance_error [energy].
std::vector<std::string> energy_columns();
void append_energy_values(const Simulation& sim, std::vector<CsvHistory::Value>& values);

// "thermal": {thermal_steps, thermal_stable_step, mechanical_steps_per_thermal_step,
// heat_balance: {stored, boundary, prescribed, sources, error, largest, relative_error}}.
void write_summary(JsonWriter& json, const Simulation& sim, std::int64_t cycles);

// Before the run: the elements' thermal stable step and how the heat is sub-cycled.
std::string start_line(const Simulation& sim);
// After the run: the thermal steps taken and the heat balance.
std::string end_line(const Simulation& sim, std::int64_t cycles);

}  // namespace abut::thermal_output
