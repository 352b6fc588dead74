#pragma once
// The columns of contact.csv that explicit and static runs share (README, "Using it"), and whether
// a model's contacts carry heat (then each run adds its heat columns).
#include <string>
#include <vector>

#include "abut/model/model.hpp"

namespace abut {

inline std::vector<std::string> contact_history_columns() {
  return {"contact",
          "fx",
          "fy",
          "fz",
          "normal_force",
          "tangential_force",
          "energy",
          "friction_energy",
          "max_penetration",
          "active_points"};
}

inline bool contacts_exchange_heat(const Model& model) {
  for (const ContactSpec& c : model.contacts)
    if (c.exchanges_heat()) return true;
  return false;
}

}  // namespace abut
