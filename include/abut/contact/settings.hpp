#pragma once
// Settings of one contact interface, in plain values and callbacks, so that a host code can drive
// the library without a deck, a solver or a function table. Lengths, times and stresses are in the
// caller's units. The defaults are seed 000's (IMPETUS *CONTACT). Inconsistent settings raise
// ContactSetupError naming the setting in the library's own terms.
#include <algorithm>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "abut/contact/gap.hpp"
#include "abut/contact/laws/adhesion.hpp"
#include "abut/contact/laws/normal.hpp"
#include "abut/contact/laws/tangential.hpp"
#include "abut/contact/laws/thermal.hpp"
#include "abut/contact/removed_nodes.hpp"
#include "abut/contact/stiffness_rule.hpp"

namespace abut {

// Wear rate (wear depth per unit time) from the contact pressure and the sliding speed. Pure.
using WearRateFunction = std::function<double(double pres, double vtang)>;
// Is the point (x, y, z) inside a region (gid_0 / gid_1)? Called serially.
using RegionPredicate = std::function<bool(double x, double y, double z)>;

// What acts as a contact point: integration points on the facets of a surface (seed 000) or the
// nodes of a surface or node group (Radioss TYPE25, OptiStruct DISCRET = N2S).
enum class Discretisation { SurfaceToSurface, NodeToSurface };

// What happens to points that penetrate in the initial configuration.
enum class InitialPenetration {
  Offset,  // seed 000: released beyond initial_max, else min(d0, initial_offset) subtracted until
           // separation
  Shift,   // Radioss Inacti = 5: the whole d0 subtracted (P' = P - P0) until separation
  Force,   // Radioss Inacti = -1: every initial penetration pushes from the start
};

// Whether part sets parts1 and parts2 cover the pair of parts (a, b), either way round: an empty
// parts1 is every part, an empty parts2 is parts1 with itself (PairScale, PairFriction).
inline bool covers_pair(const std::vector<std::int64_t>& parts1,
                        const std::vector<std::int64_t>& parts2, std::int64_t a, std::int64_t b) {
  auto in = [](const std::vector<std::int64_t>& set, std::int64_t part) {
    return set.empty() || std::find(set.begin(), set.end(), part) != set.end();
  };
  const std::vector<std::int64_t>& second = parts2.empty() ? parts1 : parts2;
  return (in(parts1, a) && in(second, b)) || (in(parts1, b) && in(second, a));
}

// Abaqus *CONTACT CONTROLS ASSIGNMENT, TYPE=SCALE PENALTY (seed 001): the springs between facets of
// parts1 and parts2 are scaled. Empty parts1: every part of the interface; empty parts2: parts1
// with itself. Where several assignments cover a pair, the last one wins.
struct PairScale {
  std::vector<std::int64_t> parts1, parts2;
  double scale = 1.0;
};

// Radioss /FRICTION (seed 004, fric_ID and comment 7): the tangential law and filter of the
// points between facets of parts1 and parts2 (either way round), in place of the interface's
// tangential_law and friction_filter. Empty parts1: every part of the interface; empty parts2:
// parts1 with itself. Where several cover a pair, the last one wins (as PairScale).
struct PairFriction {
  std::vector<std::int64_t> parts1, parts2;
  TangentialLaw law = Frictionless{};
  FrictionFilter filter;
};

// Edge-to-edge contact (Radioss /INTER/TYPE25 Iedge and Edge_angle, seed 004, comment 6): edges of
// surface 1 (secondary) that cross edges of surface 2 (main) are pushed apart, which a point-to-
// facet contact misses. Friction is not included (seed 004).
enum class EdgeSelection {
  None,                 // Iedge 1000 (default)
  ShellBorders,         // Iedge 1: free edges of shells on both sides
  SharpSolidEdges,      // Iedge 11: secondary sharp solid edges and shell borders; main: all
                        //   exterior solid edges and shell borders
  SharpSolidAllShells,  // Iedge 13: as 11, the main side with every shell edge
  AllEdges,             // Iedge 22: every exterior solid edge and every shell edge, both sides
};
struct EdgeSettings {
  EdgeSelection selection = EdgeSelection::None;
  // Edge_angle [degrees]: a solid edge is sharp when its two facets meet at an angle below it
  // (180 = flat), i.e. when their normals turn by more than 180 - Edge_angle.
  double angle = 135.0;
};

// What element erosion does to the contact (the host reports eroded elements, interface.hpp).
struct ErosionSettings {
  // A facet whose element has eroded leaves the contact (IMPETUS; Radioss Idel 1 and 2); false:
  // it stays (Radioss Idel 1000).
  bool remove_facets = true;
  // A node whose facets have all eroded stays in contact as a free point mass (Abaqus/Explicit
  // default, seed 001); false: it leaves (Abaqus nodal erosion; Radioss Idel 1 and 2).
  bool keep_free_nodes = true;
};

// A point within this fraction of its element thickness of its partner counts as touching:
// sticking contact ties it, and a thermal contact conducts as closed (this absorbs the round-off
// gaps of coincident surfaces).
inline constexpr double kTouchingGapFraction = 1e-6;

// Heat through the contact (issue 11; laws/thermal.hpp). Acts when the caller passes nodal
// temperatures and a heat array (ContactInput::temperature, ContactForces::heat).
struct ThermalContactSettings {
  // Conduction between the surfaces: q = h (T_point - T_partner) per unit area, h from the contact
  // pressure and the gap. Points within the search distance of a partner conduct while open when
  // the law gives h > 0 there (OptiStruct open conductance, Radioss distance law).
  std::optional<ConductanceLaw> conductance;
  // Friction work turned into heat, shared between the surfaces (IMPETUS fric_heat, Radioss Fheat).
  std::optional<FrictionHeatSplit> friction_heat;
  bool any() const { return conductance.has_value() || friction_heat.has_value(); }
};

// The defaults of a contact, each defined here once: the explicit settings below, the static
// contact (static_contact.hpp) and the model's contacts (abut/model/model.hpp) take them from here.
// Values: IMPETUS *CONTACT (seed 000): accuracy level 2, xi = 0.1, alpha_edge = 20 degrees, active
// for all time.
namespace contact_defaults {
inline constexpr int kAccuracyLevel = 2;
inline constexpr double kDamping = 0.1;     // fraction of critical damping
inline constexpr double kEdgeAngle = 20.0;  // degrees
inline constexpr double kBeginTime = 0.0;
inline constexpr double kEndTime = 1e20;
}  // namespace contact_defaults

struct ContactSettings {
  Discretisation discretisation = Discretisation::SurfaceToSurface;
  int accuracy_level = contact_defaults::kAccuracyLevel;  // S2S: 1 centre point, 2: 2x2 Gauss, >2:
                                                          // 3x3 Gauss per facet
  bool accuracy_edge = false;  // extra integration points in strips along sharp edges
  bool one_way = false;        // only surface 1's points act (else both sides, weight 1/2 each)
  // Nodes that are no secondary point on either side (Radioss Irem_i2 = 1; removed_nodes.hpp).
  RemovedNodes removed_nodes;

