// The keywords that choose the contact laws of a *CONTACT: *CONTACT_DISCRETIZATION,
// *CONTACT_NORMAL, *CONTACT_ADHESION, *CONTACT_STIFFNESS, *CONTACT_SCALE_PENALTY and
// *CONTACT_INITIAL (*CONTACT_FRICTION: keyword_contact_friction.cpp). Each refers to its *CONTACT
// by coid = ctid and may come before or after it: the row is checked here, and what depends on the
// *CONTACT's own fields once the whole deck is in (deck_finalize.cpp).
// Seeds: 000 IMPETUS *CONTACT, 001 Abaqus contact controls, 002 Metafor contact materials,
// 003 OptiStruct CONTACT, 004 Radioss /INTER/TYPE25 (../shared/seeds/).
#include "deck_reader.hpp"

namespace abut::deck {

std::string contact_at(const ContactSpec& c) {
  return "*CONTACT " + std::to_string(c.id) + " at " + c.where.file + ":" +
         std::to_string(c.where.line);
}

void refine_contact(DeckReader& d, const Row& r, std::function<void(ContactSpec&)> apply,
                    bool repeatable) {
  d.contact_keywords.push_back({d.other_id(r, 0), r.where(0), repeatable, std::move(apply)});
}

void contact_place(DeckReader& d, const Row& r, std::string_view setting, std::size_t column) {
  d.model.sources.set(SourceEntity::Contact, d.other_id(r, 0), setting, r.where(column));
}

void check_contact_options(const Model& model, const ContactSpec& c) {
  check_contact_dependency(c);
  const auto at = [&model, &c](std::string_view setting) { return model.place_of(c, setting); };
  const bool initial = c.initial_penetration != InitialPenetration::Offset ||
                       c.initial_offset != 0.0 || c.initial_max.has_value();
  const std::string initial_options =
      "the initial-penetration options given (penetration of *CONTACT_INITIAL, delta0_offset or "
      "delta0_max of *CONTACT) would do nothing";
  if (!c.friction_pairs.empty() &&
      (c.friction_law == ContactSpec::FrictionLaw::Freeze ||
       c.friction_law == ContactSpec::FrictionLaw::Stick || c.stick_stress)) {
    throw InputError(c.friction_pairs.front().where,
                     "the contact ties its points (law FREEZE or STICK, or sigma_stick), so the "
                     "friction of a part pair (*CONTACT_FRICTION_PAIR) would do nothing: remove "
                     "one of them");
  }
  if (c.friction_law == ContactSpec::FrictionLaw::Freeze && (c.clearance || initial)) {
    throw InputError(at("tangential_law"),
                     "law FREEZE ties every point at its initial distance, so " +
                         std::string(c.clearance ? "the clearance of *CONTACT_NORMAL would do "
                                                   "nothing"
                                                 : initial_options) +
                         ": remove one of them");
  }
  if (c.clearance && initial) {
    throw InputError(at("clearance"), "the clearance replaces the initial gap of every point, so " +
                                          initial_options + ": remove one of them");
  }
  if (c.sense == ContactSense::Bilateral && initial) {
    throw InputError(at("sense"),
                     "a BILATERAL contact holds every point on the surface from the start, so " +
                         initial_options + ": remove one of them");
  }
  if (c.main_shell_sides != ContactSpec::ShellSides::Both) {
    if (c.surface1.type == c.surface2.type && c.surface1.id == c.surface2.id) {
      throw InputError(at("shell_sides"),
                       "one-sided shells act on surface 2 only, which in self contact is surface "
                       "1 as well: not supported yet (use two surfaces, or BOTH)");
    }
    if (c.stiffness.rule != StiffnessRule::FacetPenalty) {
      throw InputError(at("shell_sides"),
                       "one-sided shells take the PFAC rule only, not a Radioss stiffness rule of "
                       "*CONTACT_STIFFNESS: not supported yet");
    }
  }
}

void read_contact_discretization(DeckReader& d, Block& b) {
  const Row r = b.row({"coid", "method", "symmetric", "sliding", "tied_nodes"});
  const Discretisation method = word_choice(
      r, 1, Discretisation::SurfaceToSurface,
      {{"S2S", Discretisation::SurfaceToSurface}, {"N2S", Discretisation::NodeToSurface}},
      "S2S (surface to surface) or N2S (node to surface)");
  std::optional<bool> symmetric;
  if (r.given(2)) symmetric = r.flag(2);
  // OptiStruct TRACK: SMALL pairs each point once, in the initial configuration (static steps).
  const bool small_sliding =
      word_choice(r, 3, false, {{"FINITE", false}, {"SMALL", true}},
                  "FINITE (partners searched as the bodies move) or SMALL (partners of the "
                  "initial configuration kept; static steps)");
  // Radioss Irem_i2: the nodes of exact ties (TYPE2) kept as secondary points (3) or not (1).
  const bool remove_tied = word_choice(
      r, 4, false, {{"KEEP", false}, {"REMOVE", true}, {"3", false}, {"1", true}},
      "KEEP (tied nodes stay secondary points, Radioss Irem_i2 = 3) or REMOVE (Irem_i2 = 1)");
  contact_place(d, r, "discretisation", 1);
  contact_place(d, r, "symmetric", 2);
  contact_place(d, r, "small_sliding", 3);
  refine_contact(d, r, [r, method, symmetric, small_sliding, remove_tied](ContactSpec& c) {
    const bool node_set = c.surface1.type == EntityType::NodeSet;
    if (node_set && method == Discretisation::SurfaceToSurface) {
      r.fail(1, "surface 1 of " + contact_at(c) +
                    " is a node set, which is a surface only for node-to-surface contact: "
                    "expected N2S");
    }
    if (node_set && symmetric == true) {
      r.fail(2, "surface 1 of " + contact_at(c) +
                    " is a node set: it has no facets for surface 2's nodes to meet, so the "
                    "contact is one-way; expected 0 or empty");
    }
    if (symmetric == true && c.one_way) {
      r.fail(2, "symmetric = 1 contradicts one_way = 1 of " + contact_at(c) +
                    ": give only one of them");
    }
    c.discretisation = method;
    c.symmetric = symmetric;
    c.small_sliding = small_sliding;
    c.remove_tied_nodes = remove_tied;
  });
}

void read_contact_normal(DeckReader& d, Block& b) {
  const Row r = b.row({"coid", "law", "fid", "sense", "depth", "clearance"});
  const bool curve = word_choice(r, 1, false, {{"LINEAR", false}, {"CURVE", true}},
                                 "LINEAR (pressure = pfac x penetration) or CURVE (pressure = "
                                 "fid(penetration))");
  const auto fid = d.optional_other_id(r, 2);
  if (curve && !fid) {
    r.fail(2,
           "law CURVE needs the *CURVE or *FUNCTION fid that gives the contact pressure as a "
           "function of the penetration");
  }
  if (!curve && fid) {
    r.fail(2,
           "fid is used only with law CURVE (law LINEAR takes pfac of *CONTACT): leave it "
           "empty");
  }
  if (fid) {
    const std::int64_t coid = d.other_id(r, 0);
    d.bind_function(*fid, r.where(2), [coid](Model& m, FunctionRef f) {
      for (ContactSpec& c : m.contacts)
        if (c.id == coid) c.penalty_curve = f;  // a missing contact is reported at coid
    });
  }
  const ContactSense sense = word_choice(
      r, 3, ContactSense::Positive,
      {{"POSITIVE", ContactSense::Positive},
       {"NEGATIVE", ContactSense::Negative},
       {"BILATERAL", ContactSense::Bilateral}},
      "POSITIVE (stay outside), NEGATIVE (stay inside) or BILATERAL (stay on the surface)");
  std::optional<double> depth, clearance;
  if (r.given(4)) {
    depth = r.number(4);
    r.require(*depth > 0.0, 4,
              "expected a detection depth > 0 (empty: half the element thickness)");
  }
  if (r.given(5)) clearance = r.number(5);
  contact_place(d, r, "normal_law", 1);
  contact_place(d, r, "sense", 3);
  contact_place(d, r, "detection_depth", 4);
  contact_place(d, r, "clearance", 5);
  refine_contact(d, r, [r, sense, depth, clearance](ContactSpec& c) {
    if (sense != ContactSense::Positive && c.stick_stress) {
      r.fail(3, "sense " + r.word(3) +
                    " cannot be combined with the sticking contact (sigma_stick) of " +
                    contact_at(c) + ": remove one of them");
    }
    c.sense = sense;
    c.detection_depth = depth;
    c.clearance = clearance;
  });
}

void read_contact_adhesion(DeckReader& d, Block& b) {
  const Row r = b.row({"coid", "gap", "sig_max", "visc_fluid", "visc_fact"});
  Adhesion a;
  a.gap = r.number(1);
  r.require(a.gap > 0.0, 1, "expected an adhesion gap > 0 (the adhesive zone is gap/2 wide)");
  a.max_stress = r.number(2);
  r.require(a.max_stress >= 0.0, 2, "expected a maximum adhesive stress >= 0");
  a.fluid_viscosity = r.number_or(3, 0.0);
  r.require(a.fluid_viscosity >= 0.0, 3, "expected a fluid viscosity >= 0");
  a.viscous_factor = r.number_or(4, 1.0);
  r.require(a.viscous_factor >= 0.0, 4, "expected a viscous force scale factor >= 0");
  contact_place(d, r, "adhesion", 1);
  refine_contact(d, r, [a](ContactSpec& c) { c.adhesion = a; });
}

void read_contact_stiffness(DeckReader& d, Block& b) {
  const Row r = b.row({"coid", "rule", "stfac", "st_min", "st_max"});
  enum class Rule { Pfac, Element, Main, Mean, Maximum, Minimum, Series };
  const Rule rule = word_choice(r, 1, Rule::Pfac,
                                {{"PFAC", Rule::Pfac},
                                 {"ELEMENT", Rule::Element},
                                 {"MAIN", Rule::Main},
                                 {"MEAN", Rule::Mean},
                                 {"MAX", Rule::Maximum},
                                 {"MIN", Rule::Minimum},
                                 {"SERIES", Rule::Series},
                                 {"1000", Rule::Main},
                                 {"2", Rule::Mean},
                                 {"3", Rule::Maximum},
                                 {"4", Rule::Minimum},
                                 {"5", Rule::Series}},
                                "PFAC, ELEMENT, MAIN, MEAN, MAX, MIN or SERIES (or Radioss Istf "
                                "1000, 2, 3, 4, 5)");
  StiffnessSettings s;
  const bool radioss = rule != Rule::Pfac && rule != Rule::Element;
  if (!radioss) {
    for (std::size_t k = 2; k < 5; ++k) {
      if (r.given(k))
        r.fail(k, r.where(k).field +
                      " belongs to the Radioss rules MAIN, MEAN, MAX, MIN and "
                      "SERIES: leave it empty with rule " +
                      r.word(1));
    }
  } else {
    static constexpr StiffnessRule rules[] = {StiffnessRule::Main, StiffnessRule::Mean,
                                              StiffnessRule::Maximum, StiffnessRule::Minimum,
                                              StiffnessRule::Series};
    s.rule = rules[static_cast<int>(rule) - static_cast<int>(Rule::Main)];
    s.scale = r.number_or(2, 1.0);
    r.require(s.scale > 0.0, 2, "expected a stiffness scale factor > 0");
    if (rule == Rule::Main) {
      for (std::size_t k = 3; k < 5; ++k) {
        if (r.given(k))
          r.fail(k,
                 "Radioss bounds the stiffness by st_min and st_max for rules MEAN, MAX, MIN "
                 "and SERIES (Istf 2 to 5) only: leave it empty with MAIN");
      }
    }
    s.minimum = r.number_or(3, StiffnessSettings{}.minimum);
    r.require(s.minimum >= 0.0, 3, "expected a minimum stiffness >= 0");
    s.maximum = r.number_or(4, StiffnessSettings{}.maximum);
    r.require(s.maximum > s.minimum, 4, "expected a maximum stiffness > st_min");
  }
  const bool element = rule == Rule::Element;
  contact_place(d, r, "stiffness", 1);
  refine_contact(d, r, [r, s, element, radioss](ContactSpec& c) {
    if ((element || radioss) && c.penalty) {
      r.fail(1, "rule " + r.word(1) + " replaces the penalty pfac given on line 2 of " +
                    contact_at(c) + ": remove pfac or use rule PFAC");
    }
    c.stiffness = s;
    c.element_penalty = element;
  });
}

void read_contact_scale_penalty(DeckReader& d, Block& b) {
  const Row r = b.row({"coid"});
  const std::vector<std::string> names = {"entype_1", "enid_1", "entype_2", "enid_2", "scale"};
  std::vector<ContactSpec::Scale> scales;
  std::optional<Row> row = b.row(names);
  for (; row; row = b.optional_row(names)) {
    const auto set = [&d, &row](std::size_t type, std::size_t id) -> std::optional<EntityRef> {
      if (!row->given(type) && !row->given(id)) return std::nullopt;
      if (!row->given(type)) {
        row->fail(type, "expected an entity type P, PS or ALL before " + row->where(id).field +
                            " (leave both empty for the whole contact)");
      }
      const EntityRef e =
          d.entity(*row, type, id, {EntityType::Part, EntityType::PartSet, EntityType::All});
      d.entity_references.push_back(e);
      return e;
    };
    ContactSpec::Scale s;
    s.set1 = set(0, 1);
    s.set2 = set(2, 3);
    s.scale = row->number(4);
    row->require(s.scale > 0.0, 4, "expected a penalty scale factor > 0");
    s.where = row->where(4);
    scales.push_back(std::move(s));
  }
  refine_contact(
      d, r,
      [scales](ContactSpec& c) {
        c.pair_scales.insert(c.pair_scales.end(), scales.begin(), scales.end());
      },
      true);
}

void read_contact_initial(DeckReader& d, Block& b) {
  const Row r = b.row({"coid", "penetration", "adjust", "adjust_nsid"});
  const InitialPenetration penetration =
      word_choice(r, 1, InitialPenetration::Offset,
                  {{"OFFSET", InitialPenetration::Offset},
                   {"SHIFT", InitialPenetration::Shift},
                   {"FORCE", InitialPenetration::Force},
                   {"5", InitialPenetration::Shift},
                   {"-1", InitialPenetration::Force}},
                  "OFFSET, SHIFT or FORCE (or Radioss Inacti 5, -1)");
  std::optional<double> adjust;
  const std::string word = r.given(2) ? r.word(2) : "NO";
  if (word == "AUTO") {
    adjust = -1.0;  // the solver takes 5% of the mean edge length of surface 2
  } else if (word != "NO") {
    const auto depth = parse_number(word);
    r.require(depth && *depth > 0.0, 2, "expected NO, AUTO or an adjustment depth > 0");
    adjust = depth;
  }
  // OptiStruct ADJUST = SET of GRID (seed 003): only these nodes; without a depth, the contact's
  // search depth bounds the move.
  std::optional<EntityRef> adjust_nodes;
  if (r.given(3)) {
    if (word == "NO" && r.given(2))
      r.fail(3,
             "adjust_nsid selects the nodes to adjust, but adjust is NO: give AUTO, a depth, "
             "or leave adjust empty (the contact's search depth)");
    const std::int64_t id = r.integer(3);
    r.require(id > 0, 3, "expected the id of a *SET_NODE (> 0)");
    adjust_nodes = EntityRef{EntityType::NodeSet, id, r.where(3)};
    if (!adjust) adjust = 0.0;  // the search depth
  }
  contact_place(d, r, "initial_penetration", 1);
  contact_place(d, r, "adjust", 2);
  refine_contact(d, r, [r, penetration, adjust, adjust_nodes](ContactSpec& c) {
    if (penetration != InitialPenetration::Offset && (c.initial_offset != 0.0 || c.initial_max)) {
      r.fail(1, "penetration " + r.word(1) +
                    " replaces delta0_offset and delta0_max, given on "
                    "line 3 of " +
                    contact_at(c) + ": leave them empty or use OFFSET");
    }
    c.initial_penetration = penetration;
    c.adjust_depth = adjust;
    c.adjust_nodes = adjust_nodes;
  });
}

}  // namespace abut::deck
