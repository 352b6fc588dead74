// The end of reading: every reference is checked now that all ids are known, duplicated nodes are
// merged (*MERGE_DUPLICATED_NODES), then the mesh is refined and smoothed (*CHANGE_P-ORDER,
// *SMOOTH_MESH, *PART alpha_max) and the initial velocities are applied to the final nodes; the
// thermal keywords get their nodes and faces (deck_finalize_thermal.cpp); last, a deck with
// *STATIC gets its static steps' loads (deck_finalize_static.cpp).
#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "abut/mesh/refine.hpp"
#include "abut/mesh/tetrahedra.hpp"
#include "abut/solver/contact_surfaces.hpp"
#include "abut/solver/pressure_loads.hpp"
#include "deck_reader.hpp"
#include "memory_budget.hpp"

namespace abut::deck {

std::string joined(const std::set<std::int64_t>& ids) {
  std::string s;
  std::size_t n = 0;
  for (const std::int64_t id : ids) {
    if (n++ == 20) return s + ", ...";
    s += (s.empty() ? "" : ", ") + std::to_string(id);
  }
  return s.empty() ? "none" : s;
}

SourceLocation with_field(SourceLocation where, const std::string& field) {
  where.field = field;
  return where;
}

namespace {

const Geometry& geometry_of(const Model& model, const IdReference& ref) {
  const GeometryEntry* g = model.find_geometry(ref.id);
  if (!g) {
    std::set<std::int64_t> ids;
    for (const auto& e : model.geometries) ids.insert(e.id);
    throw InputError(ref.where, "geometry " + std::to_string(ref.id) +
                                    " does not exist (defined geometries: " + joined(ids) + ")");
  }
  return g->geometry;
}

// The *CONTACT_* keywords into the *CONTACT each refines, in deck order (a keyword may come before
// its *CONTACT). Then the checks that need every keyword of a contact.
void merge_contact_keywords(Model& model, const std::vector<PendingContactKeyword>& keywords) {
  std::map<std::pair<std::int64_t, std::string>, SourceLocation> given;
  for (const PendingContactKeyword& k : keywords) {
    const auto spec = std::find_if(model.contacts.begin(), model.contacts.end(),
                                   [&k](const ContactSpec& c) { return c.id == k.contact; });
    if (spec == model.contacts.end()) {
      std::set<std::int64_t> ids;
      for (const ContactSpec& c : model.contacts) ids.insert(c.id);
      throw InputError(k.where, "contact " + std::to_string(k.contact) +
                                    " does not exist: coid must be the ctid of a *CONTACT "
                                    "(defined contacts: " +
                                    joined(ids) + ")");
    }
    if (!k.repeatable) {
      const auto [first, inserted] =
          given.emplace(std::make_pair(k.contact, k.where.keyword), k.where);
      if (!inserted) {
        throw InputError(
            k.where, k.where.keyword + " is given twice for contact " + std::to_string(k.contact) +
                         " (first at " + first->second.file + ":" +
                         std::to_string(first->second.line) + "): give it once per contact");
      }
    }
    k.apply(*spec);
  }
  for (const ContactSpec& c : model.contacts) {
    check_contact_options(model, c);
    check_tool_contact(model, c);
    if (c.surface1.type == EntityType::NodeSet &&
        c.discretisation != Discretisation::NodeToSurface) {
      throw InputError(c.surface1.where,
                       "a node set is a surface only for node-to-surface contact: add "
                       "*CONTACT_DISCRETIZATION with N2S for contact " +
                           std::to_string(c.id) + ", or give a part (P), part set (PS) or ALL");
    }
  }
}

}  // namespace

DeckResult DeckReader::finish() {
  name_keyword_words(model.sources);
  if (!time_where && static_step_ends.empty()) {
    throw InputError(SourceLocation{files.front(), std::max<std::size_t>(end_line, 1), "", ""},
                     "the deck ends without *TIME: abut needs the termination time t_term (or "
                     "*STATIC steps for a static analysis)");
  }
  model.functions.resolve();
  finish_gmsh();
  Mesh& mesh = model.mesh;

  // Element nodes.
  for (const ElementNodes& e : element_nodes) {
    for (std::size_t k = 0; k < 8; ++k) {
      const std::int32_t index = node_index(e.node_ids[k]);
      if (index < 0) {
        throw InputError(element_where(e, "n" + std::to_string(k + 1)),
                         "node " + std::to_string(e.node_ids[k]) + " does not exist");
      }
      mesh.hexes[e.hex][k] = index;
    }
  }
  resolve_cell_nodes();

  // Parts, their materials, and the part of every hex.
  std::set<std::int64_t> part_ids, material_ids;
  for (const Part& p : model.parts) part_ids.insert(p.id);
  for (const Material& m : model.materials) material_ids.insert(m.id);
  for (const Part& p : model.parts) {
    if (!material_ids.count(p.material_id)) {
      throw InputError(with_field(p.where, "mid"),
                       "material " + std::to_string(p.material_id) +
                           " does not exist (defined materials: " + joined(material_ids) + ")");
    }
  }
  const auto require_part = [&](std::int64_t id, const SourceLocation& where) {
    if (!part_ids.count(id)) {
      throw InputError(where, "part " + std::to_string(id) +
                                  " does not exist (defined parts: " + joined(part_ids) + ")");
    }
  };
  for (const ElementNodes& e : element_nodes)
    require_part(mesh.hex_part[e.hex], element_where(e, "pid"));
  for (const ShellNodes& e : shell_nodes)
    require_part(mesh.shell_part[e.shell], shell_where(e, "pid"));
  for (const CellNodes& e : cell_nodes)
    for (const CellBlock& b : mesh.cells)
      if (b.type == e.type) require_part(b.part[e.cell], cell_where(e, "pid"));
  for (const MeshSource& s : mesh_sources) {
    for (std::size_t h = s.first; h < s.end; ++h)
      require_part(mesh.hex_part[h], with_field(s.where, "pid"));
    for (std::size_t e = s.first_shell; e < s.end_shell; ++e)
      require_part(mesh.shell_part[e], with_field(s.where, "pid"));
  }

  // Sets and geometries.
  for (const PendingNodeSet& s : node_sets) {
    std::vector<std::int32_t>& nodes = model.node_sets[s.index].nodes;
    for (const IdReference& n : s.nodes) {
      const std::int32_t index = node_index(n.id);
      if (index < 0) throw InputError(n.where, "node " + std::to_string(n.id) + " does not exist");
      nodes.push_back(index);
    }
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  }
  for (const auto& [id, where] : part_set_members) require_part(id, where);
  for (PartSet& s : model.part_sets) {
    std::sort(s.parts.begin(), s.parts.end());
    s.parts.erase(std::unique(s.parts.begin(), s.parts.end()), s.parts.end());
  }
  for (const auto& [id, where] : geometry_parts) require_part(id, where);
  for (const IdReference& g : geometry_references) geometry_of(model, g);

  // Curves and functions used by other commands.
  for (const FunctionBinding& f : function_bindings)
    f.bind(model, model.functions.find(f.id, f.where));
  for (const DamageBinding& b : damage_bindings) {
    const auto it = damage_properties.find(b.id);
    if (it == damage_properties.end())
      throw InputError(b.where, "damage property " + std::to_string(b.id) +
                                    " is not defined (expected a *PROP_DAMAGE_JC with this did)");
    MetalParams& metal = std::get<MetalParams>(model.materials[b.material].params);
    metal.failure = it->second;
    if (metal.failure.d5 != 0.0 && !(metal.melting_temperature > metal.room_temperature))
      throw InputError(b.where, "damage property " + std::to_string(b.id) +
                                    " has a thermal factor d5: the material needs a melting "
                                    "temperature Tm above T0 (line 2, as for softening)");
  }

  // Entities: every id must exist.
  for (const EntityRef& e : entity_references) {
    if (e.type == EntityType::Tool) {
      model.tool(e);
    } else if (e.type == EntityType::Part || e.type == EntityType::PartSet ||
               e.type == EntityType::All) {
      model.parts_of(e);
    } else {
      model.nodes_of(e);
    }
  }
  // *CONTACT_* keywords, now that every *CONTACT, function and entity is known.
  merge_contact_keywords(model, contact_keywords);
  extract_exact_ties(model);
  check_sensors(model);
  // Every element holds node indices now; joining nodes must come before refinement, contact
  // adjustment and initial velocities take them up.
  resolve_shell_nodes();
  merge_duplicated_nodes();
  check_element_volumes();
  resolve_shells();

  // Rotations are degrees of freedom of rigid parts and of shell nodes.
  std::vector<bool> shell_node(mesh.nodes.size(), false);
  for (const Quad4& q : mesh.shells)
    for (const std::int32_t node : q) shell_node[static_cast<std::size_t>(node)] = true;
  for (const MotionBoundary& m : model.motions) {
    const bool rotates =
        m.fixed_rotation != 0 || std::any_of(m.motions.begin(), m.motions.end(),
                                             [](const auto& p) { return p.direction >= 3; });
    if (!rotates) continue;
    if (m.entity.type == EntityType::Part || m.entity.type == EntityType::PartSet) {
      for (const std::int64_t pid : model.parts_of(m.entity)) {
        const bool shells =
            std::find(mesh.shell_part.begin(), mesh.shell_part.end(), pid) != mesh.shell_part.end();
        if (!is_rigid(model.material_of_part(pid)) && !shells) {
          throw InputError(m.where,
                           "rotational constraints and RX, RY, RZ motions apply to rigid parts "
                           "and shells only; part " +
                               std::to_string(pid) + " is a deformable solid");
        }
      }
      continue;
    }
    const std::vector<std::int32_t> nodes = model.nodes_of(m.entity);
    if (std::none_of(nodes.begin(), nodes.end(),
                     [&](std::int32_t i) { return shell_node[static_cast<std::size_t>(i)]; })) {
      throw InputError(m.where,
                       "rotational constraints and RX, RY, RZ motions apply to rigid parts (P or "
                       "PS) and shell nodes; none of these nodes belongs to a shell");
    }
  }

  // Mesh refinement and smoothing, once, on the complete mesh. ALL means the solid parts: shell
  // parts are neither refined nor smoothed (resolve_shells refuses them by P and PS).
  const auto solid_parts_of = [&](const EntityRef& entity) {
    std::vector<std::int64_t> parts = model.parts_of(entity);
    if (entity.type == EntityType::All) {
      std::erase_if(parts, [&](std::int64_t p) {
        return std::find(mesh.shell_part.begin(), mesh.shell_part.end(), p) !=
               mesh.shell_part.end();
      });
    }
    return parts;
  };
  std::vector<OrderChange> order_changes;
  for (const PendingOrder& o : orders) {
    OrderChange c;
    c.parts = solid_parts_of(o.entity);
    c.order = o.order;
    if (o.region) c.region = geometry_of(model, *o.region);
    c.where = with_field(o.entity.where, "");  // the line of the *CHANGE_P-ORDER row
    order_changes.push_back(std::move(c));
  }
  std::vector<SurfaceSmoothing> smoothings;
  for (const PendingSmoothing& s : smoothing) {
    SurfaceSmoothing c;
    c.parts = solid_parts_of(s.entity);
    c.max_angle = s.max_angle;
    c.internal = s.internal;
    if (s.region) c.region = geometry_of(model, *s.region);
    c.where = with_field(s.entity.where, "");  // the *SMOOTH_MESH row or the *PART row
    smoothings.push_back(std::move(c));
  }
  // Refinement and smoothing work on hexahedra: a part with other cells would be left with
  // cells that do not conform to its refined hexahedra.
  const auto require_hexahedra = [&](const std::vector<std::int64_t>& parts,
                                     const SourceLocation& where, const char* keyword) {
    for (const CellBlock& b : mesh.cells)
      for (std::size_t c = 0; c < b.size(); ++c)
        if (std::find(parts.begin(), parts.end(), b.part[c]) != parts.end())
          throw InputError(where, "part " + std::to_string(b.part[c]) + " has " +
                                      std::string(element_label(b.type)) + " elements: " + keyword +
                                      " works on 8-node hexahedra, other cells are not "
                                      "supported yet");
  };
  for (const OrderChange& c : order_changes) require_hexahedra(c.parts, c.where, "*CHANGE_P-ORDER");
  for (const SurfaceSmoothing& c : smoothings) require_hexahedra(c.parts, c.where, "*SMOOTH_MESH");
  // Order 3 makes 27 hexes of one: counted against the memory like a generated component.
  const auto fits = [&](const MeshSize& added, const SourceLocation& where) {
    const MeshSize total{
        static_cast<double>(mesh.solid_count() + mesh.shell_count()) + added.elements,
        static_cast<double>(mesh.nodes.size()) + added.nodes};
    require_memory(total, available_memory(), where);
  };
  if (!order_changes.empty() || !smoothings.empty()) {
    for (std::string& note : refine_and_smooth(mesh, order_changes, smoothings, fits, p_order_form))
      notes.push_back(std::move(note));
  }
  // Tetrahedra are cut from the hexahedra as refinement left them (SPLIT: the children).
  std::vector<TetrahedraChange> tetrahedra_changes;
  for (const PendingTetrahedra& t : tetrahedra) {
    TetrahedraChange c;
    c.parts = solid_parts_of(t.entity);
    c.type = t.type;
    if (t.region) c.region = geometry_of(model, *t.region);
    c.where = with_field(t.entity.where, "");
    tetrahedra_changes.push_back(std::move(c));
  }
  for (const TetrahedraChange& c : tetrahedra_changes)
    require_hexahedra(c.parts, c.where, "*CHANGE_TO_TETRAHEDRA");
  for (std::string& note : change_to_tetrahedra(mesh, tetrahedra_changes, fits))
    notes.push_back(std::move(note));

  // *SET_FACE rows become element faces of the final mesh.
  resolve_face_sets();

  // OptiStruct ADJUST: secondary nodes onto the main surface, before anything uses the geometry.
  for (std::string& note : adjust_contact_nodes(model)) notes.push_back(std::move(note));

  // *LOAD_PRESSURE: an entity without faces is an error of the deck, found on the final mesh.
  for (const PressureLoad& p : model.pressures) pressure_faces(model, p);

  // Initial velocities on the final nodes, in deck order (a later command overrides an earlier
  // one).
  const std::size_t n = mesh.nodes.size();
  model.vx0.assign(n, 0.0);
  model.vy0.assign(n, 0.0);
  model.vz0.assign(n, 0.0);
  model.wx0.assign(n, 0.0);
  model.wy0.assign(n, 0.0);
  model.wz0.assign(n, 0.0);
  for (const PendingVelocity& v : velocities) {
    std::array<FunctionRef, 3> fcn;
    for (std::size_t k = 0; k < 3; ++k) {
      if (v.velocity[k].function_id)
        fcn[k] = model.functions.find(*v.velocity[k].function_id, v.velocity_where[k]);
    }
    for (const std::int32_t i : model.nodes_of(v.entity)) {
      const Vec3 p = mesh.nodes.position(static_cast<std::size_t>(i));
      Variables vars;
      vars.x = vars.X = p.x;
      vars.y = vars.Y = p.y;
      vars.z = vars.Z = p.z;
      Vec3 velocity = cross(v.angular_velocity, p - v.centre);
      for (int k = 0; k < 3; ++k) {
        const auto uk = static_cast<std::size_t>(k);
        velocity[k] +=
            fcn[uk].valid() ? model.functions.value(fcn[uk], vars) : v.velocity[uk].value;
        // A NaN or infinite start (acos(2), 1/0 in a *FUNCTION), or one so large that the first
        // strain rates overflow, is an error of the deck, not an instability of the run: say
        // which field, function and node gave it. No unit system makes 1e100 a speed.
        constexpr double kLargestSpeed = 1e100;
        if (!(std::fabs(velocity[k]) <= kLargestSpeed)) {
          const std::string source =
              fcn[uk].valid() ? "function " + std::to_string(*v.velocity[uk].function_id)
              : norm(v.angular_velocity) == 0.0 ? std::string("the value")
                                                : std::string("the value plus omega x (x - x0)");
          throw InputError(v.velocity_where[uk],
                           source + " gives an initial velocity of " + format_number(velocity[k]) +
                               " at node " +
                               std::to_string(mesh.nodes.id[static_cast<std::size_t>(i)]) + " (" +
                               format_number(p.x) + ", " + format_number(p.y) + ", " +
                               format_number(p.z) + "): expected a finite speed up to 1e100");
        }
      }
      model.vx0[static_cast<std::size_t>(i)] = velocity.x;
      model.vy0[static_cast<std::size_t>(i)] = velocity.y;
      model.vz0[static_cast<std::size_t>(i)] = velocity.z;
      model.wx0[static_cast<std::size_t>(i)] = v.angular_velocity.x;
      model.wy0[static_cast<std::size_t>(i)] = v.angular_velocity.y;
      model.wz0[static_cast<std::size_t>(i)] = v.angular_velocity.z;
    }
  }

  // Heat: thpid references, thermal nodes and faces (deck_finalize_thermal.cpp).
  finish_thermal();
  // *PART_SOLID; with *STATIC the loads and boundary conditions become the steps' lists.
  finish_static_steps();

  std::set<std::int64_t> parts_with_elements(mesh.hex_part.begin(), mesh.hex_part.end());
  parts_with_elements.insert(mesh.shell_part.begin(), mesh.shell_part.end());
  for (const CellBlock& b : mesh.cells) parts_with_elements.insert(b.part.begin(), b.part.end());
  for (const Part& p : model.parts) {
    if (!parts_with_elements.count(p.id)) {
      notes.push_back("part " + std::to_string(p.id) + " has no elements");
    }
  }
  return {std::move(model), std::move(notes)};
}

}  // namespace abut::deck
