#include "ties.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace abut {

namespace {

std::string node_name(const Model& model, std::int32_t node) {
  return "node " + std::to_string(model.mesh.nodes.id[static_cast<std::size_t>(node)]);
}

}  // namespace

KinematicTies::KinematicTies(const Model& model, std::vector<TiedNode> tied,
                             std::span<const double> mass,
                             std::span<const std::int32_t> rigid_body_of_node,
                             std::span<const std::uint8_t> node_fixed, const BoundaryConditions& bc,
                             std::span<const double> vx, std::span<const double> vy,
                             std::span<const double> vz)
    : tied_(std::move(tied)) {
  if (tied_.empty()) return;
  const std::size_t n = mass.size();
  role_.assign(n, kFree);
  added_mass_.assign(n, 0.0);
  added_force_.assign(3 * n, 0.0);
  for (const TiedNode& t : tied_) role_[static_cast<std::size_t>(t.node)] = kTied;
  // The nodes a *BC_MOTION acts on (fixed or prescribed translations).
  std::vector<std::uint8_t> moved(n, 0);
  for (const NodalMotion& m : bc.nodal) {
    const bool translates = (m.source->fixed_translation & 7u) != 0 ||
                            std::any_of(m.source->motions.begin(), m.source->motions.end(),
                                        [](const PrescribedMotion& p) { return p.direction < 3; });
    if (translates)
      for (const std::int32_t i : m.nodes) moved[static_cast<std::size_t>(i)] = 1;
  }
  for (const TiedNode& t : tied_) {
    const TieSpec& spec = model.ties[t.tie];
    const auto s = static_cast<std::size_t>(t.node);
    const std::string who = node_name(model, t.node) + ", tied by exact tie " +
                            std::to_string(spec.id) + " to a facet,";
    if (rigid_body_of_node[s] >= 0)
      throw InputError(exact_tie_place(model, spec),
                       who +
                           " is a node of a rigid part: tie the rigid part's facets as surface 2 "
                           "instead (not supported yet either)");
    if ((node_fixed[s] & 7u) != 0 || moved[s])
      throw InputError(exact_tie_place(model, spec),
                       who + " has " + model.sources.words("boundary_condition") +
                           ": it moves with its facet only; constrain the facet's nodes instead");
    Vec3 v_facet;
    for (int k = 0; k < t.count; ++k) {
      const auto a = static_cast<std::size_t>(t.main[k]);
      if (rigid_body_of_node[a] >= 0)
        throw InputError(exact_tie_place(model, spec),
                         who + " would follow " + node_name(model, t.main[k]) +
                             " of a rigid part: exact ties to rigid parts are not supported yet "
                             "(tie with the penalty instead: " +
                             model.sources.words("tie_by_penalty") + ")");
      if (role_[a] == kFree) role_[a] = kMain;
      added_mass_[a] += t.weight[k] * mass[s];
      v_facet += Vec3{vx[a], vy[a], vz[a]} * t.weight[k];
    }
    // The tied node must start as it will go on, with its facet point's velocity (else the tie
    // would change the momentum at t = 0).
    const Vec3 v{vx[s], vy[s], vz[s]};
    const double scale = std::max({norm(v), norm(v_facet), 1e-300});
    if (norm(v - v_facet) > 1e-9 * scale)
      throw InputError(exact_tie_place(model, spec),
                       who +
                           " starts with a velocity other than its facet point's: give the tied "
                           "bodies the same initial velocity (" +
                           model.sources.words("initial_velocity") + ")");
  }
  for (std::size_t i = 0; i < n; ++i)
    if (role_[i] == kMain) main_nodes_.push_back(static_cast<std::int32_t>(i));
}

void KinematicTies::kick(double dt_avg, std::span<const double> mass, std::span<const double> ox,
                         std::span<const double> oy, std::span<const double> oz,
                         std::span<const double> fx, std::span<const double> fy,
                         std::span<const double> fz, std::span<double> vx, std::span<double> vy,
                         std::span<double> vz) {
  if (tied_.empty()) return;
  for (const std::int32_t a : main_nodes_)
    for (int d = 0; d < 3; ++d) added_force_[3 * static_cast<std::size_t>(a) + d] = 0.0;
  for (const TiedNode& t : tied_) {
    const auto s = static_cast<std::size_t>(t.node);
    for (int k = 0; k < t.count; ++k) {
      const std::size_t a = 3 * static_cast<std::size_t>(t.main[k]);
      added_force_[a] += t.weight[k] * fx[s];
      added_force_[a + 1] += t.weight[k] * fy[s];
      added_force_[a + 2] += t.weight[k] * fz[s];
    }
  }
  for (const std::int32_t node : main_nodes_) {
    const auto a = static_cast<std::size_t>(node);
    const double m = mass[a] + added_mass_[a];
    if (!(m > 0.0)) continue;
    vx[a] = ox[a] + dt_avg * (fx[a] + added_force_[3 * a]) / m;
    vy[a] = oy[a] + dt_avg * (fy[a] + added_force_[3 * a + 1]) / m;
    vz[a] = oz[a] + dt_avg * (fz[a] + added_force_[3 * a + 2]) / m;
  }
}

void KinematicTies::follow(std::span<double> vx, std::span<double> vy, std::span<double> vz) const {
  for (const TiedNode& t : tied_) {
    double u = 0.0, v = 0.0, w = 0.0;
    for (int k = 0; k < t.count; ++k) {
      const auto a = static_cast<std::size_t>(t.main[k]);
      u += t.weight[k] * vx[a];
      v += t.weight[k] * vy[a];
      w += t.weight[k] * vz[a];
    }
    const auto s = static_cast<std::size_t>(t.node);
    vx[s] = u;
    vy[s] = v;
    vz[s] = w;
  }
}

void KinematicTies::place(std::span<double> x, std::span<double> y, std::span<double> z) const {
  for (const TiedNode& t : tied_) {
    Vec3 p = t.offset;
    for (int k = 0; k < t.count; ++k) {
      const auto a = static_cast<std::size_t>(t.main[k]);
      p += Vec3{x[a], y[a], z[a]} * t.weight[k];
    }
    const auto s = static_cast<std::size_t>(t.node);
    x[s] = p.x;
    y[s] = p.y;
    z[s] = p.z;
  }
}

}  // namespace abut
