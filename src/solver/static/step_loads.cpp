#include "solver/static/step_loads.hpp"

#include <array>
#include <cmath>
#include <string>

#include "abut/core/vec3.hpp"

namespace abut::detail {

namespace {

std::int64_t face_key(const HexFace& f) { return 6 * static_cast<std::int64_t>(f.hex) + f.face; }

// Nodal forces of a uniform pressure p on a bilinear face (nodes counter-clockwise seen from
// outside): f_a = -p int N_a (x_xi x x_eta) dxi deta, 2 x 2 Gauss points (exact for a flat face,
// whose integrand is then bilinear times constant).
void add_pressure(const std::array<Vec3, 4>& x, double p, std::array<Vec3, 4>& f) {
  static constexpr double kXi[4] = {-1, 1, 1, -1}, kEta[4] = {-1, -1, 1, 1};
  const double g = 1.0 / std::sqrt(3.0);
  for (const double xi : {-g, g})
    for (const double eta : {-g, g}) {
      Vec3 dxi{}, deta{};
      double shape[4];
      for (int a = 0; a < 4; ++a) {
        shape[a] = 0.25 * (1 + kXi[a] * xi) * (1 + kEta[a] * eta);
        dxi = dxi + x[a] * (0.25 * kXi[a] * (1 + kEta[a] * eta));
        deta = deta + x[a] * (0.25 * kEta[a] * (1 + kXi[a] * xi));
      }
      const Vec3 area = cross(dxi, deta);  // outward normal times the area per unit xi, eta
      for (int a = 0; a < 4; ++a) f[a] = f[a] - area * (p * shape[a]);
    }
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
    const Hex8& hex = mesh.hexes[r.key / 6];
    const int* face = kHexFaces[r.key % 6];
    std::array<Vec3, 4> x, nodal{};
    for (int a = 0; a < 4; ++a) {
      const auto n = static_cast<std::size_t>(hex[face[a]]);
      x[a] = mesh.nodes.position(n);
      if (nonlinear_geometry) x[a] = x[a] + Vec3{u[3 * n], u[3 * n + 1], u[3 * n + 2]};
    }
    add_pressure(x, p, nodal);
    for (int a = 0; a < 4; ++a) {
      const auto n = static_cast<std::size_t>(hex[face[a]]);
      f[3 * n] += nodal[a].x;
      f[3 * n + 1] += nodal[a].y;
      f[3 * n + 2] += nodal[a].z;
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
