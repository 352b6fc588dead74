#include "abut/contact/integration.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "abut/contact/quad.hpp"

namespace abut {
namespace {

struct Point1D {
  double s, w;
  double lo = 0.0, hi = 0.0;  // its cell: the weights laid end to end from the interval's start
};

// Gauss-Legendre rule with n points on [a, b].
void gauss_on(int n, double a, double b, std::vector<Point1D>& out) {
  const std::size_t first = out.size();
  const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
  if (n == 1) {
    out.push_back({mid, 2.0 * half});
  } else if (n == 2) {
    const double g = 1.0 / std::sqrt(3.0);
    out.push_back({mid - g * half, half});
    out.push_back({mid + g * half, half});
  } else {
    const double g = std::sqrt(0.6);
    out.push_back({mid - g * half, 5.0 / 9.0 * half});
    out.push_back({mid, 8.0 / 9.0 * half});
    out.push_back({mid + g * half, 5.0 / 9.0 * half});
  }
  double at = a;
  for (std::size_t k = first; k < out.size(); ++k) {
    out[k].lo = at;
    at = k + 1 == out.size() ? b : at + out[k].w;
    out[k].hi = at;
  }
}

// One direction of the rule: strips of width 0.5 (a quarter of the facet) at sharp ends.
std::vector<Point1D> rule_1d(int n, bool sharp_low, bool sharp_high) {
  constexpr double strip = 0.5;
  std::vector<Point1D> r;
  const double lo = sharp_low ? -1.0 + strip : -1.0;
  const double hi = sharp_high ? 1.0 - strip : 1.0;
  if (sharp_low) gauss_on(n, -1.0, lo, r);
  gauss_on(n, lo, hi, r);
  if (sharp_high) gauss_on(n, hi, 1.0, r);
  return r;
}

}  // namespace

int gauss_points_per_direction(int accuracy_level) {
  return accuracy_level <= 1 ? 1 : (accuracy_level == 2 ? 2 : 3);
}

std::vector<FacetPoint> facet_rule(int accuracy_level, bool edge_refinement, std::uint8_t sharp) {
  const int n = gauss_points_per_direction(accuracy_level);
  if (!edge_refinement) sharp = 0;
  // Edge 3 is xi = -1, edge 1 xi = +1, edge 0 eta = -1, edge 2 eta = +1.
  const auto along_xi = rule_1d(n, sharp & 8u, sharp & 2u);
  const auto along_eta = rule_1d(n, sharp & 1u, sharp & 4u);
  std::vector<FacetPoint> points;
  points.reserve(along_xi.size() * along_eta.size());
  for (const Point1D& e : along_eta)
    for (const Point1D& x : along_xi)
      points.push_back({x.s, e.s, x.w * e.w, x.lo, x.hi, e.lo, e.hi});
  return points;
}

std::vector<std::uint8_t> sharp_edges(const ContactSurface& surface, std::span<const double> x,
                                      std::span<const double> y, std::span<const double> z,
                                      double angle_degrees, std::vector<std::uint8_t>* free_edges) {
  const std::size_t n = surface.size();
  std::vector<Vec3> normal(n);
  for (std::size_t f = 0; f < n; ++f) {
    QuadCorners c;
    for (int a = 0; a < 4; ++a) {
      const auto i = surface.facets[f][a];
      c[a] = {x[i], y[i], z[i]};
    }
    normal[f] = quad_centre_normal(c);
  }
  // Edges keyed by their sorted node pair; sorting groups the facets that share an edge.
  struct EdgeUse {
    std::int32_t lo, hi, facet, local;
    bool forward;  // runs from lo to hi
  };
  std::vector<EdgeUse> uses;
  uses.reserve(4 * n);
  for (std::size_t f = 0; f < n; ++f)
    for (int e = 0; e < 4; ++e) {
      const auto a = surface.facets[f][e], b = surface.facets[f][(e + 1) % 4];
      if (a == b) continue;  // collapsed edge of a triangle
      uses.push_back({std::min(a, b), std::max(a, b), static_cast<std::int32_t>(f), e, a < b});
    }
  std::sort(uses.begin(), uses.end(), [](const EdgeUse& p, const EdgeUse& q) {
    if (p.lo != q.lo) return p.lo < q.lo;
    if (p.hi != q.hi) return p.hi < q.hi;
    return p.facet < q.facet;
  });
  const double cos_limit = std::cos(angle_degrees * std::numbers::pi / 180.0);
  const bool shells = !surface.twin.empty();
  std::vector<std::uint8_t> sharp(n, 0);
  if (free_edges) free_edges->assign(n, 0);
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i + 1;
    while (j < uses.size() && uses[j].lo == uses[i].lo && uses[j].hi == uses[i].hi) ++j;
    for (std::size_t k = i; k < j; ++k) {
      // Neighbours across the edge: the facets that run it the other way (a consistently
      // oriented surface), except the other side of the same shell, which meets every edge of it.
      bool neighbour = false, is_sharp = false;
      for (std::size_t m = i; m < j; ++m) {
        if (m == k || uses[m].forward == uses[k].forward) continue;
        if (shells && surface.twin[uses[k].facet] == uses[m].facet) continue;
        neighbour = true;
        if (dot(normal[uses[k].facet], normal[uses[m].facet]) < cos_limit) is_sharp = true;
      }
      const auto bit = static_cast<std::uint8_t>(1u << uses[k].local);
      if (!neighbour || is_sharp) sharp[uses[k].facet] |= bit;
      if (!neighbour && free_edges) (*free_edges)[uses[k].facet] |= bit;
    }
    i = j;
  }
  return sharp;
}

}  // namespace abut
