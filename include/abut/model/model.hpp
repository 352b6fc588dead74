#pragma once
// The model: everything a deck describes, resolved to plain data (deck units). The deck reader
// (src/io) builds it; the solver runs it. Ids are the user's ids; node references are indices.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "abut/contact/analytic_tool.hpp"
#include "abut/contact/settings.hpp"
#include "abut/core/error.hpp"
#include "abut/core/functions.hpp"
#include "abut/core/units.hpp"
#include "abut/element/shell_block.hpp"
#include "abut/element/solid_block.hpp"
#include "abut/material/material.hpp"
#include "abut/mesh/geometry.hpp"
#include "abut/mesh/mesh.hpp"
#include "abut/model/entity.hpp"
#include "abut/model/model_static.hpp"
#include "abut/model/model_thermal.hpp"
#include "abut/model/output.hpp"
#include "abut/model/sources.hpp"

namespace abut {

// *TIME
struct TimeControl {
  double end_time = 0.0;          // t_term
  double step_scale = 0.9;        // sf_dt
  double min_step = 0.0;          // dt_min: the run stops if the stable step falls below it
  double max_step = 1e10;         // dt_max
  double start_time = 0.0;        // t_start
};

// *CONTROL_BULK_VISCOSITY: the artificial bulk viscosity of every deformable hexahedron
// (SolidBlock::set_bulk_viscosity; its defaults are LS-DYNA's). Both 0: none.
struct BulkViscosity {
  double quadratic = SolidBlock::kDefaultBulkViscosityQuadratic;  // q1
  double linear = SolidBlock::kDefaultBulkViscosityLinear;        // q2
};

struct Material {
  std::int64_t id = 0;
  MaterialParams params;
  SourceLocation where;
  std::int64_t thermal_id = 0;  // thpid: ThermalModel::properties; 0 = no thermal properties
};

struct Part {
  std::int64_t id = 0;
  std::string title;
  std::int64_t material_id = 0;
  ErosionCriteria erosion;  // dt_erode, eps_geo_erode, eps_v_erode
  double thickness = 1.0;   // h: shell thickness (used by shell elements only)
  // *PART_SHELL: integration points through the thickness (odd) and hourglass coefficient.
  int shell_points = ShellSection{}.points;
  double shell_hourglass = ShellSection{}.hourglass;
  // Integration of the part's solids: reduced (8-node hexahedra: one point with hourglass
  // control, explicit and Abaqus C3D8R; 20-node: 2x2x2 points, C3D20R) or full (the static
  // solver's C3D8, C3D20; tetrahedra and wedges have only this one).
  enum class SolidIntegration { Reduced, Full } solid_integration = SolidIntegration::Reduced;
  SourceLocation where;
};

struct NodeSet {
  std::int64_t id = 0;
  std::vector<std::int32_t> nodes;  // node indices
};

struct PartSet {
  std::int64_t id = 0;
  std::vector<std::int64_t> parts;  // part ids
};

// One `pmeth, direc, cid, sf, fid` line of *BC_MOTION.
struct PrescribedMotion {
  enum class Kind { Acceleration, Velocity, Displacement } kind = Kind::Velocity;
  int direction = 0;  // 0..2 = X, Y, Z; 3..5 = RX, RY, RZ (rigid parts only)
  FunctionRef curve;  // value as a function of time
  double scale = 1.0;
  FunctionRef activation;  // optional: motion acts while this is > 0
  SourceLocation where;
};

// *BC_MOTION
struct MotionBoundary {
  std::int64_t id = 0;
  EntityRef entity;
  std::uint8_t fixed_translation = 0;  // DofMask bits
  std::uint8_t fixed_rotation = 0;     // DofMask bits (x, y, z rotations), rigid parts only
  double begin_time = 0.0;
  double end_time = 1e10;
  std::vector<PrescribedMotion> motions;
  SourceLocation where;
};

// *LOAD_GRAVITY: the curve gives the acceleration component along `direction` (0..2).
struct Gravity {
  int direction = 2;
  FunctionRef curve;
  double scale = 1.0;
  SourceLocation where;
};

// *LOAD_PRESSURE: a pressure, function of time, on the exterior faces of the solid elements and
// on the shells of an entity (P, PS, ALL, or G: the faces whose nodes all lie in the region).
// Positive pressure pushes against the face normal: it compresses a solid; on a shell it acts
// along -n, n = (x3 - x1) x (x4 - x2).
struct PressureLoad {
  EntityRef entity;
  FunctionRef curve;  // pressure [stress] as a function of time
  double scale = 1.0;
  SourceLocation where;
};

// *SENSOR (abut's own, after Radioss /SENSOR TIME, DIST and INTER): a condition on the run that,
// once met, stays met (the sensor has triggered); it is on from `delay` after that. Sensors
// switch contacts on or off (ContactSpec::sensor; seed 004 sens_ID).
struct Sensor {
  enum class Kind { Time, Distance, ContactForce } kind = Kind::Time;
  std::int64_t id = 0;
  double threshold = 0.0;    // Time: the time; Distance: a length; ContactForce: a force
  bool below = false;        // Distance, ContactForce: triggers below the threshold (else above)
  double delay = 0.0;        // on this long after it triggers
  EntityRef node1, node2;    // Distance: the two nodes (EntityType::Node)
  std::int64_t contact = 0;  // ContactForce: the *CONTACT whose total normal force is watched
  SourceLocation where;
};

// *CONTACT, field by field (seed 000; keyword reference §6). Optional fields are empty when
// the deck leaves them out, so that the contact code applies the documented defaults.
struct ContactSpec {
  std::int64_t id = 0;
  std::string title;
  int accuracy_level = contact_defaults::kAccuracyLevel;
  bool accuracy_edge = false;
  EntityRef surface1, surface2;
  double friction = 0.0;          // used when friction_function is invalid
  FunctionRef friction_function;  // mu = fcn(fid)
  std::optional<double> penalty;  // pfac; automatic when empty
  double begin_time = contact_defaults::kBeginTime;
  double end_time = contact_defaults::kEndTime;
  bool merge = false;
  double damping = contact_defaults::kDamping;       // fraction of critical damping
  std::optional<std::int64_t> initial_geometry;      // gid_0
  std::optional<std::int64_t> moving_geometry;       // gid_1
  double initial_offset = 0.0;                       // delta0_offset
  std::optional<double> initial_max;                 // delta0_max (default 4% of element thickness)
  double edge_tolerance = 0.0;                       // delta_edge
  FunctionRef wear1, wear2, thermal;                 // fid_wear1, fid_wear2, fid_thermal
  double edge_angle = contact_defaults::kEdgeAngle;  // alpha_edge [degrees]
  bool one_way = false;
  bool no_internal = false;
  std::optional<double> stick_stress;  // sigma_stick
  bool friction_heat = false;
  SourceLocation where;

