#pragma once
// A *SET_FACE (issue 33) listing the exterior faces of parts of a model by their corner node ids,
// for the tests that compare a face-set surface with the whole part.
#include <cstdint>
#include <string>
#include <vector>

#include "abut/mesh/skin.hpp"

namespace abut::verification {

// `*SET_FACE` setid, one row per exterior face of `parts` (skin.hpp order).
inline std::string skin_face_set(const Mesh& mesh, const std::vector<std::int64_t>& parts,
                                 std::int64_t setid) {
  std::string rows = "*SET_FACE\n" + std::to_string(setid) + "\n";
  for (const SkinFace& f : exterior_faces(mesh, parts, false)) {
    for (int a = 0; a < 4; ++a)
      rows += (a ? ", " : "") + std::to_string(mesh.nodes.id[static_cast<std::size_t>(f.nodes[a])]);
    rows += "\n";
  }
  return rows;
}

}  // namespace abut::verification
