// The end of reading for the thermal keywords (keyword_thermal.cpp), on the final mesh: every
// thpid names a *PROP_THERMAL, the entities of the temperature conditions become nodes and those
// of the face loads become exterior faces (node quads counter-clockwise seen from outside, as
// *LOAD_PRESSURE selects them: pressure_loads.hpp), and the decks abut cannot run are refused
// here, at the keyword, rather than silently run without heat.
//
// Which nodes and faces a thermal entity means: a part (P, PS) must have thermal properties (the
// heat solver holds a temperature only in the hexahedra and shells of such parts, heat.hpp:
// thermal_node_flags); ALL and a region (G) mean
// the nodes and faces of the thermal parts among them, and are an error when there are none.
#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include "abut/model/entity_name.hpp"
#include "abut/solver/heat.hpp"
#include "abut/solver/pressure_loads.hpp"
#include "deck_reader.hpp"

namespace abut::deck {
namespace {

std::string at(const SourceLocation& w) { return w.file + ":" + std::to_string(w.line); }

// The thermal parts and the nodes that carry a temperature (heat.hpp: hexahedra and shells).
struct ThermalMesh {
  std::set<std::int64_t> parts;
  std::vector<std::uint8_t> node;

  explicit ThermalMesh(const Model& model) : node(thermal_node_flags(model)) {
    for (const Part& p : model.parts)
      if (is_thermal_part(model, p.id)) parts.insert(p.id);
  }
  bool has(std::int32_t n) const { return node[static_cast<std::size_t>(n)] != 0; }
};

// P and PS: every part must be thermal.
void require_thermal_parts(const Model& model, const ThermalMesh& thermal, const EntityRef& e) {
  if (e.type != EntityType::Part && e.type != EntityType::PartSet) return;
  for (const std::int64_t pid : model.parts_of(e)) {
    if (thermal.parts.count(pid)) continue;
    const Part* part = model.find_part(pid);
    throw InputError(e.where, "part " + std::to_string(pid) +
                                  " has no thermal properties: the thpid of its material " +
                                  std::to_string(part ? part->material_id : 0) +
                                  " is 0 (give the material the thpid of a *PROP_THERMAL)");
  }
}

std::vector<std::int32_t> thermal_nodes(const Model& model, const ThermalMesh& thermal,
                                        const EntityRef& e) {
  require_thermal_parts(model, thermal, e);
  std::vector<std::int32_t> nodes = model.nodes_of(e);
  if (e.type == EntityType::Node || e.type == EntityType::NodeSet) {
    for (const std::int32_t n : nodes)
      if (!thermal.has(n))
        throw InputError(
            e.where, "node " + std::to_string(model.mesh.nodes.id[static_cast<std::size_t>(n)]) +
                         " is not in a part with thermal properties (thpid)");
  }
  std::erase_if(nodes, [&](std::int32_t n) { return !thermal.has(n); });
  if (nodes.empty())
    throw InputError(e.where, entity_name(e) + " has no node in a part with thermal properties");
  return nodes;
}

std::vector<Quad4> thermal_faces(const Model& model, const ThermalMesh& thermal,
                                 const EntityRef& e) {
  require_thermal_parts(model, thermal, e);
  PressureLoad selection;
  selection.entity = e;
  std::vector<Quad4> faces;
  try {
    faces = pressure_faces(model, selection);
  } catch (const InputError&) {
    faces.clear();  // no face at all: the message below says what is missing
  }
  // Solid faces, then shells: a shell's face is its mid-surface, loaded once (one side).
  std::erase_if(faces, [&](const Quad4& q) {
    return !std::all_of(q.begin(), q.end(), [&](std::int32_t n) { return thermal.has(n); });
  });
  if (faces.empty())
    throw InputError(e.where, entity_name(e) +
                                  " has no exterior face of a solid and no shell with thermal "
                                  "properties to carry the heat load");
  return faces;
}

}  // namespace

void DeckReader::finish_thermal() {
  ThermalModel& thermal = model.thermal;
  if (thermal_bindings.empty()) {
    if (!thermal_keywords.empty()) {
      const SourceLocation& w = thermal_keywords.front();
      throw InputError(w, w.keyword +
                              " has no effect: no material has a thermal property (give "
                              "the thpid field of a *MAT_ line the id of a *PROP_THERMAL)");
    }
    return;
  }
  std::set<std::int64_t> ids, used;
  for (const ThermalProperties& p : thermal.properties) ids.insert(p.id);
  for (const ThermalBinding& b : thermal_bindings) {
    if (!ids.count(b.id))
      throw InputError(b.where, "thermal property " + std::to_string(b.id) +
                                    " does not exist: thpid must be the id of a *PROP_THERMAL "
                                    "(defined thermal properties: " +
                                    joined(ids) + ")");
    used.insert(b.id);
  }
  for (const Material& m : model.materials) {
    const ThermalProperties* p = m.thermal_id != 0 ? thermal.find(m.thermal_id) : nullptr;
    if (p && p->expansion != 0.0 && is_rigid(m.params))
      notes.push_back("rigid material " + std::to_string(m.id) + " at " + at(m.where) +
                      " conducts heat but does not expand (alpha of *PROP_THERMAL " +
                      std::to_string(p->id) + " acts on deformable parts only)");
  }
  for (const ThermalProperties& p : thermal.properties)
    if (!used.count(p.id))
      notes.push_back("*PROP_THERMAL " + std::to_string(p.id) + " at " + at(p.where) +
                      " is not the thpid of any material");

  const ThermalMesh mesh(model);
  std::size_t last_all = 0;  // 1 + the index of the last *INITIAL_TEMPERATURE ALL row
  for (const PendingThermal& p : thermal_entities) {
    switch (p.kind) {
      case PendingThermal::Kind::Initial:
        if (p.entity.type == EntityType::All) {
          thermal.initial_temperature = thermal.initial[p.index].value;
          last_all = p.index + 1;
        } else {
          thermal.initial[p.index].nodes = thermal_nodes(model, mesh, p.entity);
        }
        break;
      case PendingThermal::Kind::Prescribed:
        thermal.prescribed[p.index].nodes = thermal_nodes(model, mesh, p.entity);
        break;
      case PendingThermal::Kind::Flux:
        thermal.fluxes[p.index].faces = thermal_faces(model, mesh, p.entity);
        break;
      case PendingThermal::Kind::Convection:
        thermal.convection[p.index].faces = thermal_faces(model, mesh, p.entity);
        break;
    }
  }
  // ALL sets every node: the rows before it (and itself) are the default temperature now, so the
  // deck order holds (a later row overrides an earlier one).
  thermal.initial.erase(thermal.initial.begin(),
                        thermal.initial.begin() + static_cast<std::ptrdiff_t>(last_all));
}

}  // namespace abut::deck