  // *CONTACT_THERMAL (abut's own): a conductance law other than fid_thermal's function, and how
  // the friction heat is shared (laws/thermal.hpp).
  struct Conductance {
    enum class Law { Pressure, OpenClosed, Distance } law = Law::Pressure;
    double nominal = 0.0, hardness = 1.0, exponent = 1.0;  // Pressure: h_c0 (p / H_v)^w (Metafor)
    double closed = 0.0, open = 0.0;                       // OpenClosed (OptiStruct)
  };
  std::optional<Conductance> conductance;
  FunctionRef distance_conductance;        // Distance: h(gap) (Radioss)
  double friction_heat_to_surface1 = 0.5;  // share of the friction heat going to surface 1
  bool exchanges_heat() const { return thermal.valid() || conductance || friction_heat; }

  // *CONTACT_DISCRETIZATION
  Discretisation discretisation = Discretisation::SurfaceToSurface;
  std::optional<bool> symmetric;  // empty: symmetric unless one_way (node groups: one-way)
  // Radioss Irem_i2 = 1: the nodes that exact ties (TieSpec) tie are no secondary points here.
  bool remove_tied_nodes = false;
  // *CONTACT_NORMAL
  FunctionRef penalty_curve;  // pressure as a function of penetration (law CURVE)
  ContactSense sense = ContactSense::Positive;
  std::optional<double> detection_depth;
  std::optional<double> clearance;
  // *CONTACT_ADHESION
  std::optional<Adhesion> adhesion;
  // *CONTACT_FRICTION (when absent: Coulomb with mu of *CONTACT)
  enum class FrictionLaw {
    Impetus,
    None,
    Coulomb,
    Tresca,
    Stick,
    Freeze,
    Viscous,
    Darmstad,
    Renard
  };
  FrictionLaw friction_law = FrictionLaw::Impetus;
  bool exact_tie = false;  // FREEZE as a kinematic constraint (tie = EXACT); moved to Model::ties
  double mu_static = 0.0, mu_dynamic = 0.0;
  std::optional<double> tangential_penalty;
  std::array<double, 6> friction_c{};  // C1..C6 (Radioss laws), m_s, m_d, k (Tresca)
  FrictionFilter friction_filter;
  // *CONTACT_FRICTION_PAIR (Radioss fric_ID, /FRICTION): the law between facets of two part sets,
  // in place of the law above; in deck order, the last covering pair winning. Laws NONE, COULOMB,
  // TRESCA, VISCOUS, DARMSTAD and RENARD; the tangential penalty is the contact's.
  struct FrictionPair {
    std::optional<EntityRef> set1, set2;  // empty set1: every part; empty set2: set1 with itself
    FrictionLaw law = FrictionLaw::None;
    double mu_static = 0.0, mu_dynamic = 0.0;
    std::array<double, 6> c{};  // as friction_c
    FrictionFilter filter;
    SourceLocation where;
  };
  std::vector<FrictionPair> friction_pairs;
  // *CONTACT_DEPENDENCY (Metafor TM / GD, seed 002): the functions that multiply a parameter;
  // invalid when not given.
  FunctionRef pfac_in_time;                           // PEN_NORMALE TM
  FunctionRef mu_static_in_time, mu_dynamic_in_time;  // COEF_FROT_STA/DYN, TRESCA_STA_M/DYN_M TM
  FunctionRef yield_in_time;                          // TRESCA_K TM
  FunctionRef pen_t_in_time, pen_t_of_gap;            // PEN_TANGENT TM, GD (of the penetration)
  struct Dependency {
    enum class Parameter { Pfac, MuStatic, MuDynamic, Yield, PenT } parameter = Parameter::Pfac;
    bool gap = false;  // GAP (else TIME)
    SourceLocation where;
    // The parameter's name in *CONTACT_DEPENDENCY (for messages, the log and summary.json).
    const char* name() const {
      static constexpr const char* names[] = {"PFAC", "MU_S", "MU_D", "K", "PEN_T"};
      return names[static_cast<int>(parameter)];
    }
  };
  std::vector<Dependency> dependencies;
  // *CONTACT_STIFFNESS
  StiffnessSettings stiffness;
  bool element_penalty = false;  // rule ELEMENT: automatic penalty from the element step
  // *CONTACT_SCALE_PENALTY, in deck order
  struct Scale {
    std::optional<EntityRef> set1, set2;
    double scale = 1.0;
    SourceLocation where;
  };
  std::vector<Scale> pair_scales;
  // *CONTACT_INITIAL
  InitialPenetration initial_penetration = InitialPenetration::Offset;
  // ADJUST (seed 003): secondary nodes within this depth moved onto surface 2. -1.0 is AUTO, which
  // the solver turns into 5% of the mean edge length of surface 2; 0.0 is the contact's search
  // depth (detection_depth, else half the thinnest element of surface 2).
  std::optional<double> adjust_depth;
  // ADJUST = SET of GRID (seed 003): only the secondary nodes in this node set are adjusted.
  std::optional<EntityRef> adjust_nodes;
  GapSettings gaps;  // *CONTACT_GAP
  // *CONTACT_GAP shell_side (OptiStruct MORIENT, seed 003): which sides of surface 2's shells act.
  // Both: two-sided shells (OPENGAP); Normal / Reverse: one side on the mid-surface (NORM,
  // REVNORM; ContactSurface::add_shell_side); Overlap: one side per facet, facing away from the
  // secondary nodes through it at the start (OVERLAP; shell_orientation.hpp).
  enum class ShellSides { Both, Normal, Reverse, Overlap } main_shell_sides = ShellSides::Both;
  ErosionSettings erosion;  // *CONTACT_EROSION
  EdgeSettings edges;       // *CONTACT_EDGE
  // Abaqus/CalculiX *SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=EXPONENTIAL (CalculiX form): the
  // pressure is p0 at zero distance and falls exponentially to 1% of p0 at the clearance c0.
  struct Exponential {
    double c0 = 0.0, p0 = 0.0;
  };
  std::optional<Exponential> exponential;
  // *CONTACT PAIR, SMALL SLIDING (OptiStruct TRACK = small): partners found once, at the start.
  bool small_sliding = false;
  // *CONTACT_STABILIZATION (abut's own; OptiStruct CNTSTB, seed 003 comment 7): viscous damping
  // of nearby surfaces in static steps (laws/stabilization.hpp), ramped from `start` to `end`
  // over each step; range empty: the contact's search distance.
  struct Stabilization {
    double scale = 1.0, start = 1.0, end = 0.0, tangent_fraction = 1.0;
    std::optional<double> range;
    SourceLocation where;
  };
  std::optional<Stabilization> stabilization;
  // *CONTACT_SMOOTHING (OptiStruct SMOOTH / SMSIDE, seed 003): the surfaces of an S2S contact
  // that meet as smooth Nagata patches over their facets in static steps (smoothing.hpp); crease
  // empty: kSmoothingCrease.
  struct Smoothing {
    bool surface1 = false, surface2 = false;
    std::optional<double> crease;
    // OptiStruct SMREG = SURF id: only the facets of these faces (a FaceSet) are smoothed, their
    // nodal normals from them alone; empty: every facet of the side (SMREG ALL).
    std::optional<EntityRef> region;
    SourceLocation where;
  };
  std::optional<Smoothing> smoothing;
  // *CONTACT_SENSOR (Radioss sens_ID): the contact acts while the sensor is on (switches_off:
  // until it is on); t_beg and t_end are then not used (seed 004, comment 10). Explicit runs.
  std::optional<std::int64_t> sensor;
  bool sensor_switches_off = false;
  // *CONTACT_RELEASE_BC (Radioss IBCX, IBCY, IBCZ): DofMask bits of the fixed directions released
  // on every node of surface 1 from its first contact. Explicit runs.
  std::uint8_t release_bc = 0;
};

// *CONTACT_TOOL (abut's own, after Metafor's analytic rigid contact matrices, seed 002): a plane,
// cylinder or sphere moved rigidly: velocity component d = velocity_scale[d] * velocity[d](t)
// (no curve: 0), and a cylinder's spin about its axis spin_scale * spin(t) [rad / time].
struct RigidTool {
  std::int64_t id = 0;
  AnalyticTool tool;
  std::array<FunctionRef, 3> velocity;
  std::array<double, 3> velocity_scale{1.0, 1.0, 1.0};
  FunctionRef spin;
  double spin_scale = 1.0;
  SourceLocation where;
};

// An exact kinematic tie (*CONTACT_FRICTION FREEZE with tie = EXACT; OptiStruct FREEZE as a TIE
// kinematic condition, seed 003 comment 10): every node of surface 1 found at t = 0 within the
// detection depth of a facet of surface 2 follows that facet, x_s = sum N_a(xi) x_a + offset
// (solver/tie_search.hpp). A constraint, not a spring: the contact keywords of its *CONTACT set
// only which nodes and facets are tied.
struct TieSpec {
  std::int64_t id = 0;  // ctid of the *CONTACT
  std::string title;
  EntityRef surface1, surface2;
  bool merge = false;
  std::optional<double> detection_depth;  // *CONTACT_NORMAL depth (empty: the contact default)
  double edge_tolerance = 0.0, edge_angle = contact_defaults::kEdgeAngle;
  SourceLocation where;  // the contact (Sources: "exact", the field that asks for the tie)
};

// A geometry of *GEOMETRY_* with its id.
struct GeometryEntry {
  std::int64_t id = 0;
  Geometry geometry;
  SourceLocation where;
};

struct Model {
  std::string title;
  std::string deck_path;
  std::optional<UnitSystem> units;  // set by *UNIT_SYSTEM
  TimeControl time;
  OutputRequests output;  // output.hpp
  BulkViscosity bulk_viscosity;

