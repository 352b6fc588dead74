// The end of reading, part 2: contact pairs into ContactSpecs, amplitudes into curves,
// equations, and the static steps with OP=NEW/MOD resolved, so that each StaticStep lists
// everything in force during it (CalculiX manual: *BOUNDARY, *CLOAD, *DLOAD, *AMPLITUDE, *NODE
// PRINT).
#include <algorithm>
#include <map>

#include "inp_reader.hpp"

namespace abut::inp {
namespace {

std::size_t find_interaction(const Reader& r, const std::string& name, Loc at,
                             const std::string& keyword) {
  const auto it = r.interaction_names.find(upper_name(name));
  if (it == r.interaction_names.end()) {
    throw InputError(r.where(at, keyword, "INTERACTION"),
                     "surface interaction " + name +
                         " is not defined (no *SURFACE INTERACTION, NAME=" + name + ")");
  }
  return it->second;
}

const SurfaceRecord& find_surface(const Reader& r, const std::string& name, Loc at,
                                  const std::string& field) {
  const auto it = r.surface_names.find(upper_name(name));
  if (it == r.surface_names.end()) {
    throw InputError(r.where(at, "*CONTACT PAIR", field),
                     "surface " + name + " is not defined (no *SURFACE, NAME=" + name + ")");
  }
  return r.surfaces[it->second];
}

// A value in force on one degree of freedom or face while the steps are resolved.
struct Entry {
  double value = 0.0;
  int amplitude = -1;  // index into Reader::amplitudes
  Loc where;
  bool this_step = false;  // defined by a card of the current step
};
using State = std::map<std::pair<std::int32_t, int>, Entry>;

int amplitude_of(const Reader& r, const LoadCard& card, const std::string& keyword) {
  if (card.amplitude.empty()) return -1;
  const auto it = r.amplitude_names.find(upper_name(card.amplitude));
  if (it == r.amplitude_names.end()) {
    throw InputError(r.where(card.where, keyword, "AMPLITUDE"),
                     "amplitude " + card.amplitude +
                         " is not defined (no *AMPLITUDE, NAME=" + card.amplitude + ")");
  }
  return static_cast<int>(it->second);
}

const char* keyword_of(LoadKind kind) {
  return kind == LoadKind::Boundary ? "*BOUNDARY" : kind == LoadKind::Force ? "*CLOAD" : "*DLOAD";
}

// A card's lines into the state: *BOUNDARY replaces per (node, dof); *CLOAD and *DLOAD add to a
// value given earlier in the same step and replace one from an earlier step (CalculiX). The
// amplitude of the last card applies.
void apply(const Reader& r, const LoadCard& card, State& state) {
  const std::string keyword = keyword_of(card.kind);
  const int amplitude = amplitude_of(r, card, keyword);
  for (const LoadLine& line : card.lines) {
    const std::vector<std::int32_t> targets = card.kind == LoadKind::Pressure
                                                  ? solids_of(r, line.target, keyword)
                                                  : nodes_of(r, line.target, keyword);
    for (const std::int32_t t : targets) {
      if (card.kind == LoadKind::Pressure)
        require_face(r, t, line.first, line.target.where, "*DLOAD");
      for (int k = line.first; k <= line.last; ++k) {
        Entry& e = state[{t, k}];
        const bool add = card.kind != LoadKind::Boundary && e.this_step;
        e.value = add ? e.value + line.value : line.value;
        e.amplitude = amplitude;
        e.where = line.target.where;
        e.this_step = true;
      }
    }
  }
}

// The end of a step: amplitudes of step time lapse, their reference values replaced by the
// values at the end of the step (CalculiX *AMPLITUDE); TIME=TOTAL TIME ones stay.
void carry_over(const Reader& r, State& state, double period) {
  for (auto& [key, e] : state) {
    e.this_step = false;
    if (e.amplitude < 0) continue;
    const AmplitudeRecord& a = r.amplitudes[static_cast<std::size_t>(e.amplitude)];
    if (a.total_time) continue;
    e.value *= r.model.functions.value(a.curve, period, Variables{});
    e.amplitude = -1;
  }
}

StepAmplitude step_amplitude(const Reader& r, int amplitude) {
  if (amplitude < 0) return {};
  const AmplitudeRecord& a = r.amplitudes[static_cast<std::size_t>(amplitude)];
  return {a.curve, a.total_time};
}

PrintRequest print_request(const Reader& r, const PrintCard& p) {
  PrintRequest q;
  q.kind = p.kind;
  q.quantities = p.quantities;
  q.set_name = p.set;
  q.totals = p.totals;
  q.totals_only = p.totals_only;
  q.frequency = p.frequency;
  q.where = r.where(p.where, p.kind == PrintRequest::Kind::Node      ? "*NODE PRINT"
                             : p.kind == PrintRequest::Kind::Element ? "*EL PRINT"
                                                                     : "*CONTACT PRINT");
  const Model& m = r.model;
  switch (p.kind) {
    case PrintRequest::Kind::Node:
      if (!p.set.empty()) {
        q.members = node_set_members(r, p.set, p.where, q.where.keyword);
      } else {
        for (std::size_t i = 0; i < m.mesh.nodes.size(); ++i)
          q.members.push_back(static_cast<std::int32_t>(i));
      }
      break;
    case PrintRequest::Kind::Element:
      if (!p.set.empty()) {
        q.members = element_set_members(r, p.set, p.where, q.where.keyword);
      } else {
        for (std::size_t e = 0; e < m.mesh.solid_count(); ++e)
          q.members.push_back(static_cast<std::int32_t>(e));
      }
      break;
    case PrintRequest::Kind::Contact:  // empty: every slave node
      if (!p.set.empty()) q.members = node_set_members(r, p.set, p.where, q.where.keyword);
      break;
  }
  return q;
}

void make_amplitudes(Reader& r) {
  for (AmplitudeRecord& a : r.amplitudes) {
    const std::int64_t id = r.next_function_id++;
    const SourceLocation where = r.where(a.where, "*AMPLITUDE", "NAME");
    r.model.functions.add_curve(id, Curve{a.time, a.value}, where);
    a.curve = r.model.functions.find(id, where);
  }
}

// *EQUATION -> LinearConstraint; a dependent degree of freedom is eliminated, so it may be
// dependent in one equation only. Returns where each dependent dof is defined.
std::map<std::pair<std::int32_t, int>, Loc> make_equations(Reader& r) {
  std::map<std::pair<std::int32_t, int>, Loc> dependent;
  for (const EquationRecord& eq : r.equations) {
    LinearConstraint c;
    c.where = r.where(eq.where, "*EQUATION");
    for (const EquationRecord::Term& t : eq.terms) {
      const std::int32_t node = nodes_of(r, Item{t.node, "", t.where}, "*EQUATION").front();
      c.terms.push_back({node, t.dof, t.coefficient});
    }
    const auto [it, inserted] =
        dependent.emplace(std::make_pair(c.terms.front().node, c.terms.front().dof), eq.where);
    if (!inserted) {
      throw InputError(r.where(eq.terms.front().where, "*EQUATION", "node"),
                       "node " + std::to_string(eq.terms.front().node) + " dof " +
                           std::to_string(eq.terms.front().dof + 1) +
                           " is already the dependent term of the equation at " + r.at(it->second) +
                           ": a degree of freedom can be dependent in one equation only");
    }
    r.model.equations.push_back(std::move(c));
  }
  return dependent;
}

}  // namespace

void finish_contacts(Reader& r) {
  std::map<std::size_t, FunctionRef> tables;  // interaction -> its TABULAR curve
  for (const PairRecord& p : r.pairs) {
    const std::size_t i = find_interaction(r, p.interaction, p.card, "*CONTACT PAIR");
    const InteractionRecord& in = r.interactions[i];
    if (!in.behaviour) {
      throw InputError(r.where(in.defined, "*SURFACE INTERACTION"),
                       "surface interaction " + in.name +
                           " has no *SURFACE BEHAVIOR: abut needs its pressure-overclosure law");
    }
    const SurfaceRecord& slave = find_surface(r, p.slave, p.where, "slave");
    const SurfaceRecord& master = find_surface(r, p.master, p.where, "master");
    if (master.node_based) {
      throw InputError(r.where(p.where, "*CONTACT PAIR", "master"),
                       "the master surface " + master.name +
                           " is made of nodes: it must be made of element faces (*SURFACE, "
                           "TYPE=ELEMENT)");
    }
    if (slave.node_based && !p.node_to_surface) {
      throw InputError(r.where(p.where, "*CONTACT PAIR", "slave"),
                       "the slave surface " + slave.name +
                           " is made of nodes, which suits TYPE=NODE TO SURFACE only: use "
                           "element faces for SURFACE TO SURFACE");
    }
    ContactSpec c;
    c.id = static_cast<std::int64_t>(r.model.contacts.size()) + 1;
    c.title = slave.name + "/" + master.name;
    c.where = r.where(p.where, "*CONTACT PAIR");
    c.surface1 = slave.entity;
    c.surface1.where = r.where(p.where, "*CONTACT PAIR", "slave");
    c.surface2 = master.entity;
    c.surface2.where = r.where(p.where, "*CONTACT PAIR", "master");
    c.discretisation =
        p.node_to_surface ? Discretisation::NodeToSurface : Discretisation::SurfaceToSurface;
    c.one_way = true;  // CalculiX pairs act one way: slave points against master faces
    c.symmetric = false;
    c.damping = 0.0;  // static
    // CalculiX: an initial overclosure is a real penetration (contact6; ADJUST removes it).
    c.initial_penetration = InitialPenetration::Force;
    c.adjust_depth = p.adjust;
    c.small_sliding = p.small_sliding;
    // Where each setting is, for the errors found once the contact is built (Sources).
    Sources& sources = r.model.sources;
    const auto place = [&sources, id = c.id](std::string_view setting, SourceLocation where) {
      sources.set(SourceEntity::Contact, id, setting, std::move(where));
    };
    place("surface1", c.surface1.where);
    place("secondary_nodes", c.surface1.where);
    place("surface2", c.surface2.where);
    place("discretisation", r.where(p.where, "*CONTACT PAIR", "TYPE"));
    place("small_sliding", r.where(p.where, "*CONTACT PAIR", "SMALL SLIDING"));
    place("adjust", r.where(p.where, "*CONTACT PAIR", "ADJUST"));
    const Behaviour& b = *in.behaviour;
    const SourceLocation normal_where =
        r.where(b.where, "*SURFACE BEHAVIOR", "PRESSURE-OVERCLOSURE");
    place("normal_law", normal_where);
    place("penalty", normal_where);
    switch (b.kind) {
      case Behaviour::Kind::Linear:
      case Behaviour::Kind::Tied:
        c.penalty = b.slope;
        break;
      case Behaviour::Kind::Exponential:
        c.exponential = ContactSpec::Exponential{b.c0, b.p0};
        break;
      case Behaviour::Kind::Tabular: {
        auto [it, inserted] = tables.emplace(i, FunctionRef{});
        if (inserted) {
          const std::int64_t id = r.next_function_id++;
          r.model.functions.add_curve(id, Curve{b.overclosure, b.pressure}, normal_where);
          it->second = r.model.functions.find(id, normal_where);
        }
        c.penalty_curve = it->second;
        break;
      }
    }
    if (in.friction) {
      place("tangential_law", r.where(in.friction->where, "*FRICTION"));
      place("tangential_penalty", r.where(in.friction->where, "*FRICTION"));
    }
    if (b.kind == Behaviour::Kind::Tied) {
      if (!in.friction || !in.friction->stick_slope) {
        throw InputError(normal_where,
                         "PRESSURE-OVERCLOSURE=TIED needs the stick slope of a *FRICTION card in "
                         "surface interaction " +
                             in.name + " (it ties the tangential directions with that slope)");
      }
      c.friction_law = ContactSpec::FrictionLaw::Freeze;
      c.tangential_penalty = in.friction->stick_slope;
    } else if (in.friction) {
      c.friction_law = ContactSpec::FrictionLaw::Coulomb;
      c.friction = c.mu_static = c.mu_dynamic = in.friction->mu;
      c.tangential_penalty = in.friction->stick_slope;
    } else {
      c.friction_law = ContactSpec::FrictionLaw::None;
    }
    r.model.contacts.push_back(std::move(c));
  }
}

// *TIE -> TieSpec (model.hpp): the slave surface's nodes (all nodes of its faces, or its nodes)
// follow the master faces; the position tolerance is the search depth.
void finish_ties(Reader& r) {
  for (const TieRecord& t : r.ties) {
    const SurfaceRecord& slave = find_surface(r, t.slave, t.where, "slave");
    const SurfaceRecord& master = find_surface(r, t.master, t.where, "master");
    if (master.node_based) {
      throw InputError(r.where(t.where, "*TIE", "master"),
                       "the master surface " + master.name +
                           " is made of nodes: it must be made of element faces (*SURFACE, "
                           "TYPE=ELEMENT)");
    }
    TieSpec s;
    s.id = static_cast<std::int64_t>(r.model.contacts.size() + r.model.ties.size()) + 1;
    s.title = t.name;
    s.surface1 = slave.entity;
    s.surface1.where = r.where(t.where, "*TIE", "slave");
    s.surface2 = master.entity;
    s.surface2.where = r.where(t.where, "*TIE", "master");
    s.detection_depth = t.tolerance;
    s.where = r.where(t.where, "*TIE");
    r.model.sources.set(SourceEntity::Tie, s.id, "exact", r.where(t.card, "*TIE", "NAME"));
    r.model.sources.set(SourceEntity::Tie, s.id, "detection_depth",
                        r.where(t.card, "*TIE", "POSITION TOLERANCE"));
    r.model.ties.push_back(std::move(s));
  }
}

void finish_steps(Reader& r) {
  make_amplitudes(r);
  const auto dependent = make_equations(r);

  // Model-level *BOUNDARY cards act as if given at the start of the first step.
  State boundaries, forces, pressures;
  for (const LoadCard& card : r.model_loads) apply(r, card, boundaries);
  for (auto& [key, e] : boundaries) e.this_step = false;  // an OP=NEW of step 1 removes them

  bool nlgeom = false;
  std::vector<PrintRequest> printed[3];  // Node, Element, Contact: in force from step to step
  double total_time = 0.0;
  for (std::size_t s = 0; s < r.steps.size(); ++s) {
    const StepRecord& rec = r.steps[s];
    State* states[] = {&boundaries, &forces, &pressures};
    bool cleared[3] = {false, false, false};
    for (const LoadCard& card : rec.loads) {
      const auto k = static_cast<std::size_t>(card.kind);
      // OP=NEW removes what earlier steps (and the model data) prescribed, not the cards of
      // this step.
      if (card.op_new && !cleared[k]) {
        std::erase_if(*states[k], [](const auto& e) { return !e.second.this_step; });
        cleared[k] = true;
      }
      apply(r, card, *states[k]);
    }

    StaticStep step;
    step.title = rec.title;
    step.where = r.where(rec.where, "*STEP");
    nlgeom = nlgeom || rec.nlgeom.value_or(false);
    step.nonlinear_geometry = nlgeom;
    step.period = rec.period;
    step.initial_increment = rec.initial;
    step.min_increment = rec.min_increment.value_or(std::min(rec.initial, 1e-5 * rec.period));
    step.max_increment = rec.max_increment.value_or(rec.period);
    step.fixed_increments = rec.direct;
    step.max_increments = rec.max_increments;
    step.force_tolerance = rec.force_tolerance;
    step.displacement_tolerance = rec.displacement_tolerance;
    for (const auto& [key, e] : boundaries) {
      const auto dep = dependent.find(key);
      if (dep != dependent.end()) {
        throw InputError(r.where(e.where, "*BOUNDARY"),
                         "node " + std::to_string(r.model.mesh.nodes.id[key.first]) + " dof " +
                             std::to_string(key.second + 1) +
                             " is the dependent term of the *EQUATION at " + r.at(dep->second) +
                             ", so it cannot be prescribed too (in step " + rec.title + ")");
      }
      step.displacements.push_back({key.first, key.second, e.value, step_amplitude(r, e.amplitude),
                                    r.where(e.where, "*BOUNDARY")});
    }
    for (const auto& [key, e] : forces) {
      step.forces.push_back({key.first, key.second, e.value, step_amplitude(r, e.amplitude),
                             r.where(e.where, "*CLOAD")});
    }
    for (const auto& [key, e] : pressures) {
      step.pressures.push_back({SolidFace{key.first, static_cast<std::int8_t>(key.second)}, e.value,
                                step_amplitude(r, e.amplitude), r.where(e.where, "*DLOAD")});
    }

    for (const ChangeRecord& change : rec.changes) {
      const char* keyword =
          change.surface_behaviour ? "*CHANGE SURFACE BEHAVIOR" : "*CHANGE FRICTION";
      const std::size_t i = find_interaction(r, change.interaction, change.where, keyword);
      const InteractionRecord& in = r.interactions[i];
      bool used = false;
      for (std::size_t k = 0; k < r.pairs.size(); ++k) {
        if (upper_name(r.pairs[k].interaction) != upper_name(in.name)) continue;
        used = true;
        if (!change.surface_behaviour) {
          step.contact_changes.push_back({k,
                                          change.friction->mu,
                                          change.friction->stick_slope,
                                          r.where(change.friction->where, "*FRICTION"),
                                          {}});
          continue;
        }
        // The new pressure-overclosure law; a tied contact becomes a sliding one with the
        // interaction's *FRICTION (frictionless without one), as in CalculiX.
        const Behaviour& b = *change.behaviour;
        const SourceLocation where = r.where(b.where, "*SURFACE BEHAVIOR");
        OverclosureChange law;
        if (b.kind == Behaviour::Kind::Linear) law.slope = b.slope;
        if (b.kind == Behaviour::Kind::Exponential) law.c0 = b.c0, law.p0 = b.p0;
        if (b.kind == Behaviour::Kind::Tabular) {
          const std::int64_t id = r.next_function_id++;
          r.model.functions.add_curve(id, Curve{b.overclosure, b.pressure}, where);
          law.table = r.model.functions.find(id, where);
        }
        ContactChange c{k, std::nullopt, std::nullopt, where, law};
        if (in.behaviour && in.behaviour->kind == Behaviour::Kind::Tied) {
          c.friction = in.friction ? in.friction->mu : 0.0;
          if (in.friction) c.stick_slope = in.friction->stick_slope;
        }
        step.contact_changes.push_back(c);
      }
      if (!used) {
        throw InputError(r.where(change.where, keyword, "INTERACTION"),
                         "no *CONTACT PAIR uses surface interaction " + change.interaction +
                             ": changing it would do nothing");
      }
    }

    // The first print card of a kind in a step replaces the requests of that kind; without
    // one, the previous step's stay (CalculiX).
    bool replaced[3] = {false, false, false};
    for (const PrintCard& p : rec.prints) {
      const auto k = static_cast<std::size_t>(p.kind);
      if (!replaced[k]) printed[k].clear();
      replaced[k] = true;
      if (!p.quantities.empty()) printed[k].push_back(print_request(r, p));
    }
    for (const auto& kind : printed)
      step.prints.insert(step.prints.end(), kind.begin(), kind.end());

    total_time += rec.period;
    r.model.static_steps.push_back(std::move(step));
    for (State* state : states) carry_over(r, *state, rec.period);
  }
  r.model.time.end_time = total_time;
}

}  // namespace abut::inp
