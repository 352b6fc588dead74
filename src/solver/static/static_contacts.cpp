#include "solver/static/static_contacts.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>

#include "abut/contact/smoothing.hpp"
#include "abut/core/error.hpp"
#include "abut/solver/contact_surfaces.hpp"
#include "abut/solver/curved_faces.hpp"
#include "solver/contact_set.hpp"
#include "solver/contact_settings_of.hpp"
#include "solver/tool_motion.hpp"

namespace abut::detail {

namespace {

// Default delta0_max of seed 000: 4% of the element thickness (as the explicit interface).
constexpr double kDefaultInitialMaxFraction = 0.04;

[[noreturn]] void not_static(const SourceLocation& where, const std::string& what) {
  throw InputError(where, what + " is not supported in static steps yet");
}

// Everything of the contact the static contact does not do: an error where the input asks for it.
void check_static(const Model& model, const ContactSpec& spec) {
  const auto at = [&model, &spec](std::string_view setting) {
    return model.place_of(spec, setting);
  };
  const auto given = [&model, &spec](std::string_view setting) {
    return model.gives(spec, setting);
  };
  if (spec.begin_time != contact_defaults::kBeginTime)
    not_static(at("begin_time"), "an activation window (a begin and end time)");
  if (spec.end_time < contact_defaults::kEndTime)
    not_static(at("end_time"), "an activation window (a begin and end time)");
  if (spec.initial_geometry || spec.moving_geometry)
    not_static(at("regions"), "a contact region (a geometry that limits the contact)");
  if (spec.wear1.valid() || spec.wear2.valid()) not_static(at("wear"), "wear");
  // Conductance acts in the steady heat of each state (static_heat.hpp); friction heat is a power
  // over time, which a steady state has not.
  if (spec.friction_heat) not_static(at("friction_heat"), "friction heat");
  if (spec.stick_stress) not_static(at("stick_stress"), "sticking up to a failure stress");
  if (spec.accuracy_edge) not_static(at("accuracy_edge"), "extra points along sharp edges");
  if (spec.sense != ContactSense::Positive)
    not_static(at("sense"), "a contact sense other than positive (one-sided from outside)");
  if (!spec.pair_scales.empty())
    not_static(spec.pair_scales.front().where, "a penalty scale factor of a part pair");
  for (const ContactSpec::FrictionPair& fp : spec.friction_pairs)
    if (fp.filter.kind != FrictionFilter::Kind::None) not_static(fp.where, "friction filtering");
  if (given("stiffness"))
    not_static(at("stiffness"), "a stiffness rule (the static penalty is " +
                                    model.sources.words("penalty") + ", or 10 E / L)");
  // A padding alone (OptiStruct GPAD) acts in static steps; the shell gaps do not.
  GapSettings padding_only;
  padding_only.padding = spec.gaps.padding;
  if (given("gaps") && !(spec.gaps == padding_only))
    not_static(at("gaps"), "a contact gap other than a padding");
  if (given("erosion")) not_static(at("erosion"), "the contact's handling of eroded elements");
  if (given("edges")) not_static(at("edges"), "edge-to-edge contact");
  if (spec.friction_filter.kind != FrictionFilter::Kind::None)
    not_static(at("friction_filter"), "friction filtering");
  // Sensors and impact watch the run in time; a static step has no impact to release at.
  if (spec.sensor) not_static(at("sensor"), "a contact switched by a sensor");
  if (spec.release_bc) not_static(at("release_bc"), "releasing boundary conditions at impact");
}

// The damping coefficient of *CONTACT_STABILIZATION at scale 1, as a fraction of the contact's
// penalty per unit of step time: over one increment the size of the step, a stiffness of 1e-4 of
// the penalty (1e-3 E / L for the automatic 10 E / L). Small against the elements' stiffness, so
// that the damping does not hold the loads (its work is reported beside the friction work), yet
// a pivot 1e-3 of the elements' is far above the solver's singular ratio (1e-13). The fraction
// is abut's choice: Abaqus's "fixed, small fraction" is not published; OptiStruct's SCALE
// multiplies its own.
constexpr double kStabilizationFraction = 1e-4;

// Young's modulus of a part from its initial moduli: E = 9 K G / (3 K + G).
double young_of(const Model& model, std::int64_t part) {
  const ElasticModuli m = initial_moduli(model.material_of_part(part));
  return m.shear > 0.0 ? 9.0 * m.bulk * m.shear / (3.0 * m.bulk + m.shear) : 0.0;
}

// The surface of a contact side: its faces, or, for a node set, every exterior face with one of
// its nodes (which gives each node a quarter of every face around it: CalculiX's area rule for
// nodal slave surfaces, tiefaccont.f) and the nodes themselves.
struct Side {
  std::vector<SkinFace> faces;
  std::vector<std::int32_t> nodes;  // node set only
  bool smooth = false;              // *CONTACT_SMOOTHING of this side
  // Its region (SMREG): the solid faces, sorted; empty: every facet.
  std::vector<std::pair<std::int32_t, std::int8_t>> region;
};

// Whether `region` (empty: everything) holds the solid face of facet f.
bool in_region(const std::vector<std::pair<std::int32_t, std::int8_t>>& region, const SkinFace& f) {
  return region.empty() ||
         std::binary_search(region.begin(), region.end(), std::pair{f.solid, f.face});
}

// Replaces each plain facet of `facets` (one without a curved face) in `region` by the facets of
// its smooth patch (smoothing.hpp), which join `dependents`.
void smooth_plain_facets(std::vector<SkinFace>& facets, std::vector<FacetParent>& parents,
                         const std::vector<std::pair<std::int32_t, std::int8_t>>& region,
                         NagataSmoothing& smoothing, DependentNodes& dependents) {
  std::vector<std::array<std::int32_t, 4>> plain;
  std::vector<std::uint8_t> smoothed_here(facets.size(), 0);
  for (std::size_t i = 0; i < facets.size(); ++i)
    if (!parents[i].curved() && in_region(region, facets[i])) {
      plain.push_back(facets[i].nodes);
      smoothed_here[i] = 1;
    }
  const NagataSmoothing::Facets smoothed =
      smoothing.smooth(plain, dependents, kCurvedFaceDivisions);
  std::vector<SkinFace> out_facets;
  std::vector<FacetParent> out_parents;
  std::size_t k = 0, next = 0;  // the plain facet, and its first smoothed facet
  for (std::size_t i = 0; i < facets.size(); ++i) {
    if (!smoothed_here[i]) {
      out_facets.push_back(facets[i]);
      out_parents.push_back(parents[i]);
      continue;
    }
    for (; next < smoothed.facets.size() && smoothed.source[next] == k; ++next) {
      SkinFace f = facets[i];
      f.nodes = smoothed.facets[next];
      out_facets.push_back(f);
      out_parents.push_back(smoothed.parents[next]);
    }
    ++k;
  }
  facets = std::move(out_facets);
  parents = std::move(out_parents);
}

Side side_of(const Model& model, const EntityRef& entity) {
  Side s;
  if (entity.type != EntityType::NodeSet) {
    s.faces = contact_faces(model, entity, false);
    return s;
  }
  const Mesh& mesh = model.mesh;
  s.nodes = model.nodes_of(entity);
  std::vector<std::uint8_t> in_set(mesh.nodes.size(), 0);
  for (const std::int32_t n : s.nodes) in_set[n] = 1;
  for (const SkinFace& f : exterior_faces(mesh, false)) {
    int inside = 0;
    for (const std::int32_t n : f.nodes) inside += in_set[n];
    if (inside > 0) s.faces.push_back(f);
  }
  return s;
}

double mean_thickness(const std::vector<SkinFace>& faces) {
  double t = 0.0;
  for (const SkinFace& f : faces) t += f.thickness / static_cast<double>(faces.size());
  return t;
}

// One pass: the points of `own` against the faces of `target`.
StaticContact make_pass(const Model& model, const ContactSpec& spec, const Side& own,
                        const Side& target, double weight, const RemovedNodes& tied) {
  const Mesh& mesh = model.mesh;
  using Law = ContactSpec::FrictionLaw;
  StaticContactSettings s;
  // A tool meets nodes (the deck refuses S2S with one).
  s.node_to_surface = spec.discretisation == Discretisation::NodeToSurface || !own.nodes.empty() ||
                      spec.surface2.type == EntityType::Tool;
  s.accuracy_level = spec.accuracy_level;
  // A node set's nodes: CalculiX's area rule (side_of); a surface's nodes: the facing area.
  if (!own.nodes.empty()) s.node_area = StaticContactSettings::NodeArea::EveryFace;
  s.small_sliding = spec.small_sliding;
  s.weight = weight;
  s.tangential_law = tangential_law_of(spec, &model.functions, model.time.end_time);
  s.pair_frictions = pair_frictions_of(model, spec);
  if (spec.remove_tied_nodes) s.removed_nodes = tied;
  s.stick = spec.friction_law == Law::Stick;
  s.adhesion = spec.adhesion;
  s.tied = spec.friction_law == Law::Freeze;
  // Automatic penalty: 10 E / L, E the stiffest material of the target surface and L its mean
  // element size normal to the surface (CalculiX recommends 5 to 50 times the modulus per unit
  // length); against a tool, which has no elements, the own surface's.
  const bool tool = spec.surface2.type == EntityType::Tool;
  const std::vector<SkinFace>& stiff = tool ? own.faces : target.faces;
  double young = 0.0;
  for (const SkinFace& f : stiff) young = std::max(young, young_of(model, f.part));
  const double thickness = mean_thickness(stiff);
  s.penalty = spec.penalty ? *spec.penalty : 10.0 * young / thickness;
  s.stick_slope = spec.tangential_penalty.value_or(s.penalty);
  if (spec.penalty_curve.valid()) s.normal = curve_penalty(model, spec.penalty_curve);
  const FunctionTable* table = &model.functions;
  const double term = model.time.end_time;
  s.normal_in_time = {function_of_one(table, spec.pfac_in_time, term)};
  s.stick_slope_factor = {function_of_one(table, spec.pen_t_of_gap, term),
                          {function_of_one(table, spec.pen_t_in_time, term)}};
  if (spec.exponential)
    s.normal = ExponentialOverclosure{spec.exponential->c0, spec.exponential->p0};
  // A tool is solid: any depth inside it counts, unless *CONTACT_NORMAL gives a detection depth.
  s.depth = spec.detection_depth.value_or(tool ? std::numeric_limits<double>::infinity()
                                               : 0.5 * thickness);
  s.search_distance = 0.5 * thickness;
  s.padding = spec.gaps.padding;
  s.clearance = spec.clearance;
  // Stabilization: c = scale x kStabilizationFraction x the penalty (laws/stabilization.hpp), to
  // an opening of LMTGAP, by default the search distance.
  if (spec.stabilization)
    s.stabilization =
        ContactStabilization{spec.stabilization->scale * kStabilizationFraction * s.penalty,
                             spec.stabilization->range.value_or(s.search_distance),
                             spec.stabilization->tangent_fraction};
  s.initial_penetration = spec.initial_penetration;
  // Against a tool the default (an offset of 0, nothing released) pushes every penetration, as
  // in explicit runs; the options proper are refused (StaticContact's tool constructor).
  if (tool && spec.initial_penetration == InitialPenetration::Offset &&
      spec.initial_offset == 0.0 && !spec.initial_max)
    s.initial_penetration = InitialPenetration::Force;
  s.initial_offset = spec.initial_offset;
  s.initial_max = spec.initial_max.value_or(kDefaultInitialMaxFraction * mean_thickness(own.faces));
  const auto no_penalty = [](const SkinFace&) { return 0.0; };
  const Nodes& nodes = mesh.nodes;
  const ContactInput initial{nodes.x, nodes.y, nodes.z, {}, {}, {}, 0.0, 0.0, {}};
  if (tool) {  // node to surface against the tool where its velocities have taken it by then
    const RigidTool& rigid = model.tool(spec.surface2);
    const ToolMotion motion(model, rigid);
    try {
      return StaticContact(
          std::move(s), contact_surface(mesh, own.faces, no_penalty), rigid.tool,
          [motion](double t) { return motion.pose_at(t); }, own.nodes, initial);
    } catch (const std::invalid_argument& e) {
      throw InputError(spec.surface2.where,
                       "contact " + std::to_string(spec.id) + ": " + e.what() + " in static steps");
    }
  }
  CurvedFaces curved(mesh);  // quadratic faces: facets on the true face
  std::vector<FacetParent> own_parents, target_parents;
  std::vector<SkinFace> own_facets = curved.facets(own.faces, &own_parents);
  std::vector<SkinFace> target_facets = curved.facets(target.faces, &target_parents);
  DependentNodes dependents = curved.dependents();
  NagataSmoothing smoothing(spec.smoothing ? spec.smoothing->crease.value_or(kSmoothingCrease)
                                           : kSmoothingCrease);
  if (own.smooth) smooth_plain_facets(own_facets, own_parents, own.region, smoothing, dependents);
  if (target.smooth)
    smooth_plain_facets(target_facets, target_parents, target.region, smoothing, dependents);
  ContactSurface secondary =
      contact_surface(mesh, own_facets, no_penalty, {}, ContactSpec::ShellSides::Both, own_parents);
  ContactSurface main = contact_surface(mesh, target_facets, no_penalty, {},
                                        ContactSpec::ShellSides::Both, target_parents);
  return StaticContact(std::move(s), std::move(secondary), std::move(main), own.nodes, initial,
                       std::move(dependents), std::move(smoothing));
}

}  // namespace

StaticContacts make_static_contacts(const Model& model, const RemovedNodes& tied) {
  StaticContacts out;
  for (std::size_t i = 0; i < model.contacts.size(); ++i) {
    const ContactSpec& spec = model.contacts[i];
    check_static(model, spec);
    if (spec.surface1.type == spec.surface2.type && spec.surface1.id == spec.surface2.id)
      not_static(spec.where, "self contact (the same entity on both sides)");
    if (spec.surface2.type == EntityType::NodeSet)
      throw InputError(spec.surface2.where,
                       "surface 2 of a contact must be made of element faces, not nodes");
    const bool tool = spec.surface2.type == EntityType::Tool;
    Side one = side_of(model, spec.surface1), two = tool ? Side{} : side_of(model, spec.surface2);
    if (spec.smoothing) {
      if (spec.discretisation == Discretisation::NodeToSurface || !one.nodes.empty() || tool)
        throw InputError(spec.smoothing->where,
                         "smoothing is for surface-to-surface contact (OptiStruct SMOOTH, seed "
                         "003): the points of node-to-surface contact (and of a tool's) are the "
                         "nodes themselves");
      one.smooth = spec.smoothing->surface1;
      two.smooth = spec.smoothing->surface2;
      if (const std::optional<EntityRef>& region = spec.smoothing->region) {
        const FaceSet& set = model.face_set(*region);
        std::vector<std::pair<std::int32_t, std::int8_t>> faces;
        for (const SolidFace& f : set.faces) faces.emplace_back(f.solid, f.face);
        std::sort(faces.begin(), faces.end());
        for (Side* side : {&one, &two}) {
          if (!side->smooth) continue;
          side->region = faces;
          if (std::none_of(side->faces.begin(), side->faces.end(),
                           [&](const SkinFace& f) { return in_region(faces, f); }))
            throw InputError(region->where,
                             "the smoothing region, face set " + std::to_string(set.id) +
                                 ", has no face of surface " + (side == &one ? "1" : "2") +
                                 " of contact " + std::to_string(spec.id) +
                                 ": it must name faces of the side it smooths");
        }
      }
    }
    // Symmetric unless one-way (the explicit interface's rule, each way with weight 1/2): node
    // sets act one way.
    const bool symmetric = spec.symmetric.value_or(!spec.one_way) && one.nodes.empty() && !tool;
    const double weight = symmetric ? 0.5 : 1.0;
    out.passes.push_back(make_pass(model, spec, one, two, weight, tied));
    out.contact_of.push_back(i);
    if (symmetric) {
      out.passes.push_back(make_pass(model, spec, two, one, weight, tied));
      out.contact_of.push_back(i);
    }
  }
  return out;
}

}  // namespace abut::detail