  // Normal direction.
  NormalLaw normal_law = LinearPenalty{};
  // Metafor PEN_NORMALE (TM): the normal law's pressure times f(t) (laws/dependency.hpp); not
  // for ties (freeze, stick_stress), whose springs keep the penalty.
  TimeFactor normal_in_time;
  ContactSense sense = ContactSense::Positive;
  std::optional<double> detection_depth;  // default: half the element thickness of either facet
  std::optional<double> clearance;  // OptiStruct CLEARANCE: initial opening of every point found
  GapSettings gaps;                 // shell gaps (Radioss Igap, Gap_scale, Gap_max_s/m)
  EdgeSettings edges;               // edge-to-edge contact
  ErosionSettings erosion;
  std::optional<Adhesion> adhesion;  // Radioss IVIS2 = -1
  double damping =
      contact_defaults::kDamping;  // xi: fraction of critical damping of each contact spring

  // Tangential direction.
  TangentialLaw tangential_law = Frictionless{};
  std::optional<double> tangential_penalty;  // [stress / length]; default: the normal penalty
  // Metafor PEN_TANGENT (GD, TM): the tangential spring times g(penetration) f(t).
  TangentialPenalty tangential_penalty_factor;
  FrictionFilter friction_filter;
  std::vector<PairFriction> pair_frictions;  // per part pair, over tangential_law (in order)
  bool freeze =
      false;  // OptiStruct FREEZE: points found at t = 0 tied in every direction, open or closed
  std::optional<double> stick_stress;  // sigma_stick (seed 000): tied on touch until this traction

  // Springs.
  StiffnessSettings stiffness;
  std::vector<PairScale> pair_scales;

  // Time window, regions, initial state, edges, wear.
  double begin_time = contact_defaults::kBeginTime;  // t_beg
  double end_time = contact_defaults::kEndTime;      // t_end
  RegionPredicate initial_region;  // gid_0: facets whose centroid is outside at t=0 never contact
  RegionPredicate moving_region;   // gid_1: facets whose centroid leaves it are deactivated
  InitialPenetration initial_penetration = InitialPenetration::Offset;
  double initial_offset = 0.0;        // delta0_offset
  std::optional<double> initial_max;  // delta0_max; default 4% of the point's element thickness
  double edge_tolerance = 0.0;        // delta_edge: accepted overshoot beyond sharp edges
  double edge_angle = contact_defaults::kEdgeAngle;  // alpha_edge [degrees]
  WearRateFunction wear_rate1, wear_rate2;
  ThermalContactSettings thermal;
  // Bytes the contact points may take (their count is known before they are made); more is a
  // ContactSetupError "memory". A host passes what it can spare (abut: abut/core/memory.hpp).
  double memory_limit = std::numeric_limits<double>::infinity();
  std::optional<double>
      search_margin;  // broad-phase margin; default: half the smallest detection depth
  // Speed only, results are the same either way (tested): points that are surely open are skipped
  // before their projections (penetration_zone.hpp). Off: every point near a facet is projected.
  bool skip_open_points = true;
};

// A setting the library cannot work with; `setting` names the ContactSettings member (or the
// surface, "surface1" / "surface2"), so that a caller can point at its own input.
class ContactSetupError : public std::invalid_argument {
 public:
  ContactSetupError(std::string setting, const std::string& message)
      : std::invalid_argument(message), setting_(std::move(setting)) {}
  const std::string& setting() const { return setting_; }

 private:
  std::string setting_;
};

}  // namespace abut
