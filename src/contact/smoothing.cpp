#include "abut/contact/smoothing.hpp"

#include <algorithm>
#include <cmath>

#include "abut/contact/quad.hpp"
#include "abut/core/face_subdivision.hpp"

namespace abut {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The 8-node serendipity quadrilateral on [-1, 1]^2: corners 0-3 as quad.hpp's, then the
// mid-points of edges 0-3 (edge e joins corners e and e + 1).
void quad8_shape(const double xi[2], double* n) {
  const double s = xi[0], t = xi[1];
  constexpr double cs[4] = {-1.0, 1.0, 1.0, -1.0}, ct[4] = {-1.0, -1.0, 1.0, 1.0};
  for (int a = 0; a < 4; ++a)
    n[a] = 0.25 * (1.0 + s * cs[a]) * (1.0 + t * ct[a]) * (s * cs[a] + t * ct[a] - 1.0);
  n[4] = 0.5 * (1.0 - s * s) * (1.0 - t);
  n[5] = 0.5 * (1.0 + s) * (1.0 - t * t);
  n[6] = 0.5 * (1.0 - s * s) * (1.0 + t);
  n[7] = 0.5 * (1.0 - s) * (1.0 - t * t);
}

// The 6-node triangle on (s, t), corners at (0, 0), (1, 0), (0, 1), then the mid-points of edges
// 0-1, 1-2 and 2-0.
void tri6_shape(const double xi[2], double* n) {
  const double l[3] = {1.0 - xi[0] - xi[1], xi[0], xi[1]};
  for (int a = 0; a < 3; ++a) n[a] = l[a] * (2.0 * l[a] - 1.0);
  n[3] = 4.0 * l[0] * l[1];
  n[4] = 4.0 * l[1] * l[2];
  n[5] = 4.0 * l[2] * l[0];
}

// The least-norm solution of the normal equations m c = r of an edge's conditions, from
// (m + eps I) c = r with eps = 1e-8 trace(m), refined: it leaves out the directions no condition
// sets (Nagata's coefficient lies in the span of the normals) and fades those that nearly
// parallel normals set only weakly (1 - cos of their angle below some 1e-8, where the two
// conditions nearly coincide and their difference is round-off).
Vec3 least_norm_solution(const double (&m)[3][3], const Vec3& r) {
  const double eps = 1e-8 * (m[0][0] + m[1][1] + m[2][2]);
  if (!(eps > 0.0)) return {};
  double a[3][3];
  for (int p = 0; p < 3; ++p)
    for (int q = 0; q < 3; ++q) a[p][q] = m[p][q] + (p == q ? eps : 0.0);
  // Cramer's rule on the symmetric positive definite 3 x 3 system.
  const auto det3 = [](const double(&b)[3][3]) {
    return b[0][0] * (b[1][1] * b[2][2] - b[1][2] * b[2][1]) -
           b[0][1] * (b[1][0] * b[2][2] - b[1][2] * b[2][0]) +
           b[0][2] * (b[1][0] * b[2][1] - b[1][1] * b[2][0]);
  };
  const double det = det3(a);
  const auto solve = [&](const Vec3& rhs) {
    Vec3 c;
    for (int k = 0; k < 3; ++k) {
      double b[3][3];
      for (int p = 0; p < 3; ++p)
        for (int q = 0; q < 3; ++q) b[p][q] = q == k ? rhs[p] : a[p][q];
      c[k] = det3(b) / det;
    }
    return c;
  };
  // Two steps of iterative refinement towards m c = r: the error of a direction the conditions
  // set with weight lambda falls as (eps / (lambda + eps))^3, to round-off where lambda >> eps.
  Vec3 c = solve(r);
  for (int step = 0; step < 2; ++step) {
    Vec3 residual = r;
    for (int p = 0; p < 3; ++p)
      for (int q = 0; q < 3; ++q) residual[p] -= m[p][q] * c[q];
    c += solve(residual);
  }
  return c;
}

}  // namespace

NagataSmoothing::NagataSmoothing(double crease_degrees)
    : crease_cos_(std::cos(crease_degrees * kPi / 180.0)) {}

