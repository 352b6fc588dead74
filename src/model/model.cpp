#include "abut/model/model.hpp"

#include <algorithm>

namespace abut {
namespace {

// "1, 2, 5" (the first 20 ids), for messages that say what exists.
template <typename Items, typename Id>
std::string id_list(const Items& items, Id id_of) {
  std::vector<std::int64_t> ids;
  for (const auto& item : items) ids.push_back(id_of(item));
  std::sort(ids.begin(), ids.end());
  std::string s;
  for (std::size_t i = 0; i < ids.size() && i < 20; ++i)
    s += (i ? ", " : "") + std::to_string(ids[i]);
  if (ids.size() > 20) s += ", ...";
  return s.empty() ? "none" : s;
}

template <typename Items>
auto find_by_id(const Items& items, std::int64_t id) -> decltype(&items.front()) {
  const auto it =
      std::find_if(items.begin(), items.end(), [id](const auto& x) { return x.id == id; });
  return it == items.end() ? nullptr : &*it;
}

void sort_unique(std::vector<std::int32_t>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

}  // namespace

const Part* Model::find_part(std::int64_t id) const { return find_by_id(parts, id); }
const Material* Model::find_material(std::int64_t id) const { return find_by_id(materials, id); }
const GeometryEntry* Model::find_geometry(std::int64_t id) const {
  return find_by_id(geometries, id);
}

const MaterialParams& Model::material_of_part(std::int64_t part_id) const {
  const Part* part = find_part(part_id);
  if (!part) {
    throw InputError("part " + std::to_string(part_id) + " does not exist (defined parts: " +
                     id_list(parts, [](const Part& p) { return p.id; }) + ")");
  }
  const Material* material = find_material(part->material_id);
  if (!material) {
    SourceLocation where = part->where;
    where.field = "mid";
    throw InputError(where, "material " + std::to_string(part->material_id) + " of part " +
                                std::to_string(part_id) + " does not exist (defined materials: " +
                                id_list(materials, [](const Material& m) { return m.id; }) + ")");
  }
  return material->params;
}

std::vector<std::int64_t> Model::parts_of(const EntityRef& entity) const {
  const auto require_part = [&](std::int64_t id) {
    if (!find_part(id)) {
      throw InputError(entity.where, "part " + std::to_string(id) +
                                         " does not exist (defined parts: " +
                                         id_list(parts, [](const Part& p) { return p.id; }) + ")");
    }
  };
  switch (entity.type) {
    case EntityType::Part:
      require_part(entity.id);
      return {entity.id};
    case EntityType::PartSet: {
      const PartSet* set = find_by_id(part_sets, entity.id);
      if (!set) {
        throw InputError(entity.where,
                         "part set " + std::to_string(entity.id) +
                             " does not exist (defined part sets: " +
                             id_list(part_sets, [](const PartSet& s) { return s.id; }) + ")");
      }
      for (const std::int64_t id : set->parts) require_part(id);
      return set->parts;
    }
    case EntityType::All: {
      std::vector<std::int64_t> ids;
      for (const Part& p : parts) ids.push_back(p.id);
      std::sort(ids.begin(), ids.end());
      return ids;
    }
    default:
      throw InputError(entity.where, "expected a part (P), a part set (PS) or ALL here");
  }
}

std::vector<std::int32_t> Model::nodes_of(const EntityRef& entity) const {
  std::vector<std::int32_t> nodes;
  switch (entity.type) {
    case EntityType::Node: {
      const auto it = std::find(mesh.nodes.id.begin(), mesh.nodes.id.end(), entity.id);
      if (it == mesh.nodes.id.end()) {
        throw InputError(entity.where, "node " + std::to_string(entity.id) + " does not exist");
      }
      nodes.push_back(static_cast<std::int32_t>(it - mesh.nodes.id.begin()));
      return nodes;
    }
    case EntityType::NodeSet: {
      const NodeSet* set = find_by_id(node_sets, entity.id);
      if (!set) {
        throw InputError(entity.where,
                         "node set " + std::to_string(entity.id) +
                             " does not exist (defined node sets: " +
                             id_list(node_sets, [](const NodeSet& s) { return s.id; }) + ")");
      }
      nodes = set->nodes;
      break;
    }
    case EntityType::Part:
    case EntityType::PartSet: {
      const std::vector<std::int64_t> ids = parts_of(entity);
      for (std::size_t e = 0; e < mesh.solid_count(); ++e) {
        const SolidRef solid = mesh.solid(e);
        if (std::find(ids.begin(), ids.end(), solid.part) != ids.end())
          nodes.insert(nodes.end(), solid.nodes.begin(), solid.nodes.end());
      }
      for (std::size_t s = 0; s < mesh.shell_count(); ++s) {
        if (std::find(ids.begin(), ids.end(), mesh.shell_part[s]) != ids.end()) {
          nodes.insert(nodes.end(), mesh.shells[s].begin(), mesh.shells[s].end());
        }
      }
      break;
    }
    case EntityType::All:
      for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
        nodes.push_back(static_cast<std::int32_t>(i));
      return nodes;
    case EntityType::GeometryRegion: {
      const GeometryEntry* g = find_geometry(entity.id);
      if (!g) {
        throw InputError(
            entity.where,
            "geometry " + std::to_string(entity.id) + " does not exist (defined geometries: " +
                id_list(geometries, [](const GeometryEntry& e) { return e.id; }) + ")");
      }
      for (std::size_t i = 0; i < mesh.nodes.size(); ++i) {
        if (geometry_contains(g->geometry, mesh.nodes.position(i), mesh))
          nodes.push_back(static_cast<std::int32_t>(i));
      }
      return nodes;
    }
    case EntityType::Tool:
      throw InputError(entity.where,
                       "expected nodes here, not the analytic tool " + std::to_string(entity.id));
    case EntityType::FaceSet: {
      const FaceSet& set = face_set(entity);
      for (const SolidFace& f : set.faces) {
        const SolidRef cell = mesh.solid(static_cast<std::size_t>(f.solid));
        const FaceTopology& face = topology(cell.type).faces[static_cast<std::size_t>(f.face)];
        for (int a = 0; a < face.size(); ++a)
          nodes.push_back(cell.nodes[static_cast<std::size_t>(face.nodes[a])]);
      }
      for (const std::int32_t s : set.shells)
        nodes.insert(nodes.end(), mesh.shells[static_cast<std::size_t>(s)].begin(),
                     mesh.shells[static_cast<std::size_t>(s)].end());
      break;
    }
  }
  sort_unique(nodes);
  return nodes;
}

std::vector<std::int32_t> Model::history_nodes() const {
  std::vector<std::int32_t> nodes;
  for (const EntityRef& e : output.history_nodes) {
    const std::vector<std::int32_t> some = nodes_of(e);
    nodes.insert(nodes.end(), some.begin(), some.end());
  }
  sort_unique(nodes);
  return nodes;
}

SourceLocation Model::place_of(const ContactSpec& c, std::string_view setting) const {
  return sources.of(SourceEntity::Contact, c.id, setting, c.where);
}

bool Model::gives(const ContactSpec& c, std::string_view setting) const {
  return sources.given(SourceEntity::Contact, c.id, setting);
}

const RigidTool& Model::tool(const EntityRef& entity) const {
  const RigidTool* t = find_by_id(tools, entity.id);
  if (!t || entity.type != EntityType::Tool)
    throw InputError(entity.where,
                     "tool " + std::to_string(entity.id) + " does not exist (defined tools: " +
                         id_list(tools, [](const RigidTool& r) { return r.id; }) + "; expected " +
                         sources.words("analytic_tool") + " with this id)");
  return *t;
}

const FaceSet& Model::face_set(const EntityRef& entity) const {
  const FaceSet* set = find_by_id(face_sets, entity.id);
  if (!set) {
    throw InputError(entity.where, "face set " + std::to_string(entity.id) +
                                       " does not exist (defined face sets: " +
                                       id_list(face_sets, [](const FaceSet& s) { return s.id; }) +
                                       ")");
  }
  return *set;
}

}  // namespace abut
