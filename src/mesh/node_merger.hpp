#pragma once
// Spatial hash that finds an existing node within a distance tolerance of a point, so that
// structured blocks and refined hexes share the nodes on their common boundaries.
#include <cstdint>
#include <functional>
#include <unordered_map>
#include <vector>

#include "abut/core/vec3.hpp"
#include "abut/mesh/mesh.hpp"

namespace abut::detail {

class NodeMerger {
 public:
  // tolerance: points closer than this are the same node, and the largest tolerance a query may
  // pass (a query with its own, smaller tolerance follows the local node spacing).
  explicit NodeMerger(double tolerance);

  // Registers an existing node so later points can merge with it.
  void insert(std::int32_t node, const Vec3& p);
  // The node within tolerance of p, or -1.
  std::int32_t find(const Vec3& p) const { return find(p, tolerance_); }
  std::int32_t find(const Vec3& p, double tolerance) const;
  // The nearest node within tolerance of p (ties: the lowest index), or -1.
  std::int32_t nearest(const Vec3& p) const {
    return nearest(p, [](std::int32_t, double) { return true; });
  }
  // The same among the nodes n at distance d for which accept(n, d) holds (a tolerance of each
  // pair of nodes, at most the merger's).
  std::int32_t nearest(const Vec3& p,
                       const std::function<bool(std::int32_t node, double distance)>& accept) const;
  // The node within tolerance of p; a new node (user id next_id++) when there is none.
  std::int32_t find_or_add(Nodes& nodes, const Vec3& p, std::int64_t& next_id) {
    return find_or_add(nodes, p, next_id, tolerance_);
  }
  std::int32_t find_or_add(Nodes& nodes, const Vec3& p, std::int64_t& next_id, double tolerance);

 private:
  struct Entry {
    std::int32_t node;
    Vec3 p;
  };
  struct Cell {
    std::int64_t i, j, k;
  };
  Cell cell_of(const Vec3& p) const;
  static std::uint64_t key(std::int64_t i, std::int64_t j, std::int64_t k);
  double tolerance_;
  double cell_;  // hash cell edge; a tolerance ball touches at most 2 cells per axis
  std::unordered_map<std::uint64_t, std::vector<Entry>> cells_;
};

// The tolerance within which a generated point is the same node as another: a small fraction
// of the shortest edge that meets it (the local node spacing, not the size of the component, so
// that slender components keep their nodes), and never below the rounding of its coordinates
// (so that components far from the origin still join their blocks).
double merge_tolerance(const Vec3& p, double shortest_edge);
// The largest merge_tolerance of a component whose points lie within `reach` of the origin and
// whose edges are at most `longest_edge` long: the tolerance to build its NodeMerger with.
double largest_merge_tolerance(double reach, double longest_edge);

}  // namespace abut::detail
