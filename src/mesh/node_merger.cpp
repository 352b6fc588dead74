#include "mesh/node_merger.hpp"

#include <algorithm>
#include <cmath>

namespace abut::detail {
namespace {

// Fraction of the local edge within which points are one node: far above the rounding of block
// interfaces (~1e-16 relative), far below any element.
constexpr double kEdgeFraction = 1e-6;
// Relative rounding of a coordinate that shape maps may leave (a few hundred ulps).
constexpr double kRounding = 1e-13;
// Never more than this fraction of the shortest edge at the point: far from the origin (a
// 1e12 m model) the rounding floor above would reach across small elements whose nodes are
// still distinct at the coordinates' precision (2.2e-16 relative) and join them (issue 28).
constexpr double kLargestEdgeFraction = 0.25;
// Cell indices are clamped here: far enough to keep distinct cells apart, near enough that
// the +-1 neighbour never overflows.
constexpr double kLargestIndex = 4.0e18;

std::int64_t index_of(double coordinate, double cell) {
  const double c = std::floor(coordinate / cell);
  if (!(c == c)) return 0;  // NaN: any cell, the distance test decides
  return static_cast<std::int64_t>(std::clamp(c, -kLargestIndex, kLargestIndex));
}

}  // namespace

NodeMerger::NodeMerger(double tolerance) : tolerance_(tolerance), cell_(4.0 * tolerance) {}

NodeMerger::Cell NodeMerger::cell_of(const Vec3& p) const {
  return {index_of(p.x, cell_), index_of(p.y, cell_), index_of(p.z, cell_)};
}

std::uint64_t NodeMerger::key(std::int64_t i, std::int64_t j, std::int64_t k) {
  // Mixing with large odd constants in unsigned arithmetic (wraps by definition); collisions only
  // cost a longer bucket scan.
  return static_cast<std::uint64_t>(i) * 73856093ULL ^ static_cast<std::uint64_t>(j) * 19349663ULL ^
         static_cast<std::uint64_t>(k) * 83492791ULL;
}

void NodeMerger::insert(std::int32_t node, const Vec3& p) {
  const Cell c = cell_of(p);
  cells_[key(c.i, c.j, c.k)].push_back({node, p});
}

std::int32_t NodeMerger::find(const Vec3& p, double tolerance) const {
  const Cell c = cell_of(p);
  const double tol = std::min(tolerance, tolerance_);
  for (std::int64_t di = -1; di <= 1; ++di) {
    for (std::int64_t dj = -1; dj <= 1; ++dj) {
      for (std::int64_t dk = -1; dk <= 1; ++dk) {
        const auto it = cells_.find(key(c.i + di, c.j + dj, c.k + dk));
        if (it == cells_.end()) continue;
        for (const Entry& e : it->second) {
          if (norm(e.p - p) <= tol) return e.node;
        }
      }
    }
  }
  return -1;
}

std::int32_t NodeMerger::nearest(
    const Vec3& p, const std::function<bool(std::int32_t node, double distance)>& accept) const {
  const Cell c = cell_of(p);
  std::int32_t best = -1;
  double best_distance = 0.0;
  for (std::int64_t di = -1; di <= 1; ++di) {
    for (std::int64_t dj = -1; dj <= 1; ++dj) {
      for (std::int64_t dk = -1; dk <= 1; ++dk) {
        const auto it = cells_.find(key(c.i + di, c.j + dj, c.k + dk));
        if (it == cells_.end()) continue;
        for (const Entry& e : it->second) {
          const double d = norm(e.p - p);
          if (d > tolerance_ || !accept(e.node, d)) continue;
          // Hash collisions may list a cell twice; the order of the scan must not matter.
          if (best < 0 || d < best_distance || (d == best_distance && e.node < best)) {
            best = e.node;
            best_distance = d;
          }
        }
      }
    }
  }
  return best;
}

std::int32_t NodeMerger::find_or_add(Nodes& nodes, const Vec3& p, std::int64_t& next_id,
                                     double tolerance) {
  const std::int32_t found = find(p, tolerance);
  if (found >= 0) return found;
  const std::int32_t added = nodes.add(next_id++, p);
  insert(added, p);
  return added;
}

double merge_tolerance(const Vec3& p, double shortest_edge) {
  const double reach = std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
  const double tolerance = std::max(kEdgeFraction * shortest_edge, kRounding * reach);
  return shortest_edge > 0.0 ? std::min(tolerance, kLargestEdgeFraction * shortest_edge)
                             : tolerance;
}

double largest_merge_tolerance(double reach, double longest_edge) {
  return std::max(kEdgeFraction * longest_edge, kRounding * reach);
}

}  // namespace abut::detail