  Mesh mesh;
  std::vector<Material> materials;
  std::vector<Part> parts;
  std::vector<NodeSet> node_sets;
  std::vector<PartSet> part_sets;
  std::vector<GeometryEntry> geometries;
  FunctionTable functions;

  // Initial nodal velocities (*INITIAL_VELOCITY already applied), one entry per node.
  std::vector<double> vx0, vy0, vz0;
  // Initial nodal angular velocities (the omega of *INITIAL_VELOCITY); used by shell nodes.
  std::vector<double> wx0, wy0, wz0;

  std::vector<MotionBoundary> motions;
  std::vector<Gravity> gravity;
  std::vector<PressureLoad> pressures;
  std::vector<ContactSpec> contacts;
  std::vector<RigidTool> tools;  // *CONTACT_TOOL
  std::vector<TieSpec> ties;     // exact ties (not in `contacts`: they have no penalty springs)
  std::vector<Sensor> sensors;   // *SENSOR, in deck order
  // The static procedure (model_static.hpp): empty for an explicit run.
  std::vector<StaticStep> static_steps;
  std::vector<FaceSet> face_sets;
  std::vector<LinearConstraint> equations;
  // Heat (model_thermal.hpp): empty properties = no temperature field.
  ThermalModel thermal;
  // Where the input gave the settings, and its words for them (sources.hpp): the reader fills it.
  Sources sources;

