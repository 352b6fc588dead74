#include "abut/contact/shell_orientation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <queue>
#include <utility>

#include "abut/contact/narrow_phase.hpp"
#include "abut/contact/quad.hpp"

namespace abut {

std::vector<std::uint8_t> overlap_push_reversed(std::span<const std::array<std::int32_t, 4>> facets,
                                                std::span<const double> x,
                                                std::span<const double> y,
                                                std::span<const double> z,
                                                std::span<const std::int32_t> secondary_nodes) {
  const std::size_t nf = facets.size();
  std::vector<Vec3> normal(nf);
  // Per facet: the push's sign along its normal, once known (0: not yet).
  std::vector<int> sign(nf, 0);
  for (std::size_t f = 0; f < nf; ++f) {
    const QuadCorners c = quad_corners(facets[f], x, y, z);
    normal[f] = quad_centre_normal(c);
    const double size = std::max(norm(c[2] - c[0]), norm(c[3] - c[1]));
    double nearest = std::numeric_limits<double>::infinity();
    for (const std::int32_t n : secondary_nodes) {
      if (std::find(facets[f].begin(), facets[f].end(), n) != facets[f].end()) continue;
      const Vec3 p{x[n], y[n], z[n]};
      const QuadProjection q = project_onto_quad(c, p);
      if (q.overshoot > kOnBorder * size || !(std::abs(q.gap) < nearest)) continue;
      nearest = std::abs(q.gap);
      // A node exactly on the mid-surface says nothing: keep looking.
      sign[f] = q.gap > 0.0 ? -1 : q.gap < 0.0 ? 1 : sign[f];
    }
  }
  // Facets across each edge (the edge by its sorted nodes).
  std::map<std::pair<std::int32_t, std::int32_t>, std::vector<std::int32_t>> by_edge;
  for (std::size_t f = 0; f < nf; ++f)
    for (int e = 0; e < 4; ++e) {
      const std::int32_t a = facets[f][e], b = facets[f][(e + 1) % 4];
      if (a != b) by_edge[std::minmax(a, b)].push_back(static_cast<std::int32_t>(f));
    }
  std::vector<std::vector<std::int32_t>> neighbours(nf);
  for (const auto& [edge, around] : by_edge)
    for (const std::int32_t f : around)
      for (const std::int32_t g : around)
        if (f != g) neighbours[f].push_back(g);
  // A neighbour pushes the same way in space: its sign follows the turn of its normal.
  const auto spread = [&](std::queue<std::int32_t>& front) {
    while (!front.empty()) {
      const std::int32_t f = front.front();
      front.pop();
      for (const std::int32_t g : neighbours[f]) {
        if (sign[g] != 0) continue;
        sign[g] = dot(normal[f], normal[g]) * sign[f] >= 0.0 ? 1 : -1;
        front.push(g);
      }
    }
  };
  std::queue<std::int32_t> front;
  for (std::size_t f = 0; f < nf; ++f)
    if (sign[f] != 0) front.push(static_cast<std::int32_t>(f));
  spread(front);
  for (std::size_t f = 0; f < nf; ++f)
    if (sign[f] == 0) {  // a patch that sees no node: along its normals
      sign[f] = 1;
      front.push(static_cast<std::int32_t>(f));
      spread(front);
    }
  std::vector<std::uint8_t> reversed(nf);
  for (std::size_t f = 0; f < nf; ++f) reversed[f] = sign[f] < 0 ? 1 : 0;
  return reversed;
}

}  // namespace abut
