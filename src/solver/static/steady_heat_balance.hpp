#pragma once
// The heat balance of a steady temperature field (SteadyHeatBalance, static_heat.hpp) from the
// heat flowing to each node. The face loads are evaluated again from the model at the solved
// temperature, not taken from the solver's right-hand side, and each held node's reaction is what
// closes its equation; so the balance checks the solve: its error is the sum of the free nodes'
// residuals, plus whatever the conduction or a contact would create (nothing, to round-off).
#include <span>

#include "abut/model/model.hpp"
#include "abut/solver/static_heat.hpp"

namespace abut {

// `inflow`: per node the heat flowing in by conduction through the elements and through the
// contacts [power]; `temperature` the steady field at time t on the shape x, y, z.
SteadyHeatBalance steady_heat_balance(const Model& model, double t, std::span<const double> x,
                                      std::span<const double> y, std::span<const double> z,
                                      std::span<const double> temperature,
                                      std::span<const double> inflow);

}  // namespace abut
