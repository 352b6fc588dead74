// Points that are surely open: skipped before their frame and projections are evaluated.
#include "abut/contact/interface.hpp"
#include "abut/contact/penetration_zone.hpp"
#include "abut/core/parallel.hpp"

namespace abut {

// Contacts where an open point still acts or changes state: heat across the gap, adhesion,
// bilateral and reversed contact, sticking contact (a tie forms at a touching distance) and
// clearance (a shifted gap).
bool ContactInterface::skips_open_points() const {
  const ContactSettings& s = settings_;
  return s.skip_open_points && !s.thermal.any() && !s.adhesion &&
         s.sense == ContactSense::Positive && !s.stick_stress && !s.clearance;
}

void ContactInterface::update_near_facets() {
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

void ContactInterface::update_bands(const ContactInput& in) {
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
bool ContactInterface::surely_open(const Pass& pass, std::size_t p, const ContactInput& in) const {
  if (!skips_open_points()) return false;
  if (pass.htx[p] != 0.0 || pass.hty[p] != 0.0 || pass.htz[p] != 0.0 || pass.sliding[p] ||
      pass.offset[p] != 0.0 || pass.shift_at(p) != 0.0 || pass.adhered[p])
    return false;
  const Side& own = sides_[pass.own];
  const Side& target = sides_[pass.target];
  const std::array<std::int32_t, 4> nodes = own.point_nodes(p);
  // Where the point is, as frame() finds it.
  const std::int32_t node = own.point_node[p];
  const Vec3 x = node >= 0 ? Vec3{in.x[node], in.y[node], in.z[node]}
                           : quad_point(quad_corners(nodes, in.x, in.y, in.z), own.point_xi[p],
                                        own.point_eta[p]);
  const TargetFacets facets = target_facets(target, target.depth, in);
  const PartnerRules rules = partner_rules(own, p);
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

}  // namespace abut
