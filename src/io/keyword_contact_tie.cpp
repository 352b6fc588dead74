// The exact tie of *CONTACT_FRICTION FREEZE with tie = EXACT: the *CONTACT leaves the penalty
// contacts and becomes a TieSpec (model.hpp). Only its surfaces, merge, the detection depth and
// the edge rules of the partner search act; every option of a penalty contact it would ignore is
// an error at its field (nothing is read without acting).
#include <algorithm>

#include "deck_reader.hpp"

namespace abut::deck {

namespace {

SourceLocation at(const SourceLocation& where, const SourceLocation& fallback, const char* field) {
  SourceLocation w = where.file.empty() ? fallback : where;
  w.field = field;
  return w;
}

// InputError unless the options of `c` are those an exact tie reads.
void check_exact_tie(const ContactSpec& c) {
  const std::string why = " with an exact tie (tie = EXACT of *CONTACT_FRICTION at line " +
                          std::to_string(c.friction_where.line) + ")";
  const auto refuse = [&why](const SourceLocation& where, const std::string& what) {
    throw InputError(where, what + why + ": remove it, or tie with the penalty (tie = PENALTY)");
  };
  if (c.surface1.type == c.surface2.type && c.surface1.id == c.surface2.id)
    refuse(at({}, c.where, "enid_2"), "a surface cannot be tied to itself (self contact)");
  if (c.surface2.type == EntityType::Tool)
    refuse(at({}, c.where, "enid_2"), "an analytic tool (*CONTACT_TOOL) cannot be tied");
  if (c.penalty) refuse(at({}, c.where, "pfac"), "a tie is a constraint: pfac has no use");
  if (c.begin_time != 0.0 || c.end_time != 1e20)
    refuse(at({}, c.where, "t_beg"), "a tie holds for the whole run: t_beg and t_end have no use");
  if (c.initial_geometry || c.moving_geometry)
    refuse(at({}, c.where, "gid_0"), "regions gid_0 and gid_1 are not supported");
  if (c.wear1.valid() || c.wear2.valid())
    refuse(at({}, c.where, "fid_wear1"), "a tie does not slide: wear has no use");
  if (c.exchanges_heat())
    refuse(at(c.thermal_where, c.where, "fid_thermal"), "heat exchange is not supported yet");
  if (c.symmetric && *c.symmetric)
    refuse(at(c.discretisation_where, c.where, "symmetric"),
           "a tie binds the nodes of surface 1 to the facets of surface 2 only (one way)");
  if (c.penalty_curve.valid() || c.sense != ContactSense::Positive || c.clearance)
    refuse(at(c.normal_where, c.where, "law"),
           "*CONTACT_NORMAL gives the tie its detection depth only; law, sense and clearance have "
           "no use");
  if (c.adhesion) refuse(at({}, c.where, "gap"), "*CONTACT_ADHESION has no use");
  if (!c.dependencies.empty())
    refuse(at(c.dependency_where, c.where, "parameter"), "*CONTACT_DEPENDENCY has no use");
  if (!c.stiffness_where.file.empty() || c.element_penalty || !c.pair_scales.empty())
    refuse(at(c.stiffness_where, c.where, "rule"),
           "a tie has no springs: *CONTACT_STIFFNESS and *CONTACT_SCALE_PENALTY have no use");
  if (c.adjust_depth || !c.initial_where.file.empty())
    refuse(at(c.initial_where, c.where, "penetration"),
           "*CONTACT_INITIAL is not supported (the tie keeps every initial gap)");
  if (!c.gap_where.file.empty() || c.main_shell_sides != ContactSpec::ShellSides::Both)
    refuse(at(c.gap_where, c.where, "igap"), "*CONTACT_GAP has no use");
  if (!c.erosion_where.file.empty())
    refuse(at(c.erosion_where, c.where, "facets"), "*CONTACT_EROSION is not supported");
  if (!c.edge_where.file.empty())
    refuse(at(c.edge_where, c.where, "iedge"), "a tie has no edge-to-edge contact");
  if (c.sensor) refuse(at(c.sensor_where, c.where, "sens_id"), "a sensor cannot switch a tie");
  if (c.release_bc)
    refuse(at(c.release_bc_where, c.where, "ibcx"), "*CONTACT_RELEASE_BC is not supported");
  if (c.stabilization)
    refuse(at(c.stabilization->where, c.where, "scale"),
           "a tie holds from the start: *CONTACT_STABILIZATION has nothing to stabilize");
  if (c.smoothing)
    refuse(at(c.smoothing->where, c.where, "side"),
           "a tie binds nodes where they are: *CONTACT_SMOOTHING has no use");
}

}  // namespace

void extract_exact_ties(Model& model) {
  for (const ContactSpec& c : model.contacts) {
    if (!c.exact_tie) continue;
    check_exact_tie(c);
    TieSpec t;
    t.id = c.id;
    t.title = c.title;
    t.surface1 = c.surface1;
    t.surface2 = c.surface2;
    t.merge = c.merge;
    t.detection_depth = c.detection_depth;
    t.edge_tolerance = c.edge_tolerance;
    t.edge_angle = c.edge_angle;
    t.where = c.where;
    t.exact_where = with_field(c.friction_where, "tie");
    model.ties.push_back(std::move(t));
  }
  std::erase_if(model.contacts, [](const ContactSpec& c) { return c.exact_tie; });
}

}  // namespace abut::deck
