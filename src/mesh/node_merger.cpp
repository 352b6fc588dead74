#include "mesh/node_merger.hpp"

#include <cmath>

namespace abut::detail {

NodeMerger::NodeMerger(double tolerance) : tolerance_(tolerance), cell_(4.0 * tolerance) {}

std::int64_t NodeMerger::key(std::int64_t i, std::int64_t j, std::int64_t k) const {
  // Mixing with large odd constants; collisions only cost a longer bucket scan.
  return i * 73856093LL ^ j * 19349663LL ^ k * 83492791LL;
}

void NodeMerger::insert(std::int32_t node, const Vec3& p) {
  const auto i = static_cast<std::int64_t>(std::floor(p.x / cell_));
  const auto j = static_cast<std::int64_t>(std::floor(p.y / cell_));
  const auto k = static_cast<std::int64_t>(std::floor(p.z / cell_));
  cells_[key(i, j, k)].push_back({node, p});
}

std::int32_t NodeMerger::find(const Vec3& p) const {
  const auto i = static_cast<std::int64_t>(std::floor(p.x / cell_));
  const auto j = static_cast<std::int64_t>(std::floor(p.y / cell_));
  const auto k = static_cast<std::int64_t>(std::floor(p.z / cell_));
  for (std::int64_t di = -1; di <= 1; ++di) {
    for (std::int64_t dj = -1; dj <= 1; ++dj) {
      for (std::int64_t dk = -1; dk <= 1; ++dk) {
        const auto it = cells_.find(key(i + di, j + dj, k + dk));
        if (it == cells_.end()) continue;
        for (const Entry& e : it->second) {
          if (norm(e.p - p) <= tolerance_) return e.node;
        }
      }
    }
  }
  return -1;
}

std::int32_t NodeMerger::nearest(const Vec3& p) const {
  const auto i = static_cast<std::int64_t>(std::floor(p.x / cell_));
  const auto j = static_cast<std::int64_t>(std::floor(p.y / cell_));
  const auto k = static_cast<std::int64_t>(std::floor(p.z / cell_));
  std::int32_t best = -1;
  double best_distance = 0.0;
  for (std::int64_t di = -1; di <= 1; ++di) {
    for (std::int64_t dj = -1; dj <= 1; ++dj) {
      for (std::int64_t dk = -1; dk <= 1; ++dk) {
        const auto it = cells_.find(key(i + di, j + dj, k + dk));
        if (it == cells_.end()) continue;
        for (const Entry& e : it->second) {
          const double d = norm(e.p - p);
          if (d > tolerance_) continue;
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

std::int32_t NodeMerger::find_or_add(Nodes& nodes, const Vec3& p, std::int64_t& next_id) {
  const std::int32_t found = find(p);
  if (found >= 0) return found;
  const std::int32_t added = nodes.add(next_id++, p);
  insert(added, p);
  return added;
}

}  // namespace abut::detail
