#include "abut/mesh/skin.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "abut/core/error.hpp"
#include "abut/mesh/shape_functions.hpp"

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
  std::array<std::int32_t, 4> key;  // sorted corners (-1 first for a triangle): equal for the
                                    // two sides of a face
  std::int32_t solid;
  std::int32_t local;
  std::int32_t exposed_by = -1;  // an interior face: the solid on its other side
};

std::array<std::int32_t, 4> face_key(const SolidRef& cell, const FaceTopology& face) {
  std::array<std::int32_t, 4> key{-1, -1, -1, -1};
  const int corners = face_corner_count(face.type);
  for (int k = 0; k < corners; ++k) key[k] = cell.nodes[static_cast<std::size_t>(face.nodes[k])];
  std::sort(key.begin(), key.end());
  return key;
}

// A solid's volume, which must be positive (nodes in the type's order).
double positive_volume(const Mesh& mesh, std::size_t solid) {
  const double volume = solid_volume(mesh, solid);
  const SolidRef cell = mesh.solid(solid);
  if (!(volume > 0.0))
    throw InputError("element " + std::to_string(cell.id) +
                     " has a non-positive volume: expected " +
                     std::string(topology(cell.type).node_order));
  return volume;
}

// The area of a solid's face, through all of its nodes.
double area_of_face(const Mesh& mesh, const SolidRef& cell, const FaceTopology& face) {
  double x[3 * kMaxFaceNodes];
  for (int a = 0; a < face.size(); ++a) {
    const Vec3 p = mesh.nodes.position(static_cast<std::size_t>(cell.nodes[face.nodes[a]]));
    x[3 * a] = p.x, x[3 * a + 1] = p.y, x[3 * a + 2] = p.z;
  }
  return face_area(face.type,
                   std::span<const double>(x, 3 * static_cast<std::size_t>(face.size())));
}

std::vector<SkinFace> extract(const Mesh& mesh, bool all_parts, std::span<const std::int64_t> parts,
                              bool merge, const std::function<bool(std::int32_t)>& erodible) {
  std::vector<std::int64_t> selected(parts.begin(), parts.end());
  std::sort(selected.begin(), selected.end());
  const std::size_t solids = mesh.solid_count();
  std::vector<std::int64_t> part_of(solids);
  for (std::size_t e = 0; e < solids; ++e) part_of[e] = mesh.solid(e).part;
  auto is_selected = [&](std::int32_t solid) {
    return all_parts || std::binary_search(selected.begin(), selected.end(), part_of[solid]);
  };

  // Sorting the faces of all solids by their corners pairs up the two sides of interior faces
  // in O(n log n), deterministically.
  std::vector<FaceRecord> records;
  records.reserve(solids * 6);
  for (std::size_t e = 0; e < solids; ++e) {
    const SolidRef cell = mesh.solid(e);
    const auto& faces = topology(cell.type).faces;
    for (std::size_t local = 0; local < faces.size(); ++local)
      records.push_back({face_key(cell, faces[local]), static_cast<std::int32_t>(e),
                         static_cast<std::int32_t>(local)});
  }
  std::sort(records.begin(), records.end(), [](const FaceRecord& a, const FaceRecord& b) {
    if (a.key != b.key) return a.key < b.key;
    return a.solid != b.solid ? a.solid < b.solid : a.local < b.local;
  });

  std::vector<FaceRecord> kept;
  for (std::size_t i = 0; i < records.size();) {
    std::size_t j = i + 1;
    while (j < records.size() && records[j].key == records[i].key) ++j;
    const std::size_t users = j - i;
    if (users == 1) {
      if (is_selected(records[i].solid)) kept.push_back(records[i]);
    } else if (users == 2 && merge && part_of[records[i].solid] != part_of[records[i + 1].solid]) {
      for (std::size_t k = i; k < j; ++k)
        if (is_selected(records[k].solid)) kept.push_back(records[k]);
    } else if (users == 2 && erodible) {  // each side, exposed when the other one erodes
      for (std::size_t k = i; k < j; ++k) {
        const std::int32_t other = records[k == i ? i + 1 : i].solid;
        if (is_selected(records[k].solid) && erodible(other)) {
          kept.push_back(records[k]);
          kept.back().exposed_by = other;
        }
      }
    }
    i = j;
  }
  std::sort(kept.begin(), kept.end(), [](const FaceRecord& a, const FaceRecord& b) {
    return a.solid != b.solid ? a.solid < b.solid : a.local < b.local;
  });

  std::vector<SkinFace> faces;
  faces.reserve(kept.size());
  std::int32_t volume_of = -1;
  double volume = 0.0;
  for (const FaceRecord& r : kept) {
    if (r.solid != volume_of) {
      volume_of = r.solid;
      volume = positive_volume(mesh, static_cast<std::size_t>(r.solid));
    }
    const std::size_t first = faces.size();
    append_facets(mesh, r.solid, r.local, volume, faces);
    for (std::size_t k = first; k < faces.size(); ++k) faces[k].exposed_by = r.exposed_by;
  }
  return faces;
}

}  // namespace

void append_facets(const Mesh& mesh, std::int32_t solid, int face, double volume,
                   std::vector<SkinFace>& out) {
  const SolidRef cell = mesh.solid(static_cast<std::size_t>(solid));
  const FaceTopology& ft = topology(cell.type).faces[static_cast<std::size_t>(face)];
  if (volume <= 0.0) volume = positive_volume(mesh, static_cast<std::size_t>(solid));
  SkinFace f;
  f.solid = solid;
  f.face = static_cast<std::int8_t>(face);
  f.part = cell.part;
  f.thickness = volume / area_of_face(mesh, cell, ft);
  for (const auto& facet : linear_facets(ft.type)) {
    for (int a = 0; a < 4; ++a)
      f.nodes[a] = cell.nodes[static_cast<std::size_t>(ft.nodes[facet[a]])];
    out.push_back(f);
  }
}

std::vector<SkinFace> exterior_faces(const Mesh& mesh, std::span<const std::int64_t> parts,
                                     bool merge,
                                     const std::function<bool(std::int32_t)>& erodible) {
  return extract(mesh, false, parts, merge, erodible);
}

std::vector<SkinFace> exterior_faces(const Mesh& mesh, bool merge,
                                     const std::function<bool(std::int32_t)>& erodible) {
  return extract(mesh, true, {}, merge, erodible);
}

double solid_volume(const Mesh& mesh, std::size_t solid) {
  const SolidRef cell = mesh.solid(solid);
  if (cell.type == CellType::hex8) return hex_volume(mesh.nodes, mesh.hexes[solid]);
  double X[3 * kMaxCellNodes];
  for (std::size_t a = 0; a < cell.nodes.size(); ++a) {
    const Vec3 p = mesh.nodes.position(static_cast<std::size_t>(cell.nodes[a]));
    X[3 * a] = p.x, X[3 * a + 1] = p.y, X[3 * a + 2] = p.z;
  }
  return cell_volume(cell.type, std::span<const double>(X, 3 * cell.nodes.size()));
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
