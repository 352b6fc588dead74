#pragma once
// One contact interface: penalty contact between two surfaces, or self contact when both are the
// same facets. Each step runs the pipeline
//   broad phase (bucket grid, rebuilt only when nodes moved more than half the search margin)
//   -> narrow phase (narrow_phase.hpp: the partner facet of each contact point)
//   -> enforcement (laws/: normal law, damping, tangential law, ties, adhesion)
//   -> scatter (forces to the nodes in a fixed order; energies, stable step, wear, statistics).
// Contact points are integration points on the facets (surface-to-surface, integration.hpp) or
// surface nodes (node-to-surface). Input and output are plain nodal arrays owned by the caller;
// the library depends on abut::core only. The result is bitwise identical for any number of
// OpenMP threads: points are evaluated in parallel into per-point slots and their forces are added
// to the nodes serially in a fixed order. See docs/contact.md.
//
// The interface's state lives behind this header (src/contact/interface_impl.hpp): a host sees
// the settings, the surfaces, the nodal arrays in and out, and the results.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <vector>

#include "abut/contact/settings.hpp"
#include "abut/contact/surface.hpp"
#include "abut/core/vec3.hpp"

namespace abut {

class InterfaceImpl;
class StateArchive;

struct ContactInput {
  std::span<const double> x, y, z;     // current nodal coordinates
  std::span<const double> vx, vy, vz;  // current nodal velocities (may be empty at construction)
  double time = 0.0;
  double dt = 0.0;  // step over which friction, damping work and wear are integrated
  std::span<const double> temperature;  // nodal temperatures; empty: no heat exchange
  // The energy the host's balance is measured against (its largest total so far), the scale of
  // ContactStats::kink_step; with 0 (or less) the contact takes the kinetic energy of its surface
  // nodes plus its springs' energy.
  double energy_scale = 0.0;
};

// Nodal force arrays owned by the caller; the contact forces are added to them.
// With thermal contact (ContactSettings::thermal) also the heat flowing into each node [power]
// and each node's conductance to the other surface [power / temperature] (sum over its points of
// N_a h A), from which the caller bounds its thermal step; empty spans: not wanted.
struct ContactForces {
  std::span<double> fx, fy, fz;
  std::span<double> heat, conductance;
  void add(std::int32_t node, const Vec3& f) const {
    fx[node] += f.x;
    fy[node] += f.y;
    fz[node] += f.z;
  }
};

// The share of the energy in play that the penalty's kink may do in one step (ContactStats::
// kink_step).
inline constexpr double kKinkShare = 0.01;

struct ContactStats {
  Vec3 force;                     // total contact force acting on the nodes of surface 1
  double normal_force = 0.0;      // sum of the normal forces of the active points
  double tangential_force = 0.0;  // sum of the magnitudes of their tangential forces
  double elastic_energy = 0.0;    // energy stored in the penalty springs now
  // Work of the contact damping so far: over each step, the mean of the damping forces at its
  // two ends times the nodes' motion, 1/2 (F_d^n + F_d^(n+1)) . (x^(n+1) - x^n), the work the
  // kinetic energy's product form 1/2 m v^(n-1/2) . v^(n+1/2) sees (booked one step late, when
  // the motion over the step is known). F_d^n . v^(n-1/2) dt alone overstates it by
  // F_d^n . a^n dt^2 / 2, about (omega dt)^2 / 8 of it for a ringing spring (1% at omega dt = 0.3).
  double damping_energy = 0.0;
  double friction_energy = 0.0;  // energy dissipated by friction so far
  // Spring energy that vanished without doing work so far: adhesive bonds that broke, ties that
  // failed, the springs of points whose facet eroded or left or that lost their partner while
  // pressed, every spring when the time window closes. (A point that separates lets go of forces
  // that fell to zero on the way: nothing is released.)
  double released_energy = 0.0;
  // Thermal contact: heat conducted from surface 1 to surface 2 now [power] and so far [energy],
  // and friction work turned into heat so far (both surfaces) [energy].
  double heat_flow = 0.0, conducted_heat = 0.0, friction_heat = 0.0;
  double max_penetration = 0.0;  // largest penetration beyond the initial offsets
  // Range of the gaps (gap.hpp) of the point-facet pairs found in contact so far; 0, 0 if none.
  double gap_min = 0.0, gap_max = 0.0;
  std::size_t active_points = 0;
  double stable_step = std::numeric_limits<double>::infinity();  // 2/omega of the stiffest spring
  // The bound before touching (initial_stable_step) over the points that touch (a tie that holds
  // included) or may come within the narrow phase's reach of a candidate facet in the next step:
  // a point at box distance d from its nearest candidate allows (d - reach) / (2 (1 + sqrt 3)
  // v_max) (open_points.cpp, approach_limit). The points without a candidate are at least half
  // the search margin from every facet: they cannot touch before the next broad-phase build sees
  // them while no surface node moves more than a quarter of the margin in a step
  // (margin / (4 v_max)). At rest, with edge-to-edge contact, or while the caller's step (dt) is
  // below half the bound, the bound holds for every point with a candidate.
  double approach_step = std::numeric_limits<double>::infinity();
  // The penalty's kink: a spring that engages or lets go part way through a step does the work of
  // the whole step, up to (1/8) k (v_n dt)^2 for a point meeting its facet at normal speed v_n
  // (half a step's travel each side of the touch). Where every point of a face touches in the same
  // step (a flat impact) these errors add up instead of averaging out, and at the springs' full
  // bound they reach several percent of the impact's energy (issue 27). kink_step holds their sum
  // over the points that may start or stop touching in the next step to kKinkShare of the energy
  // in play (ContactInput::energy_scale, at least the largest kinetic energy of the surface nodes
  // plus spring energy so far):
  // dt = sqrt(kKinkShare E / sum (1/8) k v_n^2), held while the springs load or hold more than
  // kKinkShare E (scatter.cpp; docs/contact.md). Scattered touches (folds of a crushed tube)
  // hardly lower it. A caller's step is min(stable_step, approach_step, kink_step).
  double kink_step = std::numeric_limits<double>::infinity();
  // The largest step the contact allows next: min(stable_step, approach_step, kink_step).
  double step_bound() const { return std::min({stable_step, approach_step, kink_step}); }
  // Work done on the nodes by a moving analytic tool so far (tool_contact.hpp): over each step,
  // the mean of its forces at the step's two ends times the tool's displacement at the nodes.
  // 0 for contacts between meshed surfaces (their motion's work is the solver's).
  double tool_work = 0.0;
};

// The spring a part pair gets (after the stiffness rule and pair scaling), for reports.
struct PairStiffness {
  std::int64_t part1 = 0, part2 = 0;  // part on surface 1, part on surface 2
  double scale = 1.0;                 // pair scale factor applied
  // Range over the pair: pfac [stress / length] under the facet-penalty rule, the spring K of a
  // node (N2S) or facet (S2S) [force / length] under the Radioss rules.
  double penalty_min = 0.0, penalty_max = 0.0;
};

// Contact points that start deeper inside the other surface than the detection depth of their
// pair: the search never finds them, so nothing pushes them out (a start-up check, issue 13).
// One entry per (part of the points, part they are inside).
struct DeepStart {
  std::int64_t part = 0;
  std::int64_t other_part = 0;
  std::size_t points = 0;
  double deepest = 0.0;          // the deepest of them [length]
  double detection_depth = 0.0;  // the largest detection depth of their pairs [length]
};

class ContactInterface {
 public:
  // `node_mass` and the coordinates of `initial` are indexed by node like the facets' nodes.
  // The initial coordinates fix sharp edges, nodal areas, gid_0 and the initial penetrations.
  // Surfaces with identical facets give self contact. Node-to-surface: `secondary_nodes` restricts
  // surface 1's points to these nodes (each must be a node of a surface-1 facet); empty: all of
  // them. ContactSetupError for inconsistent settings or surfaces.
  ContactInterface(ContactSettings settings, ContactSurface surface1, ContactSurface surface2,
                   std::span<const double> node_mass, const ContactInput& initial,
                   std::span<const std::int32_t> secondary_nodes = {});
  ContactInterface(ContactInterface&&) noexcept;
  ContactInterface& operator=(ContactInterface&&) noexcept;
  ~ContactInterface();

