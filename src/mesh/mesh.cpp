#include "abut/mesh/mesh.hpp"

#include <algorithm>

namespace abut {

std::int64_t Mesh::next_node_id() const {
  return nodes.id.empty() ? 1 : *std::max_element(nodes.id.begin(), nodes.id.end()) + 1;
}

std::int64_t Mesh::next_hex_id() const {
  return hex_id.empty() ? 1 : *std::max_element(hex_id.begin(), hex_id.end()) + 1;
}

std::int64_t Mesh::next_shell_id() const {
  return shell_id.empty() ? 1 : *std::max_element(shell_id.begin(), shell_id.end()) + 1;
}

void Mesh::add_shell(std::int64_t id, std::int64_t part, const Quad4& nodes_of_shell) {
  shells.push_back(nodes_of_shell);
  shell_id.push_back(id);
  shell_part.push_back(part);
}

void Mesh::add_hex(std::int64_t id, std::int64_t part, const Hex8& nodes_of_hex, std::int32_t shape,
                   const HexCell& cell, std::int64_t element) {
  // Hexes appended by code that does not know hex_shape/hex_cell leave them short: pad first.
  hex_shape.resize(hexes.size(), -1);
  hex_cell.resize(hexes.size());
  for (std::size_t h = hex_element.size(); h < hexes.size(); ++h) hex_element.push_back(hex_id[h]);
  hex_element.push_back(element != 0 ? element : id);
  hexes.push_back(nodes_of_hex);
  hex_id.push_back(id);
  hex_part.push_back(part);
  hex_shape.push_back(shape);
  hex_cell.push_back(cell);
}

}  // namespace abut
