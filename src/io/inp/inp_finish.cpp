// The end of reading, part 1: elements with their nodes and sections into solids and parts,
// materials, node and element sets, surfaces into face sets and node sets. Then Reader::finish,
// which runs the parts in order (contacts and steps: inp_finish_steps.cpp).
#include <algorithm>
#include <map>

#include "abut/mesh/shape_functions.hpp"
#include "abut/mesh/skin.hpp"
#include "abut/solver/contact_surfaces.hpp"
#include "inp_reader.hpp"

namespace abut::inp {
namespace {

void sort_unique(std::vector<std::int32_t>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

// "A, B, C" (the first 10 names) or "none", for messages that say what exists.
std::string names_of(const std::vector<IdSet>& sets) {
  std::string s;
  for (std::size_t i = 0; i < sets.size() && i < 10; ++i) s += (i ? ", " : "") + sets[i].name;
  if (sets.size() > 10) s += ", ...";
  return s.empty() ? "none" : s;
}

const IdSet& find_set(const Reader& r, const std::vector<IdSet>& sets,
                      const std::unordered_map<std::string, std::size_t>& names,
                      const std::string& name, Loc at, const std::string& keyword,
                      const std::string& kind) {
  const auto it = names.find(upper_name(name));
  if (it == names.end()) {
    throw InputError(r.where(at, keyword), kind + " set " + name + " is not defined (defined " +
                                               kind + " sets: " + names_of(sets) + ")");
  }
  return sets[it->second];
}

// Node ids of every node set, element ids of every element set -> indices.
void resolve_sets(Reader& r) {
  for (IdSet& s : r.node_sets) {
    s.members.reserve(s.ids.size());
    for (std::size_t k = 0; k < s.ids.size(); ++k) {
      const auto it = r.node_index.find(s.ids[k]);
      if (it == r.node_index.end()) {
        throw InputError(r.where(s.where[k], "*NSET"), "node " + std::to_string(s.ids[k]) +
                                                           " of node set " + s.name +
                                                           " is not defined (no *NODE line)");
      }
      s.members.push_back(it->second);
    }
    sort_unique(s.members);
    s.model_id = static_cast<std::int64_t>(r.model.node_sets.size()) + 1;
    r.model.node_sets.push_back({s.model_id, s.members});
  }
  for (IdSet& s : r.element_sets) {
    s.members.reserve(s.ids.size());
    for (std::size_t k = 0; k < s.ids.size(); ++k) {
      const auto it = r.element_index.find(s.ids[k]);
      if (it == r.element_index.end()) {
        throw InputError(r.where(s.where[k], "*ELSET"), "element " + std::to_string(s.ids[k]) +
                                                            " of element set " + s.name +
                                                            " is not defined (no *ELEMENT line)");
      }
      s.members.push_back(static_cast<std::int32_t>(it->second));
    }
    sort_unique(s.members);
  }
}

// Materials in deck order (id = position + 1); a material without *ELASTIC is left out, and an
// error if a section uses it (checked with the sections). With *PLASTIC: J2 plasticity whose
// flow curve (plastic strain -> stress) becomes a curve of the model's function table.
void make_materials(Reader& r) {
  for (std::size_t m = 0; m < r.materials.size(); ++m) {
    const MaterialRecord& rec = r.materials[m];
    if (!rec.elastic) continue;
    Material mat;
    mat.id = static_cast<std::int64_t>(m) + 1;
    if (rec.flow_stress.empty()) {
      mat.params = ElasticParams{rec.density, rec.young, rec.poisson};
    } else {
      MetalParams metal;
      metal.density = rec.density;
      metal.young = rec.young;
      metal.poisson = rec.poisson;
      const std::int64_t id = r.next_function_id++;
      const SourceLocation where = r.where(rec.plastic_defined, "*PLASTIC");
      r.model.functions.add_curve(id, Curve{rec.plastic_strain, rec.flow_stress}, where);
      metal.flow_curve = r.model.functions.find(id, where);
      mat.params = metal;
    }
    mat.where = r.where(rec.defined, "*MATERIAL", "NAME");
    r.model.materials.push_back(mat);
  }
}

// Sections -> parts (one per section and element type), and the part of every element.
std::vector<std::int64_t> assign_parts(Reader& r) {
  const std::size_t n = r.elements.size();
  std::vector<std::int32_t> section_of(n, -1);
  std::vector<std::int64_t> part_of(n, 0);
  for (std::size_t s = 0; s < r.sections.size(); ++s) {
    const SectionRecord& sec = r.sections[s];
    const auto material = r.material_names.find(upper_name(sec.material));
    if (material == r.material_names.end()) {
      throw InputError(
          r.where(sec.where, "*SOLID SECTION", "MATERIAL"),
          "material " + sec.material + " is not defined (no *MATERIAL, NAME=" + sec.material + ")");
    }
    const MaterialRecord& mat = r.materials[material->second];
    if (!mat.elastic) {
      throw InputError(r.where(mat.defined, "*MATERIAL"),
                       "material " + mat.name +
                           " has no *ELASTIC card: abut needs Young's modulus and Poisson's "
                           "ratio (its materials are linear elastic)");
    }
    const IdSet& set = find_set(r, r.element_sets, r.element_set_names, sec.elset, sec.where,
                                "*SOLID SECTION", "element");
    // One part per element name (C3D8, C3D20R, ...) in the section.
    std::map<std::pair<CellType, bool>, std::int64_t> part_ids;
    for (const std::int32_t e : set.members) {
      const ElementRecord& el = r.elements[static_cast<std::size_t>(e)];
      std::int32_t& assigned = section_of[static_cast<std::size_t>(e)];
      if (assigned >= 0) {
        throw InputError(r.where(sec.where, "*SOLID SECTION", "ELSET"),
                         "element " + std::to_string(el.id) + " already has the section of " +
                             r.at(r.sections[static_cast<std::size_t>(assigned)].where) +
                             ": every element takes exactly one *SOLID SECTION");
      }
      assigned = static_cast<std::int32_t>(s);
      std::int64_t& part = part_ids[{el.type, el.reduced}];
      if (part == 0) {
        Part p;
        p.id = static_cast<std::int64_t>(r.model.parts.size()) + 1;
        p.title = set.name;
        p.material_id = static_cast<std::int64_t>(material->second) + 1;
        p.solid_integration =
            el.reduced ? Part::SolidIntegration::Reduced : Part::SolidIntegration::Full;
        p.where = r.where(sec.where, "*SOLID SECTION");
        r.model.parts.push_back(p);
        part = p.id;
      }
      part_of[static_cast<std::size_t>(e)] = part;
    }
    // A section over several element types: say which part is which.
    if (part_ids.size() > 1) {
      for (const auto& [kind, id] : part_ids)
        r.model.parts[static_cast<std::size_t>(id - 1)].title +=
            " (" + std::string(topology(kind.first).abaqus) + (kind.second ? "R)" : ")");
    }
  }
  for (std::size_t e = 0; e < n; ++e) {
    if (section_of[e] < 0) {
      throw InputError(r.where(r.elements[e].where, "*ELEMENT"),
                       "element " + std::to_string(r.elements[e].id) +
                           " has no *SOLID SECTION: put it in an element set that has one");
    }
  }
  return part_of;
}

// The elements in the mesh's solid numbering (hexahedra, then one block per cell type in the
// order of CellType): records are sorted so that a record's index is its solid index.
void order_elements(Reader& r) {
  std::stable_sort(r.elements.begin(), r.elements.end(),
                   [](const ElementRecord& a, const ElementRecord& b) { return a.type < b.type; });
  for (std::size_t e = 0; e < r.elements.size(); ++e) r.element_index[r.elements[e].id] = e;
}

void make_solids(Reader& r, const std::vector<std::int64_t>& part_of) {
  Mesh& mesh = r.model.mesh;
  for (std::size_t e = 0; e < r.elements.size(); ++e) {
    const ElementRecord& el = r.elements[e];
    const CellTopology& t = topology(el.type);
    std::array<std::int32_t, kMaxCellNodes> nodes{};
    std::array<double, 3 * kMaxCellNodes> X{};
    for (int k = 0; k < t.nodes; ++k) {
      const auto it = r.node_index.find(el.nodes[static_cast<std::size_t>(k)]);
      if (it == r.node_index.end()) {
        throw InputError(r.where(el.where, "*ELEMENT", "n" + std::to_string(k + 1)),
                         "node " + std::to_string(el.nodes[static_cast<std::size_t>(k)]) +
                             " of element " + std::to_string(el.id) +
                             " is not defined (no *NODE line)");
      }
      nodes[static_cast<std::size_t>(k)] = it->second;
      const Vec3 p = mesh.nodes.position(static_cast<std::size_t>(it->second));
      X[3 * static_cast<std::size_t>(k)] = p.x;
      X[3 * static_cast<std::size_t>(k) + 1] = p.y;
      X[3 * static_cast<std::size_t>(k) + 2] = p.z;
    }
    const double jacobian = min_jacobian(el.type, std::span<const double>(X.data(), 3 * t.nodes));
    if (!(jacobian > 0.0)) {
      throw InputError(r.where(el.where, "*ELEMENT"),
                       "element " + std::to_string(el.id) + " (" + std::string(t.abaqus) +
                           ") is inside out or folded (det J = " + std::to_string(jacobian) +
                           " at an integration point): its nodes must follow the " +
                           std::string(t.abaqus) + " order (" + std::string(t.node_order) + ")");
    }
    if (el.type == CellType::hex8) {
      Hex8 hex;
      std::copy(nodes.begin(), nodes.begin() + 8, hex.begin());
      mesh.add_hex(el.id, part_of[e], hex);
    } else {
      mesh.add_cell(el.type, el.id, part_of[e],
                    std::span<const std::int32_t>(nodes.data(), static_cast<std::size_t>(t.nodes)));
    }
  }
}

void make_surfaces(Reader& r) {
  for (SurfaceRecord& s : r.surfaces) {
    const SourceLocation where = r.where(s.defined, "*SURFACE", "NAME");
    if (s.node_based) {
      std::vector<std::int32_t> nodes;
      for (const Item& item : s.items) {
        const std::vector<std::int32_t> more = nodes_of(r, item, "*SURFACE");
        nodes.insert(nodes.end(), more.begin(), more.end());
      }
      sort_unique(nodes);
      if (nodes.empty()) throw InputError(where, "surface " + s.name + " has no nodes");
      const auto id = static_cast<std::int64_t>(r.model.node_sets.size()) + 1;
      r.model.node_sets.push_back({id, std::move(nodes)});
      s.entity = EntityRef{EntityType::NodeSet, id, where};
      continue;
    }
    FaceSet set;
    set.id = static_cast<std::int64_t>(r.model.face_sets.size()) + 1;
    set.name = s.name;
    set.where = where;
    std::map<std::pair<std::int32_t, std::int8_t>, bool> seen;
    for (std::size_t k = 0; k < s.items.size(); ++k) {
      for (const std::int32_t solid : solids_of(r, s.items[k], "*SURFACE")) {
        require_face(r, solid, s.faces[k], s.items[k].where, "*SURFACE");
        if (seen.emplace(std::make_pair(solid, s.faces[k]), true).second)
          set.faces.push_back({solid, s.faces[k]});
      }
    }
    if (set.faces.empty()) throw InputError(where, "surface " + s.name + " has no faces");
    s.entity = EntityRef{EntityType::FaceSet, set.id, where};
    r.model.face_sets.push_back(std::move(set));
  }
}

}  // namespace

std::vector<std::int32_t> node_set_members(const Reader& r, const std::string& name, Loc at,
                                           const std::string& keyword) {
  return find_set(r, r.node_sets, r.node_set_names, name, at, keyword, "node").members;
}

std::vector<std::int32_t> element_set_members(const Reader& r, const std::string& name, Loc at,
                                              const std::string& keyword) {
  return find_set(r, r.element_sets, r.element_set_names, name, at, keyword, "element").members;
}

std::vector<std::int32_t> nodes_of(const Reader& r, const Item& item, const std::string& keyword) {
  if (!item.name.empty()) return node_set_members(r, item.name, item.where, keyword);
  const auto it = r.node_index.find(item.id);
  if (it == r.node_index.end()) {
    throw InputError(r.where(item.where, keyword),
                     "node " + std::to_string(item.id) + " is not defined (no *NODE line)");
  }
  return {it->second};
}

void require_face(const Reader& r, std::int32_t element, int face, Loc where,
                  const std::string& keyword) {
  const ElementRecord& e = r.elements[static_cast<std::size_t>(element)];
  const CellTopology& t = topology(e.type);
  if (face < static_cast<int>(t.faces.size())) return;
  const char* label = keyword == "*DLOAD" ? "P" : "S";
  throw InputError(r.where(where, keyword),
                   "element " + std::to_string(e.id) + " is a " + std::string(t.abaqus) +
                       ", which has the faces 1 to " + std::to_string(t.faces.size()) +
                       " only: use " + label + "1 to " + label + std::to_string(t.faces.size()));
}

std::vector<std::int32_t> solids_of(const Reader& r, const Item& item, const std::string& keyword) {
  if (!item.name.empty()) return element_set_members(r, item.name, item.where, keyword);
  const auto it = r.element_index.find(item.id);
  if (it == r.element_index.end()) {
    throw InputError(r.where(item.where, keyword),
                     "element " + std::to_string(item.id) + " is not defined (no *ELEMENT line)");
  }
  return {static_cast<std::int32_t>(it->second)};
}

// *NODE OUTPUT, NSET= after *OUTPUT, HISTORY: nodes.csv follows the model's node set that
// resolve_sets made of the named set.
void make_history_nodes(Reader& r) {
  for (const auto& [name, at] : r.history_node_sets) {
    const IdSet& set = find_set(r, r.node_sets, r.node_set_names, name, at, "*NODE OUTPUT", "node");
    r.model.output.history_nodes.push_back(
        EntityRef{EntityType::NodeSet, set.model_id, r.where(at, "*NODE OUTPUT", "NSET")});
  }
}

void finish_mesh(Reader& r) {
  if (r.elements.empty()) {  // at the end of the input, like a missing *STEP
    throw InputError(r.where(r.last_card.line > 0 ? r.last_card : Loc{0, 1}, ""),
                     "the input has no *ELEMENT: abut needs solid elements (C3D8, C3D8R, C3D20, "
                     "C3D20R, C3D4, C3D10 or C3D6)");
  }
  order_elements(r);
  resolve_sets(r);
  make_materials(r);
  make_solids(r, assign_parts(r));
  make_surfaces(r);
  make_history_nodes(r);
}

// Nodes that no element uses (CalculiX decks keep stray ones): the static solver gives them no
// equations, as CalculiX does; say so once.
void Reader::note_unattached_nodes() {
  const Mesh& mesh = model.mesh;
  const std::vector<std::uint8_t> used = mesh.nodes_in_elements();
  std::vector<std::int64_t> stray;
  for (std::size_t i = 0; i < used.size(); ++i)
    if (!used[i]) stray.push_back(mesh.nodes.id[i]);
  if (stray.empty()) return;
  std::string list;
  for (std::size_t i = 0; i < std::min<std::size_t>(stray.size(), 5); ++i)
    list += (i ? ", " : "") + std::to_string(stray[i]);
  if (stray.size() > 5) list += ", ...";
  const bool one = stray.size() == 1;
  notes.push_back(std::to_string(stray.size()) + (one ? " node (" : " nodes (") + list +
                  (one ? ") belongs" : ") belong") + " to no element: no stiffness holds " +
                  (one ? "it, so it takes" : "them, so they take") +
                  " no part in the analysis (as in CalculiX)");
}

DeckResult Reader::finish() {
  name_inp_words(model.sources);
  if (change_behaviour) {
    throw InputError(where(step().changes.back().where, "*CHANGE SURFACE BEHAVIOR"),
                     "*CHANGE SURFACE BEHAVIOR must be followed by a *SURFACE BEHAVIOR card with "
                     "the new law");
  }
  if (change_friction) {
    throw InputError(where(step().changes.back().where, "*CHANGE FRICTION"),
                     "*CHANGE FRICTION must be followed by a *FRICTION card with the new values");
  }
  if (in_step) {
    throw InputError(where(step().where, "*STEP"),
                     "the step has no *END STEP: close it at the end of its cards");
  }
  if (steps.empty()) {
    throw InputError(where(last_card.line > 0 ? last_card : Loc{0, 1}, ""),
                     "the input ends without *STEP: abut runs static steps (*STEP, *STATIC, "
                     "loads, *END STEP)");
  }
  for (std::size_t i = 0; i < title_lines.size(); ++i)
    model.title += (i ? " " : "") + title_lines[i];
  finish_mesh(*this);
  finish_contacts(*this);
  finish_ties(*this);
  finish_steps(*this);
  model.functions.resolve();
  note_unattached_nodes();
  // CalculiX ADJUST: slave nodes onto the master surface, in the reference configuration.
  for (std::string& n : adjust_contact_nodes(model)) notes.push_back(std::move(n));
  const std::size_t n = model.mesh.nodes.size();
  for (std::vector<double>* v :
       {&model.vx0, &model.vy0, &model.vz0, &model.wx0, &model.wy0, &model.wz0})
    v->assign(n, 0.0);
  return {std::move(model), std::move(notes)};
}

}  // namespace abut::inp
