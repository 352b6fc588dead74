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
#include "abut/solver/heat.hpp"
#include "abut/solver/model.hpp"
#include "abut/solver/static_solver.hpp"

namespace abut {

class StaticHeat {
 public:
  // InputError at the *PROP_THERMAL with an expansion coefficient, or at a *CONTACT whose
  // surfaces carry no temperature.
  explicit StaticHeat(const Model& model);

  bool active() const { return heat_.has_value(); }  // the model has thermal parts
  // The steady temperature of the state `solver` has converged to, at time t.
  void solve(const StaticSolver& solver, double t);
  std::span<const double> temperature() const { return heat_->temperature(); }
  // The heat flowing through each contact of Model::contacts from surface 1 to surface 2 in the
  // last solve [power]; 0 for a contact without conductance.
  std::span<const double> contact_heat_flow() const { return flow_; }

 private:
  const Model& model_;
  std::optional<HeatSolver> heat_;
  std::vector<std::optional<ConductanceLaw>> laws_;  // per contact
  std::vector<double> flow_;                         // per contact
};

}  // namespace abut
