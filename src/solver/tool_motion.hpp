#pragma once
// The rigid motion of a *CONTACT_TOOL: its velocity curves integrated in time into the pose the
// contact library takes (analytic_tool.hpp).
#include "abut/contact/analytic_tool.hpp"
#include "abut/core/state_archive.hpp"
#include "abut/model/model.hpp"

namespace abut {

class ToolMotion {
 public:
  ToolMotion(const Model& model, const RigidTool& tool);
  // The pose at time t: the displacement and spin angle integrated from the last call by the
  // midpoint rule (exact for a velocity linear in time over the step), and the velocity at
  // `t_velocity` (the time the nodes' velocities stand for).
  ToolPose advance(double t, double t_velocity);
  // The pose at time t from the start, whatever was asked before (static steps, whose Newton
  // iterations and cut-backs go back and forth in time): the velocity integrated by Simpson's
  // rule on kPosePanels panels (exact for velocities piecewise quadratic on them).
  ToolPose pose_at(double t) const;
  static constexpr int kPosePanels = 4096;
  void archive(StateArchive& a) { a.values(time_, displacement_, angle_); }

 private:
  Vec3 velocity(double t) const;
  double spin(double t) const;

  const FunctionTable* table_;
  RigidTool tool_;
  double term_ = 0.0;
  double start_ = 0.0;  // the run's start, where the tool is as defined
  double time_ = 0.0;   // of the pose so far
  Vec3 displacement_;
  double angle_ = 0.0;
};

}  // namespace abut
