// The Gmsh element types abut reads and how their nodes map to abut's cells (mesh/topology.hpp).
// Gmsh numbers and node coordinates: Gmsh reference manual, "Node ordering" (Gmsh 4.8); the
// coordinates below are those gmsh::model::mesh::getElementProperties returns, which
// tests/io/test_gmsh_types.cpp compares with the library.
#include <array>
#include <cmath>
#include <stdexcept>

#include "abut/io/gmsh_mesh.hpp"

namespace abut::gmsh {
namespace {

constexpr GmshElementType kTypes[] = {
    {15, "point", 0, 1, std::nullopt},     {1, "line2", 1, 2, std::nullopt},
    {8, "line3", 1, 3, std::nullopt},      {2, "tri3", 2, 3, std::nullopt},
    {3, "quad4", 2, 4, std::nullopt},      {9, "tri6", 2, 6, std::nullopt},
    {16, "quad8", 2, 8, std::nullopt},     {10, "quad9", 2, 9, std::nullopt},
    {4, "tet4", 3, 4, CellType::tet4},     {11, "tet10", 3, 10, CellType::tet10},
    {5, "hex8", 3, 8, CellType::hex8},     {17, "hex20", 3, 20, CellType::hex20},
    {12, "hex27", 3, 27, CellType::hex27}, {6, "prism6", 3, 6, CellType::wedge6},
};

using P = std::array<double, 3>;
// Gmsh's reference coordinates of the solid types' nodes, in Gmsh's order.
constexpr P kTet10[] = {{0, 0, 0},     {1, 0, 0},   {0, 1, 0},   {0, 0, 1},     {0.5, 0, 0},
                        {0.5, 0.5, 0}, {0, 0.5, 0}, {0, 0, 0.5}, {0, 0.5, 0.5}, {0.5, 0, 0.5}};
constexpr P kHex27[] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1},
                        {1, -1, 1},   {1, 1, 1},   {-1, 1, 1}, {0, -1, -1}, {-1, 0, -1},
                        {-1, -1, 0},  {1, 0, -1},  {1, -1, 0}, {0, 1, -1},  {1, 1, 0},
                        {-1, 1, 0},   {0, -1, 1},  {-1, 0, 1}, {1, 0, 1},   {0, 1, 1},
                        {0, 0, -1},   {0, -1, 0},  {-1, 0, 0}, {1, 0, 0},   {0, 1, 0},
                        {0, 0, 1},    {0, 0, 0}};  // hex20: first 20
constexpr P kPrism6[] = {{0, 0, -1}, {1, 0, -1}, {0, 1, -1}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}};

std::span<const P> gmsh_coordinates(CellType type) {
  switch (type) {
    case CellType::tet4:
    case CellType::tet10:
      return std::span<const P>(kTet10).first(static_cast<std::size_t>(topology(type).nodes));
    case CellType::hex8:
    case CellType::hex20:
    case CellType::hex27:
      return std::span<const P>(kHex27).first(static_cast<std::size_t>(topology(type).nodes));
    case CellType::wedge6:
      return kPrism6;
    case CellType::hex64:
      break;
  }
  return {};
}

// abut's node k at Gmsh's node order[k]: the node with the same natural coordinates.
struct NodeOrders {
  std::array<std::array<std::int8_t, kMaxCellNodes>, std::size(kCellTypes)> order{};
  NodeOrders() {
    for (const CellType type : kCellTypes) {
      const std::span<const P> gmsh = gmsh_coordinates(type);
      if (gmsh.empty()) continue;
      const CellTopology& t = topology(type);
      for (int k = 0; k < t.nodes; ++k) {
        int found = -1;
        for (std::size_t g = 0; g < gmsh.size(); ++g) {
          const P& a = t.natural[static_cast<std::size_t>(k)];
          if (a[0] == gmsh[g][0] && a[1] == gmsh[g][1] && a[2] == gmsh[g][2])
            found = static_cast<int>(g);
        }
        if (found < 0) throw std::logic_error("gmsh node order: no Gmsh node at an abut node");
        order[static_cast<std::size_t>(type)][static_cast<std::size_t>(k)] =
            static_cast<std::int8_t>(found);
      }
    }
  }
};

}  // namespace

const GmshElementType* element_type(int number) {
  for (const GmshElementType& t : kTypes)
    if (t.number == number) return &t;
  return nullptr;
}

std::string element_type_list() {
  std::string s;
  for (const GmshElementType& t : kTypes)
    s += (s.empty() ? "" : ", ") + std::string(t.name) + " (" + std::to_string(t.number) + ")";
  return s;
}

std::span<const std::int8_t> gmsh_node_order(CellType type) {
  static const NodeOrders orders;
  if (gmsh_coordinates(type).empty()) return {};
  return std::span<const std::int8_t>(orders.order[static_cast<std::size_t>(type)])
      .first(static_cast<std::size_t>(topology(type).nodes));
}

}  // namespace abut::gmsh
