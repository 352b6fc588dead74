#pragma once
// The thermal output of a static run (run_static.cpp), the steady counterpart of run_thermal.hpp:
// a steady state stores no heat and has no time integral, so its balance is in power. Only for
// thermal models, so the files of the other static runs keep their columns.
#include <string>
#include <vector>

#include "abut/io/csv_history.hpp"
#include "abut/io/json_writer.hpp"
#include "abut/solver/static_heat.hpp"

namespace abut::static_thermal_output {

// heat_flow_boundary_in, heat_flow_boundary_out, heat_flow_prescribed_in,
// heat_flow_prescribed_out, heat_flow_balance_error [power] (SteadyHeatBalance).
std::vector<std::string> energy_columns();
void append_energy_values(const StaticHeat& heat, std::vector<CsvHistory::Value>& values);

// "thermal": {steady_state; with one, time and heat_flow_balance: {boundary_in, boundary_out,
// prescribed_in, prescribed_out, error, relative_error, heat_flows}} of the last state.
void write_summary(JsonWriter& json, const StaticHeat& heat);

// After the run: the balance of the last steady state.
std::string end_line(const StaticHeat& heat);

}  // namespace abut::static_thermal_output
