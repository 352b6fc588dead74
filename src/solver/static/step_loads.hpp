#pragma once
// The boundary conditions and loads of one static step as functions of the step time tau in
// [0, T]. Without an amplitude a value goes linearly from where it was at the start of the step
// to its value in the step (a boundary condition from the node's displacement, a load from its
// value at the end of the previous step, 0 if new); a load of the previous step that this step no
// longer lists goes linearly to 0. With an amplitude: value x amplitude(tau, or the total time).
// This is the Abaqus/CalculiX default for static steps (Abaqus Analysis User's Guide 34.1.2,
// "Amplitude curves": RAMP for static procedures; CalculiX User's Manual, *AMPLITUDE).
#include <cstdint>
#include <map>
#include <span>
#include <vector>

#include "abut/model/model.hpp"

namespace abut::detail {

// Load values at the end of a step, keyed by 3 node + dof (forces) and 6 hex + face (pressures).
struct LoadHistory {
  std::map<std::int64_t, double> forces, pressures;
};

class StepLoads {
 public:
  // `u_start`: displacement at the start of the step (3 per node); `step_start`: total time then.
  StepLoads(const Model& model, const StaticStep& step, std::span<const double> u_start,
            const LoadHistory& previous, double step_start);

  double step_start() const { return step_start_; }  // total time at the start of the step
  // One flag per global dof (3 per node).
  std::span<const std::uint8_t> prescribed() const { return prescribed_; }
  // Sets the prescribed dofs of u to their values at step time tau.
  void prescribe(double tau, std::span<double> u) const;
  // f += the external forces at step time tau. Pressures act on the faces as they are at the
  // displacement u with NLGEOM (follower loads), on the reference faces otherwise.
  void add_external_forces(double tau, std::span<const double> u, bool nonlinear_geometry,
                           std::span<double> f) const;
  // The load values at step time tau (the next step's starting values at tau = T).
  LoadHistory history(double tau) const;

 private:
  // A value in the step: start + (end - start) tau / T, or end x amplitude.
  struct Ramp {
    std::int64_t key = 0;  // dof, or 6 hex + face
    double start = 0.0, end = 0.0;
    StepAmplitude amplitude;
  };
  double value(const Ramp& r, double tau) const;

  const Model& model_;
  double period_ = 1.0, step_start_ = 0.0;
  std::vector<std::uint8_t> prescribed_;
  std::vector<Ramp> displacements_, forces_, pressures_;
};

}  // namespace abut::detail
