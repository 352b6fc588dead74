#include <algorithm>
#include <string>

#include "abut/core/error.hpp"
#include "abut/solver/heat.hpp"

namespace abut {

bool is_thermal_part(const Model& model, std::int64_t part_id) {
  const Part* part = model.find_part(part_id);
  if (!part) return false;
  const Material* material = model.find_material(part->material_id);
  return material && material->thermal_id != 0;
}

std::vector<std::uint8_t> thermal_node_flags(const Model& model) {
  const Mesh& mesh = model.mesh;
  std::vector<std::uint8_t> flags(mesh.nodes.size(), 0);
  const auto mark = [&](std::span<const std::int32_t> nodes) {
    for (const std::int32_t n : nodes) flags[static_cast<std::size_t>(n)] = 1;
  };
  for (std::size_t h = 0; h < mesh.hex_count(); ++h)
    if (is_thermal_part(model, mesh.hex_part[h])) mark(mesh.hexes[h]);
  for (std::size_t s = 0; s < mesh.shell_count(); ++s)
    if (is_thermal_part(model, mesh.shell_part[s])) mark(mesh.shells[s]);
  return flags;
}

void check_thermal_contacts(const Model& model) {
  std::vector<std::uint8_t> thermal;
  for (const ContactSpec& spec : model.contacts) {
    if (!spec.exchanges_heat()) continue;
    if (thermal.empty()) thermal = thermal_node_flags(model);
    const std::string what = spec.friction_heat ? "friction heat" : "the contact conductance";
    if (std::find(thermal.begin(), thermal.end(), 1) == thermal.end())
      throw InputError(model.place_of(spec, spec.friction_heat ? "friction_heat"
                                            : spec.conductance ? "conductance"
                                                               : "thermal"),
                       what +
                           " needs a temperature field: give the materials of the "
                           "contacting parts thermal properties (" +
                           model.sources.words("thermal_properties") + ")");
    for (const EntityRef& surface : {spec.surface1, spec.surface2})
      for (const std::int32_t i : model.nodes_of(surface))
        if (!thermal[static_cast<std::size_t>(i)])
          throw InputError(spec.where,
                           what + " needs a temperature on both surfaces, but node " +
                               std::to_string(model.mesh.nodes.id[static_cast<std::size_t>(i)]) +
                               " of the contact has none: give the material of its part thermal "
                               "properties (thpid)");
  }
}

}  // namespace abut
