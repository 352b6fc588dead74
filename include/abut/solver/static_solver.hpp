#pragma once
// Nonlinear static analysis (Abaqus/CalculiX *STATIC, OptiStruct NLSTAT): the steps of
// Model::static_steps solved to equilibrium one load increment after the other by Newton-Raphson,
// with the consistent tangent of the elements, automatic cut-back when an increment does not
// converge and growth when it converges easily. Small strain, or total Lagrangian (NLGEOM).
// The linear systems go to a sparse direct solver (linalg/linear_solver.hpp).
#include <functional>
#include <memory>
#include <span>
#include <string>

#include "abut/contact/static_contact.hpp"
#include "abut/core/error.hpp"
#include "abut/model/model.hpp"

namespace abut {

// Newton controls. The defaults are those of Abaqus/Standard and CalculiX (*CONTROLS, field
// parameters): an increment has converged when the largest residual force is at most R_n = 0.005
// of the average nodal force and the largest correction at most C_n = 0.02 of the largest
// displacement increment (CalculiX User's Manual, *CONTROLS; Abaqus Analysis User's Guide
// 7.2.3). A residual below 1e-8 of the average force is converged whatever the correction
// (a linear problem after one iteration).
struct StaticControls {
  double force_tolerance = 0.005;
  double displacement_tolerance = 0.02;
  int max_iterations = 16;  // per attempt of an increment, then cut back
  double cutback = 0.25;    // increment factor after a failed attempt
  double growth = 1.5;      // increment factor after an easy one
  int easy_iterations = 5;  // converged in at most this many iterations: easy
};

// A converged increment, as reported to the caller.
struct StaticIncrement {
  int step = 0;       // 0-based index into Model::static_steps
  int increment = 0;  // 1-based within the step
  int attempts = 1;   // 1 + cut-backs
  int iterations = 0;
  double step_time = 0.0;
  double total_time = 0.0;
  double residual = 0.0;  // final largest residual / average force
  bool step_end = false;
};

// An increment failed to converge at the smallest increment allowed (or with fixed increments).
// Like an instability of the explicit solver: the caller keeps the last converged state.
class StaticConvergenceError : public InstabilityError {
 public:
  using InstabilityError::InstabilityError;
};

struct StaticStatistics {
  std::int64_t equations = 0;
  std::int64_t increments = 0;
  std::int64_t iterations = 0;
  std::int64_t cutbacks = 0;
  double assembly_seconds = 0.0;  // elements, loads, sparse assembly
  double solve_seconds = 0.0;     // factorisation and solution
  std::string linear_solver;
};

class StaticSolver {
 public:
  // Checks that the model can be solved (InputError naming what cannot: materials other than
  // elastic and J2 plastic, shells, explicit-only loads).
  explicit StaticSolver(const Model& model, StaticControls controls = {});
  ~StaticSolver();
  StaticSolver(const StaticSolver&) = delete;
  StaticSolver& operator=(const StaticSolver&) = delete;

  // Solves every step, calling `on_increment` after each converged increment.
  void run(const std::function<void(const StaticIncrement&)>& on_increment = {});

  // The last converged state. Per node (3 values, node-major): displacement, and reaction force
  // of the supports on the prescribed dofs (0 elsewhere). Per solid element (Mesh::solid
  // numbering), at each of its integration points (CalculiX's point order; first_point(e) is the
  // index of element e's first): Cauchy stress and strain (small or Green-Lagrange, engineering
  // shears; 6 per point, Voigt xx yy zz xy yz zx), the equivalent plastic strain and the energy
  // density; per element its energy (elastic, hourglass and plastic work) and volume.
  std::span<const double> displacement() const;
  std::span<const double> reaction() const;
  // The force of the elements on each node less the contact forces, i.e. the applied loads plus
  // the reactions: what CalculiX prints as RF (3 per node).
  std::span<const double> nodal_force() const;
  std::span<const double> stress() const;
  std::span<const double> strain() const;
  std::span<const double> plastic_strain() const;
  int integration_points(std::size_t element) const;  // 8 (C3D8), 1 (C3D8R), 27 (C3D20), ...
  std::size_t first_point(std::size_t element) const;
  std::span<const double> element_energy() const;
  std::span<const double> energy_density() const;  // per point
  std::span<const double> element_volume() const;  // current volume per element
  const StaticStatistics& statistics() const;
  // The contact passes at the last converged state: for each contact of Model::contacts, in
  // order, one (surface 1's points on surface 2) or two (symmetric: also 2 on 1); contact_of(k)
  // is the index in Model::contacts of pass k.
  std::span<const StaticContact> contacts() const;
  std::size_t contact_of(std::size_t pass) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace abut
