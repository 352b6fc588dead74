// A C++ host of abut's contact library (abut/contact/interface.hpp): the model of falling_boxes.c
// (box A falls onto box B on a fixed plane; box_model.h) through the C++ interface. The same
// contacts, steps and output, so that the two programs print the same numbers
// (examples/host/README.md).
#include <abut/contact/interface.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <exception>
#include <span>

#include "box_model.h"

namespace {

// A box's outward facets (or the plane's facet) as a contact surface of part `part`.
abut::ContactSurface surface(std::span<const std::int32_t> facets, std::int64_t part) {
  abut::ContactSurface s;
  for (std::size_t f = 0; f < facets.size() / 4; ++f)
    s.add({facets[4 * f], facets[4 * f + 1], facets[4 * f + 2], facets[4 * f + 3]}, part, kPenalty,
          kSide);
  return s;
}

abut::ContactSurface box(std::int32_t first) {
  std::array<std::int32_t, 24> facets{};
  box_facets(first, facets.data());
  return surface(facets, first == 0 ? 1 : 2);
}

// What a contact holds or took: spring energy, damping and friction work, released springs.
double held(const abut::ContactStats& s) {
  return s.elastic_energy + s.damping_energy + s.friction_energy + s.released_energy;
}

int run() {
  static BoxModel m;
  box_model_init(&m);
  const std::span<const double> mass(m.mass, NODES);
  abut::ContactInput in{{m.x, NODES}, {m.y, NODES}, {m.z, NODES}};

  abut::ContactSettings s;
  abut::Coulomb friction;
  friction.mu_static = friction.mu_dynamic = 0.3;
  s.tangential_law = friction;
  abut::ContactInterface ab(s, box(8), box(0), mass, in);
  s.tangential_law = abut::Frictionless{};
  s.discretisation = abut::Discretisation::NodeToSurface;
  s.one_way = true;
  abut::ContactSurface boxes = box(0);
  const abut::ContactSurface a = box(8);
  for (std::size_t f = 0; f < a.size(); ++f) boxes.add(a.facets[f], 2, kPenalty, kSide);
  std::array<std::int32_t, 4> plane{};
  plane_facet(plane.data());
  abut::ContactInterface ground(s, boxes, surface(plane, 3), mass, in);

  const double end = 4.0, every = 0.25;
  double t = 0.0, dt = box_model_stable_step(), next = 0.0, worst = 0.0;
  std::printf("%8s %12s %12s %12s %12s\n", "t [s]", "z_A [m]", "N_AB [N]", "N_floor [N]",
              "balance");
  for (;;) {
    box_model_forces(&m);
    in.vx = {m.vx, NODES}, in.vy = {m.vy, NODES}, in.vz = {m.vz, NODES};
    in.time = t;
    in.dt = dt;
    abut::ContactForces out{{m.fx, NODES}, {m.fy, NODES}, {m.fz, NODES}, {}, {}};
    ab.apply(in, out);
    ground.apply(in, out);
    if (t >= next - 1e-12) {
      const double stored =
          box_model_energy(&m) + m.damping_work + held(ab.stats()) + held(ground.stats());
      const double balance = (stored - m.gravity_work) / std::max(m.gravity_work, 1e-30);
      worst = std::max(worst, std::abs(balance));
      double za = 0.0;
      for (int n = 8; n < 16; ++n) za += m.z[n] / 8.0;
      std::printf("%8.3f %12.8f %12.6f %12.6f %12.3e\n", t, za, ab.stats().normal_force,
                  ground.stats().normal_force, balance);
      next += every;
    }
    if (t >= end) break;
    box_model_step(&m, dt);
    t += dt;
    dt = std::min(box_model_stable_step(),
                  0.9 * std::min(ab.stats().step_bound(), ground.stats().step_bound()));
  }
  const double g = kGravity * kNodeMass * 8.0;
  std::printf(
      "at rest: N_AB / (m_A g) = %.9f, N_floor / ((m_A + m_B) g) = %.9f, worst balance %.3e\n",
      ab.stats().normal_force / g, ground.stats().normal_force / (2.0 * g), worst);
  return 0;
}

}  // namespace

int main() {
  try {
    return run();
  } catch (const abut::ContactSetupError& e) {
    std::fprintf(stderr, "abut: %s (setting: %s)\n", e.what(), e.setting().c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "abut: %s\n", e.what());
  }
  return 1;
}
