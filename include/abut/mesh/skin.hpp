#pragma once
// Exterior faces ("skin") of the solid elements of a mesh, of every cell type (mesh/topology.hpp):
// the raw material of contact surfaces and pressure loads. A face is exterior when exactly one
// solid of the whole mesh uses it (faces are matched by their corners). With `merge`, a face
// shared by two solids of different parts is kept as well (once for each side whose part is
// selected): the faces of parts that share nodes, which become contact faces when the parts
// separate (seed 000, *CONTACT field `merge`). A quadratic face comes as its linear facets
// through its own nodes (linear_facets of topology.hpp), one SkinFace each.
#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "abut/mesh/mesh.hpp"

namespace abut {

// A contact face is also made of a whole shell (`shell` >= 0, `hex` = -1): its nodes in the
// shell's order, its thickness h; both of its sides touch (contact_surfaces.hpp).
struct SkinFace {
  // Node indices, counter-clockwise seen from outside; a triangle repeats its third node.
  std::array<std::int32_t, 4> nodes{};
  std::int32_t solid = -1;       // the owning solid (Mesh::solid numbering: hexes first)
  std::int8_t face = -1;         // its face, 0-based (S1 is 0): topology(type).faces
  std::int64_t part = 0;         // user part id of the owning solid
  double thickness = 0.0;        // owning solid's size along the face normal: volume / face area
  std::int32_t shell = -1;       // index of the shell, when the face is one
  std::int32_t exposed_by = -1;  // an interior face: the solid whose erosion exposes it
};

// Exterior faces of the solids whose part is in `parts`, in solid order, then face order (S1..Sn;
// for a hexahedron bottom, top, y-min side, x-max side, y-max side, x-min side of the reference
// cell), then facet order. With `erodible`, also each selected solid's side of the interior faces
// it shares with a solid for which erodible(solid index) holds: the faces that erosion may expose
// (exposed_by).
std::vector<SkinFace> exterior_faces(const Mesh& mesh, std::span<const std::int64_t> parts,
                                     bool merge,
                                     const std::function<bool(std::int32_t)>& erodible = {});
// Every exterior face of the mesh (entity type ALL).
std::vector<SkinFace> exterior_faces(const Mesh& mesh, bool merge,
                                     const std::function<bool(std::int32_t)>& erodible = {});

// Appends the facets of face `face` (0-based) of solid `solid` to `out`. `volume`: the solid's
// volume when the caller has it, else 0 (computed, InputError when not positive).
void append_facets(const Mesh& mesh, std::int32_t solid, int face, double volume,
                   std::vector<SkinFace>& out);

// Volume of solid `solid` (Mesh::solid numbering): hex_volume for a hexahedron, cell_volume of
// shape_functions.hpp for the other types.
double solid_volume(const Mesh& mesh, std::size_t solid);

// Volume of a trilinear hex (cell_volume of shape_functions.hpp for every type): 2x2x2 Gauss
// quadrature of det J, exact because det J is at most quadratic in each reference coordinate.
double hex_volume(const Nodes& nodes, const Hex8& hex);

// Area of a bilinear quad: 2x2 Gauss quadrature of |x_xi x x_eta| (exact when the quad is planar).
double quad_area(const Nodes& nodes, const std::array<std::int32_t, 4>& quad);

}  // namespace abut
