#include "solver/static/step_loads.hpp"

#include <array>
#include <cmath>
#include <string>

#include "abut/core/vec3.hpp"
#include "abut/mesh/shape_functions.hpp"

namespace abut::detail {

namespace {

std::int64_t face_key(const SolidFace& f) {
  return 6 * static_cast<std::int64_t>(f.solid) + f.face;
}

}  // namespace

StepLoads::StepLoads(const Model& model, const StaticStep& step, std::span<const double> u_start,
                     const LoadHistory& previous, double step_start)
    : model_(model), period_(step.period), step_start_(step_start) {
  prescribed_.assign(u_start.size(), 0);
  for (const StepDisplacement& d : step.displacements) {
    const std::int64_t dof = 3 * static_cast<std::int64_t>(d.node) + d.dof;
    if (prescribed_[dof]) {  // the reader resolves repeats; keep the last
      for (Ramp& r : displacements_)
        if (r.key == dof) r = {dof, u_start[dof], d.value, d.amplitude};
      continue;
    }
    prescribed_[dof] = 1;
    displacements_.push_back({dof, u_start[dof], d.value, d.amplitude});
  }
  // Loads: ramp from the previous value (0 if new); previous loads not listed ramp down to 0.
  auto ramps = [](const auto& items, auto key_of, const std::map<std::int64_t, double>& before) {
    std::vector<Ramp> out;
    std::map<std::int64_t, std::size_t> index;
    for (const auto& item : items) {
      const std::int64_t key = key_of(item);
      const auto it = before.find(key);
      const Ramp r{key, it == before.end() ? 0.0 : it->second, item.value, item.amplitude};
      if (const auto seen = index.find(key); seen != index.end()) {
        out[seen->second] = r;
      } else {
        index[key] = out.size();
        out.push_back(r);
      }
    }
    for (const auto& [key, value] : before)
      if (!index.count(key) && value != 0.0) out.push_back({key, value, 0.0, {}});
    return out;
  };
  forces_ = ramps(
      step.forces, [](const StepForce& f) { return 3 * static_cast<std::int64_t>(f.node) + f.dof; },
      previous.forces);
  pressures_ = ramps(
      step.pressures, [](const StepPressure& p) { return face_key(p.face); }, previous.pressures);
}

double StepLoads::value(const Ramp& r, double tau) const {
  if (r.amplitude.curve.valid()) {
    const double at = r.amplitude.total_time ? step_start_ + tau : tau;
    Variables vars;
    vars.t = at;
    return r.end * model_.functions.value(r.amplitude.curve, at, vars);
  }
  const double s = period_ > 0.0 ? tau / period_ : 1.0;
  return r.start + (r.end - r.start) * s;
}

void StepLoads::prescribe(double tau, std::span<double> u) const {
  for (const Ramp& r : displacements_) u[r.key] = value(r, tau);
}

void StepLoads::add_external_forces(double tau, std::span<const double> u, bool nonlinear_geometry,
                                    std::span<double> f) const {
  for (const Ramp& r : forces_) f[r.key] += value(r, tau);
  const Mesh& mesh = model_.mesh;
  for (const Ramp& r : pressures_) {
    const double p = value(r, tau);
    if (p == 0.0) continue;
    // The face's nodal forces on its current (NLGEOM) or reference position.
    const SolidRef solid = mesh.solid(static_cast<std::size_t>(r.key / 6));
    const FaceTopology& face = topology(solid.type).faces[static_cast<std::size_t>(r.key % 6)];
    std::array<double, 3 * kMaxFaceNodes> x{}, nodal{};
    for (int a = 0; a < face.size(); ++a) {
      const auto n = static_cast<std::size_t>(solid.nodes[static_cast<std::size_t>(face.nodes[a])]);
      const Vec3 p0 = mesh.nodes.position(n);
      const double at[3] = {p0.x, p0.y, p0.z};
      for (std::size_t i = 0; i < 3; ++i)
        x[3 * static_cast<std::size_t>(a) + i] = at[i] + (nonlinear_geometry ? u[3 * n + i] : 0.0);
    }
    face_pressure_forces(face.type, x, p, nodal);
    for (int a = 0; a < face.size(); ++a) {
      const auto n = static_cast<std::size_t>(solid.nodes[static_cast<std::size_t>(face.nodes[a])]);
      for (std::size_t i = 0; i < 3; ++i)
        f[3 * n + i] += nodal[3 * static_cast<std::size_t>(a) + i];
    }
  }
}

LoadHistory StepLoads::history(double tau) const {
  LoadHistory h;
  for (const Ramp& r : forces_)
    if (const double v = value(r, tau); v != 0.0) h.forces[r.key] = v;
  for (const Ramp& r : pressures_)
    if (const double v = value(r, tau); v != 0.0) h.pressures[r.key] = v;
  return h;
}

}  // namespace abut::detail
