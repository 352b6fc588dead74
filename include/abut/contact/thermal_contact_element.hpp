#pragma once
// A contact point as a heat conductor between its nodes, for steady heat (issue 11): the nodes of
// its element with weights w_a (+N_a on the point's own nodes, -phi_a on the partner facet's), so
// that sum_a w_a T_a = T_point - T_partner, and its conductance G = h A [power / temperature].
// The heat flowing into node a is -G w_a sum_b w_b T_b: what one side loses the other gains.
#include <array>
#include <cstdint>

#include "abut/contact/mortar.hpp"

namespace abut {

// The nodes of a contact element with their weights, repeated nodes merged (a triangle repeats
// its third node; a node-to-surface point is one node). At most the nodes of the point's own
// face and of each face of the other surface its cell covers (mortar.hpp): 4 each for linear
// facets, up to 16 for the facets of a curved face once its dependent corners are replaced by the
// face's nodes (dependent_nodes.hpp; quad8, quad9, quad16 of the cubic Lagrange hexahedron). add()
// does not check: this bound holds by construction (it was 8 until 2026-12-04, below a quad9's 9).
struct ContactWeights {
  static constexpr int kMaxFaceNodes = FacetParent::kMaxNodes;
  static constexpr int kCapacity = kMaxFaceNodes * (1 + kMaxOverlaps);
  std::array<std::int32_t, kCapacity> nodes{};
  std::array<double, kCapacity> weights{};
  int count = 0;
  void add(std::int32_t node, double weight) {
    for (int k = 0; k < count; ++k)
      if (nodes[k] == node) {
        weights[k] += weight;
        return;
      }
    nodes[count] = node;
    weights[count++] = weight;
  }
};

struct ThermalContactElement {
  ContactWeights weights;
  double conductance = 0.0;  // G = h A [power / temperature]
};

}  // namespace abut
