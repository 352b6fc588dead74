#pragma once
// The state and pipeline of one contact interface behind ContactInterface (interface.hpp), which
// forwards to it (interface_api.cpp): hosts see the settings, surfaces, inputs and results only,
// and the library may change what it keeps without changing their build. The member functions are
// defined by concept across this folder (interface_setup.cpp, enforcement.cpp, cell_cover.cpp,
// open_points.cpp, scatter.cpp, heat_exchange.cpp, erosion.cpp, ...).
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "abut/contact/broad_phase.hpp"
#include "abut/contact/corner_walls.hpp"
#include "abut/contact/edge_contact.hpp"
#include "abut/contact/interface.hpp"
#include "abut/contact/mortar.hpp"
#include "abut/contact/narrow_phase.hpp"
#include "abut/contact/penetration_zone.hpp"
#include "abut/contact/settings.hpp"
#include "abut/contact/surface.hpp"
#include "abut/core/state_archive.hpp"
#include "abut/core/vec3.hpp"

namespace abut {

class InterfaceImpl {
 public:
  // The operations of ContactInterface, which documents them (interface.hpp).
  using NodeTie = ContactInterface::NodeTie;
  InterfaceImpl(ContactSettings settings, ContactSurface surface1, ContactSurface surface2,
                std::span<const double> node_mass, const ContactInput& initial,
                std::span<const std::int32_t> secondary_nodes);
  void apply(const ContactInput& in, ContactForces& out);
  double conduct_heat(std::span<const double> temperature, double duration, std::span<double> heat);
  void book_conducted_heat(double duration) {
    stats_.conducted_heat += stats_.heat_flow * duration;
  }
  void erode(std::span<const std::uint8_t> eroded);
  const ContactStats& stats() const { return stats_; }
  void set_enabled(bool on) { enabled_ = on; }
  bool enabled() const { return enabled_; }
  void mark_secondary_nodes_in_contact(std::span<std::uint8_t> touched) const;
  double initial_stable_step() const { return initial_stable_step_ / std::sqrt(spring_factor_); }
  std::span<const double> wear() const { return wear_; }
  std::span<const double> nodal_pressure() const { return pressure_; }
  std::vector<PairStiffness> pair_stiffness() const;
  bool self_contact() const { return sides_.size() == 1; }
  std::size_t point_count() const;
  std::size_t released_points() const;
  std::span<const std::int32_t> surface_nodes() const { return surface_nodes_; }
  std::vector<DeepStart> deep_initial_points(const ContactInput& initial) const;
  std::size_t tied_points() const;
  std::vector<NodeTie> node_ties() const;
  std::size_t broad_phase_builds() const { return builds_; }
  std::size_t contact_edges() const { return edges_ ? edges_->edge_count() : 0; }
  double search_margin() const { return margin_; }
  void archive(StateArchive& a);

 private:
  enum PointState : std::uint8_t { kFree, kReleased, kTied, kUntied };

  // Why a facet is out of the contact (bits of Side::off).
  enum FacetOff : std::uint8_t { kOutsideRegion = 1, kDormant = 2, kEroded = 4 };

