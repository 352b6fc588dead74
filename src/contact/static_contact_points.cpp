// Static contact (static_contact.hpp): where the points are at an evaluation, and the facets of
// the main surface near each, before their partners are chosen (static_contact.cpp).
#include <algorithm>
#include <cmath>

#include "abut/contact/quad.hpp"
#include "abut/contact/static_contact.hpp"
#include "facet_weights.hpp"

namespace abut {
using namespace facet_weights;

StaticContact::PointGeometry StaticContact::locate_points(const ContactInput& in, bool by_cells) {
  const std::size_t np = point_facet_.size();
  PointGeometry g;
  g.qx.resize(np), g.qy.resize(np), g.qz.resize(np);
  g.own_normal.resize(np);
  g.node_area.resize(np);
  g.regions.resize(by_cells ? np : 0);
  g.cell_reach.resize(by_cells ? np : 0);
  for (std::size_t p = 0; p < np; ++p) {
    StaticContactPoint& out = points_[p];
    out = StaticContactPoint{};
    if (point_node_[p] >= 0) {
      const std::int32_t n = point_node_[p];
      out.node = n;
      out.position = {in.x[n], in.y[n], in.z[n]};
      for (std::int32_t k = node_facet_start_[n]; k < node_facet_start_[n + 1]; ++k) {
        // int N_a dA over each facet around the node, 2 x 2 Gauss points.
        const auto& f = secondary_.facets[node_facets_[k]];
        const QuadCorners c = quad_corners(f, in.x, in.y, in.z);
        const double gauss = 1.0 / std::sqrt(3.0);
        for (const double xi : {-gauss, gauss})
          for (const double eta : {-gauss, gauss}) {
            double jacobian = 0.0;
            const Vec3 n_here = quad_normal(c, xi, eta, jacobian);
            const Vec3 dA = n_here * jacobian;
            const auto shape = quad_shape(xi, eta);
            double share = 0.0;
            for (int a = 0; a < 4; ++a)
              if (f[a] == n && (a < 3 || f[3] != f[2])) share += shape[a];
            if (f[3] == f[2] && f[2] == n) share += shape[3];
            out.area += share * jacobian;
            g.node_area[p] += dA * share;
          }
      }
    } else {
      out.facet = point_facet_[p];
      const QuadCorners c = quad_corners(secondary_.facets[out.facet], in.x, in.y, in.z);
      double jacobian = 0.0;
      g.own_normal[p] = quad_normal(c, point_xi_[p], point_eta_[p], jacobian);
      out.position = quad_point(c, point_xi_[p], point_eta_[p]);
      // A point of a curved face that acts alone lies on the face itself.
      if (const FacetParent* face = parent_of(secondary_, out.facet); face && !by_cells)
        out.position =
            surface_point(secondary_.facets[out.facet], face, {point_xi_[p], point_eta_[p]}, in);
      out.area = point_weight_[p] * jacobian;
      if (by_cells) {  // the cell's box, and the distance to its farthest corner
        const CellBounds& b = point_cell_[p];
        Box& r = g.regions[p];
        r.lo = r.hi = {out.position.x, out.position.y, out.position.z};
        for (const double cxi : {b.xi0, b.xi1})
          for (const double ceta : {b.eta0, b.eta1}) {
            const Vec3 corner = quad_point(c, cxi, ceta);
            g.cell_reach[p] = std::max(g.cell_reach[p], norm(corner - out.position));
            for (int k = 0; k < 3; ++k) {
              r.lo[k] = std::min(r.lo[k], corner[k]);
              r.hi[k] = std::max(r.hi[k], corner[k]);
            }
          }
      }
    }
    out.area *= settings_.weight;
    g.qx[p] = out.position.x, g.qy[p] = out.position.y, g.qz[p] = out.position.z;
  }
  return g;
}

CandidateList StaticContact::candidate_facets(const ContactInput& in, const PointGeometry& g,
                                              bool by_cells, double reach,
                                              double edge_tolerance) const {
  std::vector<Box> boxes(main_.size());
  for (std::size_t f = 0; f < main_.size(); ++f) {
    Box& b = boxes[f];
    b.lo = {1e300, 1e300, 1e300};
    b.hi = {-1e300, -1e300, -1e300};
    for (const std::int32_t n : main_.facets[f]) {
      const double c[3] = {in.x[n], in.y[n], in.z[n]};
      for (int k = 0; k < 3; ++k) {
        b.lo[k] = std::min(b.lo[k], c[k] - reach - edge_tolerance);
        b.hi[k] = std::max(b.hi[k], c[k] + reach + edge_tolerance);
      }
    }
  }
  BucketGrid grid;
  CandidateList candidates;
  if (!boxes.empty()) {
    grid.build(boxes);
    if (by_cells)
      grid.query(g.regions, candidates);
    else
      grid.query(g.qx, g.qy, g.qz, candidates);
  }
  return candidates;
}

}  // namespace abut
