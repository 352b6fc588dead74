// The initial volume of every hexahedron, checked once its nodes are known and merged and before
// refinement: an inverted or flat hex is an error of the deck at the line that wrote it (or at
// the generator keyword), for rigid parts as for deformable ones. A rigid part has no element
// block that would find it later, and its mass and centre of mass would silently become 0 and NaN.
#include <cmath>
#include <stdexcept>
#include <vector>

#include "abut/mesh/shape_functions.hpp"
#include "abut/mesh/skin.hpp"
#include "deck_reader.hpp"

namespace abut::deck {
namespace {

// The product of the mean edge lengths along the three directions of the hex: the volume of
// the box it spans, against which its volume counts as zero (a slender hex, 1e6 x 0.005 x 0.005,
// is not flat).
double spanned_volume(const Nodes& nodes, const Hex8& hex) {
  static constexpr int kEdges[3][4][2] = {{{0, 1}, {3, 2}, {4, 5}, {7, 6}},
                                          {{0, 3}, {1, 2}, {4, 7}, {5, 6}},
                                          {{0, 4}, {1, 5}, {2, 6}, {3, 7}}};
  double product = 1.0;
  for (const auto& direction : kEdges) {
    double sum = 0.0;
    for (const auto& e : direction)
      sum += norm(nodes.position(static_cast<std::size_t>(hex[e[1]])) -
                  nodes.position(static_cast<std::size_t>(hex[e[0]])));
    product *= 0.25 * sum;
  }
  return product;
}

CellBlock& block_of(Mesh& mesh, CellType type) {
  for (CellBlock& b : mesh.cells)
    if (b.type == type) return b;
  throw std::logic_error("a cell's block is missing");
}

}  // namespace

void DeckReader::resolve_cell_nodes() {
  for (const CellNodes& e : cell_nodes) {
    CellBlock& block = block_of(model.mesh, e.type);
    const std::size_t nodes = block.nodes_per_cell();
    for (std::size_t k = 0; k < nodes; ++k) {
      const std::int32_t index = node_index(e.node_ids[k]);
      if (index < 0)
        throw InputError(cell_where(e, "n" + std::to_string(e.fields[k])),
                         "node " + std::to_string(e.node_ids[k]) + " does not exist");
      block.nodes[e.cell * nodes + k] = index;
    }
  }
}

void DeckReader::check_element_volumes() const {
  const Mesh& mesh = model.mesh;
  // The line of hex h, looked up only for the one that fails: its *ELEMENT_SOLID row or the
  // command that generated it.
  const auto where = [&](std::size_t h) {
    for (const ElementNodes& e : element_nodes)
      if (e.hex == h) return element_where(e, "");
    for (const MeshSource& s : mesh_sources)
      if (h >= s.first && h < s.end) return s.where;
    return SourceLocation{};
  };
  for (std::size_t h = 0; h < mesh.hex_count(); ++h) {
    const Hex8& hex = mesh.hexes[h];
    const double volume = hex_volume(mesh.nodes, hex);
    // Round-off in the coordinates of a flat hex leaves a volume of ~1e-16 of the box it spans,
    // either sign.
    if (volume > 1e-12 * spanned_volume(mesh.nodes, hex) && std::isfinite(volume)) continue;
    std::string nodes;
    for (const std::int32_t n : hex)
      nodes.append(nodes.empty() ? "" : ", ")
          .append(std::to_string(mesh.nodes.id[static_cast<std::size_t>(n)]));
    throw InputError(where(h),
                     "element " + std::to_string(mesh.hex_id[h]) + " (nodes " + nodes +
                         ") has volume " + format_number(volume) +
                         (volume < 0.0 ? " (inverted)" : " (degenerate)") +
                         " in the initial configuration; expected nodes n1-n4 counter-clockwise "
                         "on the bottom face seen from above, n5-n8 above them");
  }
  // The other cells: a positive Jacobian at every point of the full rule.
  for (const CellNodes& e : cell_nodes) {
    const CellBlock* block = nullptr;
    for (const CellBlock& b : mesh.cells)
      if (b.type == e.type) block = &b;
    std::vector<double> X;
    for (const std::int32_t n : block->cell(e.cell)) {
      const Vec3 p = mesh.nodes.position(static_cast<std::size_t>(n));
      X.insert(X.end(), {p.x, p.y, p.z});
    }
    const double jacobian = min_jacobian(e.type, X);
    if (jacobian > 0.0 && std::isfinite(jacobian)) continue;
    const CellTopology& t = topology(e.type);
    throw InputError(cell_where(e, ""),
                     std::string(element_label(e.type)) + " element " +
                         std::to_string(block->id[e.cell]) +
                         " is inverted or degenerate in the initial configuration (Jacobian " +
                         format_number(jacobian) + "); expected the " + std::string(t.node_order));
  }
}

}  // namespace abut::deck
