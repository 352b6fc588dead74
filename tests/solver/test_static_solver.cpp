// The static solver on problems with closed-form answers: a bar of fully integrated hexahedra
// in uniaxial tension (small strain, by force, pressure or displacement; large strain with
// NLGEOM), *EQUATION joining two separate meshes, a model without support, and thread
// independence. The trilinear hex represents a uniform stress exactly, so the answers hold to
// round-off on any mesh.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <vector>

#include "abut/mesh/generators.hpp"
#include "abut/solver/static_solver.hpp"

namespace abut {
namespace {

constexpr double kE = 210000.0, kNu = 0.3, kL = 4.0;

// A bar [0, L] x [0, 1] x [0, 1] of nx x 2 x 2 C3D8 hexes, one elastic part. Supports: the
// end x = 0 held in x; the node at the origin in y and z, the node (0, 1, 0) in z: no rigid
// motion, no lateral restraint (Poisson contraction free).
Model bar(int nx = 4) {
  Model m;
  generate_box(m.mesh, {1, nx, 2, 2, {0, 0, 0}, {kL, 1, 1}});
  Material mat;
  mat.id = 1;
  mat.params = ElasticParams{7.8e-9, kE, kNu};
  m.materials.push_back(mat);
  Part p;
  p.id = 1;
  p.material_id = 1;
  p.solid_integration = Part::SolidIntegration::Full;
  m.parts.push_back(p);
  StaticStep step;
  const Nodes& n = m.mesh.nodes;
  for (std::size_t i = 0; i < n.size(); ++i) {
    if (n.x[i] != 0.0) continue;
    step.displacements.push_back({static_cast<std::int32_t>(i), 0, 0.0, {}, {}});
    if (n.y[i] == 0.0 && n.z[i] == 0.0) {
      step.displacements.push_back({static_cast<std::int32_t>(i), 1, 0.0, {}, {}});
      step.displacements.push_back({static_cast<std::int32_t>(i), 2, 0.0, {}, {}});
    }
    if (n.y[i] == 1.0 && n.z[i] == 0.0)
      step.displacements.push_back({static_cast<std::int32_t>(i), 2, 0.0, {}, {}});
  }
  m.static_steps.push_back(step);
  m.time.end_time = 1.0;
  return m;
}

std::vector<std::int32_t> nodes_at_x(const Model& m, double x) {
  std::vector<std::int32_t> out;
  for (std::size_t i = 0; i < m.mesh.nodes.size(); ++i)
    if (std::abs(m.mesh.nodes.x[i] - x) < 1e-12) out.push_back(static_cast<std::int32_t>(i));
  return out;
}

// Uniaxial stress sigma: u_x = sigma x / E, u_y = -nu sigma y / E (y from the held corner).
void expect_uniaxial(const Model& m, const StaticSolver& s, double sigma) {
  const Nodes& n = m.mesh.nodes;
  for (std::size_t i = 0; i < n.size(); ++i) {
    EXPECT_NEAR(s.displacement()[3 * i], sigma * n.x[i] / kE, 1e-12);
    EXPECT_NEAR(s.displacement()[3 * i + 1], -kNu * sigma * n.y[i] / kE, 1e-12);
    EXPECT_NEAR(s.displacement()[3 * i + 2], -kNu * sigma * n.z[i] / kE, 1e-12);
  }
  for (std::size_t k = 0; k < s.stress().size(); k += 6) {
    EXPECT_NEAR(s.stress()[k], sigma, 1e-9 * sigma);
    for (int c = 1; c < 6; ++c) EXPECT_NEAR(s.stress()[k + c], 0.0, 1e-9 * sigma);
  }
}

TEST(StaticSolver, BarInTensionByNodalForces) {
  Model m = bar();
  const std::vector<std::int32_t> end = nodes_at_x(m, kL);
  // Consistent nodal forces of a uniform traction on a 2 x 2 face: corner 1/16, edge 1/8,
  // centre 1/4 of the total.
  const double total = 100.0;
  for (const std::int32_t i : end) {
    const double y = m.mesh.nodes.y[i], z = m.mesh.nodes.z[i];
    const double wy = (y == 0.5) ? 0.5 : 0.25, wz = (z == 0.5) ? 0.5 : 0.25;
    m.static_steps[0].forces.push_back({i, 0, total * wy * wz, {}, {}});
  }
  StaticSolver s(m);
  int increments = 0;
  s.run([&](const StaticIncrement& inc) {
    ++increments;
    EXPECT_LE(inc.iterations, 1);  // linear: one solve
  });
  EXPECT_EQ(increments, 1);
  expect_uniaxial(m, s, total);
  // The supports carry the load: the x reactions at x = 0 sum to -F.
  double rx = 0.0;
  for (const std::int32_t i : nodes_at_x(m, 0.0)) rx += s.reaction()[3 * i];
  EXPECT_NEAR(rx, -total, 1e-9);
  // Strain energy F^2 L / (2 E A).
  double energy = 0.0;
  for (const double e : s.element_energy()) energy += e;
  EXPECT_NEAR(energy, total * total * kL / (2 * kE), 1e-12);
}

TEST(StaticSolver, BarInTensionByPressureOnItsEndFaces) {
  Model m = bar();
  // Negative pressure on the x = L faces (face 3 = xi = +1, Abaqus S4) pulls.
  for (std::size_t h = 0; h < m.mesh.hex_count(); ++h) {
    bool at_end = true;
    for (const int a : kHexFaces[3]) at_end = at_end && m.mesh.nodes.x[m.mesh.hexes[h][a]] == kL;
    if (at_end)
      m.static_steps[0].pressures.push_back({{static_cast<std::int32_t>(h), 3}, -50.0, {}, {}});
  }
  ASSERT_EQ(m.static_steps[0].pressures.size(), 4u);
  StaticSolver s(m);
  s.run();
  expect_uniaxial(m, s, 50.0);
}

TEST(StaticSolver, PrescribedDisplacementGivesTheReaction) {
  Model m = bar();
  const double d = 0.004;
  for (const std::int32_t i : nodes_at_x(m, kL))
    m.static_steps[0].displacements.push_back({i, 0, d, {}, {}});
  StaticSolver s(m);
  s.run();
  const double sigma = kE * d / kL;
  expect_uniaxial(m, s, sigma);
  double rx = 0.0;
  for (const std::int32_t i : nodes_at_x(m, kL)) rx += s.reaction()[3 * i];
  EXPECT_NEAR(rx, sigma * 1.0, 1e-9 * sigma);
}

// A node that no element uses (CalculiX's cubef2f1/2 decks hold one) has no stiffness: it takes
// no equation and stays put, and the bar's answer is unchanged; a force on it is an error, since
// nothing would carry it.
TEST(StaticSolver, NodeOfNoElementTakesNoPart) {
  const double d = 0.004;
  std::int32_t stray = -1;
  auto with_stray_node = [&]() {
    Model m = bar();
    stray = m.mesh.nodes.add(999, {0.0, 0.0, 5.0});
    for (const std::int32_t i : nodes_at_x(m, kL))
      m.static_steps[0].displacements.push_back({i, 0, d, {}, {}});
    return m;
  };
  Model m = with_stray_node();
  StaticSolver s(m);
  s.run();
  m.mesh.nodes.x.pop_back();  // expect_uniaxial walks the bar's nodes
  m.mesh.nodes.y.pop_back();
  m.mesh.nodes.z.pop_back();
  expect_uniaxial(m, s, kE * d / kL);
  for (int k = 0; k < 3; ++k)
    EXPECT_EQ(s.displacement()[3 * static_cast<std::size_t>(stray) + k], 0.0);
  Model loaded = with_stray_node();
  loaded.static_steps[0].forces.push_back({stray, 2, 1.0, {}, {}});
  StaticSolver t(loaded);
  try {
    t.run();
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("node 999, which belongs to no element"),
              std::string::npos)
        << e.what();
  }
}

// Large stretch with NLGEOM, nu = 0: St Venant-Kirchhoff S11 = E (lambda^2 - 1)/2, first
// Piola-Kirchhoff P11 = lambda S11 = the end force per reference area; Cauchy = P11 (no
// contraction with nu = 0).
TEST(StaticSolver, LargeStretchWithNonlinearGeometry) {
  Model m = bar(2);
  std::get<ElasticParams>(m.materials[0].params).poisson = 0.0;
  m.static_steps[0].nonlinear_geometry = true;
  m.static_steps[0].initial_increment = 0.25;
  const double lambda = 1.5;
  for (const std::int32_t i : nodes_at_x(m, kL))
    m.static_steps[0].displacements.push_back({i, 0, (lambda - 1.0) * kL, {}, {}});
  StaticSolver s(m);
  int iterations = 0;
  s.run([&](const StaticIncrement& inc) { iterations += inc.iterations; });
  EXPECT_GT(iterations, 4);  // nonlinear: Newton iterates
  const double p11 = lambda * kE * (lambda * lambda - 1.0) / 2.0;
  double rx = 0.0;
  for (const std::int32_t i : nodes_at_x(m, kL)) rx += s.reaction()[3 * i];
  EXPECT_NEAR(rx, p11, 1e-6 * p11);
  for (std::size_t k = 0; k < s.stress().size(); k += 6)
    EXPECT_NEAR(s.stress()[k], p11, 1e-6 * p11);
}

// Two bars end to end with duplicate nodes at x = L/2, joined by *EQUATION u_right - u_left = 0
// in all three directions: the same answer as one bar.
TEST(StaticSolver, EquationsJoinTwoMeshes) {
  Model m = bar(2);  // [0, L]; now a second bar [L, 2L] with its own nodes
  Mesh second;
  generate_box(second, {1, 2, 2, 2, {kL, 0, 0}, {2 * kL, 1, 1}});
  const auto offset = static_cast<std::int32_t>(m.mesh.nodes.size());
  for (std::size_t i = 0; i < second.nodes.size(); ++i)
    m.mesh.nodes.add(1000 + static_cast<std::int64_t>(i), second.nodes.position(i));
  for (std::size_t h = 0; h < second.hex_count(); ++h) {
    Hex8 hex = second.hexes[h];
    for (auto& a : hex) a += offset;
    m.mesh.add_hex(100 + static_cast<std::int64_t>(h), 1, hex);
  }
  for (const std::int32_t right : nodes_at_x(m, kL)) {
    if (right < offset) continue;
    for (const std::int32_t left : nodes_at_x(m, kL)) {
      if (left >= offset || m.mesh.nodes.y[left] != m.mesh.nodes.y[right] ||
          m.mesh.nodes.z[left] != m.mesh.nodes.z[right])
        continue;
      for (int dof = 0; dof < 3; ++dof)
        m.equations.push_back({{{right, dof, 1.0}, {left, dof, -1.0}}, {}});
    }
  }
  ASSERT_EQ(m.equations.size(), 27u);
  const double sigma = 80.0;
  for (std::size_t h = 0; h < m.mesh.hex_count(); ++h) {
    bool at_end = true;
    for (const int a : kHexFaces[3])
      at_end = at_end && m.mesh.nodes.x[m.mesh.hexes[h][a]] == 2 * kL;
    if (at_end)
      m.static_steps[0].pressures.push_back({{static_cast<std::int32_t>(h), 3}, -sigma, {}, {}});
  }
  StaticSolver s(m);
  s.run();
  expect_uniaxial(m, s, sigma);
}

TEST(StaticSolver, MissingSupportIsAClearError) {
  Model m = bar(1);
  m.static_steps[0].displacements.clear();
  m.static_steps[0].forces.push_back({0, 0, 1.0, {}, {}});
  StaticSolver s(m);
  try {
    s.run();
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("singular at node"), std::string::npos) << e.what();
  }
}

TEST(StaticSolver, OneAndTwoThreadsBitwiseIdentical) {
  Model m = bar(6);
  m.static_steps[0].nonlinear_geometry = true;
  m.static_steps[0].initial_increment = 0.5;
  for (const std::int32_t i : nodes_at_x(m, kL)) {
    m.static_steps[0].displacements.push_back({i, 0, 0.3, {}, {}});
    m.static_steps[0].displacements.push_back({i, 2, 0.5, {}, {}});
  }
  std::vector<double> u[2];
  for (int t = 1; t <= 2; ++t) {
    omp_set_num_threads(t);
    StaticSolver s(m);
    s.run();
    u[t - 1].assign(s.displacement().begin(), s.displacement().end());
  }
  omp_set_num_threads(1);
  EXPECT_EQ(u[0], u[1]);
}

}  // namespace
}  // namespace abut
