#pragma once
// Joining coincident nodes: components generated side by side each have their own nodes on the
// common face, so they are not connected until those nodes are replaced by one node each
// (*MERGE_DUPLICATED_NODES).
#include <cstdint>
#include <vector>

#include "abut/mesh/mesh.hpp"

namespace abut {

// For every node of `secondary` that is not also in `main`: the nearest node of `main` within
// `tolerance` (> 0; ties: the lowest index). Returns one entry per node of `nodes`: that main
// node, or -1 (a node outside `secondary`, or one without a main node within tolerance).
// Every replacement is a node that keeps its place (-1 itself), as remove_nodes requires.
std::vector<std::int32_t> coincident_replacements(const Nodes& nodes,
                                                  const std::vector<std::int32_t>& secondary,
                                                  const std::vector<std::int32_t>& main,
                                                  double tolerance);
// The same with a tolerance of each node (one entry per node of `nodes`, > 0 for the nodes of
// `secondary` and `main`): a pair of nodes is within tolerance when their distance is at most the
// smaller of their two tolerances.
std::vector<std::int32_t> coincident_replacements(const Nodes& nodes,
                                                  const std::vector<std::int32_t>& secondary,
                                                  const std::vector<std::int32_t>& main,
                                                  const std::vector<double>& tolerance);

// Removes every node i with replacement[i] >= 0 and puts replacement[i] in its place in every hex
// and shell. The replacing node takes over the constraints of the node it replaces (the DofMask
// bits are ORed), so that a support given on either copy of a duplicated node survives. The other
// nodes keep their order, user ids and coordinates. Returns the new index of every old node (of
// its replacement for a removed node), to remap whatever else holds node indices.
// Precondition: replacement has one entry per node and replacement[replacement[i]] == -1.
std::vector<std::int32_t> remove_nodes(Mesh& mesh, const std::vector<std::int32_t>& replacement);

}  // namespace abut
