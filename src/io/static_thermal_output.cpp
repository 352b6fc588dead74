// Thermal output of a static run: see static_thermal_output.hpp.
#include "static_thermal_output.hpp"

#include <fmt/format.h>

namespace abut::static_thermal_output {

std::vector<std::string> energy_columns() {
  return {"heat_flow_boundary_in", "heat_flow_boundary_out", "heat_flow_prescribed_in",
          "heat_flow_prescribed_out", "heat_flow_balance_error"};
}

void append_energy_values(const StaticHeat& heat, std::vector<CsvHistory::Value>& values) {
  const SteadyHeatBalance& b = heat.balance();
  for (const double v :
       {b.boundary_in, b.boundary_out, b.prescribed_in, b.prescribed_out, b.error()})
    values.emplace_back(v);
}

void write_summary(JsonWriter& json, const StaticHeat& heat) {
  json.key("thermal").begin_object();
  json.member("steady_state", heat.steady());
  if (heat.steady()) {
    const SteadyHeatBalance& b = heat.balance();
    json.member("time", heat.balance_time());
    json.key("heat_flow_balance").begin_object();
    json.member("boundary_in", b.boundary_in).member("boundary_out", b.boundary_out);
    json.member("prescribed_in", b.prescribed_in).member("prescribed_out", b.prescribed_out);
    json.member("error", b.error()).member("relative_error", b.relative_error());
    json.member("heat_flows", b.heat_flows);
    json.end_object();
  }
  json.end_object();
}

std::string end_line(const StaticHeat& heat) {
  if (!heat.steady()) return "abut: heat: no steady temperature was found\n";
  const SteadyHeatBalance& b = heat.balance();
  if (!b.heat_flows)
    return fmt::format(
        "abut: heat: no heat flows at t = {:.6g} (the temperatures agree to round-off); balance "
        "error {:.3g}\n",
        heat.balance_time(), b.error());
  return fmt::format(
      "abut: heat: steady heat flow at t = {:.6g}: faces in {:.6g}, out {:.6g}; held temperatures "
      "in {:.6g}, out {:.6g}; balance error {:.3g} ({:.3g}% of the largest flow)\n",
      heat.balance_time(), b.boundary_in, b.boundary_out, b.prescribed_in, b.prescribed_out,
      b.error(), 100.0 * b.relative_error());
}

}  // namespace abut::static_thermal_output
