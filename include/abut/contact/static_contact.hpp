#pragma once
// Penalty contact for the implicit (Newton-Raphson) solver: the surfaces, the partner search
// (narrow_phase.hpp) and the normal laws (laws/normal.hpp) of the explicit interface, linearised.
//
// Each contact point (a Gauss point of a secondary facet, surface-to-surface, or a secondary node,
// node-to-surface) that finds a partner facet is a small contact element over the nodes of its
// own facet (or its node) and of the partner facet, with weights w_a = +N_a(point) on its own
// nodes and -phi_a(xi, eta) on the partner's. With n the partner's normal and A the point's area
// (Gauss weight x current Jacobian, or the node's tributary area):
//   gap g = n . sum_a w_a x_a (negative = penetration d = -g), pressure p = law(d),
//   tangential traction t: an elastic stick spring k_t on the relative motion since the last
//   converged state, returned to the tangential law's limit (laws/tangential.hpp, the explicit
//   interface's laws): a point that stuck at the last converged state holds up to the static
//   limit, one that slid up to the sliding one; beyond it slides at the sliding limit L (mu_d p
//   for Coulomb, m k for Tresca),
//   force on node a: f_a = w_a A (p n + t).
// A surface-to-surface point stands for its cell (mortar.hpp; issue 27): unless tied or small
// sliding, it acts over the part of its cell that lies over the facets it faces, with A that
// area, n the cell's own normal (from the other surface), w_a the integrals of the overlap over
// A (+ on its own facet's nodes, - on each covered facet's), g the mean gap over the covered
// part, and the pressure along the covered facets' slope (push, the gradient of its energy);
// uniform pressure then loads both surfaces' nodes exactly, on any two meshes (the contact patch
// test).
// Tangent (-df/du), with the partner point and normal frozen within an iteration as CalculiX
// does for its face-to-face contact (CalculiX User's Manual 2.x, "Face-to-Face Penalty Contact",
// eq. 193; the geometric terms of node-to-face contact, eqs. 118-122, are left out):
//   normal   A w_a w_b (dp/dd) m (x) m   (m: the push, the gap's gradient; n for a point)
//   stick    A w_a w_b k_t (I - n (x) n)
//   slip     A w_a w_b [(dL/dp)(dp/dd) t^ (x) n - (dL/dV) / dt t^ (x) s^
//                       + (L k_t / |t_trial|)(I - t^ (x) t^)(I - n (x) n)]
//   k_t(d)   a tangential penalty of the penetration (Metafor PEN_TANGENT GD): t_trial = t_0 -
//            k_t(d) s adds -(dk_t/dd) s (x) n to the stick tangent, and its projection
//            -(L / |t_trial|)(dk_t/dd)(I - t^ (x) t^) s (x) n to the slip tangent
// (V = |s| / dt the sliding speed over the increment dt, s the slip, s^ its direction)
// (the return-mapping tangent of Coulomb friction, e.g. Wriggers, Computational Contact Mechanics,
// 2nd ed., 2006, section 10.3.2; unsymmetric when slipping). Tied contact: a bilinear spring in
// every direction on the relative motion since the pair was found, p = k_n d in tension too.
// Evaluations do not change the history; commit() does, once an increment has converged.
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "abut/contact/analytic_tool.hpp"
#include "abut/contact/broad_phase.hpp"
#include "abut/contact/dependent_nodes.hpp"
#include "abut/contact/interface.hpp"
#include "abut/contact/laws/adhesion.hpp"
#include "abut/contact/laws/normal.hpp"
#include "abut/contact/laws/stabilization.hpp"
#include "abut/contact/laws/tangential.hpp"
#include "abut/contact/laws/thermal.hpp"
#include "abut/contact/mortar.hpp"
#include "abut/contact/settings.hpp"
#include "abut/contact/smoothing.hpp"
#include "abut/contact/surface.hpp"
#include "abut/contact/thermal_contact_element.hpp"

