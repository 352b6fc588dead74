// *CONTACT: four lines into ContactSpec field by field (keyword reference §6, seed 000).
#include "deck_reader.hpp"

namespace abut::deck {

void read_contact(DeckReader& d, Block& b) {
  ContactSpec c;
  c.title = b.title().value_or("");
  const Row r1 = b.row({"ctid", "accuracy_level", "accuracy_edge"});
  c.id = d.other_id(r1, 0);
  d.claim_id("contact", c.id, r1.where(0));
  c.where = r1.where();
  // Where each setting of the card is, for the errors found once the contact is built (Sources).
  const auto place = [&d, id = c.id](std::string_view setting, const Row& r, std::size_t column) {
    d.model.sources.set(SourceEntity::Contact, id, setting, r.where(column));
  };
  place("accuracy_level", r1, 1);
  place("accuracy_edge", r1, 2);
  const std::int64_t level = r1.integer_or(1, c.accuracy_level);
  r1.require(level >= 1, 1, "expected an accuracy level >= 1 (1 low, 2 standard, > 2 high)");
  c.accuracy_level = static_cast<int>(level);
  c.accuracy_edge = r1.flag(2);

  const std::size_t index = d.model.contacts.size();
  const auto bind = [&](std::int64_t fid, const SourceLocation& where,
                        FunctionRef ContactSpec::*member) {
    d.bind_function(fid, where,
                    [index, member](Model& m, FunctionRef f) { m.contacts[index].*member = f; });
  };

  const Row r2 =
      b.row({"entype_1", "enid_1", "entype_2", "enid_2", "mu", "pfac", "t_beg", "t_end"});
  // A node set (NS) is a surface 1 of node-to-surface contact only (*CONTACT_DISCRETIZATION N2S,
  // checked once the whole deck is in).
  if (r2.given(0) && r2.word(0) == "TOOL")
    r2.fail(0,
            "an analytic tool (TOOL) is a surface 2 only: give the body as surface 1 and the "
            "tool as entype_2, enid_2");
  c.surface1 = d.entity(r2, 0, 1,
                        {EntityType::NodeSet, EntityType::Part, EntityType::PartSet,
                         EntityType::All, EntityType::FaceSet});
  // An analytic rigid tool (*CONTACT_TOOL, entype TOOL) is a surface 2 only.
  c.surface2 = d.entity(r2, 2, 3,
                        {EntityType::Part, EntityType::PartSet, EntityType::All,
                         EntityType::FaceSet, EntityType::Tool});
  const auto mu = r2.number_or_function(4, 0.0);
  if (mu.function_id) {
    bind(*d.function_id(r2, 4, mu), r2.where(4), &ContactSpec::friction_function);
  } else {
    c.friction = mu.value;
    r2.require(c.friction >= 0.0, 4, "expected a friction coefficient >= 0 or fcn(fid)");
  }
  if (r2.given(5)) {
    c.penalty = r2.number(5);
    r2.require(*c.penalty > 0.0, 5, "expected a penalty stiffness > 0 (empty: automatic)");
  }
  place("surface1", r2, 1);
  place("secondary_nodes", r2, 1);
  place("surface2", r2, 3);
  place("penalty", r2, 5);
  place("begin_time", r2, 6);
  place("end_time", r2, 7);
  c.begin_time = r2.number_or(6, c.begin_time);
  c.end_time = r2.number_or(7, c.end_time);
  r2.require(c.end_time > c.begin_time, 7, "expected t_end > t_beg");

  if (auto r3 = b.optional_row(
          {"merge", "xi", "gid_0", "gid_1", "delta0_offset", "delta0_max", "delta_edge"})) {
    place("damping", *r3, 1);
    place("regions", *r3, 2);
    place("initial_offset", *r3, 4);
    place("initial_max", *r3, 5);
    place("edge_tolerance", *r3, 6);
    c.merge = r3->flag(0);
    c.damping = r3->number_or(1, c.damping);
    r3->require(c.damping >= 0.0, 1, "expected a fraction of critical damping >= 0");
    c.initial_geometry = d.optional_other_id(*r3, 2);
    if (c.initial_geometry) d.geometry_references.push_back({*c.initial_geometry, r3->where(2)});
    c.moving_geometry = d.optional_other_id(*r3, 3);
    if (c.moving_geometry) d.geometry_references.push_back({*c.moving_geometry, r3->where(3)});
    c.initial_offset = r3->number_or(4, 0.0);
    r3->require(c.initial_offset >= 0.0, 4, "expected a penetration offset >= 0");
    if (r3->given(5)) {
      c.initial_max = r3->number(5);
      r3->require(*c.initial_max > 0.0, 5,
                  "expected a maximum initial penetration > 0 (empty: 4% of element thickness)");
    }
    c.edge_tolerance = r3->number_or(6, 0.0);
    r3->require(c.edge_tolerance >= 0.0, 6, "expected a tolerance >= 0");
  }

  if (auto r4 = b.optional_row({"fid_wear1", "fid_wear2", "fid_thermal", "alpha_edge", "one_way",
                                "no_internal", "sigma_stick", "fric_heat"})) {
    place("wear", *r4, 0);
    place("thermal", *r4, 2);
    place("edge_angle", *r4, 3);
    place("one_way", *r4, 4);
    place("stick_stress", *r4, 6);
    place("friction_heat", *r4, 7);
    if (const auto fid = d.optional_other_id(*r4, 0)) bind(*fid, r4->where(0), &ContactSpec::wear1);
    if (const auto fid = d.optional_other_id(*r4, 1)) bind(*fid, r4->where(1), &ContactSpec::wear2);
    if (const auto fid = d.optional_other_id(*r4, 2))
      bind(*fid, r4->where(2), &ContactSpec::thermal);
    c.edge_angle = r4->number_or(3, c.edge_angle);
    r4->require(c.edge_angle > 0.0 && c.edge_angle < 180.0, 3,
                "expected an angle in (0, 180) degrees");
    c.one_way = r4->flag(4);
    c.no_internal = r4->flag(5);
    if (r4->given(6)) {
      c.stick_stress = r4->number(6);
      r4->require(*c.stick_stress > 0.0, 6,
                  "expected a sticking failure stress > 0 (empty: no sticking)");
    }
    c.friction_heat = r4->flag(7);
  }
  d.entity_references.push_back(c.surface1);
  d.entity_references.push_back(c.surface2);
  d.model.contacts.push_back(c);
}

}  // namespace abut::deck
