#include "abut/mesh/mesh.hpp"

#include <algorithm>
#include <utility>

namespace abut {

std::int64_t Mesh::next_node_id() const {
  return nodes.id.empty() ? 1 : *std::max_element(nodes.id.begin(), nodes.id.end()) + 1;
}

std::int64_t Mesh::next_hex_id() const {
  std::int64_t next = hex_id.empty() ? 1 : *std::max_element(hex_id.begin(), hex_id.end()) + 1;
  for (const CellBlock& b : cells)
    for (const std::int64_t id : b.id) next = std::max(next, id + 1);
  return next;
}

std::size_t Mesh::solid_count() const {
  std::size_t n = hexes.size();
  for (const CellBlock& b : cells) n += b.size();
  return n;
}

SolidRef Mesh::solid(std::size_t e) const {
  if (e < hexes.size()) return {CellType::hex8, hexes[e], hex_id[e], hex_part[e]};
  e -= hexes.size();
  for (const CellBlock& b : cells) {
    if (e < b.size()) return {b.type, b.cell(e), b.id[e], b.part[e]};
    e -= b.size();
  }
  return {};
}

void Mesh::add_cell(CellType type, std::int64_t id, std::int64_t part,
                    std::span<const std::int32_t> nodes_of_cell) {
  auto block =
      std::find_if(cells.begin(), cells.end(), [&](const CellBlock& b) { return b.type == type; });
  if (block == cells.end()) {
    cells.push_back({type, {}, {}, {}});
    block = cells.end() - 1;
  }
  block->nodes.insert(block->nodes.end(), nodes_of_cell.begin(), nodes_of_cell.end());
  block->id.push_back(id);
  block->part.push_back(part);
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

std::vector<std::uint8_t> Mesh::nodes_in_elements() const {
  std::vector<std::uint8_t> used(nodes.size(), 0);
  for (std::size_t e = 0; e < solid_count(); ++e)
    for (const std::int32_t node : solid(e).nodes) used[static_cast<std::size_t>(node)] = 1;
  for (const Quad4& q : shells)
    for (const std::int32_t node : q) used[static_cast<std::size_t>(node)] = 1;
  return used;
}

void Mesh::take_hexes(Mesh&& from) {
  hexes = std::move(from.hexes);
  hex_id = std::move(from.hex_id);
  hex_part = std::move(from.hex_part);
  hex_shape = std::move(from.hex_shape);
  hex_cell = std::move(from.hex_cell);
  hex_element = std::move(from.hex_element);
}

}  // namespace abut
