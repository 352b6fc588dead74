#pragma once
// Smooth surface through the exterior nodes of a hex mesh, for *SMOOTH_MESH: every exterior
// edge becomes a quadratic curve x(t) = (1-t) x0 + t x1 - c t (1-t) (Nagata, "Simple local
// interpolation of surfaces using normal vectors", CAGD 22 (2005) 327-347), and every face the
// Coons patch of its four edge curves, which is Nagata's quadrilateral patch. Edges whose two
// faces' normals differ by max_angle or more are feature edges and stay straight (c = 0).
#include <array>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "abut/core/vec3.hpp"
#include "abut/mesh/mesh.hpp"

namespace abut::detail {

// Nagata's curvature vector c of the edge x0 -> x1 with unit normals n0, n1 at its ends: the
// quadratic curve through x0 and x1 whose tangents are perpendicular to n0 and n1.
Vec3 nagata_curvature(const Vec3& x0, const Vec3& x1, const Vec3& n0, const Vec3& n1);

// Key of the edge between node indices a and b (order-free).
inline std::uint64_t edge_key(std::int32_t a, std::int32_t b) {
  const auto lo = static_cast<std::uint64_t>(a < b ? a : b);
  const auto hi = static_cast<std::uint64_t>(a < b ? b : a);
  return lo << 32 | hi;
}

// Curvature vectors of the curved edges of the smooth surface (absent edges are straight).
// `faces` are the exterior faces to smooth (4 node indices each, counter-clockwise seen from
// outside); an edge is curved when both of its faces are in the list and their normals differ
// by less than max_angle_degrees. The normal at an edge end is the area-weighted mean of the
// listed faces around that node whose normals are within max_angle of both edge faces.
// An edge whose curve would bulge by more than its chord (normals that disagree with the
// facets, e.g. at a step) is kept straight and counted in `rejected_edges`.
std::unordered_map<std::uint64_t, Vec3> smooth_edge_curvatures(
    const Nodes& nodes, const std::vector<std::array<std::int32_t, 4>>& faces,
    double max_angle_degrees, std::size_t& rejected_edges);

}  // namespace abut::detail
