#include "abut/solver/curved_faces.hpp"

#include <algorithm>
#include <cmath>

#include "abut/mesh/shape_functions.hpp"

namespace abut {
namespace {

template <FaceType T>
void shape(const double xi[2], double* n) {
  double dn[kMaxFaceNodes][2];
  face_shape_functions(T, xi, n, dn);
}

// The shape functions of a curved face; null for a linear one.
FacetParent::Shape shape_of(FaceType type) {
  switch (type) {
    case FaceType::tri3:
    case FaceType::quad4:
      return nullptr;
    case FaceType::tri6:
      return shape<FaceType::tri6>;
    case FaceType::quad8:
      return shape<FaceType::quad8>;
    case FaceType::quad9:
      return shape<FaceType::quad9>;
    case FaceType::quad16:
      return shape<FaceType::quad16>;
  }
  return nullptr;
}

}  // namespace

CurvedFaces::CurvedFaces(const Mesh& mesh, int divisions) : mesh_(mesh), divisions_(divisions) {
  dependents_.first = static_cast<std::int32_t>(mesh.nodes.size());
}

std::int32_t CurvedFaces::corner(std::span<const std::int32_t> nodes,
                                 std::span<const double> weights) {
  std::vector<std::pair<std::int32_t, std::int64_t>> key;
  for (std::size_t a = 0; a < nodes.size(); ++a)
    key.emplace_back(nodes[a], std::llround(std::ldexp(weights[a], 40)));
  std::sort(key.begin(), key.end());
  const auto it = index_.find(key);
  if (it != index_.end()) return it->second;
  const std::int32_t k = dependents_.add(nodes, weights);
  index_.emplace(std::move(key), k);
  return k;
}

std::vector<SkinFace> CurvedFaces::facets(std::span<const SkinFace> faces,
                                          std::vector<FacetParent>* parents) {
  std::vector<SkinFace> out;
  const auto plain = [&](std::size_t from, std::size_t to) {
    out.insert(out.end(), faces.begin() + static_cast<std::ptrdiff_t>(from),
               faces.begin() + static_cast<std::ptrdiff_t>(to));
    if (parents) parents->resize(out.size());
  };
  for (std::size_t i = 0; i < faces.size();) {
    const SkinFace& f = faces[i];
    if (f.shell >= 0 || f.solid < 0) {
      plain(i, i + 1), ++i;
      continue;
    }
    const SolidRef cell = mesh_.solid(static_cast<std::size_t>(f.solid));
    const FaceTopology& face = topology(cell.type).faces[static_cast<std::size_t>(f.face)];
    std::size_t j = i + 1;  // the facets of the same face
    while (j < faces.size() && faces[j].solid == f.solid && faces[j].face == f.face &&
           faces[j].shell < 0)
      ++j;
    const FacetParent::Shape face_shape = shape_of(face.type);
    if (!face_shape) {
      plain(i, j), i = j;
      continue;
    }
    const FaceSubdivision sub = subdivide_face(face.type, divisions_);
    std::vector<std::int32_t> node_of(sub.corners.size(), -1);
    const auto node_at = [&](std::int32_t c) {
      if (node_of[static_cast<std::size_t>(c)] >= 0) return node_of[static_cast<std::size_t>(c)];
      double n[kMaxFaceNodes], dn[kMaxFaceNodes][2];
      face_shape_functions(face.type, sub.corners[static_cast<std::size_t>(c)].data(), n, dn);
      std::vector<std::int32_t> nodes;
      std::vector<double> weights;
      for (int a = 0; a < face.size(); ++a) {
        if (std::abs(n[a]) < 1e-14) continue;
        nodes.push_back(cell.nodes[static_cast<std::size_t>(face.nodes[a])]);
        weights.push_back(n[a]);
      }
      // A corner at a node of the face is that node.
      const std::int32_t v = nodes.size() == 1 && std::abs(weights[0] - 1.0) < 1e-14
                                 ? nodes[0]
                                 : corner(nodes, weights);
      node_of[static_cast<std::size_t>(c)] = v;
      return v;
    };
    SkinFace g = f;
    FacetParent parent;
    parent.shape = face_shape;
    parent.count = face.size();
    for (int a = 0; a < face.size(); ++a)
      parent.nodes[static_cast<std::size_t>(a)] =
          cell.nodes[static_cast<std::size_t>(face.nodes[a])];
    for (const auto& facet : sub.facets) {
      for (int a = 0; a < 4; ++a) {
        g.nodes[a] = node_at(facet[a]);
        parent.corner_xi[static_cast<std::size_t>(a)] =
            sub.corners[static_cast<std::size_t>(facet[a])];
      }
      out.push_back(g);
      if (parents) parents->push_back(parent);
    }
    i = j;
  }
  return out;
}

}  // namespace abut
