// The initial volume of every hexahedron, checked once its nodes are known and merged and before
// refinement: an inverted or flat hex is an error of the deck at the line that wrote it (or at
// the generator keyword), for rigid parts as for deformable ones. A rigid part has no element
// block that would find it later, and its mass and centre of mass would silently become 0 and NaN.
#include <algorithm>
#include <cmath>

#include "abut/mesh/skin.hpp"
#include "deck_reader.hpp"

namespace abut::deck {
namespace {

// The longest edge of the hex: the scale against which a volume counts as zero.
double longest_edge(const Nodes& nodes, const Hex8& hex) {
  static constexpr int kEdges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                        {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  double longest = 0.0;
  for (const auto& e : kEdges)
    longest = std::max(longest, norm(nodes.position(static_cast<std::size_t>(hex[e[1]])) -
                                     nodes.position(static_cast<std::size_t>(hex[e[0]]))));
  return longest;
}

}  // namespace

void DeckReader::check_element_volumes() const {
  const Mesh& mesh = model.mesh;
  // The line of each hex: its *ELEMENT_SOLID row or the command that generated it.
  std::vector<SourceLocation> where(mesh.hex_count());
  for (const ElementNodes& e : element_nodes) where[e.hex] = element_where(e, "");
  for (const MeshSource& s : mesh_sources)
    for (std::size_t h = s.first; h < s.end && h < where.size(); ++h) where[h] = s.where;
  for (std::size_t h = 0; h < mesh.hex_count(); ++h) {
    const Hex8& hex = mesh.hexes[h];
    const double volume = hex_volume(mesh.nodes, hex);
    const double edge = longest_edge(mesh.nodes, hex);
    // Round-off in the coordinates of a flat hex leaves a volume of ~1e-16 edge^3, either sign.
    if (volume > 1e-12 * edge * edge * edge && std::isfinite(volume)) continue;
    std::string nodes;
    for (const std::int32_t n : hex)
      nodes.append(nodes.empty() ? "" : ", ")
          .append(std::to_string(mesh.nodes.id[static_cast<std::size_t>(n)]));
    throw InputError(where[h],
                     "element " + std::to_string(mesh.hex_id[h]) + " (nodes " + nodes +
                         ") has volume " + format_number(volume) +
                         (volume < 0.0 ? " (inverted)" : " (degenerate)") +
                         " in the initial configuration; expected nodes n1-n4 counter-clockwise "
                         "on the bottom face seen from above, n5-n8 above them");
  }
}

}  // namespace abut::deck
