// *SET_FACE on the final mesh: each row's corner nodes matched to the one solid face or shell
// they bound. A face set holds faces where surfaces act (contact, pressure, heat): on the
// exterior of the mesh, so a face between two solids, a face that is also a shell, or corners
// that bound no face are errors at the row, saying which.
#include <algorithm>
#include <map>
#include <string>

#include "deck_reader.hpp"

namespace abut::deck {
namespace {

// A face by its distinct corner nodes, sorted (a triangle's fourth slot is -1).
using Corners = std::array<std::int32_t, 4>;

Corners corners_key(std::array<std::int32_t, 4> nodes) {
  std::sort(nodes.begin(), nodes.end());
  const auto end = std::unique(nodes.begin(), nodes.end());
  Corners key{-1, -1, -1, -1};
  std::copy(nodes.begin(), end, key.begin());
  return key;
}

struct FaceIndex {
  std::map<Corners, std::vector<SolidFace>> solids;
  std::map<Corners, std::vector<std::int32_t>> shells;

  explicit FaceIndex(const Mesh& mesh) {
    for (std::size_t e = 0; e < mesh.solid_count(); ++e) {
      const SolidRef cell = mesh.solid(e);
      const CellTopology& t = topology(cell.type);
      for (std::size_t f = 0; f < t.faces.size(); ++f) {
        const FaceTopology& face = t.faces[f];
        std::array<std::int32_t, 4> nodes{};
        const int corners = face_corner_count(face.type);
        for (int a = 0; a < 4; ++a)
          nodes[static_cast<std::size_t>(a)] =
              cell.nodes[static_cast<std::size_t>(face.nodes[std::min(a, corners - 1)])];
        solids[corners_key(nodes)].push_back(
            {static_cast<std::int32_t>(e), static_cast<std::int8_t>(f)});
      }
    }
    for (std::size_t s = 0; s < mesh.shell_count(); ++s)
      shells[corners_key(mesh.shells[s])].push_back(static_cast<std::int32_t>(s));
  }
};

}  // namespace

void DeckReader::resolve_face_sets() {
  if (face_sets.empty()) return;
  const Mesh& mesh = model.mesh;
  const FaceIndex index(mesh);
  const bool remeshed = !orders.empty() || !tetrahedra.empty();
  for (const PendingFaceSet& pending : face_sets) {
    FaceSet& set = model.face_sets[pending.index];
    for (const PendingFaceSet::Face& face : pending.faces) {
      std::string listed;
      std::array<std::int32_t, 4> nodes{};
      for (std::size_t a = 0; a < 4; ++a) {
        std::int64_t id = face.nodes[a];
        // A node that *MERGE_DUPLICATED_NODES removed stands for the one it was merged into.
        if (const auto merged = merged_nodes_.find(id); merged != merged_nodes_.end())
          id = merged->second.first;
        nodes[a] = node_index(id);
        if (nodes[a] < 0)
          throw InputError(face.where, "node " + std::to_string(face.nodes[a]) + " does not exist");
        if (a < 3 || face.nodes[3] != face.nodes[2])
          listed += (listed.empty() ? "" : ", ") + std::to_string(face.nodes[a]);
      }
      const Corners key = corners_key(nodes);
      if (key[2] < 0)
        throw InputError(face.where, "face (" + listed +
                                         ") has fewer than 3 distinct corner nodes: a face is a "
                                         "triangle or a quadrilateral");
      const auto solids = index.solids.find(key);
      const auto shells = index.shells.find(key);
      const std::size_t n_solids = solids == index.solids.end() ? 0 : solids->second.size();
      const std::size_t n_shells = shells == index.shells.end() ? 0 : shells->second.size();
      const std::string what = "face (" + listed + ")";
      if (n_solids > 1)
        throw InputError(face.where, what +
                                         " lies between two solid elements, inside the mesh: "
                                         "a face set holds faces on its exterior, where "
                                         "contact, pressure and heat loads act");
      if (n_solids == 1 && n_shells > 0)
        throw InputError(face.where, what +
                                         " is both a solid element's face and a shell: which "
                                         "one the set means is not clear (give the shell's "
                                         "part or the solid's faces only)");
      if (n_shells > 1)
        throw InputError(face.where, what +
                                         " is the corners of several coincident shells: "
                                         "which one the set means is not clear");
      if (n_solids == 1) {
        set.faces.push_back(solids->second.front());
      } else if (n_shells == 1) {
        set.shells.push_back(shells->second.front());
      } else {
        throw InputError(
            face.where,
            what +
                " does not bound a solid element or a shell: its nodes are not the corners of "
                "one face" +
                (remeshed ? " (*CHANGE_P-ORDER and *CHANGE_TO_TETRAHEDRA re-mesh the faces of "
                            "their parts: a face set on such a part is not supported yet)"
                          : std::string()));
      }
    }
    // Each face once, in solid and face order (the order of a part's exterior faces).
    std::sort(set.faces.begin(), set.faces.end(), [](const SolidFace& a, const SolidFace& b) {
      return a.solid != b.solid ? a.solid < b.solid : a.face < b.face;
    });
    set.faces.erase(std::unique(set.faces.begin(), set.faces.end(),
                                [](const SolidFace& a, const SolidFace& b) {
                                  return a.solid == b.solid && a.face == b.face;
                                }),
                    set.faces.end());
    std::sort(set.shells.begin(), set.shells.end());
    set.shells.erase(std::unique(set.shells.begin(), set.shells.end()), set.shells.end());
  }
}

}  // namespace abut::deck
