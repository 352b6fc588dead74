#pragma once
// Deck cards for a box meshed with cells of any type (tests/element/cell_grid.hpp): *NODE rows
// and the element cards a user writes for them: *ELEMENT_SOLID for hexahedra and, in LS-DYNA's
// degenerate forms, tetrahedra (n4 = ... = n8) and pentahedra (n5 = n6, n7 = n8);
// *ELEMENT_SOLID_TET10 and *ELEMENT_SOLID_H20 for the quadratic cells.
#include <fmt/format.h>

#include <cstdint>
#include <string>

#include "../element/cell_grid.hpp"

namespace abut::verification {

// The cards of grid g as part `part`, its node and element ids after `first_node` and
// `first_element`, moved by `shift`.
inline std::string cell_cards(CellType type, const test::CellGrid& g, std::int64_t part,
                              std::int64_t first_node, std::int64_t first_element,
                              Vec3 shift = {}) {
  std::string deck = "*NODE\n";
  for (std::size_t a = 0; a < g.nodes.size(); ++a)
    deck +=
        fmt::format("{}, {:.17g}, {:.17g}, {:.17g}\n", first_node + static_cast<std::int64_t>(a),
                    g.nodes.x[a] + shift.x, g.nodes.y[a] + shift.y, g.nodes.z[a] + shift.z);
  const char* keyword = type == CellType::tet10   ? "*ELEMENT_SOLID_TET10"
                        : type == CellType::hex20 ? "*ELEMENT_SOLID_H20"
                                                  : "*ELEMENT_SOLID";
  deck += std::string(keyword) + "\n";
  for (std::size_t e = 0; e < g.cells.size(); ++e) {
    const auto id = [&](int k) { return first_node + g.cells[e][static_cast<std::size_t>(k)]; };
    std::string row = fmt::format("{}, {}", first_element + static_cast<std::int64_t>(e), part);
    switch (type) {
      case CellType::tet4:  // n1 n2 n3 n4 n4 n4 n4 n4
        for (const int k : {0, 1, 2, 3, 3, 3, 3, 3}) row += fmt::format(", {}", id(k));
        break;
      case CellType::wedge6:  // C3D6 a b c d e f is the row a c f d b b e e
        for (const int k : {0, 2, 5, 3, 1, 1, 4, 4}) row += fmt::format(", {}", id(k));
        break;
      default:
        for (std::size_t k = 0; k < g.cells[e].size(); ++k)
          row += fmt::format(", {}", id(static_cast<int>(k)));
    }
    deck += row + "\n";
  }
  return deck;
}

}  // namespace abut::verification
