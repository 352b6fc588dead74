// What the sensors switch in an explicit run (seed 004 /INTER/TYPE25 sens_ID, IBC): contacts on or
// off, decided before every apply of the contacts at t^n, and the fixed directions of a contact's
// secondary nodes released at their first contact, after that apply (so the kick that follows
// already lets them move with the contact force). A released direction stays released. The
// reactions of the constraints leave the external work as they stop (kick: m dv - dt f_int over
// every node), so the energy balance needs nothing more.
#include <fmt/format.h>

#include "simulation_impl.hpp"

namespace abut {

void Simulation::Impl::setup_sensors() {
  sensors = std::make_unique<SensorSet>(model);
  bool releases = false;
  for (const ContactSpec& c : model.contacts) releases = releases || c.release_bc != 0;
  if (!releases) return;
  released.assign(n_nodes, 0);
  touched.assign(n_nodes, 0);
  constrained = node_fixed;
  for (const NodalMotion& nm : bc.nodal)
    for (const std::int32_t i : nm.nodes)
      constrained[static_cast<std::size_t>(i)] |= nm.source->fixed_translation;
}

void Simulation::Impl::switch_contacts() {
  if (sensors->empty()) return;
  sensors->update(t, x, y, z, contacts->reports(), messages);
  for (std::size_t c = 0; c < model.contacts.size(); ++c) {
    const ContactSpec& spec = model.contacts[c];
    if (!spec.sensor) continue;
    const bool on = sensors->on(*spec.sensor, t);
    contacts->set_enabled(c, spec.sensor_switches_off ? !on : on);
  }
}

void Simulation::Impl::release_at_impact() {
  if (released.empty()) return;
  static constexpr const char* kDirections[] = {"",  "x",    "y",    "x, y",
                                                "z", "x, z", "y, z", "x, y, z"};
  for (std::size_t c = 0; c < model.contacts.size(); ++c) {
    const ContactSpec& spec = model.contacts[c];
    if (!spec.release_bc) continue;
    // Only the contacts' surface nodes can be marked: clear and scan those, not the whole mesh.
    const std::span<const std::int32_t> nodes = contacts->surface_nodes();
    for (const std::int32_t i : nodes) touched[i] = 0;
    contacts->mark_secondary_nodes_in_contact(c, touched);
    std::size_t count = 0;
    for (const std::int32_t i : nodes) {
      if (!touched[i]) continue;
      // Only the directions the node is held in count for the log; every one is released.
      if (constrained[i] & spec.release_bc & ~released[i]) ++count;
      released[i] |= spec.release_bc;
    }
    if (count > 0)
      messages.push_back(fmt::format(
          "abut: contact {} released the {} boundary conditions of {} node{} at impact, t = "
          "{:.6g}",
          spec.id, kDirections[spec.release_bc & 7u], count, count == 1 ? "" : "s", t));
  }
}

double Simulation::sensor_trigger_time(std::int64_t id) const {
  return impl_->sensors->triggered_at(id);
}

std::vector<std::string> Simulation::take_messages() {
  std::vector<std::string> out;
  out.swap(impl_->messages);
  return out;
}

}  // namespace abut
