#include "abut/contact/penalty.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>

#include "abut/core/error.hpp"
#include "abut/mesh/skin.hpp"

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

double smallest_element_volume(const Mesh& mesh, std::int64_t part) {
  // Per user element: the hexes *CHANGE_P-ORDER made of one order-p element count together, so
  // L_min is the size of the element as defined (seed 000 computes it for its cubic elements).
  std::map<std::int64_t, double> volume_of_element;
  for (std::size_t h = 0; h < mesh.hexes.size(); ++h)
    if (mesh.hex_part[h] == part) volume_of_element[mesh.element_of(h)] += hex_volume(mesh.nodes, mesh.hexes[h]);
  if (volume_of_element.empty())
    throw InputError("part " + std::to_string(part) +
                     " has no solid elements, so its automatic contact penalty is undefined");
  double smallest = std::numeric_limits<double>::infinity();
  for (const auto& [element, volume] : volume_of_element) smallest = std::min(smallest, volume);
  return smallest;
}

}  // namespace abut
