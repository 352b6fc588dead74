#pragma once
// Facet corners that are not nodes of the host: points of a curved face, each a fixed linear
// combination of the face's nodes,
//   x_v = sum_a T_va x_a,      T_va = N_a(xi_v), the face's shape functions at the corner,
// so that a facet subdivision of a quadratic face keeps its corners on the true face. A force f_v
// on such a corner goes to the nodes as f_a = T_va f_v, its work being the same (the transpose
// of the same map), and a contact element's weight w_v on it becomes w_v T_va on each node a:
// the force of a contact point is spread over the face's nodes by the face's own shape functions
// taken at the corners of its facet (docs/contact.md, "Curved faces").
//
// A smoothed surface (smoothing.hpp) adds to some of them an offset o_v that it sets at each
// evaluation, x_v = sum_a T_va x_a + o_v (the curvature of its patches); forces still go to the
// nodes through T_va, so the offset's own dependence on the nodes is left out of the forces.
//
// Dependent node k has index first + k: the host's nodes come first, so that facets can name
// both kinds in one index space.
#include <cstdint>
#include <span>
#include <vector>

#include "abut/contact/thermal_contact_element.hpp"

namespace abut {

struct DependentNodes {
  std::int32_t first = 0;              // the host's node count
  std::vector<std::int32_t> start{0};  // node k's terms: [start[k], start[k + 1])
  std::vector<std::int32_t> node;      // host node of each term
  std::vector<double> weight;          // T_va of each term
  std::vector<double> offset;          // o_v, 3 per node (x, y, z); empty: none

  std::size_t size() const { return start.size() - 1; }
  bool empty() const { return size() == 0; }
  // Appends a dependent node; returns its index (first + k).
  std::int32_t add(std::span<const std::int32_t> nodes, std::span<const double> weights);
  // The host's coordinates followed by those of the dependent nodes.
  void extend(std::span<const double> x, std::span<const double> y, std::span<const double> z,
              std::vector<double>& ex, std::vector<double>& ey, std::vector<double>& ez) const;
  // Replaces every dependent node of `w` by its host nodes (weights w_v T_va, merged with the
  // host nodes `w` already has).
  ContactWeights expand(const ContactWeights& w) const;
};

}  // namespace abut