  struct Side {  // one contact surface and its contact points
    ContactSurface surface;
    std::vector<std::uint8_t> sharp;       // sharp-edge bits per facet
    std::vector<std::uint8_t> free_edges;  // free-edge bits per facet (a shell's border)
    std::vector<std::uint8_t> off;         // FacetOff bits per facet
    std::vector<std::uint8_t> active;      // off == 0
    std::vector<double> depth;             // detection depth per facet
    std::vector<double> facet_gap;         // g_m per facet, capped by Gap_max_m (gap.hpp)
    std::vector<double> facet_min_edge;    // its shortest edge (g_m_l)
    std::vector<double> node_area;         // tributary area of each node (global index)
    std::vector<double> facet_km;          // Radioss main-segment stiffness per facet
    std::vector<std::int32_t> facet_part;  // local part index per facet
    // Node-to-surface: the facets around each node (CSR over global node index).
    std::vector<std::int32_t> node_facet_start, node_facets;
    // Contact points. S2S: a point on facet point_facet at (xi, eta); N2S: node point_node.
    std::vector<std::int32_t> point_facet, point_node;
    std::vector<double> point_xi, point_eta, point_weight;
    // S2S: the cell each point stands for (mortar.hpp), xi0, xi1, eta0, eta1 per point, and how
    // far its cell reached from it at the start (a point beyond its partner's border still acts
    // with the part of its cell over it). Node points: a whole square and 0.
    std::vector<double> point_cell, point_reach;
    std::vector<double> point_pfac, point_ks, point_share, point_depth, point_thickness;
    std::vector<double> point_gap;       // g_s, capped by Gap_max_s (gap.hpp)
    std::vector<double> point_min_edge;  // g_s_l: shortest edge at the point in self contact
    double max_point_gap = 0.0;
    double max_facet_gap = 0.0;
    std::vector<std::int32_t> point_part;
    std::vector<std::uint8_t> node_free;  // per node: every facet of the node has eroded
    double max_point_depth = 0.0;
    double max_km = 0.0;    // stiffest main segment (stable-step bound)
    double max_pfac = 0.0;  // stiffest facet penalty (stable-step bound)
    // Some facet is a shell's, whose facets the other side's cells meet by cell only near its
    // free border (cell_cover.cpp); from the surface as given, not archived.
    bool shell_facets = false;
    // Derived, not archived (open_points.cpp): the facets that are some point's candidate at the
    // last build, and their bands (boxes, mean planes) of this step, indexed by facet.
    std::vector<std::int32_t> near_facets;
    std::vector<FacetBand> bands;
    // Everything but the surface (fixed); erosion adds points and switches facets.
    void archive(StateArchive& a) {
      a.values(sharp, free_edges, off, active, depth, facet_gap, facet_min_edge, node_area,
               facet_km, facet_part, node_facet_start, node_facets, point_facet, point_node,
               point_xi, point_eta, point_weight, point_cell, point_reach, point_pfac, point_ks,
               point_share, point_depth, point_thickness, point_gap, point_min_edge, max_point_gap,
               max_facet_gap, point_part, node_free, max_point_depth, max_km, max_pfac);
    }
    CellBounds cell(std::size_t p) const {
      return {point_cell[4 * p], point_cell[4 * p + 1], point_cell[4 * p + 2],
              point_cell[4 * p + 3]};
    }
    std::array<std::int32_t, 4> point_nodes(std::size_t p) const {
      const std::int32_t n = point_node[p];
      return n >= 0 ? std::array<std::int32_t, 4>{n, n, n, n} : surface.facets[point_facet[p]];
    }
  };

  // The push of one more wall of a concave corner on a node, besides its partner's
  // (corner_walls.hpp): a frictionless normal spring with damping, this step's.
  struct CornerPress {
    std::int32_t facet = -1;  // -1: none
    double xi = 0.0, eta = 0.0;
    Vec3 force;    // on the node (before the pass's weight)
    Vec3 damping;  // the damping part of `force`
    double normal_force = 0.0, area = 0.0, energy = 0.0, penetration = 0.0;
    double omega2 = 0.0;  // k / m of its spring
  };

