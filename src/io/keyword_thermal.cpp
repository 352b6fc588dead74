// The thermal keywords (issue 11): *PROP_THERMAL, *INITIAL_TEMPERATURE, *BC_TEMPERATURE,
// *LOAD_THERMAL_SURFACE, *LOAD_THERMAL_CONVECTION, and the thpid field of the material lines.
// They fill Model::thermal (model_thermal.hpp); entities become nodes and faces once the mesh is
// final (deck_finalize_thermal.cpp).
//
// *LOAD_THERMAL_SURFACE follows the IMPETUS command help (coid, entype, enid, cid, sf, t_beg,
// t_end, erode). The IMPETUS field order of *PROP_THERMAL, *INITIAL_TEMPERATURE and
// *BC_TEMPERATURE was not available to us, and IMPETUS has no convection command: those rows and
// *LOAD_THERMAL_CONVECTION are abut's own, written in the IMPETUS manner (entype, enid first; a
// curve and a scale factor). docs/deck-reference.md says so at each keyword.
#include "deck_reader.hpp"

namespace abut::deck {
namespace {

// The entity types a temperature condition takes: nodes, parts, everything, a region.
constexpr std::initializer_list<EntityType> kNodeEntities = {
    EntityType::Node,    EntityType::NodeSet, EntityType::Part,
    EntityType::PartSet, EntityType::All,     EntityType::GeometryRegion};
// Face loads act on exterior faces: of parts, of everything, of a region, of a face set (as
// *LOAD_PRESSURE).
constexpr std::initializer_list<EntityType> kFaceEntities = {
    EntityType::Part, EntityType::PartSet, EntityType::All, EntityType::GeometryRegion,
    EntityType::FaceSet};

void start(DeckReader& d, Block& b, const std::string& expected) {
  if (b.done()) throw InputError(b.where(), "missing data line: expected " + expected);
  d.thermal_keywords.push_back(b.where());
}

void pend(DeckReader& d, PendingThermal::Kind kind, const EntityRef& entity, std::size_t index) {
  d.thermal_entities.push_back({kind, entity, index});
  d.entity_references.push_back(entity);
}

// The optional coid of the thermal loads: unique among the commands of the same keyword.
void command_id(DeckReader& d, const Row& r, std::size_t i) {
  if (const auto id = d.optional_other_id(r, i)) d.claim_id(r.where().keyword, *id, r.where(i));
}

}  // namespace

std::int64_t thermal_property_id(DeckReader& d, const Row& r, std::size_t i) {
  const auto id = r.optional_id(i);
  if (!id) return 0;
  d.thermal_bindings.push_back({*id, r.where(i)});
  return *id;
}

// thpid, c_p, k, alpha, chi (abut's layout).
void read_prop_thermal(DeckReader& d, Block& b) {
  b.title();
  start(d, b, "thpid, c_p, k, alpha, chi");
  while (!b.done()) {
    const Row r = b.row({"thpid", "c_p", "k", "alpha", "chi"});
    ThermalProperties p;
    p.id = r.id(0);
    d.claim_id("thermal property", p.id, r.where(0));
    p.specific_heat = r.number(1);
    r.require(p.specific_heat > 0.0, 1, "expected a specific heat c_p > 0");
    p.conductivity = r.number(2);
    r.require(p.conductivity >= 0.0, 2, "expected a thermal conductivity k >= 0");
    p.expansion = r.number_or(3, 0.0);
    p.taylor_quinney = r.number_or(4, ThermalProperties{}.taylor_quinney);
    r.require(p.taylor_quinney >= 0.0 && p.taylor_quinney <= 1.0, 4,
              "expected a Taylor-Quinney factor chi in [0, 1]");
    p.where = r.where();
    d.model.thermal.properties.push_back(p);
  }
}

// entype, enid, T (abut's layout). ALL sets the temperature of every node (the model default).
void read_initial_temperature(DeckReader& d, Block& b) {
  start(d, b, "entype, enid, T");
  while (!b.done()) {
    const Row r = b.row({"entype", "enid", "T"});
    InitialTemperature t;
    const EntityRef entity = d.entity(r, 0, 1, kNodeEntities);
    t.value = r.number(2);
    t.where = r.where();
    pend(d, PendingThermal::Kind::Initial, entity, d.model.thermal.initial.size());
    d.model.thermal.initial.push_back(std::move(t));
  }
}

// entype, enid, cid, sf (abut's layout): T(t) = sf x curve(t), or sf without a curve.
void read_bc_temperature(DeckReader& d, Block& b) {
  start(d, b, "entype, enid, cid, sf");
  while (!b.done()) {
    const Row r = b.row({"entype", "enid", "cid", "sf"});
    PrescribedTemperature p;
    const EntityRef entity = d.entity(r, 0, 1, kNodeEntities);
    const auto cid = d.optional_other_id(r, 2);
    if (!cid && !r.given(3))
      r.fail(3, "give the temperature: sf (constant) or a curve cid with its scale factor sf");
    p.scale = r.number_or(3, 1.0);
    p.where = r.where();
    const std::size_t i = d.model.thermal.prescribed.size();
    if (cid)
      d.bind_function(*cid, r.where(2),
                      [i](Model& model, FunctionRef f) { model.thermal.prescribed[i].curve = f; });
    pend(d, PendingThermal::Kind::Prescribed, entity, i);
    d.model.thermal.prescribed.push_back(std::move(p));
  }
}

// coid, entype, enid, cid, sf, t_beg, t_end, erode (IMPETUS): q(t) = sf x curve(t) [power/area]
// into the body, or sf without a curve.
void read_load_thermal_surface(DeckReader& d, Block& b) {
  b.title();
  start(d, b, "coid, entype, enid, cid, sf");
  while (!b.done()) {
    const Row r = b.row({"coid", "entype", "enid", "cid", "sf", "t_beg", "t_end", "erode"});
    command_id(d, r, 0);
    SurfaceHeatFlux f;
    const EntityRef entity = d.entity(r, 1, 2, kFaceEntities);
    const auto cid = d.optional_other_id(r, 3);
    if (!cid && !r.given(4))
      r.fail(4, "give the heat flux: sf (constant) or a curve cid with its scale factor sf");
    f.scale = r.number_or(4, 1.0);
    r.unsupported_unless(5, 0.0, "a start time (t_beg) of a thermal surface load");
    r.unsupported_unless(6, 1e20, "an end time (t_end) of a thermal surface load");
    r.unsupported_unless(7, 0.0, "updating the surface at erosion (erode)");
    f.where = r.where();
    const std::size_t i = d.model.thermal.fluxes.size();
    if (cid)
      d.bind_function(*cid, r.where(3),
                      [i](Model& model, FunctionRef fn) { model.thermal.fluxes[i].curve = fn; });
    pend(d, PendingThermal::Kind::Flux, entity, i);
    d.model.thermal.fluxes.push_back(std::move(f));
  }
}

// coid, entype, enid, h, T_amb (abut's own keyword): q = h (T_amb - T) [power/area] into the body.
void read_load_thermal_convection(DeckReader& d, Block& b) {
  b.title();
  start(d, b, "coid, entype, enid, h, T_amb");
  while (!b.done()) {
    const Row r = b.row({"coid", "entype", "enid", "h", "T_amb"});
    command_id(d, r, 0);
    SurfaceConvection c;
    const EntityRef entity = d.entity(r, 1, 2, kFaceEntities);
    c.coefficient = r.number(3);
    r.require(c.coefficient > 0.0, 3, "expected a heat transfer coefficient h > 0");
    c.ambient = r.number(4);
    c.where = r.where();
    pend(d, PendingThermal::Kind::Convection, entity, d.model.thermal.convection.size());
    d.model.thermal.convection.push_back(std::move(c));
  }
}

}  // namespace abut::deck
