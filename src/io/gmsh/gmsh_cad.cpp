// Meshing a .geo, STEP or BREP file with Gmsh's library (Debian libgmsh-dev, Gmsh 4.8; API:
// gmsh.h) and taking the mesh as a MshMesh, as if it had been saved and read back.
#include <gmsh.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

#include "abut/core/error.hpp"
#include "abut/io/gmsh_mesh.hpp"

namespace abut::gmsh {
namespace {

// Gmsh's library holds one model in global state: one meshing at a time.
std::mutex& gmsh_mutex() {
  static std::mutex m;
  return m;
}

// initialize() on entry, finalize() on every way out.
struct GmshSession {
  GmshSession() {
    ::gmsh::initialize(0, nullptr, /*readConfigFiles=*/false);
    // Messages are collected, not printed. Errors are only logged (General.AbortOnError = 0;
    // the API's default 2 throws): Gmsh 4.8 throws out of its .geo parser before it flushes its
    // lexer, and the next file read in the process then starts with the rest of the broken one.
    // mesh_cad looks at the log after each step instead.
    ::gmsh::option::setNumber("General.Terminal", 0);
    ::gmsh::option::setNumber("General.AbortOnError", 0);
    ::gmsh::logger::start();
  }
  ~GmshSession() {
    try {
      ::gmsh::logger::stop();
      ::gmsh::finalize();
    } catch (...) {
    }
  }
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;

  // Gmsh's error messages of this session, one per line ("Error: ..." prefixes removed).
  static std::string errors() {
    std::vector<std::string> log;
    ::gmsh::logger::get(log);
    std::string s;
    for (const std::string& l : log) {
      if (l.rfind("Error", 0) != 0) continue;
      std::string text = l.substr(std::min(l.size(), l.find(':') + 1));
      while (!text.empty() && text.front() == ' ') text.erase(0, 1);
      s += (s.empty() ? "" : "; ") + text;
    }
    return s;
  }
};

// About 6 tetrahedra per cube of side h (a cube cut into 6 tetrahedra; Delaunay meshes of
// size h come close), over the bounding box of the model: an upper estimate for a solid that does
// not fill its box.
double estimated_elements(double h) {
  double x0 = 0, y0 = 0, z0 = 0, x1 = 0, y1 = 0, z1 = 0;
  ::gmsh::model::getBoundingBox(-1, -1, x0, y0, z0, x1, y1, z1);
  const auto cells = [h](double a, double b) { return std::max(1.0, (b - a) / h); };
  return 6.0 * cells(x0, x1) * cells(y0, y1) * cells(z0, z1);
}

// Gmsh's logged errors (they name a .geo file's line), else what it threw.
[[noreturn]] void fail(const SourceLocation& where, const std::string& thrown) {
  std::string message = GmshSession::errors();
  if (message.empty()) message = thrown.empty() ? "an unknown error" : thrown;
  throw InputError(where, "Gmsh could not mesh the file: " + message);
}

void take_mesh(MshMesh& m) {
  std::vector<std::size_t> node_tags;
  std::vector<double> xyz, parametric;
  ::gmsh::model::mesh::getNodes(node_tags, xyz, parametric, -1, -1, false, false);
  m.node_tags.reserve(node_tags.size());
  for (std::size_t k = 0; k < node_tags.size(); ++k) {
    m.node_tags.push_back(static_cast<std::int64_t>(node_tags[k]));
    m.coordinates.push_back({xyz[3 * k], xyz[3 * k + 1], xyz[3 * k + 2]});
  }
  ::gmsh::vectorpair entities;
  ::gmsh::model::getEntities(entities);
  for (const auto& [dim, tag] : entities) {
    std::vector<int> groups;
    ::gmsh::model::getPhysicalGroupsForEntity(dim, tag, groups);
    if (!groups.empty()) m.entity_groups[{dim, tag}] = groups;
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> element_tags, element_nodes;
    ::gmsh::model::mesh::getElements(types, element_tags, element_nodes, dim, tag);
    for (std::size_t t = 0; t < types.size(); ++t) {
      const GmshElementType* type = element_type(types[t]);
      if (!type) {
        throw InputError(SourceLocation{m.file, 0, "", ""},
                         "Gmsh made elements of type " + std::to_string(types[t]) +
                             ", which abut does not read (it reads " + element_type_list() + ")");
      }
      MshElementBlock block;
      block.dim = dim;
      block.entity = tag;
      block.type = types[t];
      for (const std::size_t e : element_tags[t])
        block.tags.push_back(static_cast<std::int64_t>(e));
      for (const std::size_t n : element_nodes[t])
        block.nodes.push_back(static_cast<std::int64_t>(n));
      m.blocks.push_back(std::move(block));
    }
  }
  ::gmsh::vectorpair groups;
  ::gmsh::model::getPhysicalGroups(groups);
  for (const auto& [dim, tag] : groups) {
    std::string name;
    ::gmsh::model::getPhysicalName(dim, tag, name);
    if (!name.empty()) m.group_names[{dim, tag}] = name;
  }
}

}  // namespace

std::optional<GmshFile> gmsh_file_kind(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".msh") return GmshFile::mesh;
  if (ext == ".geo") return GmshFile::geo;
  if (ext == ".step" || ext == ".stp" || ext == ".brep" || ext == ".brp") return GmshFile::cad;
  return std::nullopt;
}

MshMesh mesh_cad(const std::filesystem::path& path, const CadMeshing& meshing) {
  MshMesh m;
  m.file = path.string();
  const SourceLocation where{m.file, 0, "", ""};
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw InputError(where, "cannot open the file");
  const std::lock_guard<std::mutex> lock(gmsh_mutex());
  GmshSession session;
  try {
    // One thread: the same mesh on every machine.
    ::gmsh::option::setNumber("General.NumThreads", 1);
    ::gmsh::option::setNumber("Mesh.MaxNumThreads1D", 1);
    ::gmsh::option::setNumber("Mesh.MaxNumThreads2D", 1);
    ::gmsh::option::setNumber("Mesh.MaxNumThreads3D", 1);
    ::gmsh::open(path.string());
    if (!GmshSession::errors().empty()) throw std::runtime_error("");
    if (meshing.order > 0) ::gmsh::option::setNumber("Mesh.ElementOrder", meshing.order);
    if (meshing.size > 0.0) {
      // h is the element size: Gmsh's sizes at the geometry's points (a .geo's lc, the
      // defaults of OpenCASCADE shapes, about 1/10 of their extent) would otherwise win below it.
      ::gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
      ::gmsh::option::setNumber("Mesh.MeshSizeMax", meshing.size);
      if (meshing.check_size) {
        // A tetrahedral mesh has about a fifth as many vertices as tetrahedra; order 2 adds
        // about one midside node per element.
        const double elements = estimated_elements(meshing.size);
        meshing.check_size(elements, elements * (meshing.order == 2 ? 1.4 : 0.2));
      }
    }
    ::gmsh::model::mesh::generate(3);
    if (!GmshSession::errors().empty()) throw std::runtime_error("");
    take_mesh(m);
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    fail(where, e.what());
  } catch (const std::string& e) {  // what Gmsh 4.8 throws on an error (General.AbortOnError = 2)
    fail(where, e);
  } catch (...) {
    fail(where, "");
  }
  return m;
}

}  // namespace abut::gmsh
