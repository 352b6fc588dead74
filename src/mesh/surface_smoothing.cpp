#include "mesh/surface_smoothing.hpp"

#include <array>
#include <cmath>
#include <numbers>

namespace abut::detail {

Vec3 nagata_curvature(const Vec3& x0, const Vec3& x1, const Vec3& n0, const Vec3& n1) {
  // Nagata (2005), eq. for c(d, n0, n1): with v = (n0 + n1)/2, dv = (n0 - n1)/2,
  // dc = n0 . dv, c = (d . dv)/(1 - dc) v + (d . v)/dc dv; c = 0 for parallel normals.
  const Vec3 d = x1 - x0;
  const Vec3 v = 0.5 * (n0 + n1);
  const Vec3 dv = 0.5 * (n0 - n1);
  const double dc = dot(n0, dv);
  if (dc < 1e-14 || 1.0 - dc < 1e-14) return {};  // parallel or opposite normals
  return (dot(d, dv) / (1.0 - dc)) * v + (dot(d, v) / dc) * dv;
}

std::unordered_map<std::uint64_t, Vec3> smooth_edge_curvatures(
    const Nodes& nodes, const std::vector<std::array<std::int32_t, 4>>& faces,
    double max_angle_degrees, std::size_t& rejected_edges) {
  rejected_edges = 0;
  const double cos_max = std::cos(max_angle_degrees * std::numbers::pi / 180.0);
  // Face area vectors: half the cross product of the diagonals of the (bilinear) quad.
  std::vector<Vec3> area(faces.size()), unit(faces.size());
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> faces_of_edge;
  std::unordered_map<std::int32_t, std::vector<std::size_t>> faces_of_node;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const auto& q = faces[f];
    auto x = [&](int a) { return nodes.position(static_cast<std::size_t>(q[a])); };
    area[f] = 0.5 * cross(x(2) - x(0), x(3) - x(1));
    unit[f] = normalized(area[f]);
    for (int a = 0; a < 4; ++a) {
      faces_of_edge[edge_key(q[a], q[(a + 1) % 4])].push_back(f);
      faces_of_node[q[a]].push_back(f);
    }
  }
  // Normal at `node` for the edge between faces f1 and f2.
  auto edge_end_normal = [&](std::int32_t node, std::size_t f1, std::size_t f2) {
    Vec3 sum;
    for (std::size_t f : faces_of_node[node]) {
      if (dot(unit[f], unit[f1]) > cos_max && dot(unit[f], unit[f2]) > cos_max) sum += area[f];
    }
    return normalized(sum);
  };
  std::unordered_map<std::uint64_t, Vec3> curvature;
  for (const auto& [key, adjacent] : faces_of_edge) {
    if (adjacent.size() != 2) continue;  // edge of the smoothed region: straight
    const std::size_t f1 = adjacent[0], f2 = adjacent[1];
    if (!(dot(unit[f1], unit[f2]) > cos_max)) continue;  // feature edge: straight
    const auto a = static_cast<std::int32_t>(key >> 32);
    const auto b = static_cast<std::int32_t>(key & 0xffffffffu);
    const Vec3 xa = nodes.position(static_cast<std::size_t>(a));
    const Vec3 xb = nodes.position(static_cast<std::size_t>(b));
    const Vec3 c = nagata_curvature(xa, xb, edge_end_normal(a, f1, f2), edge_end_normal(b, f1, f2));
    if (norm(c) > norm(xb - xa)) {  // see header: reported, not silently dropped
      ++rejected_edges;
      continue;
    }
    if (norm(c) > 0.0) curvature.emplace(key, c);
  }
  return curvature;
}

}  // namespace abut::detail