namespace abut {

struct StaticContactSettings {
  bool node_to_surface = false;
  // A node's area (node to surface): the part of its vector area int N_a n dA that faces its
  // partner (Facing: a node on a block's edge bears with its share of the face that touches, not
  // of the side face), or the sum of its shares of every face around it (EveryFace: CalculiX's
  // rule for a nodal slave surface, *SURFACE TYPE=NODE, whose faces are every face at a node).
  enum class NodeArea { Facing, EveryFace } node_area = NodeArea::Facing;
  int accuracy_level = contact_defaults::kAccuracyLevel;  // Gauss points per direction of a
                                                          // secondary facet: 1, 2 or 3 levels
  NormalLaw normal = LinearPenalty{};
  double penalty = 0.0;  // pfac [stress / length], passed to the normal law
  // Its limits per unit area (normal force p, area 1), at the sliding speed |slip| / dt over the
  // increment (ContactInput::dt).
  TangentialLaw tangential_law = Frictionless{};
  // Per part pair, over tangential_law (Radioss /FRICTION; settings.hpp); their filters are
  // the explicit solver's (a static step has no time history to filter).
  std::vector<PairFriction> pair_frictions;
  // Nodes that are no secondary point (Radioss Irem_i2 = 1; removed_nodes.hpp).
  RemovedNodes removed_nodes;
  double stick_slope = 0.0;  // k_t [stress / length]; 0: the normal penalty
  // Metafor dependencies (laws/dependency.hpp), at the time of the evaluation (ContactInput::time,
  // constant within an increment): the normal law's pressure times f(t) (PEN_NORMALE TM), and
  // k_t times g(d) f(t) (PEN_TANGENT GD, TM). Ties keep the constant penalties.
  TimeFactor normal_in_time;
  TangentialPenalty stick_slope_factor;
  bool tied = false;           // bonded in every direction from the first evaluation on
  bool small_sliding = false;  // partners found at the first evaluation only
  // A point pairs with a facet when it lies at most `search_distance` outside it or at most
  // `depth` inside it (beyond: the far side of the body).
  double search_distance = 0.0;
  double depth = 0.0;
  // OptiStruct GPAD (seed 003): the surfaces touch at this distance [length] (a layer on the main
  // surface); the search reaches this much further out.
  double padding = 0.0;
  double edge_angle = contact_defaults::kEdgeAngle;  // degrees: edges sharper than this end the
                                                     // surface (narrow_phase.hpp)
  // Share of this pass in its contact: 1, or 1/2 for each of the two passes of a symmetric
  // contact (as the explicit interface weighs them); scales the points' areas.
  double weight = 1.0;
  // Radioss IVIS2 = -1 (laws/adhesion.hpp): a point that touched at a converged state and is
  // now open within the zone is pulled back, p = -SigMaxAdh s / (Gap/2) at the opening s
  // (tangent dp/dd = SigMaxAdh / (Gap/2)), and resisted sideways by the zone's viscosity over the
  // increment, t = -(ViscAdhFact ViscFluid / (Gap/2)) slip / dt (tangent the same factor over
  // dt, along the surface); beyond the zone the bond breaks until the point touches again.
  std::optional<Adhesion> adhesion;
  // STICK (OptiStruct TYPE = STICK, Metafor's sticking contact): no sliding while closed, the
  // stick spring k_t however large the traction; the surfaces may still separate.
  bool stick = false;
  // The reference configuration (the `initial` coordinates of the constructor), treated as the
  // explicit interface does (settings.hpp): a point paired there with a clearance starts with
  // that opening whatever its distance, for the whole run (OptiStruct CLEARANCE; negative:
  // interference); without one, an initial penetration d0 pushes from the start (Force, as
  // CalculiX), is subtracted until the point first separates (Shift, Radioss Inacti = 5), or is
  // subtracted up to initial_offset and released for good beyond initial_max (Offset, seed 000).
  std::optional<double> clearance;
  // Viscous stabilization of nearby surfaces (OptiStruct CNTSTB; laws/stabilization.hpp), scaled
  // by the factor of stabilize(); points open within its range get an element of it alone.
  std::optional<ContactStabilization> stabilization;
  InitialPenetration initial_penetration = InitialPenetration::Force;
  double initial_offset = 0.0;  // [length], Offset only
  double initial_max = 0.0;     // [length], Offset only
};

// A contact element of the last evaluation: its nodes (no repeats) with their weights w_a, the
// point's area A, its traction tau = p n + t and the 3 x 3 tangent C, so that
//   force on node a   f_a = w_a A tau,      -d f_a / d u_b = A w_a w_b C.
// A surface-to-surface cell integrated point by point (mortar.hpp, CellSample) carries its normal
// spring apart, summed over its samples q with areas A_q, weights W_qa, pressures p_q and
// stiffnesses k_q, and tau is its friction alone:
//   f_a += F_a m,  F_a = sum_q A_q p_q W_qa;
//   -d f_a / d u_b += S_ab m m^T,  S_ab = sum_q A_q k_q W_qa W_qb
// (m: the cell's push, the gradient of its gap).
struct StaticContactElement {
  std::array<std::int32_t, ContactWeights::kCapacity> nodes{};
  std::array<double, ContactWeights::kCapacity> weights{};
  int count = 0;
  double area = 0.0;
  Vec3 traction;
  std::array<double, 9> tangent{};       // row-major
  std::vector<double> spring_force;      // F_a, count entries; empty: no separate spring
  std::vector<double> spring_stiffness;  // S_ab, count x count, row-major
  Vec3 push;

