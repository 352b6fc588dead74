#include "abut/contact/penalty.hpp"

#include <algorithm>
#include <cmath>

namespace abut {

double penalty_speed_factor(double max_initial_speed, UnitSystem units) {
  const double reference_speed = from_si(units, 100.0, 1, 0, -1);  // 100 m/s
  const double r = max_initial_speed / reference_speed;
  return std::min(1.0 + r * r, 100.0);
}

double automatic_penalty(double bulk_modulus, double smallest_element_volume,
                         double max_initial_speed, UnitSystem units) {
  const double l_min = std::cbrt(smallest_element_volume);
  return bulk_modulus / l_min * penalty_speed_factor(max_initial_speed, units);
}

double rigid_penalty(double max_initial_speed, UnitSystem units) {
  const double rigid_si = 1e13;  // Pa/m = kg m^-2 s^-2
  return from_si(units, rigid_si, -2, 1, -2) * penalty_speed_factor(max_initial_speed, units);
}

}  // namespace abut
