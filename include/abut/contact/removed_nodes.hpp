#pragma once
// Nodes that act as no secondary point of a contact: Radioss /INTER/TYPE25 Irem_i2 = 1 (seed 004:
// "secondary nodes in /INTER/TYPE2 tied contacts are removed from this contact"), so that a tie
// and a contact between the same surfaces do not fight. Node-to-surface drops the node's point;
// surface-to-surface drops the points of a facet whose nodes are all removed (a facet partly tied
// keeps its points: its free nodes are still secondary nodes there).
#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

namespace abut {

class RemovedNodes {
 public:
  RemovedNodes() = default;
  explicit RemovedNodes(std::vector<std::int32_t> nodes) : nodes_(std::move(nodes)) {
    std::sort(nodes_.begin(), nodes_.end());
    nodes_.erase(std::unique(nodes_.begin(), nodes_.end()), nodes_.end());
  }
  bool empty() const { return nodes_.empty(); }
  bool has(std::int32_t node) const {
    return std::binary_search(nodes_.begin(), nodes_.end(), node);
  }
  // Every node of a facet (or face) removed.
  bool covers(std::span<const std::int32_t> nodes) const {
    return !nodes_.empty() &&
           std::all_of(nodes.begin(), nodes.end(), [this](std::int32_t n) { return has(n); });
  }
  std::span<const std::int32_t> nodes() const { return nodes_; }

 private:
  std::vector<std::int32_t> nodes_;
};

}  // namespace abut
