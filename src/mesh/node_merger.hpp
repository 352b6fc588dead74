#pragma once
// Spatial hash that finds an existing node within a distance tolerance of a point, so that
// structured blocks and refined hexes share the nodes on their common boundaries.
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "abut/core/vec3.hpp"
#include "abut/mesh/mesh.hpp"

namespace abut::detail {

class NodeMerger {
 public:
  // tolerance: points closer than this are the same node (choose it relative to model size).
  explicit NodeMerger(double tolerance);

  // Registers an existing node so later points can merge with it.
  void insert(std::int32_t node, const Vec3& p);
  // The node within tolerance of p, or -1.
  std::int32_t find(const Vec3& p) const;
  // The nearest node within tolerance of p (ties: the lowest index), or -1.
  std::int32_t nearest(const Vec3& p) const;
  // The node within tolerance of p; a new node (user id next_id++) when there is none.
  std::int32_t find_or_add(Nodes& nodes, const Vec3& p, std::int64_t& next_id);

 private:
  struct Entry {
    std::int32_t node;
    Vec3 p;
  };
  std::int64_t key(std::int64_t i, std::int64_t j, std::int64_t k) const;
  double tolerance_;
  double cell_;  // hash cell edge; a tolerance ball touches at most 2 cells per axis
  std::unordered_map<std::int64_t, std::vector<Entry>> cells_;
};

}  // namespace abut::detail