  // Adds the nodal forces f_a to f (3 per node, in the element's node order).
  void add_forces(double* f) const;
  // The local stiffness -d f / d u, (3 count) x (3 count), row-major.
  void stiffness(double* k) const;
};

struct StaticContactPoint {
  std::int32_t node = -1;   // node-to-surface: the secondary node
  std::int32_t facet = -1;  // surface-to-surface: its own facet
  Vec3 position;
  bool paired = false;        // has a partner facet, open or closed
  std::int32_t partner = -1;  // paired: the partner facet (of the main surface)
  ContactWeights weights;     // paired: the nodes of its element with +N own, -phi partner
  bool active = false;        // closed: carries a spring
  bool slipping = false;
  double area = 0.0;
  Vec3 normal;             // the normal along which the gap is measured (the point's partner's;
                           // a cell's own, from the other surface)
  Vec3 push;               // direction of the normal traction: n, or a cell's push (mortar.hpp)
  double gap = 0.0;        // negative = penetration (after the initial shifts, see settings)
  double least_gap = 0.0;  // the smallest over a cell's samples (mortar.hpp); else the gap
  double pressure = 0.0;   // normal traction, positive in compression
  Vec3 traction;           // tangential traction on the point
  Vec3 slip;               // tangential relative motion since the last converged state
  Vec3 total_slip;         // tangential relative motion accumulated while in contact
  double energy = 0.0;     // elastic energy of its springs (normal and stick) [energy]
};

class StaticContact {
 public:
  // `secondary_nodes` (node-to-surface only): the nodes that act as points; empty: every node of
  // the secondary facets. The coordinates of `initial` are the reference configuration: tied and
  // small-sliding pairs are formed there, once. `dependents`: facet corners of curved faces that
  // are not host nodes (dependent_nodes.hpp); the inputs give the host's nodes only, and the
  // elements and points name host nodes only. `smoothing`: the smoothed surfaces' patches, whose
  // dependent nodes (among `dependents`) it places at each evaluation (smoothing.hpp).
  StaticContact(StaticContactSettings settings, ContactSurface secondary, ContactSurface main,
                std::span<const std::int32_t> secondary_nodes, const ContactInput& initial,
                DependentNodes dependents = {}, NagataSmoothing smoothing = NagataSmoothing{});

  // Node to surface against an analytic rigid tool (analytic_tool.hpp; Metafor's rigid contact
  // matrices in implicit steps) instead of a main surface: each node of `secondary` (or of
  // `secondary_nodes`) meets the tool where `pose` (of the total time, ContactInput::time) puts it,
  // with the laws of `settings`; its friction takes the slip relative to the tool's material, and
  // its tangent the turn of a curved tool's normal. std::invalid_argument for settings a tool
  // does not take (S2S, ties, small sliding, adhesion, clearance, initial-penetration options,
  // pair frictions, removed nodes).
  using ToolPoseAt = std::function<ToolPose(double time)>;
  StaticContact(StaticContactSettings settings, ContactSurface secondary, AnalyticTool tool,
                ToolPoseAt pose, std::span<const std::int32_t> secondary_nodes,
                const ContactInput& initial);

  // Evaluates every point at the coordinates of `in`.
  void evaluate(const ContactInput& in);
  // The evaluated state becomes the history (friction, tied pairs, small-sliding partners).
  void commit();
  // *CHANGE FRICTION: a new Coulomb coefficient (when given) and stick slope from the next
  // evaluation on.
  void change_friction(std::optional<double> mu, double stick_slope) {
    if (mu) settings_.tangential_law = Coulomb{*mu, *mu, {}, {}, {}, {}};  // constant, as given
    settings_.stick_slope = stick_slope;
  }
  // *CHANGE SURFACE BEHAVIOR: a new normal law and penalty from the next evaluation on; a tied
  // contact lets go (its points search partners again and may separate or slide).
  void change_normal(const NormalLaw& law, double penalty) {
    settings_.normal = law;
    settings_.penalty = penalty;
    settings_.tied = false;
  }
  // The stabilization's factor from the next evaluation on: the step's ramp times its period
  // (laws/stabilization.hpp); 0 switches it off.
  void stabilize(double factor) { stabilization_factor_ = factor; }
  const StaticContactSettings& settings() const { return settings_; }

