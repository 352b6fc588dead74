#include "abut/solver/static_heat.hpp"

#include "abut/core/error.hpp"
#include "solver/contact_settings_of.hpp"
#include "steady_heat_balance.hpp"

namespace abut {

StaticHeat::StaticHeat(const Model& model) : model_(model) {
  for (const ThermalProperties& p : model.thermal.properties)
    if (p.expansion != 0.0)
      throw InputError(p.where,
                       "thermal expansion in static steps is not supported yet (the steady "
                       "temperature of a static analysis does not act on the mechanics): give "
                       "alpha = 0");
  if (!model.thermal.properties.empty() && !model.mesh.cells.empty())
    throw InputError(model.thermal.properties.front().where,
                     "heat conduction in " +
                         std::string(element_label(model.mesh.cells.front().type)) +
                         " elements is not supported yet: only 8-node hexahedra and shells "
                         "conduct heat");
  check_thermal_contacts(model);
  flow_.assign(model.contacts.size(), 0.0);
  no_flow_.assign(model.mesh.nodes.size(), 0.0);
  for (const ContactSpec& spec : model.contacts)
    laws_.push_back(thermal_of(model, spec).conductance);
  if (model.thermal.properties.empty()) return;
  heat_.emplace(model);
  if (!heat_->active()) heat_.reset();
}

std::span<const double> StaticHeat::heat_flow() const {
  return steady_ ? heat_->conduction_rate() : std::span<const double>(no_flow_);
}

void StaticHeat::solve(const StaticSolver& solver, double t) {
  if (!heat_) return;
  steady_ = false;  // until solve_steady returns
  const Nodes& nodes = model_.mesh.nodes;
  const std::size_t n = nodes.size();
  const std::span<const double> u = solver.displacement();
  std::vector<double> x(n), y(n), z(n);
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = nodes.x[i] + u[3 * i];
    y[i] = nodes.y[i] + u[3 * i + 1];
    z[i] = nodes.z[i] + u[3 * i + 2];
  }
  // The conducting points of every pass, and each pass's range among them.
  const std::span<const StaticContact> passes = solver.contacts();
  std::vector<ThermalContactElement> elements;
  std::vector<std::size_t> first(passes.size() + 1, 0);
  for (std::size_t k = 0; k < passes.size(); ++k) {
    if (const auto& law = laws_[solver.contact_of(k)]) {
      const std::vector<ThermalContactElement> e = passes[k].thermal_elements(*law);
      elements.insert(elements.end(), e.begin(), e.end());
    }
    first[k + 1] = elements.size();
  }
  heat_->solve_steady(t, x, y, z, {}, elements);
  // Heat flow G (T_point - T_partner): a contact's first pass has surface 1's points, the second
  // (symmetric) surface 2's, which flow the other way. Per node, the heat each point's conduction
  // brings (-G w_a (T_point - T_partner)) joins the elements' for the balance.
  const std::span<const double> temperature = heat_->temperature();
  std::fill(flow_.begin(), flow_.end(), 0.0);
  std::vector<double> inflow(heat_->conduction_rate().begin(), heat_->conduction_rate().end());
  for (std::size_t k = 0; k < passes.size(); ++k) {
    const std::size_t contact = solver.contact_of(k);
    const double direction = k > 0 && solver.contact_of(k - 1) == contact ? -1.0 : 1.0;
    for (std::size_t e = first[k]; e < first[k + 1]; ++e) {
      const ContactWeights& w = elements[e].weights;
      double difference = 0.0;
      for (int a = 0; a < w.count; ++a)
        difference += w.weights[a] * temperature[static_cast<std::size_t>(w.nodes[a])];
      flow_[contact] += direction * elements[e].conductance * difference;
      for (int a = 0; a < w.count; ++a)
        inflow[static_cast<std::size_t>(w.nodes[a])] -=
            elements[e].conductance * w.weights[a] * difference;
    }
  }
  balance_ = steady_heat_balance(model_, t, x, y, z, temperature, inflow);
  balance_time_ = t;
  steady_ = true;
}

}  // namespace abut
