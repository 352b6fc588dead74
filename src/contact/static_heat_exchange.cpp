// Thermal contact for steady heat (issue 11): the paired points of the last evaluation as heat
// conductors, G = h(p, g) A, with h from the contact's conductance law (laws/thermal.hpp) at the
// point's pressure and gap, as the explicit interface conducts (heat_exchange.cpp).
#include <algorithm>

#include "abut/contact/static_contact.hpp"

namespace abut {

std::vector<ThermalContactElement> StaticContact::thermal_elements(
    const ConductanceLaw& law) const {
  std::vector<ThermalContactElement> out;
  for (const StaticContactPoint& point : points_) {
    if (!point.paired) continue;
    // Touching within round-off counts as closed, as in the explicit interface (settings.hpp).
    const double touching = kTouchingGapFraction * main_.thickness[point.partner];
    const double gap = point.gap <= touching ? std::min(point.gap, 0.0) : point.gap;
    const double h = conductance(law, point.pressure, gap);
    // A negative or undefined conductance (a user function) conducts nothing.
    if (!(h > 0.0) || !(point.area > 0.0)) continue;
    out.push_back({point.weights, h * point.area});
  }
  return out;
}

}  // namespace abut
