#include "abut/mesh/skin.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "abut/core/error.hpp"

namespace abut {
namespace {

// Reference coordinates of the hex nodes.
constexpr std::array<std::array<double, 3>, 8> kHexCorners{{
    {-1, -1, -1},
    {1, -1, -1},
    {1, 1, -1},
    {-1, 1, -1},
    {-1, -1, 1},
    {1, -1, 1},
    {1, 1, 1},
    {-1, 1, 1},
}};

struct FaceRecord {
  std::array<std::int32_t, 4> key;  // sorted node indices: equal for the two sides of a face
  std::int32_t hex;
  std::int32_t local;
  std::int32_t exposed_by = -1;  // an interior face: the hex on its other side
};

std::array<std::int32_t, 4> face_nodes(const Hex8& hex, int local) {
  std::array<std::int32_t, 4> f{};
  for (int k = 0; k < 4; ++k) f[k] = hex[kHexFaces[local][k]];
  return f;
}

std::vector<SkinFace> extract(const Mesh& mesh, bool all_parts, std::span<const std::int64_t> parts,
                              bool merge, const std::function<bool(std::int32_t)>& erodible) {
  // Faces of the other cell types are not in the skin yet: a hexahedron's face shared with one
  // of them would pass for exterior. Say so rather than build a wrong surface.
  if (!mesh.cells.empty()) {
    throw InputError("surfaces (contact, pressure) on a mesh with " +
                     std::string(topology(mesh.cells.front().type).abaqus) +
                     " elements are not supported yet: only meshes of "
                     "8-node hexahedra and shells have them");
  }
  std::vector<std::int64_t> selected(parts.begin(), parts.end());
  std::sort(selected.begin(), selected.end());
  auto is_selected = [&](std::int32_t hex) {
    return all_parts || std::binary_search(selected.begin(), selected.end(), mesh.hex_part[hex]);
  };

  // Sorting the faces of all hexes by their node set pairs up the two sides of interior faces
  // in O(n log n), deterministically.
  std::vector<FaceRecord> records;
  records.reserve(mesh.hexes.size() * 6);
  for (std::size_t h = 0; h < mesh.hexes.size(); ++h) {
    for (int local = 0; local < 6; ++local) {
      auto key = face_nodes(mesh.hexes[h], local);
      std::sort(key.begin(), key.end());
      records.push_back({key, static_cast<std::int32_t>(h), local});
    }
  }
  std::sort(records.begin(), records.end(), [](const FaceRecord& a, const FaceRecord& b) {
    if (a.key != b.key) return a.key < b.key;
    return a.hex != b.hex ? a.hex < b.hex : a.local < b.local;
  });

  std::vector<FaceRecord> kept;
  for (std::size_t i = 0; i < records.size();) {
    std::size_t j = i + 1;
    while (j < records.size() && records[j].key == records[i].key) ++j;
    const std::size_t users = j - i;
    if (users == 1) {
      if (is_selected(records[i].hex)) kept.push_back(records[i]);
    } else if (users == 2 && merge &&
               mesh.hex_part[records[i].hex] != mesh.hex_part[records[i + 1].hex]) {
      for (std::size_t k = i; k < j; ++k)
        if (is_selected(records[k].hex)) kept.push_back(records[k]);
    } else if (users == 2 && erodible) {  // each side, exposed when the other one erodes
      for (std::size_t k = i; k < j; ++k) {
        const std::int32_t other = records[k == i ? i + 1 : i].hex;
        if (is_selected(records[k].hex) && erodible(other)) {
          kept.push_back(records[k]);
          kept.back().exposed_by = other;
        }
      }
    }
    i = j;
  }
  std::sort(kept.begin(), kept.end(), [](const FaceRecord& a, const FaceRecord& b) {
    return a.hex != b.hex ? a.hex < b.hex : a.local < b.local;
  });

  std::vector<SkinFace> faces;
  faces.reserve(kept.size());
  std::int32_t volume_of = -1;
  double volume = 0.0;
  for (const FaceRecord& r : kept) {
    if (r.hex != volume_of) {
      volume_of = r.hex;
      volume = hex_volume(mesh.nodes, mesh.hexes[r.hex]);
      if (!(volume > 0.0))
        throw InputError("element " + std::to_string(mesh.hex_id[r.hex]) +
                         " has a non-positive volume: expected nodes n1-n4 counter-clockwise on "
                         "the bottom face seen from above, n5-n8 above them");
    }
    SkinFace f;
    f.nodes = face_nodes(mesh.hexes[r.hex], r.local);
    f.hex = r.hex;
    f.part = mesh.hex_part[r.hex];
    f.thickness = volume / quad_area(mesh.nodes, f.nodes);
    f.exposed_by = r.exposed_by;
    faces.push_back(f);
  }
  return faces;
}

}  // namespace

std::vector<SkinFace> exterior_faces(const Mesh& mesh, std::span<const std::int64_t> parts,
                                     bool merge,
                                     const std::function<bool(std::int32_t)>& erodible) {
  return extract(mesh, false, parts, merge, erodible);
}

std::vector<SkinFace> exterior_faces(const Mesh& mesh, bool merge,
                                     const std::function<bool(std::int32_t)>& erodible) {
  return extract(mesh, true, {}, merge, erodible);
}

double hex_volume(const Nodes& nodes, const Hex8& hex) {
  const double g = 1.0 / std::sqrt(3.0);
  double volume = 0.0;
  for (int q = 0; q < 8; ++q) {
    const double r[3] = {(q & 1) ? g : -g, (q & 2) ? g : -g, (q & 4) ? g : -g};
    double jac[3][3] = {};  // jac[i][k] = d x_i / d r_k
    for (int a = 0; a < 8; ++a) {
      const auto& c = kHexCorners[a];
      const double n0 = 1.0 + c[0] * r[0], n1 = 1.0 + c[1] * r[1], n2 = 1.0 + c[2] * r[2];
      const double dn[3] = {c[0] * n1 * n2 / 8.0, n0 * c[1] * n2 / 8.0, n0 * n1 * c[2] / 8.0};
      const double x[3] = {nodes.x[hex[a]], nodes.y[hex[a]], nodes.z[hex[a]]};
      for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k) jac[i][k] += x[i] * dn[k];
    }
    volume += jac[0][0] * (jac[1][1] * jac[2][2] - jac[1][2] * jac[2][1]) -
              jac[0][1] * (jac[1][0] * jac[2][2] - jac[1][2] * jac[2][0]) +
              jac[0][2] * (jac[1][0] * jac[2][1] - jac[1][1] * jac[2][0]);
  }
  return volume;  // unit Gauss weights
}

double quad_area(const Nodes& nodes, const std::array<std::int32_t, 4>& quad) {
  constexpr double cx[4] = {-1, 1, 1, -1}, cy[4] = {-1, -1, 1, 1};
  const double g = 1.0 / std::sqrt(3.0);
  double area = 0.0;
  for (int q = 0; q < 4; ++q) {
    const double xi = (q & 1) ? g : -g, eta = (q & 2) ? g : -g;
    Vec3 d_xi, d_eta;
    for (int a = 0; a < 4; ++a) {
      const Vec3 p = nodes.position(quad[a]);
      d_xi += p * (cx[a] * (1.0 + cy[a] * eta) / 4.0);
      d_eta += p * (cy[a] * (1.0 + cx[a] * xi) / 4.0);
    }
    area += norm(cross(d_xi, d_eta));
  }
  return area;
}

}  // namespace abut
