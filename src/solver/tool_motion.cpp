#include "tool_motion.hpp"

namespace abut {

ToolMotion::ToolMotion(const Model& model, const RigidTool& tool)
    : table_(&model.functions),
      tool_(tool),
      term_(model.time.end_time),
      start_(model.time.start_time),
      time_(model.time.start_time) {}

Vec3 ToolMotion::velocity(double t) const {
  Variables v;
  v.t = t;
  v.term = term_;
  double c[3] = {0.0, 0.0, 0.0};
  for (std::size_t d = 0; d < 3; ++d)
    if (tool_.velocity[d].valid())
      c[d] = tool_.velocity_scale[d] * table_->value(tool_.velocity[d], v);
  return {c[0], c[1], c[2]};
}

double ToolMotion::spin(double t) const {
  if (!tool_.spin.valid()) return 0.0;
  Variables v;
  v.t = t;
  v.term = term_;
  return tool_.spin_scale * table_->value(tool_.spin, v);
}

ToolPose ToolMotion::advance(double t, double t_velocity) {
  if (t != time_) {
    const double mid = 0.5 * (t + time_);
    displacement_ += velocity(mid) * (t - time_);
    angle_ += spin(mid) * (t - time_);
    time_ = t;
  }
  return {displacement_, angle_, velocity(t_velocity), spin(t_velocity)};
}

ToolPose ToolMotion::pose_at(double t) const {
  const double t0 = start_;
  const double h = (t - t0) / kPosePanels;
  Vec3 displacement;
  double angle = 0.0;
  for (int k = 0; k < kPosePanels; ++k) {
    const double a = t0 + k * h, m = a + 0.5 * h, b = a + h;
    displacement += (velocity(a) + velocity(m) * 4.0 + velocity(b)) * (h / 6.0);
    angle += (spin(a) + 4.0 * spin(m) + spin(b)) * (h / 6.0);
  }
  return {displacement, angle, velocity(t), spin(t)};
}

}  // namespace abut
