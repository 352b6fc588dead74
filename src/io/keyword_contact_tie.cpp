// The exact tie of *CONTACT_FRICTION FREEZE with tie = EXACT: the *CONTACT leaves the penalty
// contacts and becomes a TieSpec (model.hpp). Only its surfaces, merge, the detection depth and
// the edge rules of the partner search act; every option of a penalty contact it would ignore is
// an error at its field (nothing is read without acting).
#include <algorithm>

#include "deck_reader.hpp"

namespace abut::deck {

namespace {

// InputError unless the options of `c` are those an exact tie reads.
void check_exact_tie(const Model& model, const ContactSpec& c) {
  const auto at = [&model, &c](std::string_view setting) { return model.place_of(c, setting); };
  const auto given = [&model, &c](std::string_view setting) { return model.gives(c, setting); };
  const std::string why = " with an exact tie (tie = EXACT of *CONTACT_FRICTION at line " +
                          std::to_string(at("tangential_law").line) + ")";
  const auto refuse = [&why](const SourceLocation& where, const std::string& what) {
    throw InputError(where, what + why + ": remove it, or tie with the penalty (tie = PENALTY)");
  };
  if (c.surface1.type == c.surface2.type && c.surface1.id == c.surface2.id)
    refuse(at("surface2"), "a surface cannot be tied to itself (self contact)");
  if (c.surface2.type == EntityType::Tool)
    refuse(at("surface2"), "an analytic tool (*CONTACT_TOOL) cannot be tied");
  if (c.penalty) refuse(at("penalty"), "a tie is a constraint: pfac has no use");
  if (c.begin_time != 0.0 || c.end_time != 1e20)
    refuse(at("begin_time"), "a tie holds for the whole run: t_beg and t_end have no use");
  if (c.initial_geometry || c.moving_geometry)
    refuse(at("regions"), "regions gid_0 and gid_1 are not supported");
  if (c.wear1.valid() || c.wear2.valid())
    refuse(at("wear"), "a tie does not slide: wear has no use");
  if (c.exchanges_heat())
    refuse(at(c.conductance       ? "conductance"
              : c.thermal.valid() ? "thermal"
                                  : "friction_heat"),
           "heat exchange is not supported yet");
  if (c.symmetric && *c.symmetric)
    refuse(at("symmetric"),
           "a tie binds the nodes of surface 1 to the facets of surface 2 only (one way)");
  if (c.penalty_curve.valid() || c.sense != ContactSense::Positive || c.clearance)
    refuse(at("normal_law"),
           "*CONTACT_NORMAL gives the tie its detection depth only; law, sense and clearance have "
           "no use");
  if (c.adhesion) refuse(at("adhesion"), "*CONTACT_ADHESION has no use");
  if (!c.dependencies.empty()) refuse(at("dependencies"), "*CONTACT_DEPENDENCY has no use");
  if (given("stiffness") || c.element_penalty || !c.pair_scales.empty())
    refuse(c.pair_scales.empty() ? at("stiffness") : c.pair_scales.front().where,
           "a tie has no springs: *CONTACT_STIFFNESS and *CONTACT_SCALE_PENALTY have no use");
  if (c.adjust_depth || given("initial_penetration"))
    refuse(at("initial_penetration"),
           "*CONTACT_INITIAL is not supported (the tie keeps every initial gap)");
  if (given("gaps") || c.main_shell_sides != ContactSpec::ShellSides::Both)
    refuse(at("gaps"), "*CONTACT_GAP has no use");
  if (given("erosion")) refuse(at("erosion"), "*CONTACT_EROSION is not supported");
  if (given("edges")) refuse(at("edges"), "a tie has no edge-to-edge contact");
  if (c.sensor) refuse(at("sensor"), "a sensor cannot switch a tie");
  if (c.release_bc) refuse(at("release_bc"), "*CONTACT_RELEASE_BC is not supported");
  if (c.stabilization)
    refuse(with_field(c.stabilization->where, "scale"),
           "a tie holds from the start: *CONTACT_STABILIZATION has nothing to stabilize");
  if (c.smoothing)
    refuse(with_field(c.smoothing->where, "side"),
           "a tie binds nodes where they are: *CONTACT_SMOOTHING has no use");
}

}  // namespace

void extract_exact_ties(Model& model) {
  for (const ContactSpec& c : model.contacts) {
    if (!c.exact_tie) continue;
    check_exact_tie(model, c);
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
    // The places of the tie's own settings that its *CONTACT gave.
    for (const std::string_view setting : Sources::settings(SourceEntity::Tie))
      if (Sources::has_setting(SourceEntity::Contact, setting) &&
          model.sources.given(SourceEntity::Contact, c.id, setting))
        model.sources.set(SourceEntity::Tie, t.id, setting,
                          model.sources.of(SourceEntity::Contact, c.id, setting));
    model.ties.push_back(std::move(t));
  }
  std::erase_if(model.contacts, [](const ContactSpec& c) { return c.exact_tie; });
}

}  // namespace abut::deck
