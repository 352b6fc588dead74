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

}  // namespace abut
