#pragma once
// *LOAD_PRESSURE in the time loop: the loaded faces, resolved once from the reference mesh, and
// each cycle the nodal forces of the current pressure on the current coordinates (a follower
// load: the force turns and grows with the face).
//
// A face is a Quad4 of node indices (a triangle repeats its third node, n4 == n3), ordered so
// that its normal n = (x3 - x1) x (x4 - x2) points out of the solid (skin.hpp) or is the shell's
// own normal. Positive pressure pushes against n.
#include <cstdint>
#include <span>
#include <vector>

#include "abut/core/vec3.hpp"
#include "abut/mesh/mesh.hpp"
#include "abut/model/model.hpp"

namespace abut {

// The faces `load` acts on, at t = 0: the exterior faces of the solid parts and the shells of
// the entity (P, PS, ALL), or for G every exterior solid face and shell whose nodes all lie in
// the region. Solid faces come first (hex order, then local face order), then shells (shell
// order). A solid face collapsed to a triangle is written (a, b, c, c); one with less than three
// distinct nodes has no area and is left out. InputError at the entity when it has no face, or
// when a part, part set or geometry does not exist.
std::vector<Quad4> pressure_faces(const Model& model, const PressureLoad& load);

// The same faces for the static steps, which load element faces (model_static.hpp): the solid
// faces as (solid, local face) in the order of pressure_faces (a quadratic face once), and the
// indices of the shells of the entity.
// The same InputError when there is neither.
struct PressureSolidFaces {
  std::vector<SolidFace> faces;
  std::vector<std::int32_t> shells;
};
PressureSolidFaces pressure_solid_faces(const Model& model, const PressureLoad& load);

// Vector area of a face: (1/2) (x3 - x1) x (x4 - x2), exact for a warped quad too (the vector
// area of a closed polygon depends on its boundary only); for a triangle (1/2) (x2 - x1) x
// (x3 - x1), which the same formula gives when x4 = x3.
Vec3 face_vector_area(const Quad4& face, std::span<const double> x, std::span<const double> y,
                      std::span<const double> z);

class PressureLoads {
 public:
  PressureLoads() = default;
  // Resolves the faces of every *LOAD_PRESSURE of `model` (which must outlive this object).
  explicit PressureLoads(const Model& model);

  bool empty() const { return loads_.empty(); }

  // The nodal forces of every pressure at time t on the coordinates x, y, z, in this object's
  // arrays, then added to fx, fy, fz. Faces are visited in a fixed order on one thread, so the
  // sums do not depend on the thread count.
  void add_forces(double t, std::span<const double> x, std::span<const double> y,
                  std::span<const double> z, std::span<double> fx, std::span<double> fy,
                  std::span<double> fz);

  // sum_a f_a . (v_a^old + v_a^new) / 2 with the forces of the last add_forces: the pressure's
  // share of the external power over a step, to be multiplied by the step.
  double mid_step_power(std::span<const double> vx_old, std::span<const double> vy_old,
                        std::span<const double> vz_old, std::span<const double> vx_new,
                        std::span<const double> vy_new, std::span<const double> vz_new) const;

  // The pressure forces of the last add_forces, one entry per node.
  const std::vector<double>& fx() const { return fx_; }
  const std::vector<double>& fy() const { return fy_; }
  const std::vector<double>& fz() const { return fz_; }

 private:
  struct Surface {
    const PressureLoad* source = nullptr;
    std::vector<Quad4> faces;
  };
  const Model* model_ = nullptr;
  std::vector<Surface> loads_;
  std::vector<std::int32_t> loaded_nodes_;  // sorted: the nodes that can carry a pressure force
  std::vector<double> fx_, fy_, fz_;
};

}  // namespace abut
