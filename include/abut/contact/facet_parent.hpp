#pragma once
// A facet that is a piece of a curved face (a quadratic solid's face cut into facets whose corners
// are dependent nodes, dependent_nodes.hpp): the face's nodes, its shape functions and the natural
// coordinates of the facet's corners in the face. The static contact integrates the face's own
// shape functions over each overlap of a surface-to-surface cell (mortar.hpp), so a contact
// pressure loads the face's nodes with the face's consistent shares, and measures the gap between
// the points of the true faces these weights make (docs/contact.md, "Curved faces").
#include <array>
#include <cstdint>

#include "abut/contact/quad.hpp"

namespace abut {

struct FacetParent {
  // n[a] = N_a(xi) for a < count, at the face's natural coordinates xi; null: a plain facet.
  using Shape = void (*)(const double xi[2], double* n);
  static constexpr int kMaxNodes = 16;  // a cubic Lagrange face
  Shape shape = nullptr;
  int count = 0;
  std::array<std::int32_t, kMaxNodes> nodes{};
  // Of the facet's corners 0-3 (a triangle repeats corner 2 as corner 3).
  std::array<std::array<double, 2>, 4> corner_xi{};

  bool curved() const { return shape != nullptr; }
  // The face's shape functions at the facet's reference point (s, t) in [-1, 1]^2, whose natural
  // coordinates are the bilinear interpolation of the corners'.
  void at(double s, double t, double* n) const {
    const auto w = quad_shape(s, t);
    double xi[2] = {0.0, 0.0};
    for (int v = 0; v < 4; ++v)
      for (int r = 0; r < 2; ++r) xi[r] += w[v] * corner_xi[v][r];
    shape(xi, n);
  }
};

}  // namespace abut
