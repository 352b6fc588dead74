#pragma once
// Exterior faces ("skin") of a hexahedral mesh: the raw material of contact surfaces.
// A face is exterior when exactly one hex of the whole mesh uses it. With `merge`, a face
// shared by two hexes of different parts is kept as well (once for each side whose part is
// selected): the faces of parts that share nodes, which become contact faces when the parts
// separate (seed 000, *CONTACT field `merge`).
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
  std::array<std::int32_t, 4> nodes{};  // node indices, counter-clockwise seen from outside
  std::int32_t hex = -1;                // index of the owning hex
  std::int64_t part = 0;                // user part id of the owning hex
  double thickness = 0.0;               // owning hex's size along the face normal: volume / area
  std::int32_t shell = -1;              // index of the shell, when the face is one
  std::int32_t exposed_by = -1;         // an interior face: the hex whose erosion exposes it
};

// Exterior faces of the hexes whose part is in `parts`, in hex order then local face order
// (bottom, top, y-min side, x-max side, y-max side, x-min side of the reference hex). With
// `erodible`, also each selected hex's side of the interior faces it shares with a hex for which
// erodible(hex index) holds: the faces that erosion may expose (exposed_by).
std::vector<SkinFace> exterior_faces(const Mesh& mesh, std::span<const std::int64_t> parts,
                                     bool merge,
                                     const std::function<bool(std::int32_t)>& erodible = {});
// Every exterior face of the mesh (entity type ALL).
std::vector<SkinFace> exterior_faces(const Mesh& mesh, bool merge,
                                     const std::function<bool(std::int32_t)>& erodible = {});

// Volume of a trilinear hex: 2x2x2 Gauss quadrature of det J, exact because det J is at most
// quadratic in each reference coordinate.
double hex_volume(const Nodes& nodes, const Hex8& hex);

// Area of a bilinear quad: 2x2 Gauss quadrature of |x_xi x x_eta| (exact when the quad is planar).
double quad_area(const Nodes& nodes, const std::array<std::int32_t, 4>& quad);

}  // namespace abut