  struct Pass {  // the points of side `own` against the facets of side `target`
    int own = 0, target = 0;
    double weight = 1.0;  // 1/2 when both sides' points act (symmetric and self contact)
    BucketGrid grid;
    CandidateList candidates;
    // History per point.
    std::vector<std::uint8_t> state, adhered;
    // Per point: the bound on the square of its spring's frequency while it may touch (its
    // facet's springs on the facet's lightest node, 2 k / m_min; initial_state).
    std::vector<double> approach_omega2;
    std::vector<double> offset;           // initial penetration subtracted until separation
    std::vector<double> shift;            // permanent gap shift (clearance; else empty)
    std::vector<double> htx, hty, htz;    // tangential spring force (friction history)
    std::vector<double> slip;             // slip since the point last stuck (stick_slip.hpp)
    std::vector<std::int32_t> tie_facet;  // tied contact: fixed partner (ties only; else empty)
    std::vector<double> tie_xi, tie_eta;
    double shift_at(std::size_t p) const { return shift.empty() ? 0.0 : shift[p]; }
    void forget_friction(std::size_t p) {
      htx[p] = hty[p] = htz[p] = 0.0;
      slip[p] = 0.0;
    }
    // Point p has something a step without a partner would forget: friction history, an initial
    // offset, an adhesive bond.
    bool remembers(std::size_t p) const {
      return htx[p] != 0.0 || hty[p] != 0.0 || htz[p] != 0.0 || slip[p] != 0.0 ||
             offset[p] != 0.0 || adhered[p];
    }
    // Results of the current step, one slot per point.
    std::vector<std::uint8_t> hit;
    std::vector<std::int32_t> hit_facet;
    std::vector<double> hit_xi, hit_eta;
    std::vector<double> fx, fy, fz;     // force on the point (before `weight`)
    std::vector<double> dfx, dfy, dfz;  // the damping part of it
    std::vector<double> area, pressure, slip_speed, normal_force, tangential_force;
    std::vector<double> energy, slip_work, penetration, omega2, pair_gap;
    std::vector<double> released;  // spring energy the point let go of in this step
    // (1/8) k v_n^2 when the point may start or stop touching in the next step (its kink may do
    // that times dt^2 of work), else 0 (ContactStats::kink_step). Written for every awake point.
    std::vector<double> kink;
    // S2S (mortar.hpp): how the point's force spreads, as fractions of it: over its own facet's
    // nodes (4 per point) and over the nodes of each facet of the other surface its cell covers
    // (kMaxOverlaps facets of 4 per point; mortar_count of them used). Empty for node points.
    std::vector<double> mortar_own, mortar_target;
    std::vector<std::int32_t> mortar_facet;
    std::vector<std::uint8_t> mortar_count;
    // N2S: kMaxCornerWalls slots per point for the other walls of a concave corner it presses
    // (this step's, like the results above; not archived: every step finds them anew). Empty for
    // integration points.
    std::vector<CornerPress> corner;
    // Thermal contact: the partner the point exchanges heat with (-1: none; open points within
    // the search distance too) and the conductance h A of the point [power / temperature].
    // Empty when the contact exchanges no heat.
    std::vector<std::int32_t> heat_facet;
    std::vector<double> heat_xi, heat_eta, heat_conductance;
    // The points that may act until the next build, in point order (apply; not archived: the
    // first step after a restart finds them again). The others are quiet (ContactInterface::quiet).
    std::vector<std::int32_t> awake;
    void archive(StateArchive& a) {
      a.values(own, target, weight, grid, candidates, state, adhered, approach_omega2, offset,
               shift, htx, hty, htz, slip, tie_facet, tie_xi, tie_eta, hit, hit_facet, hit_xi,
               hit_eta, fx, fy, fz, dfx, dfy, dfz, area, pressure, slip_speed, normal_force,
               tangential_force, energy, slip_work, penetration, omega2, pair_gap, released,
               mortar_own, mortar_target, mortar_facet, mortar_count, heat_facet, heat_xi, heat_eta,
               heat_conductance);
    }
  };

  // Where a contact point is now.
  struct PointFrame {
    std::array<std::int32_t, 4> nodes;
    std::array<double, 4> shape;
    Vec3 x, v, normal;
    double area = 0.0;  // S2S: the point's area; N2S: see vector_area
    Vec3 vector_area;   // N2S: a quarter of each adjacent facet's area vector, summed
    bool active = false;
    bool two_sided = false;  // N2S: a node of a shell (no normal; either side may touch)
    bool free = false;       // a node whose facets have all eroded: its whole area touches
  };

