// Points that are surely open: skipped before their frame and projections are evaluated.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "abut/contact/penetration_zone.hpp"
#include "abut/core/parallel.hpp"
#include "interface_impl.hpp"

namespace abut {

// Contacts where an open point still acts or changes state: heat across the gap, adhesion,
// bilateral and reversed contact, sticking contact (a tie forms at a touching distance) and
// clearance (a shifted gap).
bool InterfaceImpl::skips_open_points() const {
  const ContactSettings& s = settings_;
  return s.skip_open_points && !s.thermal.any() && !s.adhesion &&
         s.sense == ContactSense::Positive && !s.stick_stress && !s.clearance;
}

void InterfaceImpl::update_near_facets() {
  for (Side& side : sides_) {
    std::vector<std::uint8_t> near(side.surface.size(), 0);
    for (const Pass& pass : passes_)
      if (&sides_[pass.target] == &side)
        for (const std::int32_t f : pass.candidates.facets) near[static_cast<std::size_t>(f)] = 1;
    side.near_facets.clear();
    for (std::size_t f = 0; f < near.size(); ++f)
      if (near[f]) side.near_facets.push_back(static_cast<std::int32_t>(f));
    side.bands.resize(near.size());
  }
}

void InterfaceImpl::update_bands(const ContactInput& in) {
  for (Side& side : sides_) {
    const auto n = static_cast<std::int64_t>(side.near_facets.size());
#pragma omp parallel for schedule(static) if (n >= kParallelMinimum / 4)
    for (std::int64_t k = 0; k < n; ++k) {
      const std::int32_t f = side.near_facets[static_cast<std::size_t>(k)];
      side.bands[static_cast<std::size_t>(f)] =
          facet_band(quad_corners(side.surface.facets[f], in.x, in.y, in.z));
    }
  }
}

// A point without a partner last step, without friction history, initial offset or bond, whose
// candidate facets all leave it outside their penetration zone (penetration_zone.hpp), ends the
// full evaluation with no partner that pushes and nothing to reset: the full path would record
// nothing and leave its history as it is.
bool InterfaceImpl::surely_open(const Pass& pass, std::size_t p, const ContactInput& in) const {
  if (!skips_open_points()) return false;
  if (pass.remembers(p) || pass.shift_at(p) != 0.0) return false;
  const Side& own = sides_[pass.own];
  const Side& target = sides_[pass.target];
  const Vec3 x = point_at(own, p, in);  // where frame() finds it
  const TargetFacets facets = target_facets(target, target.depth, in);
  const PartnerRules rules = border_rules(own, p);  // a cell may reach beyond its border
  // The broad phase leaves out the facets that share a node with the point's own (its keep
  // filter); the narrow phase passes over inactive ones.
  for (auto k = pass.candidates.offsets[p]; k < pass.candidates.offsets[p + 1]; ++k) {
    const std::int32_t f = pass.candidates.facets[k];
    if (!target.active[f]) continue;
    const PairReach r = pair_reach(facets, f, rules);
    if (!outside_penetration_zone(target.bands[static_cast<std::size_t>(f)], x, r.gap, r.below,
                                  r.reach))
      return false;
  }
  return true;
}

// A point near a facet but not touching it needs its spring's bound on the step only once it may
// touch in the next step. The narrow phase accepts a facet only within `reach` of the facet's box
// (pair_reach). In one step of length dt every node moves at most v dt (v the largest nodal speed
// of the contact's surfaces), so each face of the box and the point (a combination of its nodes)
// move at most v dt, and the point's distance d from the box shrinks by at most (1 + sqrt 3) v dt.
// A step no longer than (d - reach) / (2 (1 + sqrt 3) v) cannot bring it within reach of any
// candidate, with a factor 2 in reserve for the speeds changing within the step (v is that of the
// last step); the broad phase's margin covers the facets that are not candidates. The step allowed
// is the larger of that and the spring's bound. A point whose spring's bound is at least `least`
// cannot lower the least step: it is not looked at (the least step is the same either way).
double InterfaceImpl::approach_limit(const Pass& pass, std::size_t p, const ContactInput& in,
                                     double speed, double least) const {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  constexpr double kSqrt3 = 1.7320508075688772;
  if (pass.hit[p] || pass.state[p] == kReleased) return kInfinity;  // scatter takes a hit's bound
  const auto first = pass.candidates.offsets[p], last = pass.candidates.offsets[p + 1];
  if (first == last) return kInfinity;  // beyond the margin (apply's rule for far points)
  const double omega2 = pass.approach_omega2[p];
  if (!(omega2 > 0.0)) return kInfinity;
  const double spring = approach_spring_step(omega2);
  if (spring >= least) return kInfinity;
  const Side& own = sides_[pass.own];
  const Side& target = sides_[pass.target];
  const Vec3 x = point_at(own, p, in);
  const TargetFacets facets = target_facets(target, target.depth, in);
  const PartnerRules rules = border_rules(own, p);  // a cell may reach beyond its border
  double clearance = kInfinity;
  for (auto k = first; k < last; ++k) {
    const std::int32_t f = pass.candidates.facets[k];
    if (!target.active[f]) continue;  // the narrow phase passes over it
    const FacetBand& band = target.bands[static_cast<std::size_t>(f)];
    const double d = std::sqrt(box_distance2(band.lo, band.hi, x));
    clearance = std::min(clearance, d - pair_reach(facets, f, rules).reach);
  }
  return std::max(spring, clearance / (2.0 * (1.0 + kSqrt3) * speed));
}

bool InterfaceImpl::bounds_kinks() const {
  return settings_.sense != ContactSense::Bilateral && !settings_.adhesion;
}

// An open point touches in the next step only if it comes within the narrow phase's reach of a
// candidate's box (the travel of approach_limit) and its height above the facet's mean plane, less
// the pair's gap and the band's slack (penetration_zone.hpp), is within a step's travel at its
// speed w towards the facet (the facet moving with its corners' mean velocity). The step is at
// most the point's spring bound: approach_limit (or, at rest and with edges, the bound for every
// near point) holds a longer one off before the point may touch.
double InterfaceImpl::onset_kink(const Pass& pass, std::size_t p, const ContactInput& in,
                                 double speed) const {
  constexpr double kSqrt3 = 1.7320508075688772;
  if (pass.state[p] == kReleased || pass.state[p] == kTied || in.vx.empty()) return 0.0;
  const auto first = pass.candidates.offsets[p], last = pass.candidates.offsets[p + 1];
  if (first == last || !(pass.approach_omega2[p] > 0.0)) return 0.0;
  const double step = approach_spring_step(pass.approach_omega2[p]);
  const Side& own = sides_[pass.own];
  const Side& target = sides_[pass.target];
  const Vec3 x = point_at(own, p, in);
  const TargetFacets facets = target_facets(target, target.depth, in);
  const PartnerRules rules = border_rules(own, p);
  const double travel = 2.0 * (1.0 + kSqrt3) * speed * step;
  const double sense = settings_.sense == ContactSense::Negative ? -1.0 : 1.0;
  double kink = 0.0;
  std::optional<PointFrame> frame_now;  // the point's velocity and area, once needed
  for (auto k = first; k < last; ++k) {
    const std::int32_t f = pass.candidates.facets[k];
    if (!target.active[f]) continue;
    const FacetBand& band = target.bands[static_cast<std::size_t>(f)];
    if (!band.usable) continue;
    const PairReach r = pair_reach(facets, f, rules);
    const double d = std::sqrt(box_distance2(band.lo, band.hi, x));
    if (d - r.reach > travel) continue;
    const double height = sense * dot(x - band.centre, band.normal) - r.gap;
    const double slack = band_slack(band, x);
    if (height + slack < 0.0) continue;  // at or behind the facet without touching it: beside it
    if (!frame_now) frame_now = frame(own, p, in);
    Vec3 v_facet;
    for (const std::int32_t node : target.surface.facets[f])
      v_facet += Vec3{in.vx[node], in.vy[node], in.vz[node]} * 0.25;
    const double w = -sense * dot(frame_now->v - v_facet, band.normal);
    if (!(w > 0.0) || height - slack > w * step) continue;
    const double k_spring = spring(own, p, frame_now->area, target, f);
    kink = std::max(kink, 0.125 * k_spring * w * w);
  }
  return kink;
}

}  // namespace abut