  // Look-ups by user id; nullptr when absent.
  const Part* find_part(std::int64_t id) const;
  const Material* find_material(std::int64_t id) const;
  const GeometryEntry* find_geometry(std::int64_t id) const;
  // The *CONTACT_TOOL of an entity of type Tool; InputError at its location if it does not exist.
  const RigidTool& tool(const EntityRef& entity) const;
  const MaterialParams& material_of_part(std::int64_t part_id) const;
  // Where the input gave `setting` of contact c (sources), else the contact's own place; and
  // whether it gave it.
  SourceLocation place_of(const ContactSpec& c, std::string_view setting) const;
  bool gives(const ContactSpec& c, std::string_view setting) const;

  // Node indices of an entity (sorted, unique); InputError at the entity's location if the
  // id does not exist.
  std::vector<std::int32_t> nodes_of(const EntityRef& entity) const;
  // The nodes of every output.history_nodes entity (sorted, unique); InputError as nodes_of.
  std::vector<std::int32_t> history_nodes() const;
  // Part ids of an entity of type Part, PartSet or All.
  std::vector<std::int64_t> parts_of(const EntityRef& entity) const;
  // The face set of an entity of type FaceSet; InputError at its location if it does not exist.
  const FaceSet& face_set(const EntityRef& entity) const;
};

}  // namespace abut
