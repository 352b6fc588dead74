#pragma once
// The contacts of a model for the static solver: each ContactSpec (*CONTACT PAIR of an .inp deck,
// *CONTACT of abut's own) becomes one pass of the contact library's StaticContact (surface 1's
// points against surface 2), or two when the contact is symmetric (also surface 2's points
// against surface 1, each with weight 1/2, as the explicit interface does). Features the static
// solver does not have are InputErrors at their card, never ignored.
#include <cstddef>
#include <vector>

#include "abut/contact/removed_nodes.hpp"
#include "abut/contact/static_contact.hpp"
#include "abut/model/model.hpp"

namespace abut::detail {

struct StaticContacts {
  std::vector<StaticContact> passes;
  std::vector<std::size_t> contact_of;  // per pass: its index in Model::contacts
};

// `tied_nodes`: the exact ties' nodes, which contacts with tied_nodes REMOVE drop.
StaticContacts make_static_contacts(const Model& model, const RemovedNodes& tied_nodes);

}  // namespace abut::detail
