// A *CONTACT card in the contact library's terms (settings.hpp): its laws, gaps, edges and heat,
// the deck field behind each setting for error messages, and its description for the log.
#include "contact_settings_of.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "abut/contact/describe.hpp"
#include "abut/solver/contact_surfaces.hpp"
#include "contact_checks.hpp"

namespace abut {

namespace {

// The law of a *CONTACT_FRICTION card other than IMPETUS's mu: law, coefficients and the Metafor
// TM factors of mu_s / m_s, mu_d / m_d and k (*CONTACT_DEPENDENCY).
TangentialLaw law_of_card(ContactSpec::FrictionLaw law, double mu_s, double mu_d,
                          const std::array<double, 6>& c, TimeFactor static_in_time,
                          TimeFactor dynamic_in_time, TimeFactor yield_in_time) {
  using Law = ContactSpec::FrictionLaw;
  switch (law) {
    case Law::Impetus:  // not a card law (tangential_law_of)
    case Law::None:
    case Law::Freeze:
      return Frictionless{};
    case Law::Coulomb:
      return Coulomb{mu_s, mu_d, {}, {}, static_in_time, dynamic_in_time};
    case Law::Tresca:
      return Tresca{c[0], c[1], c[2], static_in_time, dynamic_in_time, yield_in_time};
    case Law::Stick:
      return Sticking{};
    case Law::Viscous:
      return Coulomb{0.0, 0.0, {}, ViscousFriction{mu_s, c}, {}, {}};
    case Law::Darmstad:
      return Coulomb{0.0, 0.0, {}, DarmstadFriction{mu_s, c}, {}, {}};
    case Law::Renard:
      return Coulomb{0.0, 0.0, {}, RenardFriction{c}, {}, {}};
  }
  return Frictionless{};
}

}  // namespace

// One-way unless *CONTACT_DISCRETIZATION says symmetric: *CONTACT one_way, or a node group as
// surface 1 (it has no facets of its own to be a main side).
bool one_way_of(const ContactSpec& spec) {
  if (spec.symmetric) return !*spec.symmetric;
  return spec.one_way || spec.surface1.type == EntityType::NodeSet;
}

TangentialLaw tangential_law_of(const ContactSpec& spec, const FunctionTable* table, double term) {
  if (spec.friction_law != ContactSpec::FrictionLaw::Impetus) {
    // Metafor TM (*CONTACT_DEPENDENCY): a coefficient times a function of the time.
    const auto in_time = [table, term](FunctionRef f) {
      return TimeFactor{function_of_one(table, f, term)};
    };
    return law_of_card(spec.friction_law, spec.mu_static, spec.mu_dynamic, spec.friction_c,
                       in_time(spec.mu_static_in_time), in_time(spec.mu_dynamic_in_time),
                       in_time(spec.yield_in_time));
  }
  Coulomb law{spec.friction, spec.friction, {}, {}, {}, {}};
  if (spec.friction_function.valid()) {
    const FunctionRef mu = spec.friction_function;
    law.function = [table, mu, term](double pres, double vtang, double t, double x, double y,
                                     double z) {
      Variables v;
      v.pres = pres;
      v.vtang = vtang;
      v.t = t;
      v.term = term;
      v.x = x;
      v.y = y;
      v.z = z;
      return table->value(mu, v);
    };
  } else if (spec.friction == 0.0) {
    return Frictionless{};
  }
  return law;
}

// Heat through the contact: fid_thermal of *CONTACT (h of pres and gap; a *CURVE: of pres) or
// the law of *CONTACT_THERMAL, and fric_heat with its share.
ThermalContactSettings thermal_of(const Model& model, const ContactSpec& spec) {
  ThermalContactSettings s;
  if (spec.thermal.valid() && spec.conductance)
    throw InputError(model.place_of(spec, "conductance"),
                     "contact " + std::to_string(spec.id) + " has a conductance function (" +
                         model.sources.words("conductance_function") +
                         ") already: give one of them");
  const FunctionTable* table = &model.functions;
  const double term = model.time.end_time;
  if (spec.thermal.valid()) {
    const FunctionRef f = spec.thermal;
    s.conductance = FunctionConductance{[table, f, term](double pres, double gap) {
      Variables v;
      v.pres = pres;
      v.gap = gap;
      v.term = term;
      return table->value(f, pres, v);
    }};
  } else if (spec.conductance) {
    using Law = ContactSpec::Conductance::Law;
    const ContactSpec::Conductance& c = *spec.conductance;
    switch (c.law) {
      case Law::Pressure:
        s.conductance = PressureConductance{c.nominal, c.hardness, c.exponent};
        break;
      case Law::OpenClosed:
        s.conductance = OpenClosedConductance{c.closed, c.open};
        break;
      case Law::Distance: {
        const FunctionRef f = spec.distance_conductance;
        s.conductance = DistanceConductance{[table, f, term](double gap) {
          Variables v;
          v.gap = gap;
          v.term = term;
          return table->value(f, gap, v);
        }};
        break;
      }
    }
  }
  if (spec.friction_heat) s.friction_heat = FrictionHeatSplit{spec.friction_heat_to_surface1};
  return s;
}

std::vector<PairFriction> pair_frictions_of(const Model& model, const ContactSpec& spec) {
  std::vector<PairFriction> out;
  for (const ContactSpec::FrictionPair& fp : spec.friction_pairs) {
    PairFriction pf;
    if (fp.set1) pf.parts1 = model.parts_of(*fp.set1);
    if (fp.set2) pf.parts2 = model.parts_of(*fp.set2);
    pf.law = law_of_card(fp.law, fp.mu_static, fp.mu_dynamic, fp.c, {}, {}, {});
    pf.filter = fp.filter;
    out.push_back(std::move(pf));
  }
  return out;
}

ContactSettings settings_of(const Model& model, const ContactSpec& spec) {
  ContactSettings s;
  s.thermal = thermal_of(model, spec);
  s.accuracy_level = spec.accuracy_level;
  s.accuracy_edge = spec.accuracy_edge;
  const FunctionTable* table = &model.functions;
  const double term = model.time.end_time;
  s.discretisation = spec.discretisation;
  s.tangential_law = tangential_law_of(spec, table, term);
  s.freeze = spec.friction_law == ContactSpec::FrictionLaw::Freeze;
  s.tangential_penalty = spec.tangential_penalty;
  s.normal_in_time = {function_of_one(table, spec.pfac_in_time, term)};
  s.tangential_penalty_factor = {function_of_one(table, spec.pen_t_of_gap, term),
                                 {function_of_one(table, spec.pen_t_in_time, term)}};
  s.friction_filter = spec.friction_filter;
  if (spec.penalty_curve.valid()) s.normal_law = curve_penalty(model, spec.penalty_curve);
  s.sense = spec.sense;
  s.detection_depth = spec.detection_depth;
  s.clearance = spec.clearance;
  s.adhesion = spec.adhesion;
  s.stiffness = spec.stiffness;
  s.initial_penetration = spec.initial_penetration;
  for (const ContactSpec::Scale& sc : spec.pair_scales) {
    PairScale ps;
    if (sc.set1) ps.parts1 = model.parts_of(*sc.set1);
    if (sc.set2) ps.parts2 = model.parts_of(*sc.set2);
    ps.scale = sc.scale;
    s.pair_scales.push_back(std::move(ps));
  }
  s.pair_frictions = pair_frictions_of(model, spec);
  const auto wear_rate = [table, term](FunctionRef f) -> WearRateFunction {
    if (!f.valid()) return {};
    return [table, f, term](double pres, double vtang) {
      Variables v;
      v.pres = pres;
      v.vtang = vtang;
      v.term = term;
      return table->value(f, v);
    };
  };
  s.wear_rate1 = wear_rate(spec.wear1);
  s.wear_rate2 = wear_rate(spec.wear2);
  const auto region = [&model, &spec](const std::optional<std::int64_t>& gid) -> RegionPredicate {
    if (!gid) return {};
    const GeometryEntry* g = model.find_geometry(*gid);
    if (!g) throw InputError(spec.where, "geometry " + std::to_string(*gid) + " does not exist");
    const Geometry* geometry = &g->geometry;
    const Mesh* mesh = &model.mesh;
    return [geometry, mesh](double x, double y, double z) {
      return geometry_contains(*geometry, {x, y, z}, *mesh);
    };
  };
  s.initial_region = region(spec.initial_geometry);
  s.moving_region = region(spec.moving_geometry);
  // A contact switched by a sensor ignores t_beg and t_end (seed 004, comment 10): the solver
  // switches it (ContactInterface::set_enabled).
  s.begin_time = spec.sensor ? -std::numeric_limits<double>::infinity() : spec.begin_time;
  s.end_time = spec.sensor ? std::numeric_limits<double>::infinity() : spec.end_time;
  s.damping = spec.damping;
  s.initial_offset = spec.initial_offset;
  s.initial_max = spec.initial_max;
  s.edge_tolerance = spec.edge_tolerance;
  s.edge_angle = spec.edge_angle;
  s.one_way = one_way_of(spec);
  s.stick_stress = spec.stick_stress;
  s.gaps = spec.gaps;
  s.erosion = spec.erosion;
  s.edges = spec.edges;
  return s;
}

// The deck field behind a contact-library setting, for error messages.
SourceLocation location_of(const Model& model, const ContactSpec& spec,
                           const std::string& setting) {
  if (setting == "pair_frictions" && !spec.friction_pairs.empty())
    return spec.friction_pairs.front().where;
  return model.place_of(spec, setting);
}

// The laws of a contact in the model's words: the contact library's description of its settings,
// with what the model adds around them (the element penalty, the faces erosion exposes).
ContactDescription describe(const ContactSpec& spec, const ContactSettings& settings) {
  ContactDescription d = describe(settings);
  if (spec.element_penalty) d.stiffness_rule = "facet penalty from each element's stable step";
  d.erosion_rule +=
      spec.no_internal ? ", faces inside a part never join" : ", faces that erosion exposes join";
  return d;
}

}  // namespace abut
