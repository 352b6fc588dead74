#pragma once
// Small nodal worlds for the contact tests: structure-of-arrays nodes with masses and
// velocities, and flat plates of quad facets.
#include <vector>

#include "abut/contact/interface.hpp"

namespace abut::testing {

struct World {
  std::vector<double> x, y, z, vx, vy, vz, mass;
  std::vector<double> fx, fy, fz;

  std::int32_t add_node(double px, double py, double pz, double m) {
    for (auto* v : {&vx, &vy, &vz, &fx, &fy, &fz}) v->push_back(0.0);
    x.push_back(px);
    y.push_back(py);
    z.push_back(pz);
    mass.push_back(m);
    return static_cast<std::int32_t>(x.size() - 1);
  }
  ContactInput input(double time = 0.0, double dt = 0.0) const {
    return {x, y, z, vx, vy, vz, time, dt, {}};
  }
  ContactForces forces() { return {fx, fy, fz, {}, {}}; }
  void clear_forces() {
    for (auto* v : {&fx, &fy, &fz}) std::fill(v->begin(), v->end(), 0.0);
  }
  void shift(std::int32_t first, std::int32_t last, double dx, double dy, double dz) {
    for (std::int32_t i = first; i < last; ++i) {
      x[i] += dx;
      y[i] += dy;
      z[i] += dz;
    }
  }
};

// An n x m plate of facets over [x0, x0+lx] x [y0, y0+ly] at height h, facing +z (up) or -z.
// Nodes get `node_mass` each. Returns the surface; nodes are appended to the world.
inline ContactSurface add_plate(World& w, int n, int m, double x0, double y0, double lx, double ly,
                                double h, bool facing_up, double pfac, double thickness = 1.0,
                                double node_mass = 1.0, std::int64_t part = 1) {
  const auto first = static_cast<std::int32_t>(w.x.size());
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i <= n; ++i) w.add_node(x0 + lx * i / n, y0 + ly * j / m, h, node_mass);
  ContactSurface s;
  auto id = [&](int i, int j) { return first + j * (n + 1) + i; };
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i) {
      if (facing_up)
        s.add({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)}, part, pfac, thickness);
      else
        s.add({id(i, j), id(i, j + 1), id(i + 1, j + 1), id(i + 1, j)}, part, pfac, thickness);
    }
  return s;
}

}  // namespace abut::testing
