#pragma once
// A block of solid cells of one type (mesh/topology.hpp: tet4, tet10, hex20, wedge6; hex8 too)
// of one part and one deformable material, for the explicit solver: isoparametric elements
// integrated at the points of their full rule (shape_functions.hpp), no hourglass modes to
// control. The time stepping contract is SolidBlock's (solid_block.hpp): update() takes x^n and
// v^{n-1/2}, advances each point's stress from t^{n-1} to t^n with the velocity gradient of
// v^{n-1/2} at the mid-step configuration, and stores the forces acting on the nodes at x^n
// (3 per node of the cell, node-major, per element).
//
// Per point: the velocity gradient L at x^{n-1/2}, the Hughes-Winget rotation of the old stress
// (as SolidBlock), the material-point law of point_law.hpp (elastic, metal) or Mooney-Rivlin from
// F = dx/dX at the point (total Lagrangian, with its viscous terms). Per element: the artificial
// bulk viscosity of SolidBlock on the element's mean volume rate.
//
// Mass: the HRZ lumping of lumped_mass.hpp (positive on every node of the quadratic cells).
//
// Stable step: the element eigenvalue inequality (the largest frequency of the assembled mesh is
// at most the largest of its elements' with the same lumped masses; Hughes, The Finite Element
// Method, 1987/2000, section 9.3, after Irons 1970) gives dt_e = 2 / omega_max,e, found once per
// element from M^-1/2 K M^-1/2 of the elastic element at the initial moduli
// (element_frequency.hpp). The run then scales it with the element's current characteristic length
// l = V / (largest face area, through the face corners): dt_e(t) = dt_e(0) l(t) / l(0), and
// shortens it for the bulk viscosity as SolidBlock does.
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "abut/core/functions.hpp"
#include "abut/element/solid_block.hpp"
#include "abut/material/material.hpp"
#include "abut/mesh/mesh.hpp"

namespace abut {

class StateArchive;

class SolidCellBlock {
 public:
  // `connectivity`: topology(type).nodes node indices per element, in the type's order.
  // `reference`: the initial coordinates. InputError for a bad material, a node index outside
  // `reference`, or an element with a non-positive Jacobian at an integration point.
  SolidCellBlock(std::int64_t part_id, const MaterialParams& material, CellType type,
                 std::vector<std::int32_t> connectivity, const Nodes& reference,
                 const FunctionTable* functions = nullptr);
  ~SolidCellBlock();
  SolidCellBlock(SolidCellBlock&&) noexcept;
  SolidCellBlock& operator=(SolidCellBlock&&) noexcept;

  std::int64_t part_id() const;
  CellType type() const;
  std::size_t size() const;
  int nodes_per_element() const;
  std::span<const std::int32_t> element(std::size_t e) const;

  // Adds rho times the HRZ volume shares of every element to nodal_mass.
  void add_lumped_mass(std::vector<double>& nodal_mass) const;
  // Stable time step at the initial configuration (no scale factor): the smallest dt_e(0).
  double initial_stable_step() const;

  // One step (SolidBlock's contract). InstabilityError naming the element when a Jacobian at a
  // point becomes <= 0 or a value non-finite.
  BlockStep update(const NodalState& state, double dt);
  const std::vector<double>& element_forces() const;  // 3 * nodes_per_element() per element

  // Per-element results at the last update: the volume-weighted mean over the element's points.
  void von_mises_stress(std::vector<double>& out) const;     // of the mean stress
  void plastic_strain(std::vector<double>& out) const;       // 0 if elastic
  void plastic_strain_rate(std::vector<double>& out) const;  // of the last step
  void damage(std::vector<double>& out) const;
  void pressure(std::vector<double>& out) const;
  void stress(std::vector<double>& out) const;  // 6 per element (xx, yy, zz, xy, yz, zx)

  // Erosion as SolidBlock: an element's step below min_step, its mean deviatoric logarithmic
  // strain or its volumetric strain above the limits; with a damage property, every point of it
  // failed.
  void set_erosion(const ErosionCriteria& criteria);
  const std::vector<std::uint8_t>& eroded() const;  // 1 per eroded element; empty without
  void set_bulk_viscosity(double quadratic, double linear);
  // The average nodal pressure of Bonet & Burton ("A simple average nodal pressure tetrahedral
  // element for incompressible and nearly incompressible dynamic explicit applications",
  // Communications in Numerical Methods in Engineering 14, 1998), on by default for 4-node
  // tetrahedra and refused (InputError) for other types. A constant-strain tetrahedron has one
  // volume constraint per element and about one node per five elements, so a nearly
  // incompressible mesh of them cannot deform (volumetric locking). Here each node takes the
  // volume-weighted mean of its elements' volumetric strain increments (hypoelastic laws) or of
  // their volume ratios J (Mooney-Rivlin), and each element's volumetric strain is the mean over
  // its four nodes: one constraint per node. The averaging is symmetric, so the pressure's work
  // is that of a nodal energy sum_a V_a K eps_a^2 / 2: the energy balance still closes.
  void set_nodal_pressure(bool on);
  bool nodal_pressure() const;
  // InputError when the coupling would change anything: the coupling of these elements to the
  // temperature is not supported yet.
  void set_thermal(const ThermalCoupling& coupling);
  void set_element_ids(std::vector<std::int64_t> ids);
  void archive(StateArchive& a);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace abut
