// Cell-wise segment-to-segment integration (mortar.hpp): projection, Sutherland-Hodgman clipping
// and the integrals of the shape functions over the overlap polygons. Fixed-size buffers only:
// this runs for every touching point every step.
#include "abut/contact/mortar.hpp"

#include <algorithm>
#include <cmath>

#include "abut/core/triangle_rule.hpp"

namespace abut {
namespace {

using P2 = std::array<double, 2>;
constexpr int kMaxVertices = 16;  // a quad clipped by a quad has at most 8

struct Polygon {
  std::array<P2, kMaxVertices> v;
  int n = 0;
};

double cross2(const P2& a, const P2& b, const P2& c) {  // (b - a) x (c - a)
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

double signed_area(const Polygon& p) {
  double s = 0.0;
  for (int i = 0; i < p.n; ++i) {
    const P2& a = p.v[i];
    const P2& b = p.v[(i + 1) % p.n];
    s += a[0] * b[1] - a[1] * b[0];
  }
  return 0.5 * s;
}

// Sutherland-Hodgman: the part of `subject` on the left of each edge of the convex,
// counter-clockwise `clip`. A collapsed edge (a triangle's) keeps everything.
void clip_polygon(const Polygon& subject, const Polygon& clip, Polygon& out) {
  Polygon a = subject, b;
  for (int e = 0; e < clip.n && a.n > 0; ++e) {
    const P2& p = clip.v[e];
    const P2& q = clip.v[(e + 1) % clip.n];
    if (p == q) continue;
    b.n = 0;
    for (int i = 0; i < a.n; ++i) {
      const P2& s = a.v[i];
      const P2& t = a.v[(i + 1) % a.n];
      const double ds = cross2(p, q, s), dt = cross2(p, q, t);
      if (ds >= 0.0 && b.n < kMaxVertices) b.v[b.n++] = s;
      if ((ds >= 0.0) != (dt >= 0.0) && b.n < kMaxVertices) {
        const double r = ds / (ds - dt);
        b.v[b.n++] = {s[0] + r * (t[0] - s[0]), s[1] + r * (t[1] - s[1])};
      }
    }
    a = b;
  }
  out = a;
}

// A triangle is a quad whose last corner repeats the third (mesh.hpp, Quad4).
bool is_triangle(const std::array<P2, 4>& c) { return c[2] == c[3]; }

// Area coordinates of the point x of the plane in the triangle c[0], c[1], c[2].
std::array<double, 3> area_coordinates(const std::array<P2, 4>& c, const P2& x) {
  const double whole = cross2(c[0], c[1], c[2]);
  if (whole == 0.0) return {1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0};
  const double l1 = cross2(c[0], x, c[2]) / whole, l2 = cross2(c[0], c[1], x) / whole;
  return {1.0 - l1 - l2, l1, l2};
}

// Reference coordinates of the point x of the plane in the bilinear quad with plane corners c
// (Newton from the centre; one step for a parallelogram). A triangle's map collapses its edge
// eta = 1 into the third corner, where Newton's method fails: its exact inverse from the area
// coordinates instead (eta = 2 l2 - 1, xi = (l1 - l0) / (l0 + l1)).
P2 reference_of(const std::array<P2, 4>& c, const P2& x) {
  if (is_triangle(c)) {
    const auto l = area_coordinates(c, x);
    const double base = l[0] + l[1];
    return {base != 0.0 ? (l[1] - l[0]) / base : 0.0, 2.0 * l[2] - 1.0};
  }
  double xi = 0.0, eta = 0.0;
  for (int it = 0; it < 12; ++it) {
    const auto n = quad_shape(xi, eta);
    double rx = -x[0], ry = -x[1];
    for (int a = 0; a < 4; ++a) rx += n[a] * c[a][0], ry += n[a] * c[a][1];
    // d/dxi and d/deta of the map.
    const double ax = 0.25 * ((c[1][0] - c[0][0]) * (1 - eta) + (c[2][0] - c[3][0]) * (1 + eta));
    const double ay = 0.25 * ((c[1][1] - c[0][1]) * (1 - eta) + (c[2][1] - c[3][1]) * (1 + eta));
    const double bx = 0.25 * ((c[3][0] - c[0][0]) * (1 - xi) + (c[2][0] - c[1][0]) * (1 + xi));
    const double by = 0.25 * ((c[3][1] - c[0][1]) * (1 - xi) + (c[2][1] - c[1][1]) * (1 + xi));
    const double det = ax * by - ay * bx;
    if (det == 0.0) break;
    const double dxi = -(rx * by - ry * bx) / det, deta = -(ax * ry - ay * rx) / det;
    xi += dxi, eta += deta;
    if (std::abs(dxi) + std::abs(deta) < 1e-13) break;
  }
  return {xi, eta};
}

// Adds int over the polygon of each N_a of the quads `first` and `second` (reference
// coordinates affine on each triangle of a fan: the edge-midpoint rule, exact for quadratics).
// On a triangle the N_a are its area coordinates, affine in the plane (the fourth, a repeat of
// the third node, gets 0): the same rule is exact for them.
void integrate(const Polygon& poly, const std::array<P2, 4>& first, const std::array<P2, 4>& second,
               std::array<double, 4>& n_first, std::array<double, 4>& n_second, double scale) {
  std::array<P2, kMaxVertices> r1, r2;
  const bool tri1 = is_triangle(first), tri2 = is_triangle(second);
  auto coordinates = [](const std::array<P2, 4>& c, bool triangle, const P2& x) -> P2 {
    if (!triangle) return reference_of(c, x);
    const auto l = area_coordinates(c, x);
    return {l[1], l[2]};
  };
  for (int i = 0; i < poly.n; ++i) {
    r1[i] = coordinates(first, tri1, poly.v[i]);
    r2[i] = coordinates(second, tri2, poly.v[i]);
  }
  auto add_midpoint = [](bool triangle, const P2& a, const P2& b, double w,
                         std::array<double, 4>& out) {
    const double u = 0.5 * (a[0] + b[0]), v = 0.5 * (a[1] + b[1]);
    const std::array<double, 4> n =
        triangle ? std::array<double, 4>{1.0 - u - v, u, v, 0.0} : quad_shape(u, v);
    for (int k = 0; k < 4; ++k) out[k] += w * n[k];
  };
  for (int i = 1; i + 1 < poly.n; ++i) {
    const double w = cross2(poly.v[0], poly.v[i], poly.v[i + 1]) / 6.0 * scale;  // area / 3
    add_midpoint(tri1, r1[0], r1[i], w, n_first);
    add_midpoint(tri1, r1[i], r1[i + 1], w, n_first);
    add_midpoint(tri1, r1[i + 1], r1[0], w, n_first);
    add_midpoint(tri2, r2[0], r2[i], w, n_second);
    add_midpoint(tri2, r2[i], r2[i + 1], w, n_second);
    add_midpoint(tri2, r2[i + 1], r2[0], w, n_second);
  }
}

// Calls f(x, w) for each point of Dunavant's degree-4 rule on every triangle of the polygon's fan,
// w its weight times the triangle's area times `scale`.
template <class F>
void for_each_degree4_point(const Polygon& poly, double scale, F&& f) {
  for (int i = 1; i + 1 < poly.n; ++i) {
    const double area = cross2(poly.v[0], poly.v[i], poly.v[i + 1]) / 2.0 * scale;
    for (const TrianglePoint& q : kTriangleDegree4) {
      const double l0 = 1.0 - q.l1 - q.l2;
      f(P2{l0 * poly.v[0][0] + q.l1 * poly.v[i][0] + q.l2 * poly.v[i + 1][0],
           l0 * poly.v[0][1] + q.l1 * poly.v[i][1] + q.l2 * poly.v[i + 1][1]},
        q.weight * area);
    }
  }
}

// Adds int over the polygon of each N_a of a curved face whose facet has the plane corners
// `facet`: Dunavant's degree-4 rule on each triangle of a fan, each point's reference coordinates
// found in the facet (exact for a parallelogram facet, where N_a is a polynomial of degree 3 at
// most in the plane's coordinates: quad8's serendipity terms).
void integrate_face(const Polygon& poly, const std::array<P2, 4>& facet, const FacetParent& parent,
                    std::array<double, FacetParent::kMaxNodes>& out, double scale) {
  double n[FacetParent::kMaxNodes];
  for_each_degree4_point(poly, scale, [&](const P2& x, double weight) {
    const P2 r = reference_of(facet, x);
    parent.at(r[0], r[1], n);
    for (int a = 0; a < parent.count; ++a) out[a] += weight * n[a];
  });
}

// A facet's outward normal m scaled to unit component along n (mortar.hpp: the cell's push); its
// projected area times it is its area vector, which vanishes with the projection as the facet
// turns edge-on. A facet facing away adds nothing.
Vec3 slope_normal(const QuadCorners& facet, const Vec3& n) {
  const Vec3 m = quad_centre_normal(facet);
  const double along = dot(m, n);
  return along > 0.0 ? m * (1.0 / along) : Vec3{};
}

}  // namespace

double clipped_area(std::span<const std::array<double, 2>> subject,
                    std::span<const std::array<double, 2>> clip) {
  Polygon s, c, out;
  for (const auto& p : subject) s.v[s.n++] = p;
  for (const auto& p : clip) c.v[c.n++] = p;
  clip_polygon(s, c, out);
  return out.n >= 3 ? signed_area(out) : 0.0;
}

CellOverlap overlap_cell(const QuadCorners& own, const CellBounds& cell, const Vec3& normal,
                         std::span<const std::int32_t> ids, std::span<const QuadCorners> corners,
                         const FacetParent* own_parent, std::span<const FacetParent* const> parents,
                         std::vector<CellSample>* samples) {
  CellOverlap r;
  r.own_parent = own_parent;
  // A basis of the plane, and the cell's centre as its origin (round-off).
  const Vec3 helper = std::abs(normal.x) < 0.6 ? Vec3{1.0, 0.0, 0.0} : Vec3{0.0, 1.0, 0.0};
  const Vec3 e1 = normalized(cross(normal, helper));
  const Vec3 e2 = cross(normal, e1);
  const Vec3 origin = quad_point(own, 0.5 * (cell.xi0 + cell.xi1), 0.5 * (cell.eta0 + cell.eta1));
  auto in_plane = [&](const Vec3& x) -> P2 { return {dot(x - origin, e1), dot(x - origin, e2)}; };
  std::array<P2, 4> own_plane;
  for (int a = 0; a < 4; ++a) own_plane[a] = in_plane(own[a]);
  // The cell, counter-clockwise in the plane (it faces the other way than the plane's normal).
  const Vec3 x00 = quad_point(own, cell.xi0, cell.eta0), x10 = quad_point(own, cell.xi1, cell.eta0),
             x11 = quad_point(own, cell.xi1, cell.eta1), x01 = quad_point(own, cell.xi0, cell.eta1);
  Polygon subject;
  subject.n = 4;
  subject.v = {in_plane(x00), in_plane(x10), in_plane(x11), in_plane(x01)};
  double projected = signed_area(subject);
  if (projected < 0.0) {
    std::reverse(subject.v.begin(), subject.v.begin() + 4);
    projected = -projected;
  }
  const double true_area = 0.5 * norm(cross(x11 - x00, x01 - x10));
  if (!(projected > 1e-12 * true_area)) return r;  // the cell stands on edge to the plane
  const double scale = true_area / projected;
  double lo[2] = {subject.v[0][0], subject.v[0][1]}, hi[2] = {lo[0], lo[1]};
  for (int i = 1; i < 4; ++i)
    for (int k = 0; k < 2; ++k) {
      lo[k] = std::min(lo[k], subject.v[i][k]);
      hi[k] = std::max(hi[k], subject.v[i][k]);
    }
  std::array<std::size_t, kMaxOverlaps> slot_of{};  // which of `ids` each slot holds
  Vec3 push;                                        // sum of A_k m_k / (m_k . n)
  for (std::size_t k = 0; k < ids.size(); ++k) {
    std::array<P2, 4> facet_plane;
    Polygon clip;
    clip.n = 4;
    bool apart[4] = {true, true, true, true};  // entirely beyond one side of the cell's box
    for (int a = 0; a < 4; ++a) {
      facet_plane[a] = clip.v[a] = in_plane(corners[k][a]);
      apart[0] = apart[0] && clip.v[a][0] <= lo[0];
      apart[1] = apart[1] && clip.v[a][0] >= hi[0];
      apart[2] = apart[2] && clip.v[a][1] <= lo[1];
      apart[3] = apart[3] && clip.v[a][1] >= hi[1];
    }
    if (apart[0] || apart[1] || apart[2] || apart[3]) continue;
    const double facet_area = signed_area(clip);
    if (facet_area == 0.0) continue;
    if (facet_area < 0.0) std::reverse(clip.v.begin(), clip.v.begin() + 4);
    Polygon overlap;
    clip_polygon(subject, clip, overlap);
    if (overlap.n < 3) continue;
    const double a = signed_area(overlap);
    if (!(a > 0.0)) continue;
    // Overflow folds into the first slot (the partner's when the partner overlaps the cell).
    int slot = r.count;
    if (r.count == kMaxOverlaps) {
      slot = 0;
      for (int b = 0; b < 4; ++b) facet_plane[b] = in_plane(corners[slot_of[0]][b]);
    } else {
      slot_of[slot] = k;
      r.facet[slot] = ids[k];
      r.target[slot] = {};
      r.target_parent[slot] = parents.empty() ? nullptr : parents[k];
      r.target_face[slot] = {};
      ++r.count;
    }
    r.area += a * scale;
    push += slope_normal(corners[k], normal) * (a * scale);
    integrate(overlap, own_plane, facet_plane, r.own, r.target[slot], scale);
    if (own_parent && own_parent->curved())
      integrate_face(overlap, own_plane, *own_parent, r.own_face, scale);
    if (r.target_parent[slot] && r.target_parent[slot]->curved())
      integrate_face(overlap, facet_plane, *r.target_parent[slot], r.target_face[slot], scale);
    if (samples)
      for_each_degree4_point(overlap, scale, [&](const P2& x, double weight) {
        samples->push_back(
            {weight, slot, reference_of(own_plane, x), reference_of(facet_plane, x)});
      });
  }
  r.push = r.area > 0.0 ? push * (1.0 / r.area) : normal;
  return r;
}

CellOverlap cover_cell(const std::array<std::int32_t, 4>& own, const CellBounds& cell,
                       const Vec3& normal, std::int32_t partner,
                       std::span<const std::int32_t> candidates, const CoverFacets& other,
                       const FacetParent* own_parent, std::vector<CellSample>* samples) {
  std::array<std::int32_t, kMaxCoverFacets> ids{};
  std::array<QuadCorners, kMaxCoverFacets> corners{};
  std::array<const FacetParent*, kMaxCoverFacets> parents{};
  std::size_t count = 0;
  auto touches_own = [&own](const std::array<std::int32_t, 4>& nodes) {
    for (const std::int32_t i : nodes)
      if (std::find(own.begin(), own.end(), i) != own.end()) return true;
    return false;
  };
  auto add = [&](std::int32_t g) {
    const auto f = static_cast<std::size_t>(g);
    if (count == kMaxCoverFacets || (!other.active.empty() && !other.active[f]) ||
        (!other.twin.empty() && other.twin[f] >= 0) || touches_own(other.facets[f]))
      return;
    const QuadCorners c = quad_corners(other.facets[f], other.x, other.y, other.z);
    // Facing away (the far side), or edge-on: a wall whose projection is a line and whose
    // slope has no bound (the side of a block standing on the cell's plate).
    if (!(dot(quad_centre_normal(c), normal) >= kCoverMinCos)) return;
    ids[count] = g;
    parents[count] = other.parent.empty() ? nullptr : &other.parent[f];
    corners[count++] = c;
  };
  if (partner >= 0) add(partner);
  for (const std::int32_t g : candidates)
    if (g != partner) add(g);
  const QuadCorners c_own = quad_corners(own, other.x, other.y, other.z);
  CellOverlap o = overlap_cell(c_own, cell, normal, {ids.data(), count}, {corners.data(), count},
                               own_parent, {parents.data(), count}, samples);
  o.normal = normal;
  return o;
}

double cell_mean_gap(const std::array<std::int32_t, 4>& own, const CellOverlap& o,
                     const CoverFacets& other) {
  const double inv = 1.0 / o.area;
  auto at = [&other](std::int32_t i) {
    const auto k = static_cast<std::size_t>(i);
    return Vec3{other.x[k], other.y[k], other.z[k]};
  };
  // Own centroid less the other side's, over the covered part, both taken from a node of the
  // cell's facet: the weights sum to 1 on either side only to round-off, which would otherwise
  // scale with the distance from the origin (two coplanar faces would be found a few ulps of
  // their coordinates apart, open or closed at random).
  const Vec3 origin = at(own[0]);
  Vec3 centroid;
  if (o.own_parent && o.own_parent->curved()) {
    for (int a = 0; a < o.own_parent->count; ++a)
      centroid += (at(o.own_parent->nodes[a]) - origin) * (o.own_face[a] * inv);
  } else {
    for (int a = 0; a < 4; ++a) centroid += (at(own[a]) - origin) * (o.own[a] * inv);
  }
  for (int k = 0; k < o.count; ++k) {
    const FacetParent* parent = o.target_parent[k];
    if (parent && parent->curved()) {
      for (int b = 0; b < parent->count; ++b)
        centroid -= (at(parent->nodes[b]) - origin) * (o.target_face[k][b] * inv);
      continue;
    }
    for (int b = 0; b < 4; ++b)
      centroid -= (at(other.facets[static_cast<std::size_t>(o.facet[k])][b]) - origin) *
                  (o.target[k][b] * inv);
  }
  return dot(centroid, o.normal);
}

}  // namespace abut
