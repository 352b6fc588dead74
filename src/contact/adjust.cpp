#include "abut/contact/adjust.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "abut/contact/broad_phase.hpp"
#include "abut/contact/quad.hpp"

namespace abut {

std::size_t adjust_onto_surface(const ContactSurface& surface, std::span<const std::int32_t> nodes,
                                std::span<double> x, std::span<double> y, std::span<double> z,
                                double depth) {
  std::vector<Box> boxes(surface.size());
  for (std::size_t f = 0; f < surface.size(); ++f) {
    const QuadCorners c = quad_corners(surface.facets[f], x, y, z);
    for (int k = 0; k < 3; ++k) {
      boxes[f].lo[k] = std::min({c[0][k], c[1][k], c[2][k], c[3][k]}) - depth;
      boxes[f].hi[k] = std::max({c[0][k], c[1][k], c[2][k], c[3][k]}) + depth;
    }
  }
  BucketGrid grid;
  grid.build(boxes);
  std::vector<double> qx, qy, qz;
  for (auto n : nodes) {
    qx.push_back(x[n]);
    qy.push_back(y[n]);
    qz.push_back(z[n]);
  }
  CandidateList candidates;
  grid.query(qx, qy, qz, candidates);
  // Closest points first, all from the unadjusted surface; then the moves.
  std::vector<Vec3> target(nodes.size());
  std::vector<std::uint8_t> moves(nodes.size(), 0);
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    const Vec3 p{qx[k], qy[k], qz[k]};
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t c = candidates.offsets[k]; c < candidates.offsets[k + 1]; ++c) {
      const auto& facet = surface.facets[candidates.facets[c]];
      if (std::find(facet.begin(), facet.end(), nodes[k]) != facet.end()) continue;
      const QuadProjection q = project_onto_quad(quad_corners(facet, x, y, z), p);
      if (q.crossed_edges != 0 || std::abs(q.gap) > depth || q.distance >= best) continue;
      best = q.distance;
      target[k] = q.point;
      moves[k] = 1;
    }
  }
  std::size_t moved = 0;
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    if (!moves[k]) continue;
    x[nodes[k]] = target[k].x;
    y[nodes[k]] = target[k].y;
    z[nodes[k]] = target[k].z;
    ++moved;
  }
  return moved;
}

double mean_edge_length(const ContactSurface& surface, std::span<const double> x,
                        std::span<const double> y, std::span<const double> z) {
  double sum = 0.0;
  std::size_t count = 0;
  for (const auto& f : surface.facets) {
    const QuadCorners c = quad_corners(f, x, y, z);
    for (int a = 0; a < 4; ++a) {
      if (f[a] == f[(a + 1) % 4]) continue;
      sum += norm(c[(a + 1) % 4] - c[a]);
      ++count;
    }
  }
  return count ? sum / static_cast<double>(count) : 0.0;
}

}  // namespace abut
