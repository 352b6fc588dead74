#pragma once
// The cantilever of the static verification tests: 4 x 1 x 0.5, E = 1000, nu = 0, clamped at
// x = 0, tip shear P along -y on x = L, and its Timoshenko deflection
//   delta = P L^3 / (3 E I) + P L / (kappa G A),  kappa = 5/6
// (Timoshenko & Gere, Mechanics of Materials; nu = 0, so the section does not contract).
#include <cmath>
#include <utility>
#include <vector>

#include "abut/model/model.hpp"
#include "abut/solver/static_solver.hpp"

namespace abut::cantilever {

inline constexpr double kE = 1000.0, kL = 4.0, kH = 1.0, kW = 0.5, kP = 0.01;

inline Material elastic() {
  Material m;
  m.id = 1;
  m.params = ElasticParams{1e-9, kE, 0.0};
  return m;
}

inline Part part(std::int64_t id, Part::SolidIntegration integration) {
  Part p;
  p.id = id;
  p.material_id = 1;
  p.solid_integration = integration;
  return p;
}
inline Part full_part(std::int64_t id) { return part(id, Part::SolidIntegration::Full); }

// Clamp x = 0; tip shear P along -y on x = L, as consistent nodal forces of a uniform traction.
inline void clamp_and_load(Model& m) {
  StaticStep step;
  const Nodes& n = m.mesh.nodes;
  double weight_sum = 0.0;
  std::vector<std::pair<std::int32_t, double>> tip;
  for (std::size_t i = 0; i < n.size(); ++i) {
    const auto node = static_cast<std::int32_t>(i);
    if (n.x[i] == 0.0)
      for (int d = 0; d < 3; ++d) step.displacements.push_back({node, d, 0.0, {}, {}});
    if (std::abs(n.x[i] - kL) < 1e-12) {
      // Tributary share of the end face: half an element at the borders.
      double wy = 1.0, wz = 1.0;
      if (n.y[i] == 0.0 || std::abs(n.y[i] - kH) < 1e-12) wy = 0.5;
      if (n.z[i] == 0.0 || std::abs(n.z[i] - kW) < 1e-12) wz = 0.5;
      tip.push_back({node, wy * wz});
      weight_sum += wy * wz;
    }
  }
  for (const auto& [node, w] : tip) step.forces.push_back({node, 1, -kP * w / weight_sum, {}, {}});
  m.static_steps.push_back(step);
  m.time.end_time = 1.0;
}

inline double tip_deflection(const Model& m, const StaticSolver& s) {
  double sum = 0.0;
  int count = 0;
  for (std::size_t i = 0; i < m.mesh.nodes.size(); ++i)
    if (std::abs(m.mesh.nodes.x[i] - kL) < 1e-12) sum += s.displacement()[3 * i + 1], ++count;
  return -sum / count;
}

inline double timoshenko_deflection() {
  const double I = kW * kH * kH * kH / 12.0, A = kW * kH, G = kE / 2.0;
  return kP * kL * kL * kL / (3 * kE * I) + kP * kL / (5.0 / 6.0 * G * A);
}

}  // namespace abut::cantilever