std::int32_t NagataSmoothing::mid_point(std::int32_t facet, int corner_a, int corner_b,
                                        DependentNodes& dependents) {
  const std::int32_t a = facets_[static_cast<std::size_t>(facet)][corner_a];
  const std::int32_t b = facets_[static_cast<std::size_t>(facet)][corner_b];
  const auto key = std::minmax(a, b);
  auto it = edge_of_.find(key);
  if (it == edge_of_.end()) {
    it = edge_of_.emplace(key, static_cast<std::int32_t>(edges_.size())).first;
    edges_.push_back({key.first, key.second, {}});
  }
  // The facet's corners at the edge's nodes, in the edge's order.
  Edge& edge = edges_[static_cast<std::size_t>(it->second)];
  edge.sides.push_back(a == edge.a ? EdgeSide{facet, corner_a, corner_b}
                                   : EdgeSide{facet, corner_b, corner_a});
  const std::int32_t nodes[2] = {a, b};
  const double weights[2] = {0.5, 0.5};
  const std::pair<std::int32_t, double> term[1] = {{it->second, 1.0}};
  return corner(nodes, weights, term, dependents);
}

std::int32_t NagataSmoothing::corner(std::span<const std::int32_t> nodes,
                                     std::span<const double> weights,
                                     std::span<const std::pair<std::int32_t, double>> edge_terms,
                                     DependentNodes& dependents) {
  std::vector<std::pair<std::int32_t, std::int64_t>> key;
  for (std::size_t a = 0; a < nodes.size(); ++a)
    key.emplace_back(nodes[a], std::llround(std::ldexp(weights[a], 40)));
  std::sort(key.begin(), key.end());
  if (const auto it = index_.find(key); it != index_.end()) return it->second;
  const std::int32_t k = dependents.add(nodes, weights);
  for (const auto& [edge, weight] : edge_terms) terms_.push_back({k, edge, weight});
  index_.emplace(std::move(key), k);
  return k;
}

NagataSmoothing::Facets NagataSmoothing::smooth(std::span<const std::array<std::int32_t, 4>> facets,
                                                DependentNodes& dependents, int divisions) {
  Facets out;
  for (std::size_t f = 0; f < facets.size(); ++f) {
    const std::array<std::int32_t, 4>& host = facets[f];
    const auto facet = static_cast<std::int32_t>(facets_.size());
    facets_.push_back(host);
    const bool quad = host[3] != host[2];
    const int corners = quad ? 4 : 3;
    FacetParent parent;
    parent.shape = quad ? quad8_shape : tri6_shape;
    parent.count = 2 * corners;
    for (int a = 0; a < corners; ++a) {
      parent.nodes[static_cast<std::size_t>(a)] = host[a];
      parent.nodes[static_cast<std::size_t>(corners + a)] =
          mid_point(facet, a, (a + 1) % corners, dependents);
    }
    const FaceSubdivision g = subdivide_reference_face(quad, divisions);
    std::vector<std::int32_t> node_of(g.corners.size(), -1);
    const auto node_at = [&](std::int32_t c) {
      std::int32_t& v = node_of[static_cast<std::size_t>(c)];
      if (v >= 0) return v;
      double n[8];
      parent.shape(g.corners[static_cast<std::size_t>(c)].data(), n);
      // x_v = sum_a N_a x_a + sum_e N_e ((x_a + x_b) / 2 + o_e): linear weights on the corners,
      // and the mid-points' offsets.
      std::vector<double> weight(static_cast<std::size_t>(corners), 0.0);
      std::vector<std::pair<std::int32_t, double>> edge_terms;
      for (int a = 0; a < corners; ++a) {
        weight[static_cast<std::size_t>(a)] += n[a];
        const double m = n[corners + a];
        if (std::abs(m) < 1e-14) continue;
        weight[static_cast<std::size_t>(a)] += 0.5 * m;
        weight[static_cast<std::size_t>((a + 1) % corners)] += 0.5 * m;
        edge_terms.emplace_back(edge_of_.at(std::minmax(host[a], host[(a + 1) % corners])), m);
      }
      std::vector<std::int32_t> nodes;
      std::vector<double> weights;
      for (int a = 0; a < corners; ++a)
        if (std::abs(weight[static_cast<std::size_t>(a)]) >= 1e-14) {
          nodes.push_back(host[a]);
          weights.push_back(weight[static_cast<std::size_t>(a)]);
        }
      // A corner of the facet is its node.
      v = nodes.size() == 1 && std::abs(weights[0] - 1.0) < 1e-14
              ? nodes[0]
              : corner(nodes, weights, edge_terms, dependents);
      return v;
    };
    for (const auto& sub : g.facets) {
      std::array<std::int32_t, 4> piece{};
      for (int a = 0; a < 4; ++a) {
        piece[a] = node_at(sub[a]);
        parent.corner_xi[static_cast<std::size_t>(a)] = g.corners[static_cast<std::size_t>(sub[a])];
      }
      out.facets.push_back(piece);
      out.parents.push_back(parent);
      out.source.push_back(f);
    }
  }
  return out;
}

