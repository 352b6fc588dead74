#pragma once
// Trilinear hexahedron helpers shared by refinement and geometry tests (VTK_HEXAHEDRON order).
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>

#include "abut/core/vec3.hpp"
#include "abut/mesh/mesh.hpp"

namespace abut::detail {

using HexPoints = std::array<Vec3, 8>;

// Local coordinates (u, v, w) in [0, 1] of the 8 nodes: u along 0->1, v along 0->3, w along 0->4.
inline constexpr int kHexCorner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                         {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
// The 12 edges (node pairs, first node at local edge parameter 0).
inline constexpr int kHexEdges[12][2] = {{0, 1}, {3, 2}, {4, 5}, {7, 6},   // along u
                                         {0, 3}, {1, 2}, {4, 7}, {5, 6},   // along v
                                         {0, 4}, {1, 5}, {3, 7}, {2, 6}};  // along w

inline HexPoints hex_points(const Mesh& mesh, std::size_t hex) {
  HexPoints x;
  for (int a = 0; a < 8; ++a)
    x[a] = mesh.nodes.position(static_cast<std::size_t>(mesh.hexes[hex][a]));
  return x;
}

inline Vec3 hex_centroid(const Mesh& mesh, std::size_t hex) {
  Vec3 sum;
  for (std::int32_t n : mesh.hexes[hex]) sum += mesh.nodes.position(static_cast<std::size_t>(n));
  return sum / 8.0;
}

// A hex face as its sorted node indices: the key under which two hexes find the face they share.
using HexFace = std::array<std::int32_t, 4>;
struct HexFaceHash {
  std::size_t operator()(const HexFace& f) const {
    std::size_t h = 0;
    for (std::int32_t n : f) h = h * 1000003u ^ static_cast<std::size_t>(n);
    return h;
  }
};
inline HexFace sorted_face(const Mesh& mesh, std::size_t hex, int face) {
  HexFace f;
  for (int a = 0; a < 4; ++a) f[a] = mesh.hexes[hex][kHexFaces[face][a]];
  std::sort(f.begin(), f.end());
  return f;
}

// Trilinear map of the hex at local coordinates (u, v, w) in [0, 1]^3.
inline Vec3 trilinear(const HexPoints& x, double u, double v, double w) {
  const double su[2] = {1.0 - u, u}, sv[2] = {1.0 - v, v}, sw[2] = {1.0 - w, w};
  Vec3 p;
  for (int a = 0; a < 8; ++a) {
    p += (su[kHexCorner[a][0]] * sv[kHexCorner[a][1]] * sw[kHexCorner[a][2]]) * x[a];
  }
  return p;
}

// Is p inside the trilinear hex (boundary included, to a relative tolerance)? Inverts the
// trilinear map by Newton's method from the centre; a point outside the bounding box is out.
bool point_in_hex(const HexPoints& x, const Vec3& p);

}  // namespace abut::detail
