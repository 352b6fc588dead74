// The views of a Gmsh mesh that the dialects' readers share (gmsh_mesh.hpp): groups of a block,
// names of groups, solid nodes in abut's order, corners of face elements.
#include "abut/io/gmsh_mesh.hpp"

namespace abut::gmsh {

std::vector<int> block_groups(const MshMesh& m, const MshElementBlock& block) {
  if (m.entity_groups.empty()) {
    // Points' and curves' tags overlap the surfaces': only volumes and surfaces stand in.
    if (block.dim >= 2) return {block.entity};
    return {};
  }
  const auto it = m.entity_groups.find({block.dim, block.entity});
  return it == m.entity_groups.end() ? std::vector<int>{} : it->second;
}

std::string group_name(const MshMesh& m, int dim, int tag) {
  const auto it = m.group_names.find({dim, tag});
  return it == m.group_names.end() ? "" : it->second;
}

std::string group_label(const MshMesh& m, int dim, int tag) {
  static const char* const kinds[] = {"point", "curve", "surface", "volume"};
  std::string s = m.entity_groups.empty() ? "" : "physical ";
  s += kinds[dim] + std::string(" ") + std::to_string(tag);
  const std::string name = group_name(m, dim, tag);
  if (!name.empty()) s += " \"" + name + "\"";
  return s + " of " + m.file;
}

std::vector<std::int64_t> solid_nodes(const MshElementBlock& block, std::size_t e) {
  const GmshElementType& type = *element_type(block.type);
  const std::span<const std::int8_t> order = gmsh_node_order(*type.cell);
  const std::size_t first = e * static_cast<std::size_t>(type.nodes);
  std::vector<std::int64_t> nodes(order.size());
  for (std::size_t k = 0; k < order.size(); ++k)
    nodes[k] = block.nodes[first + static_cast<std::size_t>(order[k])];
  return nodes;
}

std::array<std::int64_t, 4> face_corners(const MshElementBlock& block, std::size_t e) {
  const GmshElementType& type = *element_type(block.type);
  // Gmsh's triangles and quadrilaterals list their corners first.
  const std::size_t corners = type.number == 2 || type.number == 9 ? 3 : 4;
  const std::size_t first = e * static_cast<std::size_t>(type.nodes);
  std::array<std::int64_t, 4> c{};
  for (std::size_t k = 0; k < 4; ++k) c[k] = block.nodes[first + std::min(k, corners - 1)];
  return c;
}

}  // namespace abut::gmsh