  // Adds the contact forces of the state `in` to `out` and updates energies and statistics.
  void apply(const ContactInput& in, ContactForces& out);

  // Thermal contact for a caller that advances its temperatures in steps of its own (several per
  // apply, or one over several): adds to `heat` the heat conducted into each node [power] at the
  // nodal temperatures `temperature`, through the partners and conductances the last apply found
  // (its geometry held), and books that flow over `duration` in stats() (heat_flow,
  // conducted_heat). Returns the flow from surface 1 to surface 2 [power]. apply itself conducts
  // at its input's temperatures over its step when they are given; a caller that conducts here
  // gives apply no temperatures.
  double conduct_heat(std::span<const double> temperature, double duration, std::span<double> heat);
  // Books the flow of the last conduct_heat over `duration` more (a caller whose conduction keeps
  // that flow over a span it may end early conducts with duration 0 and books each part).
  void book_conducted_heat(double duration);

  // Element erosion: `eroded` holds 1 for every eroded element, indexed like the surfaces'
  // `element` and `exposed_by`. Facets of eroded elements leave the contact (unless
  // ErosionSettings::remove_facets is off), internal faces they expose join it, and nodes left
  // without facets stay as free point masses (ErosionSettings::keep_free_nodes) or leave.
  void erode(std::span<const std::uint8_t> eroded);

