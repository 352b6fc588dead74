#pragma once
// Contact surface smoothing (OptiStruct SMOOTH, seed 003): a faceted surface replaced, for the
// contact only, by the smooth surface its nodes and nodal normals describe, so that a body
// sliding over a coarse mesh of a curved surface meets the curve and not the facets' kinks.
//
// The surface is made of Nagata patches (T. Nagata, "Simple local interpolation of surfaces using
// normal vectors", Computer Aided Geometric Design 22 (2005) 327-347). Each edge a-b becomes the
// quadratic curve
//   x(t) = x_a (1 - t) + x_b t - c t (1 - t),   t in [0, 1],
// whose tangents x'(0) = d - c and x'(1) = d + c (d = x_b - x_a) are normal to the normals at its
// ends: n . c = n . d for a normal n at a, n . c = -n . d at b. With one normal at each end, c is
// Nagata's curvature coefficient, the least-norm solution, alpha n_a + beta n_b with
//   alpha = (n_a.d + g n_b.d) / (1 - g^2),  beta = -(n_b.d + g n_a.d) / (1 - g^2),  g = n_a . n_b.
// abut solves the least-norm least-squares problem of all the edge's conditions (its normal
// equations with a Tikhonov term of 1e-8 of their trace, refined twice): the same c there, and
// where the two normals are nearly parallel (the equations then nearly coincide) the weak
// direction fades instead of dividing round-off by 1 - g^2. A node's normal is the area-weighted
// mean of the facets' normals around it, at the current coordinates. The edge's mid-point is
// (x_a + x_b) / 2 - c / 4, so a triangle's patch is the quadratic triangle on its corners and its
// edges' mid-points (Nagata's triangular patch is quadratic), and a quadrilateral's the 8-node
// serendipity patch on them (Nagata's quadrilateral patch has the same eight terms).
//
// Creases: an edge whose facets fold by more than the crease angle splits the facets around each
// of its nodes into sectors, each with its own normal (its facets' mean). An edge inside a sector
// takes the sector's normals at its ends; a crease edge takes the normals of both its sides at
// each end (four conditions), so its curve is tangent to both sides: a box's edges stay straight,
// a cylinder's rim keeps its arc, and the flat end beside it stays flat. Where the smooth surface
// ends (a free border, a crease), a node's normal comes from its side's facets alone, one facet at
// a corner: the facet next to it is then no better than its chord.
//
// The patches enter the contact as curved faces do (dependent_nodes.hpp, facet_parent.hpp): each
// facet becomes n x n facets whose corners lie on its patch, and each of them knows its patch (the
// quadratic shape functions over the facet's corners and its edges' mid-points). Mid-points and
// corners are dependent nodes: the facet's linear interpolation of its nodes (which spreads the
// forces) plus an offset, the c / 4 terms, that update() sets from the current coordinates. The
// offset's own dependence on the nodes is left out of the forces and the static tangent: exact
// for a rigid or fixed smoothed surface, and of the order of its strain times its curvature else.
#include <array>
#include <cstdint>
#include <map>
#include <span>
#include <utility>
#include <vector>

#include "abut/contact/dependent_nodes.hpp"
#include "abut/contact/facet_parent.hpp"

namespace abut {

// The default crease angle [degrees]: a coarse mesh of a curved surface folds by up to some 45
// degrees between facets (8 around a circle), a box's edges by 90.
inline constexpr double kSmoothingCrease = 60.0;

class NagataSmoothing {
 public:
  // `crease_degrees`: folds sharper than this stay sharp.
  explicit NagataSmoothing(double crease_degrees = kSmoothingCrease);

  struct Facets {
    std::vector<std::array<std::int32_t, 4>> facets;  // corners: host or dependent nodes
    std::vector<FacetParent> parents;                 // each one's patch
    std::vector<std::size_t> source;                  // the facet of the input it came from
  };
  // The n x n facets (n = `divisions`) of each of `facets` (host nodes, counter-clockwise about
  // the outward normal; a triangle repeats its last node) on its patch. New corners and the edges'
  // mid-points join `dependents` (whose `first` is the host's node count), shared where facets
  // meet; their offsets are set by update(). May be called for several surfaces in turn.
  Facets smooth(std::span<const std::array<std::int32_t, 4>> facets, DependentNodes& dependents,
                int divisions);
  // Sets the offsets of the dependent nodes made by smooth() at the host's coordinates.
  void update(std::span<const double> x, std::span<const double> y, std::span<const double> z,
              DependentNodes& dependents) const;
  bool empty() const { return facets_.empty(); }

 private:
  std::int32_t mid_point(std::int32_t facet, int corner_a, int corner_b,
                         DependentNodes& dependents);
  std::int32_t corner(std::span<const std::int32_t> nodes, std::span<const double> weights,
                      std::span<const std::pair<std::int32_t, double>> edge_terms,
                      DependentNodes& dependents);

  double crease_cos_;
  std::vector<std::array<std::int32_t, 4>> facets_;  // the facets smoothed (host nodes)
  // An edge a < b (host nodes) and the facets along it, with their corners at a and b.
  struct EdgeSide {
    std::int32_t facet = 0;
    int corner_a = 0, corner_b = 0;
  };
  struct Edge {
    std::int32_t a = 0, b = 0;
    std::vector<EdgeSide> sides;
  };
  std::vector<Edge> edges_;
  std::map<std::pair<std::int32_t, std::int32_t>, std::int32_t> edge_of_;  // sorted (a, b)
  // Offset of a dependent node k - first: sum of weight x (mid-point offset of edge).
  struct OffsetTerm {
    std::int32_t node = 0, edge = 0;
    double weight = 0.0;
  };
  std::vector<OffsetTerm> terms_;
  // A dependent node by its terms (host node, weight in units of 2^-40), so that facets that
  // share an edge share its points.
  std::map<std::vector<std::pair<std::int32_t, std::int64_t>>, std::int32_t> index_;
};

}  // namespace abut
