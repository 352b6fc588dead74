#pragma once
// A block of 4-node shells (Belytschko-Tsay, shell4.hpp) of one part: one-point in-plane
// integration, any odd number of Gauss points through the thickness, plane stress through the
// material-point seam (point_law.hpp), hourglass control and a warping correction.
//
// Kinematics (Mindlin): the velocity at height z above the mid-surface is v + z theta x e3 with
// theta the nodal angular velocity, so in the element frame v_x(z) = v_x + z theta_y and
// v_y(z) = v_y - z theta_x. Strain rates: membrane d = sym grad v, curvature
// kappa = (d theta_y/dx, -d theta_x/dy, d theta_y/dy - d theta_x/dx), transverse shear
// gamma_xz = d v_z/dx + theta_y, gamma_yz = d v_z/dy - theta_x; the transverse shear stress is
// k G gamma with the shear factor k = 5/6 (the law is handed k gamma), so Q = k G h gamma. Nodal
// forces and moments follow from the virtual power of the resultants N = int sigma dz, M = int z
// sigma dz and Q = int tau dz, so that they are exactly the forces conjugate to the nodal
// velocities.
//
// Warping: in a warped element node a lies z_a above the frame plane; the strain rates use the
// velocity of the point where the node's fibre crosses that plane, v_a - z_a theta_a x e3, and
// the forces are mapped back the same way. A warped element then has zero strain rate and zero
// hourglass rate under any rigid rotation (Belytschko, Wong & Chiang 1992, CMAME 96:93, address
// the same defect of the original element).
//
// Stress is kept in the element frame. The frame follows side 1-2; the part of the material spin
// about the normal that the frame does not follow rotates the stored stress (Jaumann rate in the
// co-rotational frame), so in-plane shear of a skewed element stays objective.
//
// Time stepping contract as SolidBlock (solid_block.hpp), with angular velocities added: forces
// and moments are stored per element, 24 values: node a at e*24 + a*6: fx, fy, fz, mx, my, mz,
// acting ON the nodes. The thickness stays constant (no thickness update).
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "abut/core/functions.hpp"
#include "abut/element/solid_block.hpp"
#include "abut/material/material.hpp"
#include "abut/mesh/mesh.hpp"

namespace abut {

class StateArchive;

struct ShellNodalState {
  const double* x;  // coordinates x^n
  const double* y;
  const double* z;
  const double* vx;  // velocities v^{n-1/2}
  const double* vy;
  const double* vz;
  const double* wx;  // angular velocities omega^{n-1/2}
  const double* wy;
  const double* wz;
};

struct ShellSection {
  double thickness = 0.0;
  int points = 5;  // Gauss points through the thickness, odd
  // Hourglass coefficient of the membrane, transverse and rotational stiffnesses. 0.01 is the
  // Radioss default for its Belytschko Q4 shells (/PROP/TYPE1 hm = hf = hr = 0.01, Ishell 1, 2, 4)
  // and the low end of the 0.01-0.05 Belytschko & Tsay recommend: the stiffness is elastic,
  // so a larger one resists the plastic folding of a crushed tube (0.05: +11% mean crushing
  // force at 2.5 mm elements, docs/verification.md).
  double hourglass = 0.01;
  static constexpr double kShearFactor = 5.0 / 6.0;
};

class ShellBlock {
 public:
  ShellBlock(std::int64_t part_id, const MaterialParams& material, const ShellSection& section,
             std::vector<Quad4> shells, const Nodes& reference,
             const FunctionTable* functions = nullptr);
  ~ShellBlock();
  ShellBlock(ShellBlock&&) noexcept;
  ShellBlock& operator=(ShellBlock&&) noexcept;

  std::int64_t part_id() const;
  const std::vector<Quad4>& shells() const;
  std::size_t size() const;
  const ShellSection& section() const;

  // Lumped mass rho h A / 4 per node (a triangle: A / 3 on each of its three nodes) and rotary
  // inertia m (h^2 + A) / 12: the A / 12 term keeps the rotational frequencies below the
  // translational ones so that the rotations do not limit the step (a standard scaling of
  // explicit shells; it changes bending frequencies by O(element size / wavelength)^2).
  void add_lumped_mass(std::vector<double>& nodal_mass, std::vector<double>& rotary_inertia) const;
  double initial_stable_step(const Nodes& reference) const;

  BlockStep update(const ShellNodalState& state, double dt);
  const std::vector<double>& element_forces() const;  // 24 per element, see above

  // Per element: the largest von Mises stress and plastic strain over its thickness points.
  void von_mises_stress(std::vector<double>& out) const;
  void plastic_strain(std::vector<double>& out) const;
  void plastic_strain_rate(std::vector<double>& out) const;
  // Stress of every thickness point in the element frame, Sym3 order (xx, yy, zz = 0, xy, yz, zx),
  // 6 * points per element, from the bottom (z = -h/2) up.
  const std::vector<double>& point_stress() const;
  // Resultants per element in its frame: N (xx, yy, xy), M (xx, yy, xy), Q (xz, yz).
  void resultants(std::size_t element, double n[3], double m[3], double q[2]) const;

  // Erosion as SolidBlock; with a damage property, a shell erodes once every thickness point
  // has failed (a failed point carries no stress before that).
  void set_erosion(const ErosionCriteria& criteria);
  const std::vector<std::uint8_t>& eroded() const;
  void set_element_ids(std::vector<std::int64_t> ids);
  // Saves or loads the evolving state for a restart (state_archive.hpp), as SolidBlock.
  void archive(StateArchive& a);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Gauss-Legendre points and weights on [-1, 1] (n >= 1), by Newton iteration on P_n.
void gauss_legendre(int n, std::vector<double>& points, std::vector<double>& weights);

}  // namespace abut
