// *INCLUDE, INPUT=mesh.msh (or a .geo, STEP or BREP file, meshed as it is read): a Gmsh mesh in
// an .inp deck (docs/inp-reference.md). Its nodes and solids become *NODE and *ELEMENT records,
// its physical groups named sets, as Gmsh's own .inp export names them: a physical volume is an
// element set (for *SOLID SECTION), a physical surface an element-based *SURFACE (its faces
// matched to the solids' faces, S1..Sn) and a node set, a physical point or curve a node set. A
// group's name is its Gmsh name, or PhysicalVolume<tag>, PhysicalSurface<tag> ... without one;
// in a mesh without physical groups, Volume<tag> and Surface<tag>. SIZE= and ORDER= (abut's own
// parameters) mesh a CAD file as `*INCLUDE_GMSH`'s h and order do.
#include <algorithm>
#include <map>
#include <set>

#include "abut/io/gmsh_mesh.hpp"
#include "inp_reader.hpp"
#include "io/deck_text.hpp"
#include "io/memory_budget.hpp"

namespace abut::inp {
namespace {

std::string set_name(const gmsh::MshMesh& m, int dim, int tag) {
  const std::string name = gmsh::group_name(m, dim, tag);
  if (!name.empty()) return name;
  static const char* const kinds[] = {"Point", "Line", "Surface", "Volume"};
  return std::string(m.entity_groups.empty() ? "" : "Physical") + kinds[dim] + std::to_string(tag);
}

using Corners = std::array<std::int64_t, 4>;

Corners sorted_corners(Corners c) {
  std::sort(c.begin(), c.end());
  const auto end = std::unique(c.begin(), c.end());
  std::fill(end, c.end(), -1);
  return c;
}

}  // namespace

void read_gmsh_include(Reader& r, const Card& c) {
  check_parameters(r, c, {{"INPUT"}, {"SIZE"}, {"ORDER"}});
  const std::string path = required_parameter(r, c, "INPUT");
  const gmsh::GmshFile kind = *gmsh::gmsh_file_kind(path);
  gmsh::CadMeshing meshing;
  if (const auto size = parameter_value(c, "SIZE")) {
    const auto h = inp_number(*size);
    if (!h || !(*h > 0.0))
      throw InputError(r.where(c, "SIZE"), "expected a mesh size > 0, got '" + *size + "'");
    meshing.size = *h;
  }
  if (const auto order = parameter_value(c, "ORDER")) {
    if (*order != "1" && *order != "2")
      throw InputError(r.where(c, "ORDER"),
                       "expected the element order 1 or 2, got '" + *order + "'");
    meshing.order = *order == "2" ? 2 : 1;
  }
  if (kind == gmsh::GmshFile::mesh && (meshing.size > 0.0 || meshing.order > 0))
    throw InputError(r.where(c, meshing.size > 0.0 ? "SIZE" : "ORDER"),
                     "a .msh file is meshed already: SIZE and ORDER are for .geo, STEP and BREP "
                     "files");
  if (kind == gmsh::GmshFile::cad && meshing.size == 0.0)
    throw InputError(r.where(c, "SIZE"),
                     "a STEP or BREP file has no mesh sizes: give SIZE=h, the element size");
  // Before Gmsh meshes: would the deck's mesh so far and the CAD part's fit in memory (as
  // *INCLUDE_GMSH h, keyword_gmsh.cpp)?
  meshing.check_size = [&r, &c](double elements, double nodes) {
    deck::require_memory({static_cast<double>(r.elements.size()) + elements,
                          static_cast<double>(r.node_where.size()) + nodes},
                         deck::available_memory(), r.where(c, "SIZE"));
  };
  gmsh::MshMesh m;
  try {
    m = kind == gmsh::GmshFile::mesh ? gmsh::read_msh_file(path) : gmsh::mesh_cad(path, meshing);
  } catch (const InputError& e) {
    // A .msh error is at its line, a memory refusal at SIZE; Gmsh's own at the file's name.
    if (kind == gmsh::GmshFile::mesh || !e.where().file.empty()) throw;
    throw InputError(r.where(c, "INPUT"), e.message());
  }
  // The mesh's file is the last one read (InpLines::include added it).
  const std::uint32_t file = r.file_index(m.file);
  const auto loc = [&](const gmsh::MshPlace& p) {
    return p.line > 0 ? Loc{file, static_cast<std::uint32_t>(p.line)} : r.loc(c);
  };
  const auto element_loc = [&](const gmsh::MshElementBlock& b, std::size_t e) {
    return b.places.empty() ? r.loc(c) : loc(b.places[e]);
  };

  // Solids and the nodes they and the grouped lower elements use.
  std::set<std::int64_t> used;
  std::map<Corners, std::pair<std::int64_t, std::int8_t>> solid_faces;  // corners -> element, face
  for (const gmsh::MshElementBlock& b : m.blocks) {
    const std::vector<int> groups = gmsh::block_groups(m, b);
    if (groups.empty()) continue;
    used.insert(b.nodes.begin(), b.nodes.end());
    if (b.dim != 3) continue;
    const CellType type = *gmsh::element_type(b.type)->cell;
    const CellTopology& t = topology(type);
    for (const int g : groups) {
      IdSet& set = r.element_set(set_name(m, 3, g), loc(b.where));
      set.ids.insert(set.ids.end(), b.tags.begin(), b.tags.end());
      for (std::size_t e = 0; e < b.size(); ++e) set.where.push_back(element_loc(b, e));
    }
    for (std::size_t e = 0; e < b.size(); ++e) {
      ElementRecord record;
      record.id = b.tags[e];
      record.type = type;
      record.where = element_loc(b, e);
      const std::vector<std::int64_t> nodes = gmsh::solid_nodes(b, e);
      std::copy(nodes.begin(), nodes.end(), record.nodes.begin());
      if (!r.element_index.emplace(record.id, r.elements.size()).second)
        throw InputError(r.where(record.where, "$Elements"),
                         "element " + std::to_string(record.id) + " is already defined");
      r.elements.push_back(record);
      for (std::size_t f = 0; f < t.faces.size(); ++f) {
        const FaceTopology& face = t.faces[f];
        const int corners = face_corner_count(face.type);
        Corners key{};
        for (int a = 0; a < 4; ++a)
          key[static_cast<std::size_t>(a)] =
              nodes[static_cast<std::size_t>(face.nodes[std::min(a, corners - 1)])];
        solid_faces.emplace(sorted_corners(key),
                            std::make_pair(record.id, static_cast<std::int8_t>(f)));
      }
    }
  }
  for (std::size_t k = 0; k < m.node_tags.size(); ++k) {
    const std::int64_t id = m.node_tags[k];
    if (!used.count(id)) continue;
    const Loc at = m.node_places.empty() ? r.loc(c) : loc(m.node_places[k]);
    const auto [it, inserted] =
        r.node_index.emplace(id, static_cast<std::int32_t>(r.model.mesh.nodes.size()));
    if (!inserted)
      throw InputError(r.where(at, "$Nodes"),
                       "node " + std::to_string(id) + " is already defined at " +
                           r.at(r.node_where[static_cast<std::size_t>(it->second)]));
    r.model.mesh.nodes.add(id, m.coordinates[k]);
    r.node_where.push_back(at);
  }

  // Surfaces and node sets.
  std::set<std::size_t> made;  // the surfaces this mesh defines (its groups span several blocks)
  for (const gmsh::MshElementBlock& b : m.blocks) {
    if (b.dim == 3) continue;
    for (const int g : gmsh::block_groups(m, b)) {
      const std::string name = set_name(m, b.dim, g);
      IdSet& nodes = r.node_set(name, loc(b.where));
      const auto per = static_cast<std::size_t>(gmsh::element_type(b.type)->nodes);
      for (std::size_t e = 0; e < b.size(); ++e) {
        for (std::size_t k = 0; k < per; ++k) {
          nodes.ids.push_back(b.nodes[e * per + k]);
          nodes.where.push_back(element_loc(b, e));
        }
      }
      if (b.dim != 2) continue;
      auto [it, inserted] = r.surface_names.emplace(upper_name(name), r.surfaces.size());
      if (inserted) {
        SurfaceRecord s;
        s.name = name;
        s.defined = loc(b.where);
        r.surfaces.push_back(s);
        made.insert(it->second);
      } else if (!made.count(it->second)) {
        throw InputError(r.where(c, "INPUT"), gmsh::group_label(m, 2, g) + " is surface " + name +
                                                  ", which is already defined at " +
                                                  r.at(r.surfaces[it->second].defined));
      }
      SurfaceRecord& surface = r.surfaces[it->second];
      for (std::size_t e = 0; e < b.size(); ++e) {
        const auto face = solid_faces.find(sorted_corners(gmsh::face_corners(b, e)));
        if (face == solid_faces.end())
          throw InputError(r.where(element_loc(b, e), "$Elements"),
                           "element " + std::to_string(b.tags[e]) + " of " +
                               gmsh::group_label(m, 2, g) +
                               " lies on no face of the mesh's solids: an .inp surface is made of "
                               "solid faces");
        surface.items.push_back({face->second.first, "", element_loc(b, e)});
        surface.faces.push_back(face->second.second);
      }
    }
  }
}

}  // namespace abut::inp
