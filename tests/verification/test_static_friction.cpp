// Static and dynamic Coulomb friction on a slope (elementary statics and dynamics, e.g. Meriam &
// Kraige, "Engineering Mechanics", vol. 1 ch. 6 and vol. 2 ch. 3). A block on a plane inclined by
// theta, with static and dynamic coefficients mu_s > mu_d:
//   - from rest it stays when tan(theta) <= mu_s: static friction holds it, whatever mu_d;
//   - launched up the slope at v0 it stops after d = v0^2 / (2 g (sin(theta) + mu_d cos(theta)))
//     and, when tan(theta) <= mu_s, stays there;
//   - from rest with tan(theta) > mu_s it slides down with a = g (sin(theta) - mu_d cos(theta)).
// The slope is a flat plane under gravity tilted by theta (components g sin(theta) along x and
// -g cos(theta) along z), so the meshes stay axis-aligned and only the load is inclined. The
// plane (0.5 x 0.2 m, 10 x 4 elements) is rigid and held; the block is 0.1 x 0.1 x 0.02 m steel,
// rigid or elastic, pfac = 6.2e9 Pa/m. References are the closed forms above; "stays" means moves
// less than 1e-4 of the block's size (1e-5 m) in 0.3 s, as issue 27 asks.
//
// The matrix (issue 27): discretisation {S2S symmetric, S2S one-way, N2S one-way, N2S symmetric}
// x mesh {matched: 2 x 2 block on the plane's grid lines; non-matching: 3 x 3, offset by a random
// fraction of an element and rotated about z by a random angle, fixed seed} x body {rigid,
// elastic} x load path {set down under full gravity, gravity ramped over 20 ms, stopping after
// sliding up}. The steeper slope checks that the static limit is not simply raised: the block
// must slide at the dynamic rate. Every cell runs; the measured values are in
// docs/verification.md.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>
#include <random>
#include <sstream>
#include <string>

#include "run_to.hpp"