  void validate(const ContactSurface& s1, const ContactSurface& s2, std::size_t coordinates) const;
  void build_sides(const ContactInput& initial, std::span<const std::int32_t> secondary_nodes);
  void build_points(Side& side, const ContactInput& in, double other_size,
                    std::span<const std::int32_t> secondary_nodes,
                    const std::vector<std::uint8_t>& free_edges);
  // Penalty, stiffness, depth, thickness, gap and part of point p from its facet (or its node's
  // facets); `share`: its part of the spring (integration points: of their facet's area).
  void init_point(Side& side, std::size_t p, const std::vector<std::uint8_t>& on_free_edge,
                  double share);
  // Slots a contact without ties, clearance or heat never uses stay empty (memory, issue 12).
  void size_pass(Pass& pass, std::size_t n) const;
  void build_parts();
  void build_passes();
  void build_edges(const ContactInput& in);  // edge_selection.cpp
  void rebuild_broad_phase(const ContactInput& in);
  // Where the points of a side are now (the broad phase's query points).
  struct PointPositions {
    std::vector<double> x, y, z;
  };
  PointPositions point_positions(const Side& own, const ContactInput& in) const;
  // The bounding box of each S2S point's cell (a node point's position), for the broad phase.
  std::vector<Box> cell_regions(const Side& own, const ContactInput& in) const;
  void update_near_bound();  // near_omega2_ from the candidates of the last build
  bool needs_rebuild(const ContactInput& in) const;
  PointFrame frame(const Side& side, std::size_t p, const ContactInput& in) const;
  // The narrow phase's view of a side's facets with a detection depth per facet (with their
  // bands of this step when `banded`: only for candidates of the last build), and its rules for
  // point p (enforcement.cpp).
  TargetFacets target_facets(const Side& target, std::span<const double> depth,
                             const ContactInput& in, bool banded = false) const;
  PartnerRules partner_rules(const Side& own, std::size_t p) const;
  // S2S (cell_cover.cpp): the part of point p's cell over the facets of the other surface that
  // face it (its partner h and its candidates), and the mean gap over it (the mortar gap) less
  // the pair's gap.
  CellOverlap cover(const Pass& pass, std::size_t p, const PointFrame& f, const Partner& h,
                    const ContactInput& in) const;
  double cell_gap(const Side& own, std::size_t p, const Side& target, const Partner& h,
                  const CellOverlap& o, const ContactInput& in) const;
  static CoverFacets cover_facets(const Side& target, const ContactInput& in);
  // Whether integration point p meets the other surface cell by cell: its partner h faces it
  // within alpha_edge, or a facing facet within its cell's reach does (h replaced); then its
  // overlap o and mortar gap (h.gap). False: h acts at the point with its whole area. The
  // narrow phase's rules for a cell (the edge tolerance widened to the cell's reach).
  bool meet_by_cell(const Pass& pass, std::size_t p, const PointFrame& f, const ContactInput& in,
                    Partner& h, CellOverlap& o) const;
  PartnerRules border_rules(const Side& own, std::size_t p) const;
  Partner nearest_facing(const Pass& pass, std::size_t p, const PointFrame& f,
                         const ContactInput& in, PartnerRules rules) const;
  // N2S (cell_cover.cpp): the fraction of node point p's area that lies over the other surface:
  // the quarters of its facets at the node, each against its partner h and the facets around
  // h; 1 where that does not apply (see there).
  double node_cover(const Pass& pass, std::size_t p, const Partner& h,
                    const ContactInput& in) const;
  // N2S (cell_cover.cpp): node point p's partner h, or, where h does not face the node within
  // alpha_edge, the nearest facet that does and that part of its area lies over (then `cover`
  // is set to node_cover against it).
  Partner facing_node_partner(const Pass& pass, std::size_t p, const PointFrame& f,
                              const ContactInput& in, const Partner& h,
                              std::optional<double>& cover) const;
  // ContactSetupError "memory" when the points made so far and `planned` more would need more
  // than settings_.memory_limit.
  void require_point_memory(std::size_t planned) const;
  // The partner among the broad-phase candidates; failing that, near `previous` (last step's
  // partner, or -1).
  Partner partner_of(const Pass& pass, std::size_t p, const PointFrame& f, const ContactInput& in,
                     std::int32_t previous) const;
  double spring(const Side& own, std::size_t p, double area, const Side& target,
                std::int32_t f) const;
  // The velocity at shape values `shape` of the facet `nodes`.
  static Vec3 velocity_at(const std::array<std::int32_t, 4>& nodes,
                          const std::array<double, 4>& shape, const ContactInput& in);
  // A point's share, for its `area`, of the masses of the nodes of `side` at `shape`.
  double mass_share(const Side& side, const std::array<std::int32_t, 4>& nodes,
                    const std::array<double, 4>& shape, double area) const;
  static double reduced_mass(double m1, double m2);  // m1 m2 / (m1 + m2), 0 without mass
  // N2S: the other walls of a concave corner that node point p presses besides its partner h, each
  // a frictionless penalty spring along its own normal into pass.corner (corner_press.cpp).
  void press_corner_walls(Pass& pass, std::size_t p, const PointFrame& f, const Partner& h,
                          const ContactInput& in);
  // Their forces to the nodes, energies and pressure into the statistics (serially, from scatter);
  // returns the sum of their springs' k / m, which the node's own spring adds to.
  double scatter_corner(const Pass& pass, std::size_t p, ContactForces& out);
  void evaluate_point(Pass& pass, std::size_t p, const ContactInput& in);
  // A point without candidates, partner or tie, with nothing to forget (friction history, offset,
  // bond), no heat partner and no released energy for scatter to add: evaluate_point leaves it as
  // it is, and so it stays until a build gives it candidates.
  bool quiet(const Pass& pass, std::size_t p) const;
  // Open points (open_points.cpp): whether this contact may skip them at all, the bands of the
  // facets near some point (after each build: which facets; at each step: their bands, which the
  // narrow phase's box test uses too), and whether the full evaluation of point p would surely
  // find it open and change nothing.
  bool skips_open_points() const;
  void update_near_facets();
  void update_bands(const ContactInput& in);
  bool surely_open(const Pass& pass, std::size_t p, const ContactInput& in) const;
  // The step point p allows before it may touch (open_points.cpp); infinity when it cannot lower
  // `least`, the least such step so far.
  double approach_limit(const Pass& pass, std::size_t p, const ContactInput& in, double speed,
                        double least) const;
  // (1/8) k w^2 of an open point that may touch a candidate facet in the next step, w its speed
  // towards the facet, else 0 (open_points.cpp; ContactStats::kink_step).
  double onset_kink(const Pass& pass, std::size_t p, const ContactInput& in, double speed) const;
  // Whether the kink is bounded at all: a unilateral contact without an adhesive zone (the
  // others' springs do not engage at a touch) while the surfaces move.
  bool bounds_kinks() const;
  Vec3 point_at(const Side& own, std::size_t p, const ContactInput& in) const;
  // `near_bound`: the bound before touching holds for every point with a candidate (at rest, with
  // edge-to-edge contact); otherwise only for the points that touch (apply takes the others).
  void scatter(const ContactInput& in, ContactForces& out, bool near_bound);
  // Half the work of the nodal damping forces over the step just taken (in.v in.dt), into
  // ContactStats::damping_energy: this step's after scatter; apply books last step's in its
  // loop over the surface nodes, where it clears them.
  void book_damping(const ContactInput& in);
  double damping_power(std::size_t node, const ContactInput& in) const {
    return damping_fx_[node] * in.vx[node] + damping_fy_[node] * in.vy[node] +
           damping_fz_[node] * in.vz[node];
  }
  // The stable step of central differences for springs of squared frequency omega2 (infinite
  // for 0), damped at the contact's fraction of critical damping xi with the velocity of the
  // half step before: (2 / omega)(sqrt(1 + xi^2) - xi) (Belytschko, Liu & Moran, Nonlinear
  // Finite Elements for Continua and Structures, 2000, section 6.2: stability with damping).
  // Undamped, 2 / omega; xi = 0.1 (the default) takes 9.5% off it.
  double spring_step(double omega2) const;
  // spring_step of a spring made at a penalty factor 1 (approach and initial bounds), at the
  // normal penalty's time factor of the last apply (settings.normal_in_time).
  double approach_spring_step(double omega2) const;
  void add_damping(std::int32_t node, const Vec3& force) {
    damping_fx_[node] += force.x;
    damping_fy_[node] += force.y;
    damping_fz_[node] += force.z;
  }
  // Thermal contact (heat_exchange.cpp): the conductance of point p with its partner, and the
  // heat of every pass to the nodes (conductance, conduction at the input's temperatures,
  // friction heat), serially in point order.
  void record_conductance(Pass& pass, std::size_t p, std::int32_t facet, double xi, double eta,
                          double pressure, double gap, double area);
  void scatter_heat(const ContactInput& in, ContactForces& out);
  // Calls link(pass, own nodes, own shape values, partner nodes, partner shape values, G) for
  // every point that conducts heat, in pass and point order (heat_exchange.cpp).
  template <class Link>
  void for_each_heat_link(const Link& link) const;
  void update_moving_region(const ContactInput& in);
  void initial_state(const ContactInput& in);

