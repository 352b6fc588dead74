#pragma once
// Integration points of surface-to-surface contact and the sharp edges that refine them.
//
// Each facet carries Gauss points in its reference square [-1, 1]^2 (accuracy_level of seed
// 000): level 1 -> the centre (1 point), 2 -> 2x2 Gauss, >2 -> 3x3 Gauss. With accuracy_edge,
// each direction whose facet edge is sharp is split into a strip of a quarter of the facet
// next to that edge and the rest, each with its own Gauss rule: the points concentrate along
// the sharp edges while the weights still integrate the facet area exactly.
#include <cstdint>
#include <span>
#include <vector>

#include "abut/contact/surface.hpp"

namespace abut {

struct FacetPoint {
  double xi = 0.0, eta = 0.0;
  double weight = 0.0;  // reference-area weight; the weights of a facet sum to 4
  // The cell the point stands for (mortar.hpp): per direction the Gauss weights laid end to end,
  // so that the cells tile the square and each has the point's weight as its area.
  double xi0 = -1.0, xi1 = 1.0, eta0 = -1.0, eta1 = 1.0;
};

// Gauss points per direction of an accuracy level: 1, 2 or 3.
int gauss_points_per_direction(int accuracy_level);

// The rule of one facet. `sharp_edges` has bit e set when edge e (see quad.hpp) is sharp; it
// only matters with edge_refinement.
std::vector<FacetPoint> facet_rule(int accuracy_level, bool edge_refinement,
                                   std::uint8_t sharp_edges);

// Sharp edges of every facet (bit e = edge e): edges where a neighbouring facet of the same
// surface has a normal turned by more than `angle_degrees` (alpha_edge), and free edges,
// which have no neighbour at all (a shell's border: its other side does not count). Uses the
// centre normals at the given coordinates. `free_edges`, if given, receives the free ones alone.
std::vector<std::uint8_t> sharp_edges(const ContactSurface& surface, std::span<const double> x,
                                      std::span<const double> y, std::span<const double> z,
                                      double angle_degrees,
                                      std::vector<std::uint8_t>* free_edges = nullptr);

}  // namespace abut
