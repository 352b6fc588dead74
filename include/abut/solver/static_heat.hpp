#pragma once
// The temperature of a static analysis (issue 11): at each converged state, the steady heat
// conduction of the model's thermal loads at the state's time on its deformed shape, with the
// conductance of its thermal contacts at their current pressures and gaps (OptiStruct's
// contact-based thermal analysis, seed 003; the laws of *CONTACT fid_thermal and
// *CONTACT_THERMAL). One-way: the temperature does not act back on the static mechanics, so
// thermal expansion is an input error here, and so is friction heat (a steady state has no time).
#include <optional>
#include <span>
#include <vector>

#include "abut/contact/laws/thermal.hpp"
#include "abut/model/model.hpp"
#include "abut/solver/heat.hpp"
#include "abut/solver/static_solver.hpp"

namespace abut {

// The heat balance of one steady state [power], positive into the model: the heat that enters
// and the heat that leaves through the face loads (flux and convection) and through the held
// temperatures (their reaction heat flow), each summed over the nodes where it enters or leaves,
// so that no term is a difference of large flows (two held ends: prescribed in = -out = the heat
// through the model). A steady state stores nothing and has no heat sources (friction and
// plastic heat need time), so the four sum to zero up to the solve's accuracy; the contacts carry
// heat within the model (StaticHeat::contact_heat_flow) and are no term of it.
struct SteadyHeatBalance {
  double boundary_in = 0.0, boundary_out = 0.0;
  double prescribed_in = 0.0, prescribed_out = 0.0;
  // False when no heat flows: the temperatures of the thermal nodes and the ambient temperatures
  // of the convecting faces agree to 1e-9 of their size and no flux acts. The flows are then
  // round-off, and so is the largest of them, which cannot scale the error.
  bool heat_flows = true;
  double error() const { return boundary_in + boundary_out + prescribed_in + prescribed_out; }
  // The largest of the four terms, the error's scale.
  double largest_flow() const;
  // error() / largest_flow(); 0 when no heat flows.
  double relative_error() const;
};

class StaticHeat {
 public:
  // InputError at the *PROP_THERMAL with an expansion coefficient, or at a *CONTACT whose
  // surfaces carry no temperature.
  explicit StaticHeat(const Model& model);

  bool active() const { return heat_.has_value(); }  // the model has thermal parts
  // The steady temperature of the state `solver` has converged to, at time t.
  void solve(const StaticSolver& solver, double t);
  std::span<const double> temperature() const { return heat_->temperature(); }
  // Whether the last solve found a steady temperature (the reference state may have none: its
  // temperature is then the initial one and it has no heat flows).
  bool steady() const { return steady_; }
  // The heat flowing into each node by conduction through the elements at the last steady state,
  // -(K T)_a [power], as the explicit run's `heat_flow`; zero without one. Steady, it is minus
  // the heat that the node's face loads, held temperature and contacts bring to it.
  std::span<const double> heat_flow() const;
  // The balance of the last steady state and its time.
  const SteadyHeatBalance& balance() const { return balance_; }
  double balance_time() const { return balance_time_; }
  // The heat flowing through each contact of Model::contacts from surface 1 to surface 2 in the
  // last solve [power]; 0 for a contact without conductance.
  std::span<const double> contact_heat_flow() const { return flow_; }

 private:
  const Model& model_;
  std::optional<HeatSolver> heat_;
  std::vector<std::optional<ConductanceLaw>> laws_;  // per contact
  std::vector<double> flow_;                         // per contact
  bool steady_ = false;
  SteadyHeatBalance balance_;
  double balance_time_ = 0.0;
  std::vector<double> no_flow_;  // zero per node: heat_flow() without a steady state
};

}  // namespace abut