  ContactSettings settings_;
  std::vector<Side> sides_;
  std::vector<Pass> passes_;
  std::vector<double> mass_;
  std::vector<std::int32_t> surface_nodes_;  // union of both sides' nodes, sorted
  std::vector<double> bx_, by_, bz_;         // their positions at the last broad-phase build
  std::vector<double> wear_, pressure_;
  // The damping forces of the last step on each node (scatter; ContactStats::damping_energy).
  std::vector<double> damping_fx_, damping_fy_, damping_fz_;
  std::vector<std::int64_t> part_ids_;  // local part index -> user part id
  std::vector<double> part_scale_;      // pair scale, part_ids_.size()^2
  // The settings.pair_frictions entry of each part pair (-1: tangential_law), part_ids_.size()^2.
  std::vector<std::int32_t> part_friction_;
  double margin_ = 0.0;
  double smooth_reach_ = 0.0;  // overshoot beyond a smooth edge per unit |gap|: tan(alpha_edge)
  double sharp_cos_ = 1.0;     // cos(alpha_edge): facets turned further meet at a sharp edge
  double initial_stable_step_ = std::numeric_limits<double>::infinity();
  std::size_t builds_ = 0;
  bool enabled_ = true;               // set_enabled
  double spring_factor_ = 1.0;        // max(normal_in_time(t), 1) of the last apply (spring_step)
  bool rebuild_pending_ = false;      // points or facets changed (erosion)
  std::size_t gap_pairs_ = 0;         // pairs counted in stats_.gap_min / gap_max
  std::optional<EdgeContact> edges_;  // edge-to-edge contact (EdgeSettings)
  // Contact points per side as built (erosion adds more): what a restart file must match.
  std::vector<std::uint64_t> initial_points_;
  bool bands_current_ = false;  // the sides' bands are of this step (while apply evaluates)
  bool awake_current_ = false;  // the passes' awake lists hold since the last build
  // The largest approach_omega2 of the points with a candidate facet at the last build.
  double near_omega2_ = 0.0;
  // The energy in play for ContactStats::kink_step: the largest of the host's energy scale and
  // the kinetic energy of the surface nodes plus spring energy at any apply so far.
  double kink_scale_ = 0.0;
  double kink_hold_ = std::numeric_limits<double>::infinity();  // the kink_step of the last apply
  double kink_elastic_ = 0.0;  // the spring energy of the last apply (ContactStats::kink_step)
  std::vector<double> x0_, y0_, z0_;  // initial coordinates (Igap 2 only)
  ContactStats stats_;
};

}  // namespace abut