  const ContactStats& stats() const;
  // Switched off by the caller (a sensor of the solver, Radioss sens_ID): apply() then acts as
  // outside the time window (no forces; the springs let go and the friction history is
  // forgotten). The caller sets it before every apply(), so it is not part of the state.
  void set_enabled(bool on);
  bool enabled() const;
  // Sets touched[node] = 1 for every node of surface 1 (the secondary side) with a point in
  // contact after the last apply(): the node itself (node to surface) or the four nodes of the
  // point's facet (surface to surface). For Radioss IBC (release of boundary conditions at impact).
  void mark_secondary_nodes_in_contact(std::span<std::uint8_t> touched) const;
  // Stable step bound of every spring that may act, spring_step of the largest 2 k / m_min over
  // the points, as if every point touched (stats().approach_step takes it over the points that may
  // touch only).
  double initial_stable_step() const;
  // Accumulated wear depth and current contact pressure per node (0 away from the surfaces).
  std::span<const double> wear() const;
  std::span<const double> nodal_pressure() const;
  // The springs of every part pair that can meet, at the initial configuration.
  std::vector<PairStiffness> pair_stiffness() const;

  bool self_contact() const;
  std::size_t point_count() const;
  std::size_t released_points() const;  // initially deeper than delta0_max
  // Every node of both surfaces, sorted (dormant facets included): the only nodes apply() and
  // the heat exchange write to.
  std::span<const std::int32_t> surface_nodes() const;
  // Points of `initial` (the configuration the interface was built with) lying inside the other
  // surface's first layer of elements, deeper than the detection depth (initial_check.cpp).
  // Empty for self contact, where a point faces its own body's far side within that layer.
  std::vector<DeepStart> deep_initial_points(const ContactInput& initial) const;
  std::size_t tied_points() const;  // currently tied (sticking or freeze)
  // A node point tied by FREEZE (ContactSettings::freeze) to its partner found at t = 0: the
  // partner facet's nodes and their shape values N_a(xi, eta) at the partner point.
  struct NodeTie {
    std::int32_t node = -1;
    std::array<std::int32_t, 4> facet{};
    std::array<double, 4> shape{};
  };
  // The node points (node-to-surface) currently tied, in pass and point order.
  std::vector<NodeTie> node_ties() const;
  std::size_t broad_phase_builds() const;
  std::size_t contact_edges() const;
  double search_margin() const;
  // Saves or loads the evolving state (contact points, friction and tie history, initial
  // offsets, wear, the broad phase as built, statistics) for a restart (state_archive.hpp).
  void archive(StateArchive& a);
  // The same state as bytes, and back: restore_state takes what save_state of an interface made
  // from the same settings, surfaces and masses wrote (else a StateArchiveError).
  std::vector<char> save_state() const;
  void restore_state(std::vector<char> bytes);

 private:
  std::unique_ptr<InterfaceImpl> impl_;
};

}  // namespace abut
