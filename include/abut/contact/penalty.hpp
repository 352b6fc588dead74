#pragma once
// Automatic penalty stiffness of seed 000 (*CONTACT, pfac left empty):
//   pfac = K / L_min * min(1 + (v_max / v_ref)^2, 100),   rigid parts: 1e13 Pa/m * min(...)
// with K the initial bulk modulus of the part, L_min the size of its smallest element,
// v_max the highest initial speed in the model and v_ref = 100 m/s. The seed's steel value
// (1.68e13 Pa/m for 0.03 x 0.03 x 0.01 m elements) fixes L_min = cube root of the smallest
// element volume (seeds/README.md). The SI constants are converted to the deck's units.
#include "abut/core/units.hpp"

namespace abut {

// min(1 + (v_max / v_ref)^2, 100), with v_ref = 100 m/s in the deck's units.
double penalty_speed_factor(double max_initial_speed, UnitSystem units);

// K / L_min * speed factor, L_min = cbrt(smallest_element_volume).
double automatic_penalty(double bulk_modulus, double smallest_element_volume,
                         double max_initial_speed, UnitSystem units);

// 1e13 Pa/m (in deck units) * speed factor.
double rigid_penalty(double max_initial_speed, UnitSystem units);

}  // namespace abut
