#pragma once
// A mesh as Gmsh describes it: nodes, element blocks by geometric entity, physical groups. Read
// from a .msh file of format 4.1, ASCII or binary (read_msh; src/io/gmsh/msh_file.cpp), or taken
// from Gmsh's library after it has meshed a .geo, STEP or BREP file (mesh_cad;
// src/io/gmsh/gmsh_cad.cpp). It knows no deck: the `.k` reader's *INCLUDE_GMSH turns it into parts
// and sets (src/io/keyword_gmsh.cpp).
//
// Format: Gmsh reference manual, section "MSH file format" (version 4.1), Gmsh 4.8.
#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "abut/core/vec3.hpp"
#include "abut/mesh/topology.hpp"

namespace abut::gmsh {

// Where a value was read: the 1-based line of an ASCII file, or the byte offset in a binary
// one's binary sections (line 0). Both 0 for a mesh from Gmsh's library.
struct MshPlace {
  std::size_t line = 0;
  std::size_t byte = 0;
};

// An element type abut knows: Gmsh's number, its dimension and node count, and the abut cell it
// becomes (a solid of that type; a surface element is a face or a shell; lines and points give
// nodes to node sets).
struct GmshElementType {
  int number = 0;
  const char* name = "";
  int dim = 0;
  int nodes = 0;
  std::optional<CellType> cell;  // solids only
};

// The type with Gmsh number `number`, or nullptr for a type abut does not read (pyramids, the
// 15- and 18-node prisms, elements above second order ...).
const GmshElementType* element_type(int number);
// The names of the types abut reads, for messages ("tet4 (4), tet10 (11), ...").
std::string element_type_list();
// For a solid type: abut's node k is Gmsh's node gmsh_node_of[k] (matched by natural
// coordinates: the two orders differ for hex20 and hex27, and in the last two nodes of tet10).
std::span<const std::int8_t> gmsh_node_order(CellType type);

struct MshElementBlock {
  int dim = 0;
  int entity = 0;  // the tag of the geometric entity (dim, entity) the elements lie on
  int type = 0;    // Gmsh element type number, one that element_type() knows
  MshPlace where;  // the block's header
  std::vector<std::int64_t> tags;   // element tags
  std::vector<std::int64_t> nodes;  // node tags, element_type(type)->nodes per element
  std::vector<MshPlace> places;     // each element's place (empty for a library mesh)
  std::size_t size() const { return tags.size(); }
};

struct MshMesh {
  std::string file;  // the file name messages give
  bool binary = false;
  std::vector<std::int64_t> node_tags;
  std::vector<Vec3> coordinates;
  std::vector<MshPlace> node_places;  // of each node's tag; empty for a library mesh
  std::vector<MshElementBlock> blocks;
  // The physical groups of each geometric entity (dim, tag), and their names (dim, group tag);
  // entities without groups are absent.
  std::map<std::pair<int, int>, std::vector<int>> entity_groups;
  std::map<std::pair<int, int>, std::string> group_names;
  std::map<std::pair<int, int>, MshPlace> group_places;  // where each group was first named
};

// What a reader takes from a mesh (src/io/gmsh/gmsh_groups.cpp), the same in every dialect:
//  - the groups of a block: its entity's physical groups; in a mesh without any physical group,
//    the entity itself for volumes and surfaces (Gmsh then saves every element); none otherwise
//    (Gmsh leaves such elements out when it saves);
//  - how messages name a group: "physical volume 2 "ball" of ball.msh", "surface 5 of part.step";
//  - a solid's node tags in abut's order (mesh/topology.hpp), a face element's corner tags (a
//    triangle repeats its third).
std::vector<int> block_groups(const MshMesh& m, const MshElementBlock& block);
std::string group_label(const MshMesh& m, int dim, int tag);
std::vector<std::int64_t> solid_nodes(const MshElementBlock& block, std::size_t e);
std::array<std::int64_t, 4> face_corners(const MshElementBlock& block, std::size_t e);
// Gmsh's name of a group ("" when it has none).
std::string group_name(const MshMesh& m, int dim, int tag);

// Reads a .msh file of format 4.1 held in `bytes`; `file` names it in messages. Every error is an
// InputError at the file and line (ASCII) or byte offset (binary) of the offending value: an
// unsupported version or element type, a truncated section, a node or element given twice, an
// element of a node that does not exist ...
MshMesh read_msh(std::string_view bytes, const std::string& file);
MshMesh read_msh_file(const std::filesystem::path& path);

// What a file is by its extension (any case): a Gmsh mesh (.msh), a file Gmsh meshes (.geo, and
// the CAD files .step, .stp, .brep, .brp, which carry no mesh sizes), or neither.
enum class GmshFile { mesh, geo, cad };
std::optional<GmshFile> gmsh_file_kind(const std::filesystem::path& path);
inline constexpr const char* kGmshFileKinds =
    "a Gmsh mesh (.msh) or a file Gmsh meshes (.geo, .step, .stp, .brep)";

// Meshes a .geo, .step/.stp or .brep file with Gmsh's library and returns the mesh, made on one
// thread (the same mesh on every machine). Gmsh's errors (a .geo syntax error with its line, a CAD
// file it cannot read, a failed meshing) become InputErrors that carry Gmsh's message.
struct CadMeshing {
  double size = 0.0;  // 0: the .geo file's own sizes
  int order = 0;      // 0: the .geo file's own order (1 unless it sets Mesh.ElementOrder)
  // Called before meshing with the estimated element and node counts (given a size): may throw
  // to refuse a mesh that would not fit in memory.
  std::function<void(double elements, double nodes)> check_size;
};
MshMesh mesh_cad(const std::filesystem::path& path, const CadMeshing& meshing);

}  // namespace abut::gmsh
