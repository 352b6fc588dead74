// Static contact against closed-form references (issue 10).
//  - Contact patch test (Taylor & Papadopoulos 1991, "On a patch test for contact problems in
//    two dimensions"; Crisfield 2000, "Re-visiting the contact patch test", IJNME 48:435): two
//    blocks with non-matching meshes pressed by a uniform pressure transmit it uniformly.
//  - Sliding with Coulomb friction under a constant normal load: once the block slides, the
//    shear force is mu times the normal force (Coulomb's law itself).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

#include "abut/mesh/generators.hpp"
#include "abut/solver/static_solver.hpp"

namespace abut {
namespace {

constexpr double kE = 210000.0, kNu = 0.3;

// Newton tolerances far below the defaults (0.5% of the average force), so that the comparison
// measures the discretisation, not the stopping rule.
StaticControls tight() {
  StaticControls c;
  c.force_tolerance = 1e-8;
  c.displacement_tolerance = 1e-6;
  return c;
}

// A lower block [0,1]^2 x [0,1] (part 1, n1 x n1 x 2 hexes) and an upper block [0,1]^2 x [1,2]
// (part 2, n2 x n2 x 2), touching at z = 1; the bottom held in z, the planes x = 0 and y = 0 in x
// and y (symmetry: no rigid motion, free Poisson expansion).
Model two_blocks(int n1, int n2) {
  Model m;
  generate_box(m.mesh, {1, n1, n1, 2, {0, 0, 0}, {1, 1, 1}});
  generate_box(m.mesh, {2, n2, n2, 2, {0, 0, 1}, {1, 1, 2}});
  Material mat;
  mat.id = 1;
  mat.params = ElasticParams{7.8e-9, kE, kNu};
  m.materials.push_back(mat);
  for (int id = 1; id <= 2; ++id) {
    Part p;
    p.id = id;
    p.material_id = 1;
    p.solid_integration = Part::SolidIntegration::Full;
    m.parts.push_back(p);
  }
  StaticStep step;
  const Nodes& n = m.mesh.nodes;
  for (std::size_t i = 0; i < n.size(); ++i) {
    const auto node = static_cast<std::int32_t>(i);
    if (n.z[i] == 0.0) step.displacements.push_back({node, 2, 0.0, {}, {}});
    if (n.x[i] == 0.0) step.displacements.push_back({node, 0, 0.0, {}, {}});
    if (n.y[i] == 0.0) step.displacements.push_back({node, 1, 0.0, {}, {}});
  }
  m.static_steps.push_back(step);
  m.time.end_time = 1.0;
  return m;
}

// The faces (local face `face`) of the hexes of `part` whose nodes all satisfy `on`.
FaceSet faces_where(const Model& m, std::int64_t id, std::int64_t part, int face,
                    const std::function<bool(const Vec3&)>& on) {
  FaceSet s;
  s.id = id;
  for (std::size_t h = 0; h < m.mesh.hex_count(); ++h) {
    if (m.mesh.hex_part[h] != part) continue;
    bool all = true;
    for (const int a : kHexFaces[face]) all = all && on(m.mesh.nodes.position(m.mesh.hexes[h][a]));
    if (all) s.faces.push_back({static_cast<std::int32_t>(h), static_cast<std::int8_t>(face)});
  }
  return s;
}

// Contact of the upper block's bottom (secondary) on the lower block's top (main).
void add_contact(Model& m, Discretisation discretisation, double penalty, double mu) {
  auto at = [](double z) { return [z](const Vec3& p) { return std::abs(p.z - z) < 1e-12; }; };
  m.face_sets.push_back(faces_where(m, 1, 2, 0, at(1.0)));  // bottom faces (S1) of part 2
  m.face_sets.push_back(faces_where(m, 2, 1, 1, at(1.0)));  // top faces (S2) of part 1
  ContactSpec c;
  c.id = 1;
  c.surface1 = {EntityType::FaceSet, 1, {}};
  c.surface2 = {EntityType::FaceSet, 2, {}};
  c.discretisation = discretisation;
  c.one_way = true;
  c.penalty = penalty;
  c.damping = 0.0;
  c.friction_law = mu > 0.0 ? ContactSpec::FrictionLaw::Coulomb : ContactSpec::FrictionLaw::None;
  c.mu_static = c.mu_dynamic = mu;
  m.contacts.push_back(c);
}

void press_top(Model& m, StaticStep& step, double p) {
  for (std::size_t h = 0; h < m.mesh.hex_count(); ++h) {
    bool top = true;
    for (const int a : kHexFaces[1]) top = top && m.mesh.nodes.z[m.mesh.hexes[h][a]] == 2.0;
    if (top) step.pressures.push_back({{static_cast<std::int32_t>(h), 1}, p, {}, {}});
  }
}

TEST(StaticContact, PatchTestNonMatchingMeshesTransmitUniformPressure) {
  const double p = 100.0, penalty = 10.0 * kE;  // 10 E / L with L = 1, CalculiX's advice
  for (const Discretisation d : {Discretisation::SurfaceToSurface, Discretisation::NodeToSurface}) {
    Model m = two_blocks(3, 4);
    add_contact(m, d, penalty, 0.0);
    press_top(m, m.static_steps[0], p);
    StaticSolver s(m, tight());
    s.run();
    // Stress uniform in both blocks: sigma_zz = -p, the rest 0.
    double worst = 0.0;
    for (std::size_t k = 0; k < s.stress().size(); k += 6) {
      worst = std::max(worst, std::abs(s.stress()[k + 2] + p));
      for (const int c : {0, 1, 3, 4, 5}) worst = std::max(worst, std::abs(s.stress()[k + c]));
    }
    // Contact pressure at every active point and the total force.
    double pressure_error = 0.0;
    for (const StaticContactPoint& pt : s.contacts()[0].points())
      if (pt.active) pressure_error = std::max(pressure_error, std::abs(pt.pressure - p));
    const Vec3 force = s.contacts()[0].total_force();
    std::cout << (d == Discretisation::SurfaceToSurface ? "S2S" : "N2S") << ": worst stress error "
              << worst / p << " of p, pressure error " << pressure_error / p << ", total force "
              << force.z << "\n";
    if (d == Discretisation::SurfaceToSurface) {
      EXPECT_LT(worst, 0.01 * p);
      EXPECT_LT(pressure_error, 0.01 * p);
    }
    // Equilibrium, to the Newton tolerance, for both discretisations.
    EXPECT_NEAR(force.z, p * 1.0, 1e-4 * p);
  }
}

TEST(StaticContact, SlidingBlockShearIsMuTimesNormalForce) {
  const double mu = 0.3, penalty = 10.0 * kE;
  Model m = two_blocks(2, 2);
  add_contact(m, Discretisation::SurfaceToSurface, penalty, mu);
  // The upper block is held only by its top face: pressed down by 1 um in step 1 (the face kept
  // level, so the block cannot tip), dragged 10 um along x in step 2 (far beyond the stick
  // limit mu p / k_t = 0.014 um: every point slides).
  StaticStep& step1 = m.static_steps[0];
  std::vector<std::uint8_t> upper(m.mesh.nodes.size(), 0);
  for (std::size_t h = 0; h < m.mesh.hex_count(); ++h)
    if (m.mesh.hex_part[h] == 2)
      for (const std::int32_t a : m.mesh.hexes[h]) upper[a] = 1;
  std::vector<StepDisplacement> kept;
  for (const StepDisplacement& d : step1.displacements)
    if (!upper[d.node]) kept.push_back(d);
  step1.displacements = kept;
  std::vector<std::int32_t> top;
  for (std::size_t i = 0; i < m.mesh.nodes.size(); ++i)
    if (m.mesh.nodes.z[i] == 2.0) top.push_back(static_cast<std::int32_t>(i));
  for (const std::int32_t i : top) {
    step1.displacements.push_back({i, 0, 0.0, {}, {}});
    step1.displacements.push_back({i, 1, 0.0, {}, {}});
    step1.displacements.push_back({i, 2, -1e-3, {}, {}});
  }
  StaticStep step2 = step1;
  step2.initial_increment = 0.1;
  for (StepDisplacement& d : step2.displacements)
    if (m.mesh.nodes.z[d.node] == 2.0 && d.dof == 0) d.value = 0.01;
  m.static_steps.push_back(step2);
  StaticSolver s(m, tight());
  s.run();
  double rx = 0.0, rz = 0.0;
  for (const std::int32_t i : top) rx += s.reaction()[3 * i], rz += s.reaction()[3 * i + 2];
  // The driven face pulls the block against friction and presses it: rx = mu |rz|.
  std::cout << "shear " << rx << ", normal " << -rz << ", ratio " << rx / -rz << "\n";
  EXPECT_GT(-rz, 100.0);
  EXPECT_NEAR(rx / -rz, mu, 0.005 * mu);
  int active = 0;
  for (const StaticContactPoint& pt : s.contacts()[0].points())
    if (pt.active) {
      ++active;
      EXPECT_TRUE(pt.slipping);
    }
  EXPECT_EQ(active, 16);
}

}  // namespace
}  // namespace abut
