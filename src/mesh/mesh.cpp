#include "abut/mesh/mesh.hpp"

#include <algorithm>

namespace abut {

std::int64_t Mesh::next_node_id() const {
  return nodes.id.empty() ? 1 : *std::max_element(nodes.id.begin(), nodes.id.end()) + 1;
}

std::int64_t Mesh::next_hex_id() const {
  return hex_id.empty() ? 1 : *std::max_element(hex_id.begin(), hex_id.end()) + 1;
}

}  // namespace abut