void NagataSmoothing::update(std::span<const double> x, std::span<const double> y,
                             std::span<const double> z, DependentNodes& dependents) const {
  if (facets_.empty()) return;
  const std::size_t nf = facets_.size();
  std::vector<Vec3> area(nf), unit(nf);
  for (std::size_t f = 0; f < nf; ++f) {
    const QuadCorners c = quad_corners(facets_[f], x, y, z);
    area[f] = cross(c[2] - c[0], c[3] - c[1]) * 0.5;
    unit[f] = normalized(area[f]);
  }
  // The facets around each node, split into sectors by the crease edges: corner k of facet f is
  // entry 4 f + k, joined with the corners of the other facets of a smooth edge at its nodes.
  std::vector<std::int32_t> root(4 * nf);
  for (std::size_t i = 0; i < root.size(); ++i) root[i] = static_cast<std::int32_t>(i);
  const auto find = [&root](std::int32_t i) {
    while (root[static_cast<std::size_t>(i)] != i)
      i = root[static_cast<std::size_t>(i)] =
          root[static_cast<std::size_t>(root[static_cast<std::size_t>(i)])];
    return i;
  };
  const auto corner = [](const EdgeSide& s, int k) { return 4 * s.facet + k; };
  for (const Edge& e : edges_) {
    bool crease = false;
    for (const EdgeSide& s : e.sides)
      for (const EdgeSide& t : e.sides)
        if (dot(unit[static_cast<std::size_t>(s.facet)], unit[static_cast<std::size_t>(t.facet)]) <
            crease_cos_)
          crease = true;
    if (crease) continue;
    for (const EdgeSide& s : e.sides) {
      root[static_cast<std::size_t>(find(corner(s, s.corner_a)))] =
          find(corner(e.sides[0], e.sides[0].corner_a));
      root[static_cast<std::size_t>(find(corner(s, s.corner_b)))] =
          find(corner(e.sides[0], e.sides[0].corner_b));
    }
  }
  // Each sector's normal: its facets' area vectors summed.
  std::vector<Vec3> sector(4 * nf);
  for (std::size_t f = 0; f < nf; ++f)
    for (int k = 0; k < 4; ++k)
      sector[static_cast<std::size_t>(find(static_cast<std::int32_t>(4 * f) + k))] += area[f];
  // Each edge's mid-point offset, -c / 4.
  std::vector<Vec3> offset(edges_.size());
  for (std::size_t i = 0; i < edges_.size(); ++i) {
    const Edge& e = edges_[i];
    const auto a = static_cast<std::size_t>(e.a), b = static_cast<std::size_t>(e.b);
    const Vec3 d = Vec3{x[b], y[b], z[b]} - Vec3{x[a], y[a], z[a]};
    // n . c = n . d for a normal n at a, n . c = -n . d at b: normal equations M c = r.
    double m[3][3] = {};
    Vec3 r;
    const auto row = [&](const Vec3& n, double value) {
      for (int p = 0; p < 3; ++p)
        for (int q = 0; q < 3; ++q) m[p][q] += n[p] * n[q];
      r += n * value;
    };
    for (const EdgeSide& s : e.sides) {
      const Vec3 na = normalized(sector[static_cast<std::size_t>(find(corner(s, s.corner_a)))]);
      const Vec3 nb = normalized(sector[static_cast<std::size_t>(find(corner(s, s.corner_b)))]);
      row(na, dot(na, d));
      row(nb, -dot(nb, d));
    }
    offset[i] = least_norm_solution(m, r) * -0.25;
  }
  dependents.offset.resize(3 * dependents.size());
  for (const OffsetTerm& t : terms_) {
    const auto k = 3 * static_cast<std::size_t>(t.node - dependents.first);
    dependents.offset[k] = dependents.offset[k + 1] = dependents.offset[k + 2] = 0.0;
  }
  for (const OffsetTerm& t : terms_) {
    const auto k = 3 * static_cast<std::size_t>(t.node - dependents.first);
    const Vec3& o = offset[static_cast<std::size_t>(t.edge)];
    dependents.offset[k] += t.weight * o.x;
    dependents.offset[k + 1] += t.weight * o.y;
    dependents.offset[k + 2] += t.weight * o.z;
  }
}

}  // namespace abut
