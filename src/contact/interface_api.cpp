// ContactInterface: the host's handle, forwarding to its state (interface_impl.hpp). One call
// through a pointer per operation; the work is in the operations themselves.
#include <stdexcept>
#include <utility>

#include "abut/contact/interface.hpp"
#include "abut/core/state_archive.hpp"
#include "interface_impl.hpp"

namespace abut {

ContactInterface::ContactInterface(ContactSettings settings, ContactSurface surface1,
                                   ContactSurface surface2, std::span<const double> node_mass,
                                   const ContactInput& initial,
                                   std::span<const std::int32_t> secondary_nodes)
    : impl_(std::make_unique<InterfaceImpl>(std::move(settings), std::move(surface1),
                                            std::move(surface2), node_mass, initial,
                                            secondary_nodes)) {}
ContactInterface::ContactInterface(ContactInterface&&) noexcept = default;
ContactInterface& ContactInterface::operator=(ContactInterface&&) noexcept = default;
ContactInterface::~ContactInterface() = default;

void ContactInterface::apply(const ContactInput& in, ContactForces& out) { impl_->apply(in, out); }
double ContactInterface::conduct_heat(std::span<const double> temperature, double duration,
                                      std::span<double> heat) {
  return impl_->conduct_heat(temperature, duration, heat);
}
void ContactInterface::book_conducted_heat(double duration) {
  impl_->book_conducted_heat(duration);
}
void ContactInterface::erode(std::span<const std::uint8_t> eroded) { impl_->erode(eroded); }
const ContactStats& ContactInterface::stats() const { return impl_->stats(); }
void ContactInterface::set_enabled(bool on) { impl_->set_enabled(on); }
bool ContactInterface::enabled() const { return impl_->enabled(); }
void ContactInterface::mark_secondary_nodes_in_contact(std::span<std::uint8_t> touched) const {
  impl_->mark_secondary_nodes_in_contact(touched);
}
double ContactInterface::initial_stable_step() const { return impl_->initial_stable_step(); }
std::span<const double> ContactInterface::wear() const { return impl_->wear(); }
std::span<const double> ContactInterface::nodal_pressure() const { return impl_->nodal_pressure(); }
std::vector<PairStiffness> ContactInterface::pair_stiffness() const {
  return impl_->pair_stiffness();
}
bool ContactInterface::self_contact() const { return impl_->self_contact(); }
std::size_t ContactInterface::point_count() const { return impl_->point_count(); }
std::size_t ContactInterface::released_points() const { return impl_->released_points(); }
std::span<const std::int32_t> ContactInterface::surface_nodes() const {
  return impl_->surface_nodes();
}
std::vector<DeepStart> ContactInterface::deep_initial_points(const ContactInput& initial) const {
  return impl_->deep_initial_points(initial);
}
std::size_t ContactInterface::tied_points() const { return impl_->tied_points(); }
std::vector<ContactInterface::NodeTie> ContactInterface::node_ties() const {
  return impl_->node_ties();
}
std::size_t ContactInterface::broad_phase_builds() const { return impl_->broad_phase_builds(); }
std::size_t ContactInterface::contact_edges() const { return impl_->contact_edges(); }
double ContactInterface::search_margin() const { return impl_->search_margin(); }
void ContactInterface::archive(StateArchive& a) { impl_->archive(a); }
std::vector<char> ContactInterface::save_state() const {
  StateArchive a = StateArchive::for_saving();
  impl_->archive(a);  // saving reads the state only
  return a.bytes();
}
void ContactInterface::restore_state(std::vector<char> bytes) {
  StateArchive a = StateArchive::for_loading(std::move(bytes));
  impl_->archive(a);
  if (!a.exhausted())
    throw StateArchiveError("contact state: bytes left over; not the state of this interface");
}

}  // namespace abut
