#pragma once
// Points and shape weights on a static contact's facets (static_contact.cpp and
// static_contact_points.cpp): a facet's bilinear shape functions, or on a facet of a curved face
// (facet_parent.hpp) the face's own, and the point they give.
#include <array>
#include <cstdint>

#include "abut/contact/interface.hpp"
#include "abut/contact/quad.hpp"
#include "abut/contact/static_contact.hpp"

namespace abut::facet_weights {

// Adds sign N_a at the facet's reference point r to w: the facet's bilinear shape functions on
// its corners, or, for a facet of a curved face, the face's own on the face's nodes.
inline void add_shape(ContactWeights& w, const std::array<std::int32_t, 4>& facet,
                      const FacetParent* parent, const std::array<double, 2>& r, double sign) {
  if (parent && parent->curved()) {
    double n[FacetParent::kMaxNodes];
    parent->at(r[0], r[1], n);
    for (int a = 0; a < parent->count; ++a) w.add(parent->nodes[a], sign * n[a]);
    return;
  }
  const auto n = quad_shape(r[0], r[1]);
  for (int a = 0; a < 4; ++a) w.add(facet[a], sign * n[a]);
}

// The point sum_a w_a x_a - origin of weights over the nodes of `in`.
inline Vec3 weighted_point(const ContactWeights& w, const ContactInput& in, const Vec3& origin) {
  Vec3 x;
  for (int k = 0; k < w.count; ++k) {
    const auto i = static_cast<std::size_t>(w.nodes[k]);
    x += (Vec3{in.x[i], in.y[i], in.z[i]} - origin) * w.weights[k];
  }
  return x;
}

// The point of a facet at its reference point r, on its curved face when it has one.
inline Vec3 surface_point(const std::array<std::int32_t, 4>& facet, const FacetParent* parent,
                          const std::array<double, 2>& r, const ContactInput& in) {
  ContactWeights w;
  add_shape(w, facet, parent, r, 1.0);
  return weighted_point(w, in, Vec3{});
}

// The curved face of a surface's facet, or null.
inline const FacetParent* parent_of(const ContactSurface& s, std::int32_t facet) {
  return s.parent.empty() || !s.parent[static_cast<std::size_t>(facet)].curved()
             ? nullptr
             : &s.parent[static_cast<std::size_t>(facet)];
}

}  // namespace abut::facet_weights
