#pragma once
// Where a point can penetrate a facet, bounded cheaply: a test that lets the contact skip the
// projection of points that are clearly open (most points near a facet, most of the time).
//
// The narrow phase (narrow_phase.hpp) reports a penetrating partner only for a point x with
//  (a) box distance from x to the facet's corners at most `reach` (pair_reach), and
//  (b) gap = q.gap - g in [-below, 0), q the closest point of the facet (around a shell's
//      rounded edge: q.distance < g).
// Write the bilinear facet as x0 + xi a + eta b + xi eta h (a, b, h from the corners) with the
// mean normal n = a x b / |a x b| (the normal of the diagonals). Every point of the facet lies
// within |h . n| of the mean plane, and every local normal a x b + xi (a x h) + eta (h x b) is
// within an angle theta of n, sin theta <= eps = max(|u + v|, |u - v|) / |a x b| with u = a x h,
// v = h x b (the deviation xi u + eta v is largest at a corner). With
// x - q = q.gap N + t (N the unit normal at q, t in its tangent plane, |t| <= |x - q| <= rho =
// |x - x0| + r, r the largest distance from x0 to a corner: the bilinear facet lies in the convex
// hull of its corners), the height of x above the mean plane, s = (x - x0) . n, then satisfies
//   min(g - below, -g) - sigma <= s < g + sigma,   sigma = |h . n| + rho eps,
// when (b) holds (for eps <= 1/2, so that N . n > 0 and q.gap cos theta keeps the sign and
// bound of q.gap). A point outside that band, or beyond the reach, cannot penetrate the facet.
// tests/contact/test_penetration_zone.cpp checks this against find_partner.
#include <algorithm>

#include "abut/contact/quad.hpp"

namespace abut {

// What the test needs of a facet, computed once per step for all the points near it.
struct FacetBand {
  Vec3 lo, hi;          // the box of the corners
  Vec3 centre, normal;  // x0 and n
  double warp = 0.0;    // |h . n|
  double tilt = 0.0;    // eps
  double radius = 0.0;  // r: the largest distance from the centre to a corner
  bool usable = false;  // a nonzero area and eps <= 1/2: the band holds
};
FacetBand facet_band(const QuadCorners& c);

// Squared distance from x to the box [lo, hi]: the narrow phase's box test (a) and the bounds
// here compute it alike, so that they decide alike.
inline double box_distance2(const Vec3& lo, const Vec3& hi, const Vec3& x) {
  double d2 = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double out = std::max({lo[i] - x[i], x[i] - hi[i], 0.0});
    d2 += out * out;
  }
  return d2;
}

// sigma above plus a margin: the narrow phase's gap and the height are rounded differently (both
// from coordinates of the facet's magnitude), so a point that touches exactly (a node on a
// matched mesh) stays with the narrow phase.
double band_slack(const FacetBand& band, const Vec3& x);

// True when point x cannot penetrate the facet, with pair gap g, detection depth below and reach
// as in pair_reach (narrow_phase.hpp).
bool outside_penetration_zone(const FacetBand& band, const Vec3& x, double g, double below,
                              double reach);
inline bool outside_penetration_zone(const QuadCorners& c, const Vec3& x, double g, double below,
                                     double reach) {
  return outside_penetration_zone(facet_band(c), x, g, below, reach);
}

// True when every closest point q of the facet to x has q.gap < 0 (usable bands only): from the
// same decomposition, s >= q.gap N . n - sigma, so q.gap >= 0 needs s >= -sigma. A shell's side
// is no partner of a point behind it.
bool surely_behind(const FacetBand& band, const Vec3& x);

}  // namespace abut
