// *CONTACT_DEPENDENCY (Metafor's TM dependencies, seed 002) in static steps. The model is the
// dragged block of test_static_contact.cpp: two elastic unit cubes (2 x 2 x 2 fully integrated
// hexahedra each), the lower one held at every node, the upper one pressed by a pressure p on its
// top and held in x and y at every node, so the contact pressure is p over A = 1 mm^2 and every
// point slips alike.
//  - PEN_NORMALE times f(t): the pressure p = pfac f(t) d, so the penetration is p / (pfac f(t))
//    at every converged increment (a penalty spring in series with nothing else: the lower block
//    is held at every node and the upper one carries p uniformly);
//  - COEF_FROT_DYN times f(t), dragged along x in step 2 far beyond the stick spring's elastic
//    range: once sliding, the shear is mu_d f(t) p A at each converged increment (Coulomb's law
//    of sliding friction), f at the increment's total time;
//  - TRESCA_DYN_M times f(t): the sliding shear is m_d f(t) k A whatever p, with A the overlap of
//    the faces, which the drag u shrinks to 1 - u (mm^2; as in test_static_contact.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <iostream>
#include <vector>

#include "abut/mesh/generators.hpp"
#include "abut/solver/static_solver.hpp"

namespace abut {
namespace {

constexpr double kE = 210000.0, kPfac = 10.0 * kE;

StaticControls tight() {
  StaticControls c;
  c.force_tolerance = 1e-8;
  c.displacement_tolerance = 1e-6;
  return c;
}

// The upper block pressed by p (step 1, [0, 1]) and dragged along x to `drag` in `increments`
// equal increments (step 2, [1, 2]). `law` sets the contact's laws; `functions` the model's.
struct DraggedBlock {
  Model m;
  std::vector<std::int32_t> upper;
  DraggedBlock(double p, double drag, int increments,
               const std::function<void(Model&, ContactSpec&)>& law) {
    generate_box(m.mesh, {1, 2, 2, 2, {0, 0, 0}, {1, 1, 1}});
    generate_box(m.mesh, {2, 2, 2, 2, {0, 0, 1}, {1, 1, 2}});
    Material mat;
    mat.id = 1;
    mat.params = ElasticParams{7.8e-9, kE, 0.3};
    m.materials.push_back(mat);
    for (int id = 1; id <= 2; ++id) {
      Part part;
      part.id = id;
      part.material_id = 1;
      part.solid_integration = Part::SolidIntegration::Full;
      m.parts.push_back(part);
    }
    m.time.end_time = 2.0;
    FaceSet s1, s2;
    s1.id = 1, s2.id = 2;
    const Nodes& n = m.mesh.nodes;
    StaticStep step1;
    for (std::size_t h = 0; h < m.mesh.hex_count(); ++h) {
      const auto hex = static_cast<std::int32_t>(h);
      const auto& nodes = m.mesh.hexes[h];
      bool bottom = true, top = true;
      for (const int a : kHexFaces[0]) bottom = bottom && n.z[nodes[a]] == 1.0;
      for (const int a : kHexFaces[1]) top = top && n.z[nodes[a]] == 1.0;
      bool loaded = true;
      for (const int a : kHexFaces[1]) loaded = loaded && n.z[nodes[a]] == 2.0;
      if (m.mesh.hex_part[h] == 2 && bottom) s1.faces.push_back({hex, 0});
      if (m.mesh.hex_part[h] == 1 && top) s2.faces.push_back({hex, 1});
      if (m.mesh.hex_part[h] == 2 && loaded) step1.pressures.push_back({{hex, 1}, p, {}, {}});
    }
    m.face_sets = {s1, s2};
    ContactSpec c;
    c.id = 1;
    c.surface1 = {EntityType::FaceSet, 1, {}};
    c.surface2 = {EntityType::FaceSet, 2, {}};
    c.discretisation = Discretisation::SurfaceToSurface;
    c.one_way = true;
    c.penalty = kPfac;
    c.damping = 0.0;
    law(m, c);
    m.contacts.push_back(c);
    std::vector<std::uint8_t> in_upper(n.size(), 0);
    for (std::size_t h = 0; h < m.mesh.hex_count(); ++h)
      if (m.mesh.hex_part[h] == 2)
        for (const std::int32_t a : m.mesh.hexes[h]) in_upper[a] = 1;
    for (std::size_t i = 0; i < n.size(); ++i) {
      const auto node = static_cast<std::int32_t>(i);
      if (!in_upper[i]) {
        for (int dof = 0; dof < 3; ++dof) step1.displacements.push_back({node, dof, 0.0, {}, {}});
        continue;
      }
      upper.push_back(node);
      step1.displacements.push_back({node, 0, 0.0, {}, {}});
      step1.displacements.push_back({node, 1, 0.0, {}, {}});
    }
    step1.initial_increment = step1.max_increment = 0.25;
    m.static_steps.push_back(step1);
    StaticStep step2 = step1;
    step2.initial_increment = step2.max_increment = 1.0 / increments;
    for (StepDisplacement& d : step2.displacements)
      if (in_upper[d.node] && d.dof == 0) d.value = drag;
    m.static_steps.push_back(step2);
  }
  double shear(const StaticSolver& s) const {
    double rx = 0.0;
    for (const std::int32_t i : upper) rx += s.reaction()[3 * i];
    return rx;
  }
};

FunctionRef add_function(Model& m, std::int64_t id, const std::string& expression) {
  m.functions.add_function(id, expression, {});
  return m.functions.find(id, {});
}

TEST(StaticContactDependency, PenetrationFollowsTimeDependentPenalty) {
  // f(t) = 1 + t: 1 at the start, 2 at the end of step 1, 3 at the end of step 2 (no drag).
  const double p = 100.0;
  DraggedBlock b(p, 0.0, 4, [](Model& m, ContactSpec& c) {
    c.friction_law = ContactSpec::FrictionLaw::None;
    c.pfac_in_time = add_function(m, 5, "1 + t");
  });
  StaticSolver s(b.m, tight());
  double worst = 0.0;
  int samples = 0;
  s.run([&](const StaticIncrement& inc) {
    const double load = inc.step == 0 ? p * inc.step_time : p;  // step 1 ramps p
    const double d = load / (kPfac * (1.0 + inc.total_time));
    for (const StaticContactPoint& pt : s.contacts()[0].points())
      if (pt.active) {
        worst = std::max(worst, std::abs(-pt.gap - d) / d);
        ++samples;
      }
  });
  std::cout << "static pfac(t): largest |d - p/(pfac f(t))| / d = " << worst << " over " << samples
            << " point-increments\n";
  EXPECT_GT(samples, 30);
  EXPECT_LT(worst, 1e-6);
}

TEST(StaticContactDependency, SlidingShearFollowsTimeDependentDynamicFriction) {
  // mu_s = 0.5, mu_d = 0.3 f(t), f(t) = 1.5 - 0.5 t: 1 at t = 1, 0.5 at t = 2. The stick spring
  // holds up to mu_s p A at a drag of mu_s p / k_t = 2.4e-5 mm; dragged to 2e-4 mm in 40 increments
  // (5e-6 mm each), every point slides from the 6th increment of step 2 on.
  const double p = 100.0;
  DraggedBlock b(p, 2e-4, 40, [](Model& m, ContactSpec& c) {
    c.friction_law = ContactSpec::FrictionLaw::Coulomb;
    c.mu_static = 0.5;
    c.mu_dynamic = 0.3;
    c.mu_dynamic_in_time = add_function(m, 6, "1.5 - 0.5 * t");
  });
  StaticSolver s(b.m, tight());
  double worst = 0.0;
  int samples = 0;
  s.run([&](const StaticIncrement& inc) {
    if (inc.step != 1 || inc.increment < 10) return;
    const double expected = 0.3 * (1.5 - 0.5 * inc.total_time) * p;
    worst = std::max(worst, std::abs(b.shear(s) - expected) / expected);
    ++samples;
  });
  std::cout << "static mu_d(t): largest |shear - mu_d f(t) p A| / (mu_d f p A) = " << worst
            << " over " << samples << " increments\n";
  EXPECT_GT(samples, 20);
  EXPECT_LT(worst, 1e-6);
}

TEST(StaticContactDependency, TrescaSlidingShearFollowsTimeDependentFactor) {
  // m_s = 0.6, m_d = 0.5 f(t), f(t) = 1.5 - 0.5 t, k = 100 MPa, A = 1 - u mm^2 at the drag
  // u = 2e-4 (t - 1) mm: shear 50 f(t) (1 - u) N.
  const double p = 100.0;
  DraggedBlock b(p, 2e-4, 40, [](Model& m, ContactSpec& c) {
    c.friction_law = ContactSpec::FrictionLaw::Tresca;
    c.friction_c = {0.6, 0.5, 100.0, 0.0, 0.0, 0.0};
    c.mu_dynamic_in_time = add_function(m, 6, "1.5 - 0.5 * t");
  });
  StaticSolver s(b.m, tight());
  double worst = 0.0;
  int samples = 0;
  s.run([&](const StaticIncrement& inc) {
    if (inc.step != 1 || inc.increment < 10) return;
    const double u = 2e-4 * (inc.total_time - 1.0);
    const double expected = 0.5 * (1.5 - 0.5 * inc.total_time) * 100.0 * (1.0 - u);
    worst = std::max(worst, std::abs(b.shear(s) - expected) / expected);
    ++samples;
  });
  std::cout << "static Tresca m_d(t): largest relative error " << worst << " over " << samples
            << " increments\n";
  EXPECT_GT(samples, 20);
  EXPECT_LT(worst, 1e-6);
}

}  // namespace
}  // namespace abut
