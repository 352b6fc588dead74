#pragma once
// The element families: for each cell type its nodes and their natural coordinates, its faces
// (which nodes, outward, in the Abaqus/CalculiX face order S1..Sn), its edges, and how it is
// written to VTK. The one place these facts live; docs/architecture.md ("Element families") lists
// what a new type adds.
//
// Node orders are those of Abaqus/CalculiX (C3D8, C3D20, C3D4, C3D10, C3D6), which for the
// hexahedra and tetrahedra are also VTK's (VTK_HEXAHEDRON, VTK_QUADRATIC_HEXAHEDRON, VTK_TETRA,
// VTK_QUADRATIC_TETRA). The Lagrange hexahedra of order 2 and 3 (hex27, hex64: the nodes of the
// equispaced (p + 1)^3 lattice, *CHANGE_P-ORDER) have no Abaqus counterpart and take VTK's order
// for VTK_LAGRANGE_HEXAHEDRON (vtkHigherOrderHexahedron::PointIndexFromIJK, VTK 9.1): the
// corners as hex8, the edge nodes edge by edge (0-1, 1-2, 3-2, 0-3, 4-5, 5-6, 7-6, 4-7, 0-4, 1-5,
// 2-6, 3-7, each in the direction of increasing coordinate), the face nodes face by face
// (xi = -1, xi = 1, eta = -1, eta = 1, zeta = -1, zeta = 1; the two free coordinates increasing,
// the first fastest), then the interior nodes (xi fastest, then eta, then zeta). hex27's first 20
// nodes are hex20's. A wedge's triangle 1-2-3 turns counter-clockwise seen from 4-5-6 in
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

enum class CellType : std::uint8_t { hex8, hex20, tet4, tet10, wedge6, hex27, hex64 };
inline constexpr CellType kCellTypes[] = {CellType::hex8,  CellType::hex20,  CellType::tet4,
                                          CellType::tet10, CellType::wedge6, CellType::hex27,
                                          CellType::hex64};

// Faces: linear and quadratic triangles and quadrilaterals, and the Lagrange quadrilaterals of the
// Lagrange hexahedra. Face nodes run counter-clockwise seen from outside the cell (right-hand
// normal outward): first the corners, then the nodes on the edges corner 0-1, 1-2, ... (the
// Abaqus/CalculiX order of a face of C3D20 or C3D10), each edge's from its first corner on, then
// (quad9, quad16) the interior nodes, the first natural coordinate (corner 0 to 1) fastest.
enum class FaceType : std::uint8_t { tri3, tri6, quad4, quad8, quad9, quad16 };

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
    case FaceType::quad9:
      return 9;
    case FaceType::quad16:
      return 16;
  }
  return 0;
}
inline constexpr int kMaxFaceNodes = 16;

// The Lagrange quadrilaterals (quad9: order 2, quad16: order 3): each face node's place (s, t) on
// the face's (p + 1) x (p + 1) lattice, corner 0 at (0, 0), corner 1 at (p, 0), corner 3 at
// (0, p); natural coordinates -1 + 2 s / p. Empty for the other faces.
std::span<const std::array<std::int8_t, 2>> face_lattice(FaceType type);

// A face as linear facets through its own nodes (face-local node indices, counter-clockwise like
// the face; a triangle repeats its third node, as contact surfaces store one): a linear face is
// its own facet; tri6 is 4 triangles (one at each corner, one of the midside nodes); quad8 the 4
// corner triangles and the quadrilateral of its midside nodes; a Lagrange quadrilateral the p x p
// quadrilaterals of its lattice. Contact surfaces use them: forces
// go to real nodes with positive shares (docs/architecture.md, "Element families").
std::span<const std::array<std::int8_t, 4>> linear_facets(FaceType type);

struct FaceTopology {
  FaceType type = FaceType::quad4;
  std::array<std::int8_t, kMaxFaceNodes> nodes{};  // local node indices; the first size()
  int size() const { return face_node_count(type); }
};

// An edge between two corners, with its midside node (-1 on a linear cell and on hex64, whose
// edges have two inner nodes).
struct EdgeTopology {
  std::int8_t a = 0, b = 0, mid = -1;
};

struct CellTopology {
  CellType type = CellType::hex8;
  std::string_view name;        // "hex20": the name messages and docs use
  std::string_view abaqus;      // the Abaqus/CalculiX element name with full integration ("C3D20");
                                // empty for the Lagrange hexahedra
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

// How messages name an element of the type: its Abaqus name ("C3D20"), or "hex27", "hex64".
inline std::string_view element_label(CellType type) {
  const CellTopology& t = topology(type);
  return t.abaqus.empty() ? t.name : t.abaqus;
}

// The most nodes a cell type has: the size of per-element scratch arrays.
inline constexpr int kMaxCellNodes = 64;

// The six faces of a hexahedron (corners), as in CalculiX's C3D8 S1..S6: bottom (zeta = -1),
// top (zeta = 1), eta = -1, xi = 1, eta = 1, xi = -1. The same as topology(hex8).faces.
inline constexpr int kHexFaces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                        {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};

}  // namespace abut
