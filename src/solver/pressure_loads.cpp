#include "abut/solver/pressure_loads.hpp"

#include <algorithm>
#include <string>

#include "abut/core/error.hpp"
#include "abut/mesh/skin.hpp"
#include "abut/model/entity_name.hpp"

namespace abut {
namespace {

// A hex face with repeated nodes (a hex collapsed into a wedge or a pyramid): with three distinct
// nodes and the repeated ones adjacent it is the triangle of the remaining nodes, in the same
// circular order (so the same normal), written (a, b, c, c). Anything else has no area.
bool normalise_face(Quad4& q) {
  int distinct = 0;
  for (int a = 0; a < 4; ++a)
    if (std::find(q.begin(), q.begin() + a, q[a]) == q.begin() + a) ++distinct;
  if (distinct == 4) return true;
  if (distinct < 3) return false;
  for (int k = 0; k < 4; ++k) {
    if (q[k] == q[(k + 1) % 4]) {
      const std::int32_t a = q[(k + 1) % 4], b = q[(k + 2) % 4], c = q[(k + 3) % 4];
      q = {a, b, c, c};
      return true;
    }
  }
  return false;  // q1 == q3 or q2 == q4: a quad folded onto its diagonal
}

// The skin's own errors (a hex of non-positive volume) have no deck line: give them the load's.
template <class Extract>
std::vector<SkinFace> located_skin(const PressureLoad& load, const Extract& extract) {
  try {
    return extract();
  } catch (const InputError& e) {
    if (!e.where().file.empty()) throw;
    throw InputError(load.entity.where, e.message());
  }
}

// The exterior solid faces and the shells (one flag per shell) of the entity of `load`.
void select_faces(const Model& model, const PressureLoad& load, std::vector<SkinFace>& skin,
                  std::vector<std::uint8_t>& shell_selected) {
  const Mesh& mesh = model.mesh;
  shell_selected.assign(mesh.shell_count(), 0);
  if (load.entity.type == EntityType::GeometryRegion) {
    // nodes_of tests the reference coordinates against the region (and checks that it exists).
    const std::vector<std::int32_t> inside = model.nodes_of(load.entity);
    const auto in_region = [&](const Quad4& q) {
      return std::all_of(q.begin(), q.end(), [&](std::int32_t node) {
        return std::binary_search(inside.begin(), inside.end(), node);
      });
    };
    for (SkinFace& f : located_skin(load, [&] { return exterior_faces(mesh, false); }))
      if (in_region(f.nodes)) skin.push_back(f);
    for (std::size_t s = 0; s < mesh.shell_count(); ++s)
      shell_selected[s] = in_region(mesh.shells[s]) ? 1 : 0;
  } else if (load.entity.type == EntityType::FaceSet) {
    const FaceSet& set = model.face_set(load.entity);
    skin = located_skin(load, [&] {
      std::vector<SkinFace> faces;
      for (const SolidFace& f : set.faces) append_facets(mesh, f.solid, f.face, 0.0, faces);
      return faces;
    });
    for (const std::int32_t s : set.shells) shell_selected[static_cast<std::size_t>(s)] = 1;
  } else {
    std::vector<std::int64_t> parts = model.parts_of(load.entity);  // sorted for P, PS, ALL
    std::sort(parts.begin(), parts.end());
    // Faces between two parts that share nodes are interior: no pressure acts there.
    skin = located_skin(load, [&] { return exterior_faces(mesh, parts, false); });
    for (std::size_t s = 0; s < mesh.shell_count(); ++s)
      shell_selected[s] = std::binary_search(parts.begin(), parts.end(), mesh.shell_part[s]);
  }
}

[[noreturn]] void no_faces(const PressureLoad& load) {
  throw InputError(load.entity.where, entity_name(load.entity) +
                                          " has no exterior face of a solid element and no "
                                          "shell element to carry the pressure");
}

}  // namespace

std::vector<Quad4> pressure_faces(const Model& model, const PressureLoad& load) {
  const Mesh& mesh = model.mesh;
  std::vector<SkinFace> skin;
  std::vector<std::uint8_t> shell_selected;
  select_faces(model, load, skin, shell_selected);

  std::vector<Quad4> faces;
  faces.reserve(skin.size());
  for (const SkinFace& f : skin) {
    Quad4 q = f.nodes;
    if (normalise_face(q)) faces.push_back(q);
  }
  for (std::size_t s = 0; s < mesh.shell_count(); ++s)
    if (shell_selected[s]) faces.push_back(mesh.shells[s]);
  if (faces.empty()) no_faces(load);
  return faces;
}

PressureSolidFaces pressure_solid_faces(const Model& model, const PressureLoad& load) {
  const Mesh& mesh = model.mesh;
  std::vector<SkinFace> skin;
  std::vector<std::uint8_t> shell_selected;
  select_faces(model, load, skin, shell_selected);
  PressureSolidFaces out;
  for (std::size_t s = 0; s < mesh.shell_count(); ++s)
    if (shell_selected[s]) out.shells.push_back(static_cast<std::int32_t>(s));
  for (const SkinFace& f : skin) {
    Quad4 q = f.nodes;
    if (!normalise_face(q)) continue;  // no area, as in pressure_faces
    // A quadratic face comes as several facets: load the face once.
    const SolidFace face{f.solid, f.face};
    if (out.faces.empty() || out.faces.back().solid != face.solid ||
        out.faces.back().face != face.face)
      out.faces.push_back(face);
  }
  if (out.faces.empty() && out.shells.empty()) no_faces(load);
  return out;
}

Vec3 face_vector_area(const Quad4& face, std::span<const double> x, std::span<const double> y,
                      std::span<const double> z) {
  const auto p = [&](std::int32_t i) {
    const auto k = static_cast<std::size_t>(i);
    return Vec3{x[k], y[k], z[k]};
  };
  return 0.5 * cross(p(face[2]) - p(face[0]), p(face[3]) - p(face[1]));
}

PressureLoads::PressureLoads(const Model& model) : model_(&model) {
  for (const PressureLoad& load : model.pressures) {
    Surface s;
    s.source = &load;
    s.faces = pressure_faces(model, load);
    for (const Quad4& q : s.faces) loaded_nodes_.insert(loaded_nodes_.end(), q.begin(), q.end());
    loads_.push_back(std::move(s));
  }
  std::sort(loaded_nodes_.begin(), loaded_nodes_.end());
  loaded_nodes_.erase(std::unique(loaded_nodes_.begin(), loaded_nodes_.end()), loaded_nodes_.end());
  const std::size_t n = model.mesh.nodes.size();
  fx_.assign(n, 0.0);
  fy_.assign(n, 0.0);
  fz_.assign(n, 0.0);
}

void PressureLoads::add_forces(double t, std::span<const double> x, std::span<const double> y,
                               std::span<const double> z, std::span<double> fx,
                               std::span<double> fy, std::span<double> fz) {
  for (const std::int32_t i : loaded_nodes_) fx_[i] = fy_[i] = fz_[i] = 0.0;
  Variables vars;
  vars.t = t;
  vars.term = model_->time.end_time;
  // Faces of eroded elements keep their load for now: the pressure acts on the faces found at
  // t = 0 whatever happens to their elements (the erosion of hexes does not reach this module).
  for (const Surface& s : loads_) {
    const double p = s.source->scale * model_->functions.value(s.source->curve, vars);
    if (p == 0.0) continue;
    for (const Quad4& q : s.faces) {
      // Consistent nodal forces f_a = -p int N_a n dA, with one-point quadrature at the centre
      // where every N_a = 1/4: -p A / 4 on each node, A the vector area (exact in sum for a
      // warped quad). A linear triangle integrates exactly: N_a integrates to A / 3.
      if (is_triangle(q)) {
        const Vec3 f = (-p / 3.0) * face_vector_area(q, x, y, z);
        for (int a = 0; a < 3; ++a) {
          fx_[q[a]] += f.x;
          fy_[q[a]] += f.y;
          fz_[q[a]] += f.z;
        }
      } else {
        const Vec3 f = (-p / 4.0) * face_vector_area(q, x, y, z);
        for (const std::int32_t a : q) {
          fx_[a] += f.x;
          fy_[a] += f.y;
          fz_[a] += f.z;
        }
      }
    }
  }
  for (const std::int32_t i : loaded_nodes_) {
    fx[i] += fx_[i];
    fy[i] += fy_[i];
    fz[i] += fz_[i];
  }
}

double PressureLoads::mid_step_power(std::span<const double> vx_old, std::span<const double> vy_old,
                                     std::span<const double> vz_old, std::span<const double> vx_new,
                                     std::span<const double> vy_new,
                                     std::span<const double> vz_new) const {
  double power = 0.0;
  for (const std::int32_t i : loaded_nodes_) {
    power += 0.5 * (fx_[i] * (vx_old[i] + vx_new[i]) + fy_[i] * (vy_old[i] + vy_new[i]) +
                    fz_[i] * (vz_old[i] + vz_new[i]));
  }
  return power;
}

}  // namespace abut
