#pragma once
// *CHANGE_TO_TETRAHEDRA: hexahedra (generated or given by cards) become 4- or 10-node
// tetrahedra, so that a model can be run and compared with tetrahedral meshes without a mesher.
//
// Conformity without new corner nodes comes from one rule: every quadrilateral face is cut along
// the diagonal through its lowest-numbered node (Dompierre, Labbé, Vallet & Camarero, "How to
// subdivide pyramids, prisms and hexahedra into tetrahedra", 8th International Meshing
// Roundtable, 1999). Two hexes that share a face see the same four nodes and cut it alike,
// whatever their local numbering. Each hex then becomes 5 or 6 tetrahedra (hex_tetrahedra).
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "abut/core/error.hpp"
#include "abut/mesh/geometry.hpp"
#include "abut/mesh/mesh.hpp"
#include "abut/mesh/refine.hpp"

namespace abut {

// The tetrahedra of one hexahedron (VTK_HEXAHEDRON local order) whose faces are cut along the
// diagonal through the node of lowest rank (`rank[a]`: any numbers, distinct, e.g. the global
// node indices). Tetrahedra are local node lists, positively oriented on the reference cube
// (node 3 on the side of 0-1-2's counter-clockwise normal).
struct HexTetrahedra {
  int count = 0;  // 5 or 6
  std::array<std::array<std::int8_t, 4>, 6> tets{};
};
HexTetrahedra hex_tetrahedra(std::span<const std::int32_t, 8> rank);

struct TetrahedraChange {  // one line of *CHANGE_TO_TETRAHEDRA, resolved
  std::vector<std::int64_t> parts;
  CellType type = CellType::tet4;  // tet4 or tet10
  std::optional<Geometry> region;  // gid: only hexes whose centroid is inside
  SourceLocation where;  // the deck line, for errors (empty: the message says the keyword)
};

// Replaces the selected hexahedra by tetrahedra (new ids after the largest solid id; the parts
// stay). Midside nodes of 10-node tetrahedra lie on the exact shape of generated components and
// on the trilinear map of other hexes (so a shared face diagonal gets one node from both sides),
// and are fixed in the directions both their end nodes are fixed in. A selected hex that shares
// a face with a hex left as it is would leave a non-conforming interface: an error. `check` may
// refuse the added size (the memory budget). Returns one note per (line, part).
std::vector<std::string> change_to_tetrahedra(Mesh& mesh,
                                              const std::vector<TetrahedraChange>& changes,
                                              const RefinementCheck& check = {});

}  // namespace abut