namespace abut {
namespace {

constexpr double kG = 9.81, kSize = 0.1;

enum class Discretisation { S2SSymmetric, S2SOneWay, N2SOneWay, N2SSymmetric };
enum class Mesh { Matched, NonMatching };
enum class Body { Rigid, Elastic };
enum class Path { SetDown, Ramped, Stopping };
// The hexahedra as they are, or both bodies cut into tetrahedra by *CHANGE_TO_TETRAHEDRA (the
// contact then meets triangles on both sides, and with 10 nodes the faces' lattice facets).
enum class Cells { Hexahedra, Tet4, Tet10 };

struct Case {
  Discretisation discretisation;
  Mesh mesh;
  Body body;
  Path path;
  Cells cells = Cells::Hexahedra;
};

std::string name(const Case& c) {
  const char* d[] = {"S2S_symmetric", "S2S_one_way", "N2S_one_way", "N2S_symmetric"};
  const char* m[] = {"matched", "non_matching"};
  const char* b[] = {"rigid", "elastic"};
  const char* p[] = {"set_down", "ramped", "stopping"};
  const char* cells[] = {"", "_tet4", "_tet10"};
  return std::string(d[static_cast<int>(c.discretisation)]) + "_" + m[static_cast<int>(c.mesh)] +
         "_" + b[static_cast<int>(c.body)] + "_" + p[static_cast<int>(c.path)] +
         cells[static_cast<int>(c.cells)];
}

struct Slope {
  double theta_deg, mu_s, mu_d, v0 = 0.0, ramp = 0.0, end = 0.3;
  int plane_elements = 10;  // along x, 0.05 m each from x = -0.2
};

// The block as nodes and hexahedra: n x n x 1 elements, shifted by (dx, dy) and turned by phi
// about the vertical through its centre.
std::string block_mesh(int n, double dx, double dy, double phi) {
  std::ostringstream s;
  s.precision(17);
  s << "*NODE\n";
  const double c = std::cos(phi), sn = std::sin(phi), h = kSize / n;
  for (int k = 0; k <= 1; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        const double x = i * h - 0.5 * kSize, y = j * h - 0.5 * kSize;
        s << 1 + i + (n + 1) * (j + (n + 1) * k) << ", " << 0.05 + dx + c * x - sn * y << ", "
          << dy + sn * x + c * y << ", " << 0.02 * k << "\n";
      }
  s << "*ELEMENT_SOLID\n";
  auto id = [n](int i, int j, int k) { return 1 + i + (n + 1) * (j + (n + 1) * k); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      s << 1 + i + n * j << ", 1, " << id(i, j, 0) << ", " << id(i + 1, j, 0) << ", "
        << id(i + 1, j + 1, 0) << ", " << id(i, j + 1, 0) << ", " << id(i, j, 1) << ", "
        << id(i + 1, j, 1) << ", " << id(i + 1, j + 1, 1) << ", " << id(i, j + 1, 1) << "\n";
  return s.str();
}

std::string deck(const Case& c, const Slope& slope) {
  const double t = slope.theta_deg * std::numbers::pi / 180.0;
  // Up the slope is -x: a block launched at +v0 up it has gravity pulling towards -x.
  const double gx = slope.v0 > 0.0 ? -kG * std::sin(t) : kG * std::sin(t);
  const double gz = -kG * std::cos(t);
  std::ostringstream s;
  s.precision(17);
  auto curve = [&](int id, double value) {
    s << "*CURVE\n" << id << "\n";
    if (slope.ramp > 0.0)
      s << "0.0, 0.0\n" << slope.ramp << ", " << value << "\n1.0, " << value << "\n";
    else
      s << "0.0, " << value << "\n1.0, " << value << "\n";
  };
  s << "*UNIT_SYSTEM\nSI\n*TIME\n" << slope.end << "\n";
  if (c.mesh == Mesh::Matched) {
    s << block_mesh(2, 0.0, 0.0, 0.0);
  } else {
    std::mt19937 random(27);  // fixed seed: a fraction of an element and an angle
    std::uniform_real_distribution<double> fraction(0.1, 0.9), angle(2.0, 15.0);
    const double h = kSize / 3.0;
    const double dx = fraction(random) * h, dy = fraction(random) * h;
    s << block_mesh(3, dx, dy, angle(random) * std::numbers::pi / 180.0);
  }
  s << "*COMPONENT_BOX\n2, 2, " << slope.plane_elements << ", 4, 1\n-0.2, -0.1, -0.02, "
    << -0.2 + 0.05 * slope.plane_elements << ", 0.1, 0.0\n";
  if (c.cells != Cells::Hexahedra)
    s << "*CHANGE_TO_TETRAHEDRA\nALL, 0, " << (c.cells == Cells::Tet4 ? 4 : 10) << "\n";
  s << (c.body == Body::Rigid ? "*MAT_RIGID\n1, 7800.0\n"
                              : "*MAT_ELASTIC\n1, 7800.0, 2.0e11, 0.3\n");
  s << "*MAT_RIGID\n2, 7800.0\n*PART\n\"block\"\n1, 1\n\"plane\"\n2, 2\n";
  if (slope.v0 > 0.0) s << "*INITIAL_VELOCITY\nP, 1, " << slope.v0 << ", 0.0, 0.0\n";
  s << "*BC_MOTION\nP, 2, XYZ, XYZ\n";
  curve(1, gz);
  curve(2, gx);
  s << "*LOAD_GRAVITY\nZ, 1\nX, 2\n*CONTACT\n1\nP, 1, P, 2, , 6.2e9\n";
  s << "*CONTACT_FRICTION\n1, COULOMB, " << slope.mu_s << ", " << slope.mu_d << "\n";
  switch (c.discretisation) {
    case Discretisation::S2SSymmetric:
      break;
    case Discretisation::S2SOneWay:
      s << "*CONTACT_DISCRETIZATION\n1, S2S, 0\n";
      break;
    case Discretisation::N2SOneWay:
      s << "*CONTACT_DISCRETIZATION\n1, N2S, 0\n";
      break;
    case Discretisation::N2SSymmetric:
      s << "*CONTACT_DISCRETIZATION\n1, N2S, 1\n";
      break;
  }
  s << "*END\n";
  return s.str();
}

struct Motion {
  double stop_distance = -1.0;  // where the velocity first reached zero (stopping runs)
  double final_distance = 0.0;  // along x from the start
  double final_speed = 0.0;
};

Motion run(const Case& c, const Slope& slope) {
  const Model model = read_deck_string(deck(c, slope), name(c) + ".k");
  Simulation sim(model);
  const double x0 = sim.part_states().at(0).centre_of_mass.x;
  Motion m;
  verification::run_to(sim, sim.end_time(), [&](const Simulation& s) {
    const PartState b = s.part_states()[0];  // a copy: part_states() returns a new vector
    if (m.stop_distance < 0.0 && slope.v0 > 0.0 && b.velocity.x <= 0.0)
      m.stop_distance = b.centre_of_mass.x - x0;
  });
  const PartState b = sim.part_states()[0];
  m.final_distance = b.centre_of_mass.x - x0;
  m.final_speed = norm(b.velocity);
  return m;
}

class StaticFriction : public ::testing::TestWithParam<Case> {};

// tan(25 deg) = 0.466 between mu_d = 0.4 and mu_s = 0.5 (issue 27's numbers); the stopping runs
// take 20 deg, mu_s = 0.5, mu_d = 0.3 and v0 = 0.5 m/s (d = 20.42 mm).
TEST_P(StaticFriction, HoldsWhereStaticFrictionShould) {
  const Case c = GetParam();
  Slope slope{25.0, 0.5, 0.4};
  if (c.path == Path::Ramped) slope.ramp = 0.02;
  if (c.path == Path::Stopping) slope = {20.0, 0.5, 0.3, 0.5};
  if (c.body == Body::Elastic) slope.end = c.path == Path::Stopping ? 0.15 : 0.1;
  const Motion m = run(c, slope);
  std::cout << name(c) << ": moved " << m.final_distance << " m, speed " << m.final_speed << " m/s";
  if (c.path == Path::Stopping) {
    const double t = slope.theta_deg * std::numbers::pi / 180.0;
    const double d = slope.v0 * slope.v0 / (2.0 * kG * (std::sin(t) + slope.mu_d * std::cos(t)));
    std::cout << "; stopped after " << m.stop_distance << " m, v0^2/(2 g (sin + mu_d cos)) = " << d
              << " m, error " << 100.0 * (m.stop_distance - d) / d << "%; then moved "
              << m.final_distance - m.stop_distance << " m\n";
    EXPECT_NEAR(m.stop_distance, d, 0.005 * d);
    EXPECT_LT(std::abs(m.final_distance - m.stop_distance), 1e-4 * kSize);
  } else {
    std::cout << "\n";
    EXPECT_LT(std::abs(m.final_distance), 1e-4 * kSize);
  }
  EXPECT_LT(m.final_speed, 1e-3);  // at rest: a speed of 1 mm/s would move it 0.3 mm
}

std::vector<Case> all_cases() {
  std::vector<Case> cases;
  for (auto d : {Discretisation::S2SSymmetric, Discretisation::S2SOneWay, Discretisation::N2SOneWay,
                 Discretisation::N2SSymmetric})
    for (auto m : {Mesh::Matched, Mesh::NonMatching})
      for (auto b : {Body::Rigid, Body::Elastic})
        for (auto p : {Path::SetDown, Path::Ramped, Path::Stopping}) cases.push_back({d, m, b, p});
  return cases;
}

INSTANTIATE_TEST_SUITE_P(Matrix, StaticFriction, ::testing::ValuesIn(all_cases()),
                         [](const auto& param_info) { return name(param_info.param); });

// The same with the block and the plane cut into 4-node tetrahedra, every discretisation, on the
// non-matching mesh with the elastic block (the hardest cells above), set down and stopping.
// With 10-node tetrahedra (Cells::Tet10, not in the suite: 1-10 minutes a cell) the stopping runs
// hold (0.002%), and so does the set-down in S2S symmetric, but set down in S2S one-way, N2S
// one-way and N2S symmetric the block slides: 1.2-1.7 mm in 0.1 s, 0.04 m/s (2026-12-04, not
// found yet; docs/verification.md).
std::vector<Case> tetrahedra_cases() {
  std::vector<Case> cases;
  for (auto d : {Discretisation::S2SSymmetric, Discretisation::S2SOneWay, Discretisation::N2SOneWay,
                 Discretisation::N2SSymmetric})
    for (auto p : {Path::SetDown, Path::Stopping})
      cases.push_back({d, Mesh::NonMatching, Body::Elastic, p, Cells::Tet4});
  return cases;
}

INSTANTIATE_TEST_SUITE_P(Tetrahedra, StaticFriction, ::testing::ValuesIn(tetrahedra_cases()),
                         [](const auto& param_info) { return name(param_info.param); });

// Steeper than atan(mu_s): tan(30 deg) = 0.577 > 0.5. The block slides from rest at the dynamic
// rate a = g (sin - mu_d cos) = 1.507 m/s^2 (mu_d = 0.4): 271 mm in 0.6 s (on a plane 1 m long).
// The slip weakening (stick_slip.hpp) keeps the limit above the dynamic one over the first
// D_c = 100 mu_s penetrations (12 um here), which delays the start by a few milliseconds: 1% of
// the distance is the tolerance for that.
TEST(StaticFrictionSteep, SlidesAtTheDynamicRate) {
  for (auto d : {Discretisation::S2SSymmetric, Discretisation::N2SOneWay}) {
    const Case c{d, Mesh::NonMatching, Body::Rigid, Path::SetDown};
    Slope slope{30.0, 0.5, 0.4};
    slope.end = 0.6;
    slope.plane_elements = 24;
    const Motion m = run(c, slope);
    const double t = 30.0 * std::numbers::pi / 180.0;
    const double a = kG * (std::sin(t) - 0.4 * std::cos(t)), expected = 0.5 * a * 0.6 * 0.6;
    std::cout << name(c) << " at 30 deg: slid " << m.final_distance
              << " m, a t^2 / 2 = " << expected << " m, error "
              << 100.0 * (m.final_distance - expected) / expected << "%\n";
    EXPECT_NEAR(m.final_distance, expected, 0.01 * expected);
  }
}

}  // namespace
}  // namespace abut
