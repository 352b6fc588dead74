#pragma once
// Contact of a surface with an analytic rigid tool (analytic_tool.hpp) as its main surface:
// node to surface, each node of surface 1 against the tool with its tributary area facing the
// tool's normal (the node points of ContactInterface, interface.hpp). The laws are the
// interface's (laws/): the normal law scaled in time, damping at a fraction of the critical
// damping of the node's spring (the tool's mass is infinite: the node's own mass), the tangential
// law with its stick-slip history and filter, the tangential penalty's dependencies. The spring of
// a node is the penalty pfac of its own facets (the largest around it) times its facing area: the
// tool has no elements to take a stiffness from. The tool's motion is the caller's (ToolPose at
// each apply); the work it does on the body is ContactStats::tool_work. See docs/contact.md.
#include <cstdint>
#include <span>
#include <vector>

#include "abut/contact/analytic_tool.hpp"
#include "abut/contact/interface.hpp"

namespace abut {

class ToolContact {
 public:
  // `surface1`: the facets whose nodes touch the tool (only `secondary_nodes` of them when not
  // empty); `node_mass` indexed by node. ContactSetupError for settings a tool contact does not
  // support (ties, adhesion, heat, wear, edges, gid regions, initial-penetration options, Radioss
  // stiffness rules, pair scales and frictions, shell-gap options beyond Gap_scale and
  // Gap_max_s, sense NEGATIVE) and for a bad tool (zero normal or axis, radius <= 0).
  ToolContact(ContactSettings settings, AnalyticTool tool, const ContactSurface& surface1,
              std::span<const double> node_mass, const ContactInput& initial,
              std::span<const std::int32_t> secondary_nodes = {});

  // Adds the forces of the tool at `pose` on the nodes of the state `in` to `out`.
  void apply(const ContactInput& in, const ToolPose& pose, ContactForces& out);

  const ContactStats& stats() const { return stats_; }
  void set_enabled(bool on) { enabled_ = on; }
  // touched[node] = 1 for the nodes in contact after the last apply (Radioss IBC).
  void mark_secondary_nodes_in_contact(std::span<std::uint8_t> touched) const;
  // Stable step bound of every node's spring as if it touched with its whole tributary area.
  double initial_stable_step() const;
  std::span<const std::int32_t> surface_nodes() const { return nodes_; }  // sorted
  std::span<const double> nodal_pressure() const { return pressure_; }
  std::size_t point_count() const { return points_.size(); }
  // The range of the node springs' pfac [stress / length] (reports).
  double penalty_min() const { return pfac_min_; }
  double penalty_max() const { return pfac_max_; }
  void archive(StateArchive& a);

 private:
  double spring_step(double omega2) const;  // as ContactInterface::spring_step
  void validate() const;

  ContactSettings settings_;
  AnalyticTool tool_;
  // Facets of surface 1 around each node (CSR over node index), for the node's vector area.
  std::vector<std::array<std::int32_t, 4>> facets_;
  std::vector<std::int32_t> twin_;
  std::vector<std::int32_t> node_facet_start_, node_facets_;
  std::vector<std::int32_t> nodes_;                          // every node of surface 1, sorted
  std::vector<std::int32_t> points_;                         // the nodes that touch the tool
  std::vector<double> mass_;                                 // per node
  std::vector<double> point_pfac_, point_gap_, point_area_;  // per point (area: tributary, t=0)
  double pfac_min_ = 0.0, pfac_max_ = 0.0;
  // Per point: friction history, the force of the last apply (tool work), its damping part, the
  // spring energy held, contact flag.
  std::vector<double> htx_, hty_, htz_, slip_;
  std::vector<double> fx_, fy_, fz_, dfx_, dfy_, dfz_, energy_;
  std::vector<std::uint8_t> hit_;
  std::vector<double> pressure_;  // per node
  ToolPose last_pose_;
  bool posed_ = false;  // last_pose_ holds the pose of a previous apply
  bool enabled_ = true;
  double initial_omega2_ = 0.0;  // the largest k / m of a node touching with its whole area
  ContactStats stats_;
};

}  // namespace abut
