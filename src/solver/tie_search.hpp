#pragma once
// The nodes of the exact ties (Model::ties, *CONTACT_FRICTION FREEZE with tie = EXACT) and the
// facets they follow, found once in the reference configuration: a node of surface 1 within the
// detection depth of a facet of surface 2 is bound to its partner point there (the node-to-surface
// partner search of the contact library, as the penalty FREEZE finds its ties), as
//     x_s = sum_a N_a(xi_0) x_a + offset,   offset = x_s(0) - sum_a N_a(xi_0) x_a(0),
// a linear constraint u_s = sum_a N_a u_a on the displacements (offset fixed in space, so the
// initial gap stays and nothing is stressed at t = 0). The explicit solver enforces it by the
// kinematic tie of ties.hpp, the static steps by eliminating u_s (static/dof_map.hpp).
#include <array>
#include <cstdint>
#include <vector>

#include "abut/contact/removed_nodes.hpp"
#include "abut/core/vec3.hpp"
#include "abut/model/model.hpp"

namespace abut {

struct TiedNode {
  std::int32_t node = -1;
  std::uint32_t tie = 0;  // index into Model::ties
  int count = 0;          // distinct main nodes (a collapsed facet corner counts once)
  std::array<std::int32_t, 4> main{};
  std::array<double, 4> weight{};  // N_a(xi_0), summing to 1
  Vec3 offset;
};

// Where the input asks for the exact tie (Sources "exact"), for its errors.
inline SourceLocation exact_tie_place(const Model& model, const TieSpec& tie) {
  return model.sources.of(SourceEntity::Tie, tie.id, "exact", tie.where);
}

// Every tied node of the model's exact ties, by tie then node. InputError at the tie for a tie that
// binds no node, a node tied by two ties (at the second), and a node that is both tied and a main
// node of a tie (chains are not resolved).
std::vector<TiedNode> find_tied_nodes(const Model& model);

// The nodes of find_tied_nodes, for the contacts that drop them as secondary points (Radioss
// Irem_i2 = 1, *CONTACT_DISCRETIZATION tied_nodes REMOVE).
RemovedNodes tied_node_set(const std::vector<TiedNode>& tied);

// The linear constraints u_s - sum_a N_a u_a = 0 of the tied nodes, three per node (x, y, z),
// located at their tie's EXACT field (static steps, model_static.hpp).
std::vector<LinearConstraint> tie_constraints(const Model& model,
                                              const std::vector<TiedNode>& tied);

}  // namespace abut
