#include "abut/solver/contact_surfaces.hpp"

#include <algorithm>
#include <limits>
#include <map>
#include <string>

#include "abut/core/error.hpp"

namespace abut {

ContactSurface contact_surface(const Mesh& mesh, std::span<const SkinFace> faces,
                               const std::function<double(const SkinFace&)>& penalty_of_face,
                               const std::function<double(std::int64_t part)>& bulk_of_part) {
  ContactSurface s;
  s.facets.reserve(faces.size());
  for (const SkinFace& f : faces) {
    const double bulk = bulk_of_part ? bulk_of_part(f.part) : 0.0;
    const double volume =
        bulk_of_part ? hex_volume(mesh.nodes, mesh.hexes[static_cast<std::size_t>(f.hex)]) : 0.0;
    s.add(f.nodes, f.part, penalty_of_face(f), f.thickness, bulk, volume);
  }
  return s;
}

double element_penalty(double element_step, double lightest_node, double face_area) {
  const double omega2 = 4.0 / (element_step * element_step);
  return kElementPenaltyFraction * lightest_node * omega2 / (2.0 * face_area);
}

double smallest_element_volume(const Mesh& mesh, std::int64_t part) {
  // Per user element: the hexes *CHANGE_P-ORDER made of one order-p element count together, so
  // L_min is the size of the element as defined (seed 000 computes it for its cubic elements).
  std::map<std::int64_t, double> volume_of_element;
  for (std::size_t h = 0; h < mesh.hexes.size(); ++h)
    if (mesh.hex_part[h] == part)
      volume_of_element[mesh.element_of(h)] += hex_volume(mesh.nodes, mesh.hexes[h]);
  if (volume_of_element.empty())
    throw InputError("part " + std::to_string(part) +
                     " has no solid elements, so its automatic contact penalty is undefined");
  double smallest = std::numeric_limits<double>::infinity();
  for (const auto& [element, volume] : volume_of_element) smallest = std::min(smallest, volume);
  return smallest;
}

}  // namespace abut
