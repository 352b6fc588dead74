#pragma once
// The element families: for each cell type its nodes and their natural coordinates, its faces
// (which nodes, outward, in the Abaqus/CalculiX face order S1..Sn), its edges, and how it is
// written to VTK. The one place these facts live; docs/architecture.md ("Element families") lists
// what a new type adds.
//
// Node orders are those of Abaqus/CalculiX (C3D8, C3D20, C3D4, C3D10, C3D6), which for the
// hexahedra and tetrahedra are also VTK's (VTK_HEXAHEDRON, VTK_QUADRATIC_HEXAHEDRON, VTK_TETRA,
// VTK_QUADRATIC_TETRA). A wedge's triangle 1-2-3 turns counter-clockwise seen from 4-5-6 in
// Abaqus and clockwise in VTK (vtkCellValidator calls the Abaqus order's faces "oriented
// incorrectly"), so it is written as 1-3-2-4-6-5.
//
// Natural coordinates: hexahedra in [-1, 1]^3, node 0 at (-1,-1,-1), 1 (1,-1,-1), 2 (1,1,-1),
// 3 (-1,1,-1), 4-7 the same at zeta = 1, midside nodes halfway along their edge; tetrahedra with
// volume coordinates, node 0 at (0,0,0), 1 (1,0,0), 2 (0,1,0), 3 (0,0,1); wedges with the triangle
// (0,0), (1,0), (0,1) at zeta = -1 (nodes 0-2) and zeta = 1 (nodes 3-5).
#include <array>
#include <cstdint>
#include <span>
#include <string_view>

namespace abut {

enum class CellType : std::uint8_t { hex8, hex20, tet4, tet10, wedge6 };
inline constexpr CellType kCellTypes[] = {CellType::hex8, CellType::hex20, CellType::tet4,
                                          CellType::tet10, CellType::wedge6};

// Faces: linear and quadratic triangles and quadrilaterals. Face nodes run counter-clockwise seen
// from outside the cell (right-hand normal outward): first the corners, then the midside nodes of
// the edges corner 0-1, 1-2, ... (the Abaqus/CalculiX order of a face of C3D20 or C3D10).
enum class FaceType : std::uint8_t { tri3, tri6, quad4, quad8 };

constexpr int face_corner_count(FaceType t) {
  return t == FaceType::tri3 || t == FaceType::tri6 ? 3 : 4;
}
constexpr int face_node_count(FaceType t) {
  switch (t) {
    case FaceType::tri3:
      return 3;
    case FaceType::tri6:
      return 6;
    case FaceType::quad4:
      return 4;
    case FaceType::quad8:
      return 8;
  }
  return 0;
}

// A face as linear facets through its own nodes (face-local node indices, counter-clockwise like
// the face; a triangle repeats its third node, as contact surfaces store one): a linear face is
// its own facet; tri6 is 4 triangles (one at each corner, one of the midside nodes); quad8 the 4
// corner triangles and the quadrilateral of its midside nodes. Contact surfaces use them: forces
// go to real nodes with positive shares (docs/architecture.md, "Element families").
std::span<const std::array<std::int8_t, 4>> linear_facets(FaceType type);

struct FaceTopology {
  FaceType type = FaceType::quad4;
  std::array<std::int8_t, 8> nodes{};  // local node indices; the first face_node_count(type)
  int size() const { return face_node_count(type); }
};

// An edge between two corners, with its midside node (-1 on a linear cell).
struct EdgeTopology {
  std::int8_t a = 0, b = 0, mid = -1;
};

struct CellTopology {
  CellType type = CellType::hex8;
  std::string_view name;        // "hex20": the name messages and docs use
  std::string_view abaqus;      // the Abaqus/CalculiX element name with full integration ("C3D20")
  std::string_view node_order;  // the node order in words, for messages
  int nodes = 0;
  int corners = 0;                      // the vertices: the first `corners` nodes
  int order = 1;                        // polynomial order along an edge
  std::span<const FaceTopology> faces;  // S1..Sn
  std::span<const EdgeTopology> edges;
  std::span<const std::array<double, 3>> natural;  // natural coordinates of each node
  int vtk_type = 0;                                // VTK cell type id
  std::span<const std::int8_t> vtk_order;          // VTK's node k is this cell's node vtk_order[k]
};

const CellTopology& topology(CellType type);

// The most nodes a cell type has: the size of per-element scratch arrays.
inline constexpr int kMaxCellNodes = 20;

// The six faces of a hexahedron (corners), as in CalculiX's C3D8 S1..S6: bottom (zeta = -1),
// top (zeta = 1), eta = -1, xi = 1, eta = 1, xi = -1. The same as topology(hex8).faces.
inline constexpr int kHexFaces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                        {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};

}  // namespace abut