  std::span<const StaticContactElement> elements() const { return elements_; }
  // Heat conduction through the contact at the last evaluation (issue 11, steady heat): one
  // element per paired point, open or closed, whose conductance h(pressure, gap) A is > 0
  // (laws/thermal.hpp; an open point has no pressure), over the weights of its contact element.
  std::vector<ThermalContactElement> thermal_elements(const ConductanceLaw& law) const;
  std::span<const StaticContactPoint> points() const { return points_; }
  bool symmetric() const { return symmetric_; }  // false when a point slips with friction
  const ContactSurface& secondary() const { return secondary_; }
  bool node_to_surface() const { return settings_.node_to_surface; }
  Vec3 total_force() const;                                // on the secondary surface
  double energy() const;                                   // sum over the points
  double friction_work() const { return friction_work_; }  // dissipated so far (committed)
  // Dissipated by the stabilization so far (committed).
  double stabilization_work() const { return stabilization_work_; }

 private:
  struct History {
    bool in_contact = false;
    std::int32_t facet = -1;  // partner facet (tied and small sliding: fixed)
    double xi = 0.0, eta = 0.0;
    Vec3 traction;         // committed tangential traction
    bool sliding = false;  // beyond the static limit: held only up to the sliding one
    bool adhered = false;  // touched, and not yet opened beyond the adhesive zone
    Vec3 offset;           // tied: relative position x_point - x_partner when the pair formed
    Vec3 total_slip;
    double slip_work = 0.0;
    double stabilization_work = 0.0;
    double initial_offset = 0.0;  // subtracted from the penetration until the point separates
  };
  void initial_gaps(const ContactInput& initial);

  // Where the points are at an evaluation (static_contact_points.cpp): their positions and areas
  // into points_, and for the search their positions, own normals (S2S), nodes' vector areas
  // (int N_a n dA over their facets, N2S) and, meeting by cells, the cells' boxes and reach.
  struct PointGeometry {
    std::vector<double> qx, qy, qz;
    std::vector<Vec3> own_normal, node_area;
    std::vector<Box> regions;
    std::vector<double> cell_reach;
  };
  PointGeometry locate_points(const ContactInput& in, bool by_cells);
  // The main facets whose boxes, grown by reach + edge_tolerance, hold each point (by_cells:
  // meet its cell's box).
  CandidateList candidate_facets(const ContactInput& in, const PointGeometry& g, bool by_cells,
                                 double reach, double edge_tolerance) const;

  // The host's coordinates extended by those of the dependent nodes (evaluate's input).
  ContactInput extended(const ContactInput& host);

  StaticContactSettings settings_;
  ContactSurface secondary_, main_;
  DependentNodes dependents_;
  NagataSmoothing smoothing_;
  // An analytic tool as the main surface (main_ then empty): where it is at a time, and where it
  // was at the last evaluation and at the last commit.
  std::optional<AnalyticTool> tool_;
  ToolPoseAt tool_pose_;
  ToolPose pose_, committed_pose_;
  std::vector<double> ex_, ey_, ez_;  // extended coordinates of the current evaluation
  std::vector<std::uint8_t> main_sharp_, main_active_, main_free_;
  std::vector<double> main_depth_, main_gap_, main_min_edge_;
  std::vector<std::int32_t> main_twin_;
  // Points: own facet and Gauss point (S2S) or node (N2S).
  std::vector<std::int32_t> point_facet_, point_node_;
  std::vector<double> point_xi_, point_eta_, point_weight_;
  std::vector<CellBounds> point_cell_;  // S2S: the cell each point stands for (mortar.hpp)
  std::vector<std::int32_t> node_facet_start_, node_facets_;  // N2S: facets around each node
  std::vector<double> x0_, y0_, z0_;                          // reference coordinates
  std::vector<double> xc_, yc_, zc_;                          // at the last commit
  std::vector<double> xe_, ye_, ze_;                          // of the last evaluation
  std::vector<History> committed_, trial_;
  std::vector<double> shift_;           // per point: clearance - initial gap (empty: none)
  std::vector<std::uint8_t> released_;  // per point: released at the start (empty: none)
  std::vector<StaticContactPoint> points_;
  std::vector<StaticContactElement> elements_;
  bool symmetric_ = true;
  bool first_ = true;
  double friction_work_ = 0.0;
  double stabilization_factor_ = 0.0;
  double stabilization_work_ = 0.0;
};

}  // namespace abut
