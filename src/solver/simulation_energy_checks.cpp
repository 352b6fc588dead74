// A run never ends "completed" with energies that are not numbers (issue 28). The nodes' check
// (non-finite coordinates or forces, Simulation::Impl::drift) does not see an energy that
// overflows while the coordinates stay finite: a mass of 1e300 kg moving at 1e5 m/s, an initial
// velocity of 1e100. The kinetic energy is a sum of squares (kick()): below zero it is corrupt.
#include <fmt/format.h>

#include <cmath>
#include <utility>

#include "simulation_impl.hpp"

namespace abut {

std::string Simulation::Impl::energy_fault() const {
  const Energies& e = energy;
  const std::pair<const char*, double> quantities[] = {
      {"kinetic energy", e.kinetic},
      {"internal energy", e.internal},
      {"hourglass energy", e.hourglass},
      {"contact energy", e.contact},
      {"friction energy", e.friction},
      {"eroded energy", e.eroded},
      {"released contact energy", e.contact_released},
      {"external work", e.external_work},
      {"thermal expansion work", e.thermal_work},
      {"total energy", e.total()},
      {"energy balance (total - total at t = 0 - external work - thermal expansion work)",
       conserved_total() - total0 - e.external_work - e.thermal_work}};
  for (const auto& [name, value] : quantities)
    if (!std::isfinite(value)) return fmt::format("the {} is {}", name, value);
  if (e.kinetic < 0.0) return fmt::format("the kinetic energy is negative ({:.6g})", e.kinetic);
  return {};
}

void Simulation::Impl::check_initial_energies() const {
  for (const PartInfo& p : parts) {
    double kinetic = 0.0, speed = 0.0;
    for (std::size_t k = 0; k < p.nodes.size(); ++k) {
      const std::int32_t i = p.nodes[k];
      const double v2 = vx[i] * vx[i] + vy[i] * vy[i] + vz[i] * vz[i];
      kinetic += 0.5 * p.node_mass[k] * v2;
      speed = std::max(speed, std::sqrt(v2));
    }
    if (std::isfinite(kinetic)) continue;
    const Part* part = model.find_part(p.part_id);
    throw InputError(
        part ? part->where : SourceLocation{},
        fmt::format("part {} has kinetic energy {} at the start (mass {:.4g}, "
                    "fastest node {:.4g}); expected a finite number: check the "
                    "density and {}",
                    p.part_id, kinetic, p.mass, speed, model.sources.words("initial_velocity")));
  }
  if (const std::string fault = energy_fault(); !fault.empty())
    throw InputError(fault + " at the start; check the densities, " +
                     model.sources.words("initial_velocity") + " and the contact stiffness");
}

}  // namespace abut
