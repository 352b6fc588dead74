// Static contact against closed-form references (issue 10).
//  - Contact patch test (Taylor & Papadopoulos 1991, "On a patch test for contact problems in
//    two dimensions"; Crisfield 2000, "Re-visiting the contact patch test", IJNME 48:435): two
//    blocks with non-matching meshes pressed by a uniform pressure transmit it uniformly.
//  - Sliding with Coulomb friction under a constant normal load: once the block slides, the
//    shear force is mu times the normal force (Coulomb's law itself).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
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

// Parts 1 and 2 of one elastic material (steel-like, N and mm), fully integrated hexes.
void add_elastic_parts(Model& m) {
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
}

// A lower block [0,1]^2 x [0,1] (part 1, n1 x n1 x 2 hexes) and an upper block [0,1]^2 x [1,2]
// (part 2, n2 x n2 x 2), touching at z = 1; the bottom held in z, the planes x = 0 and y = 0 in x
// and y (symmetry: no rigid motion, free Poisson expansion).
Model two_blocks(int n1, int n2) {
  Model m;
  generate_box(m.mesh, {1, n1, n1, 2, {0, 0, 0}, {1, 1, 1}});
  generate_box(m.mesh, {2, n2, n2, 2, {0, 0, 1}, {1, 1, 2}});
  add_elastic_parts(m);
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
void add_contact(Model& m, Discretisation discretisation, double penalty, double mu,
                 bool one_way = true) {
  auto at = [](double z) { return [z](const Vec3& p) { return std::abs(p.z - z) < 1e-12; }; };
  m.face_sets.push_back(faces_where(m, 1, 2, 0, at(1.0)));  // bottom faces (S1) of part 2
  m.face_sets.push_back(faces_where(m, 2, 1, 1, at(1.0)));  // top faces (S2) of part 1
  ContactSpec c;
  c.id = 1;
  c.surface1 = {EntityType::FaceSet, 1, {}};
  c.surface2 = {EntityType::FaceSet, 2, {}};
  c.discretisation = discretisation;
  c.one_way = one_way;
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

// The largest |sigma - (-p e_z e_z)| over the Gauss points of `part`'s hexes, over p.
double stress_error(const StaticSolver& s, const Model& m, std::int64_t part, double p) {
  double worst = 0.0;
  std::size_t k = 0;
  for (std::size_t h = 0; h < m.mesh.hex_count(); ++h)
    for (int g = 0; g < 8; ++g, k += 6) {
      if (m.mesh.hex_part[h] != part) continue;
      worst = std::max(worst, std::abs(s.stress()[k + 2] + p));
      for (const int c : {0, 1, 3, 4, 5}) worst = std::max(worst, std::abs(s.stress()[k + c]));
    }
  return worst / p;
}

// The largest |pressure - p_c| over the active points of every pass, over p. The contact
// pressure acts on the current area, which the Poisson expansion of the pressed block has grown
// by (1 + nu p / E)^2: p_c = p / (1 + nu p / E)^2 carries the load p over the reference area.
double pressure_error(const StaticSolver& s, double p) {
  const double stretch = 1.0 + kNu * p / kE;
  const double expected = p / (stretch * stretch);
  double worst = 0.0;
  for (const StaticContact& c : s.contacts())
    for (const StaticContactPoint& pt : c.points())
      if (pt.active) worst = std::max(worst, std::abs(pt.pressure - expected));
  return worst / p;
}

// The contact force on part `part`, summed over the passes (each gives the force on its
// secondary surface).
Vec3 contact_force(const StaticSolver& s, const Model& m, std::int64_t part) {
  std::vector<std::uint8_t> in_part(m.mesh.nodes.size(), 0);
  for (std::size_t h = 0; h < m.mesh.hex_count(); ++h)
    if (m.mesh.hex_part[h] == part)
      for (const std::int32_t a : m.mesh.hexes[h]) in_part[a] = 1;
  Vec3 f;
  for (const StaticContact& c : s.contacts())
    f += c.total_force() * (in_part[c.secondary().facets.at(0)[0]] ? 1.0 : -1.0);
  return f;
}

// Issue 27: surface-to-surface contact integrates each point's cell over the facets it covers
// (mortar.hpp), so a uniform pressure crosses non-matching meshes exactly, one-way and
// symmetric; node-to-surface does not pass the patch test (Taylor & Papadopoulos 1991) and is
// held to equilibrium only.
TEST(StaticContact, PatchTestNonMatchingMeshesTransmitUniformPressure) {
  const double p = 100.0, penalty = 10.0 * kE;  // 10 E / L with L = 1, CalculiX's advice
  struct Cell {
    Discretisation discretisation;
    bool one_way;
    const char* name;
  };
  for (const Cell& cell : {Cell{Discretisation::SurfaceToSurface, true, "S2S one-way"},
                           Cell{Discretisation::SurfaceToSurface, false, "S2S symmetric"},
                           Cell{Discretisation::NodeToSurface, true, "N2S one-way"}}) {
    Model m = two_blocks(3, 4);
    add_contact(m, cell.discretisation, penalty, 0.0, cell.one_way);
    press_top(m, m.static_steps[0], p);
    StaticSolver s(m, tight());
    s.run();
    // Stress uniform in both blocks: sigma_zz = -p, the rest 0.
    const double stress = std::max(stress_error(s, m, 1, p), stress_error(s, m, 2, p));
    const double pressure = pressure_error(s, p);
    const Vec3 force = contact_force(s, m, 2);
    std::cout << cell.name << ": worst stress error " << stress << " of p, pressure error "
              << pressure << ", total force " << force.z << "\n";
    if (cell.discretisation == Discretisation::SurfaceToSurface) {
      EXPECT_LT(stress, 1e-6) << cell.name;
      EXPECT_LT(pressure, 1e-6) << cell.name;
    }
    // Equilibrium, to the Newton tolerance, for both discretisations.
    EXPECT_NEAR(force.z, p * 1.0, 1e-6 * p) << cell.name;
  }
}

// The contact patch test across an interface whose meshes neither match nor line up: a block
// (4 x 4 x 2 hexes) turned about z by a random angle and offset by random fractions of an element
// (fixed seeds) stands on a larger held foundation (5 x 5 facets) and is pressed by p on its
// top. Its stress is -p e_z e_z exactly when every node of its bottom gets p times its
// consistent share of the footprint. The foundation's own points (symmetric contact, or the
// foundation as the secondary surface) see the block's border cross their cells: point-wise
// they would count whole cells or none.
TEST(StaticContact, PatchTestOnATurnedAndOffsetBlockHoldsToRoundOff) {
  const double p = 100.0, penalty = 10.0 * kE;
  std::mt19937 random(27);
  std::uniform_real_distribution<double> fraction(0.0, 1.0);
  for (int sample = 0; sample < 3; ++sample) {
    const double angle = 0.5 * fraction(random);  // radians
    const double dx = 0.2 * fraction(random), dy = 0.2 * fraction(random);
    for (const bool one_way : {true, false}) {
      for (const bool foundation_secondary : {false, true}) {
        if (!one_way && foundation_secondary) continue;  // symmetric: both ways already
        Model m;
        generate_box(m.mesh, {1, 5, 5, 1, {-1.0, -1.0, 0.0}, {2.0, 2.0, 1.0}});
        generate_box(m.mesh, {2, 4, 4, 2, {0.0, 0.0, 1.0}, {1.0, 1.0, 2.0}});
        add_elastic_parts(m);
        // Turn the block about its axis and offset it.
        std::vector<std::uint8_t> block(m.mesh.nodes.size(), 0);
        for (std::size_t h = 0; h < m.mesh.hex_count(); ++h)
          if (m.mesh.hex_part[h] == 2)
            for (const std::int32_t a : m.mesh.hexes[h]) block[a] = 1;
        Nodes& n = m.mesh.nodes;
        for (std::size_t i = 0; i < n.size(); ++i) {
          if (!block[i]) continue;
          const double x = n.x[i] - 0.5, y = n.y[i] - 0.5;
          n.x[i] = 0.5 + dx + std::cos(angle) * x - std::sin(angle) * y;
          n.y[i] = 0.5 + dy + std::sin(angle) * x + std::cos(angle) * y;
        }
        // The foundation held; the block held against rigid motion in its plane only (statically
        // determinate: no reaction): its corner at (0, 0, 2) in x and y, the next in y.
        StaticStep step;
        std::int32_t corner = -1, next = -1;
        for (std::size_t i = 0; i < n.size(); ++i) {
          const auto node = static_cast<std::int32_t>(i);
          if (!block[i]) {
            for (int d = 0; d < 3; ++d) step.displacements.push_back({node, d, 0.0, {}, {}});
            continue;
          }
          const double x = 0.5 + dx - 0.5 * std::cos(angle) + 0.5 * std::sin(angle);
          const double y = 0.5 + dy - 0.5 * std::sin(angle) - 0.5 * std::cos(angle);
          if (n.z[i] == 2.0 && std::abs(n.x[i] - x) < 1e-12 && std::abs(n.y[i] - y) < 1e-12)
            corner = node;
        }
        ASSERT_GE(corner, 0);
        for (std::size_t i = 0; i < n.size(); ++i)
          if (block[i] && n.z[i] == 2.0 && i != static_cast<std::size_t>(corner) &&
              std::abs(std::hypot(n.x[i] - n.x[corner], n.y[i] - n.y[corner]) - 0.25) < 1e-12) {
            next = static_cast<std::int32_t>(i);
            break;
          }
        ASSERT_GE(next, 0);
        step.displacements.push_back({corner, 0, 0.0, {}, {}});
        step.displacements.push_back({corner, 1, 0.0, {}, {}});
        step.displacements.push_back({next, 1, 0.0, {}, {}});
        m.static_steps.push_back(step);
        m.time.end_time = 1.0;
        press_top(m, m.static_steps[0], p);
        auto at = [](double z) { return [z](const Vec3& x) { return std::abs(x.z - z) < 1e-12; }; };
        m.face_sets.push_back(faces_where(m, 1, 2, 0, at(1.0)));  // the block's bottom
        m.face_sets.push_back(faces_where(m, 2, 1, 1, at(1.0)));  // the foundation's top
        ContactSpec c;
        c.id = 1;
        c.surface1 = {EntityType::FaceSet, foundation_secondary ? 2 : 1, {}};
        c.surface2 = {EntityType::FaceSet, foundation_secondary ? 1 : 2, {}};
        c.discretisation = Discretisation::SurfaceToSurface;
        c.one_way = one_way;
        c.penalty = penalty;
        c.damping = 0.0;
        m.contacts.push_back(c);
        StaticSolver s(m, tight());
        s.run();
        const double stress = stress_error(s, m, 2, p), pressure = pressure_error(s, p);
        const Vec3 force = contact_force(s, m, 2);
        const char* name = !one_way               ? "symmetric"
                           : foundation_secondary ? "one-way, the foundation secondary"
                                                  : "one-way, the block secondary";
        std::cout << "sample " << sample << " (" << angle << " rad, " << dx << ", " << dy << "), "
                  << name << ": stress error " << stress << " of p, pressure error " << pressure
                  << ", force " << force.z << "\n";
        EXPECT_LT(stress, 1e-6) << name << ", sample " << sample;
        EXPECT_LT(pressure, 1e-6) << name << ", sample " << sample;
        EXPECT_NEAR(force.z, p, 1e-6 * p) << name << ", sample " << sample;
      }
    }
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

// 1 for the nodes of `part`'s hexahedra.
std::vector<std::uint8_t> nodes_of_part(const Model& m, std::int64_t part) {
  std::vector<std::uint8_t> in(m.mesh.nodes.size(), 0);
  for (std::size_t h = 0; h < m.mesh.hex_count(); ++h)
    if (m.mesh.hex_part[h] == part)
      for (const std::int32_t a : m.mesh.hexes[h]) in[a] = 1;
  return in;
}

// Two blocks of two_blocks(2, 2) with the lower one held at every node (a rigid foundation) and
// the upper one pressed by a pressure p on its top, held in x and y at every node (it translates
// as a whole: no shear, no tipping, no Poisson slip sideways): the contact pressure is p and every
// point slips alike, along x only. Step 1 presses it; step 2 moves it along x to `drag` in
// `increments` fixed increments.
struct DraggedBlock {
  Model m;
  std::vector<std::int32_t> upper;
  DraggedBlock(double p, double drag, int increments,
               const std::function<void(ContactSpec&)>& law) {
    m = two_blocks(2, 2);
    add_contact(m, Discretisation::SurfaceToSurface, 10.0 * kE, 0.0);
    law(m.contacts.back());
    const std::vector<std::uint8_t> in_upper = nodes_of_part(m, 2);
    StaticStep& step1 = m.static_steps[0];
    step1.displacements.clear();
    for (std::size_t i = 0; i < m.mesh.nodes.size(); ++i) {
      const auto node = static_cast<std::int32_t>(i);
      if (!in_upper[i]) {
        for (int dof = 0; dof < 3; ++dof) step1.displacements.push_back({node, dof, 0.0, {}, {}});
        continue;
      }
      upper.push_back(node);
      step1.displacements.push_back({node, 0, 0.0, {}, {}});
      step1.displacements.push_back({node, 1, 0.0, {}, {}});
    }
    press_top(m, step1, p);
    StaticStep step2 = step1;
    step2.initial_increment = 1.0 / increments;
    step2.max_increment = 1.0 / increments;
    for (StepDisplacement& d : step2.displacements)
      if (in_upper[d.node] && d.dof == 0) d.value = drag;
    m.static_steps.push_back(step2);
  }
  // The friction force on the upper block (the reaction of its held x dofs).
  double shear(const StaticSolver& s) const {
    double rx = 0.0;
    for (const std::int32_t i : upper) rx += s.reaction()[3 * i];
    return rx;
  }
};

// Tresca (Metafor's TrescaContactMaterial, seed 002): sliding shear m_d k A whatever the pressure.
// Face A = 1 mm^2, k = 100 MPa, m_d = 0.5: 50 N, pressed by 100 and 200 MPa (Coulomb would give
// mu times those). The drag, 1e-4 mm, is far beyond the stick spring's m k / k_t = 2.4e-5 mm;
// the overlap shrinks by it (1e-4 of A).
TEST(StaticContact, TrescaSlidingShearIsMdKTimesAreaWhateverThePressure) {
  for (const double p : {100.0, 200.0}) {
    DraggedBlock b(p, 1e-4, 4, [](ContactSpec& c) {
      c.friction_law = ContactSpec::FrictionLaw::Tresca;
      c.friction_c[0] = 0.6;
      c.friction_c[1] = 0.5;
      c.friction_c[2] = 100.0;
    });
    StaticSolver s(b.m, tight());
    s.run();
    const double shear = b.shear(s);
    std::cout << "Tresca, pressed by " << p << " MPa: shear " << shear << " N\n";
    EXPECT_NEAR(shear, 0.5 * 100.0 * 1.0, 1e-3 * 50.0);
  }
}

// Friction by part pair in a static step (*CONTACT_FRICTION_PAIR, Radioss /FRICTION fric_ID, seed
// 004): the contact's Coulomb mu = 0.1, and mu = 0.3 between parts 1 and 2 either way round. The
// block dragged under p = 100 MPa on A = 1 mm^2 slides at the pair's 0.3 p A = 30 N; with the pair
// given for part 1 with itself (which no point meets here) at the contact's 0.1 p A = 10 N.
TEST(StaticContact, FrictionByPartPairReplacesTheContactsLaw) {
  struct Case {
    std::int64_t set1, set2;
    double mu;
  };
  for (const Case& c : {Case{2, 1, 0.3}, Case{1, 2, 0.3}, Case{1, 1, 0.1}}) {
    DraggedBlock b(100.0, 1e-4, 4, [&](ContactSpec& spec) {
      spec.friction_law = ContactSpec::FrictionLaw::Coulomb;
      spec.mu_static = spec.mu_dynamic = 0.1;
      ContactSpec::FrictionPair pair;
      pair.set1 = EntityRef{EntityType::Part, c.set1, {}};
      pair.set2 = EntityRef{EntityType::Part, c.set2, {}};
      pair.law = ContactSpec::FrictionLaw::Coulomb;
      pair.mu_static = pair.mu_dynamic = 0.3;
      spec.friction_pairs.push_back(pair);
    });
    StaticSolver s(b.m, tight());
    s.run();
    const double shear = b.shear(s);
    std::cout << "pair " << c.set1 << "-" << c.set2 << ": shear " << shear << " N\n";
    EXPECT_NEAR(shear, c.mu * 100.0, 1e-3 * c.mu * 100.0);
  }
}

// Static and dynamic Coulomb (Metafor's CoulombContactMaterial, seed 002), mu_s = 0.5, mu_d = 0.3,
// p = 100 MPa on A = 1 mm^2, the stick spring k_t = the penalty (2.1e6 N/mm^3): the shear is
// k_t u A while it sticks, u the drag, up to mu_s p A = 50 N at u = 2.38e-5 mm, then mu_d p A.
// Dragged in 60 increments of 1e-6 mm (0.021 of p A each): the largest shear at a converged
// increment is within one increment below mu_s p A, the last is mu_d p A.
TEST(StaticContact, StaticCoulombHoldsUpToMuSThenSlidesAtMuD) {
  const double mu_s = 0.5, mu_d = 0.3, p = 100.0;
  DraggedBlock b(p, 6e-5, 60, [&](ContactSpec& c) {
    c.friction_law = ContactSpec::FrictionLaw::Coulomb;
    c.mu_static = mu_s;
    c.mu_dynamic = mu_d;
  });
  StaticSolver s(b.m, tight());
  double largest = 0.0;
  s.run([&](const StaticIncrement& inc) {
    if (inc.step == 1) largest = std::max(largest, b.shear(s));
  });
  const double shear = b.shear(s), increment = 10.0 * kE * 1e-6 * 1.0;
  std::cout << "static/dynamic Coulomb: largest shear " << largest << " N (mu_s p A = " << mu_s * p
            << "), at the end " << shear << " N (mu_d p A = " << mu_d * p << ")\n";
  EXPECT_LE(largest, mu_s * p * (1.0 + 1e-9));
  EXPECT_GT(largest, mu_s * p - increment);
  EXPECT_NEAR(shear, mu_d * p, 1e-6 * mu_d * p);
  for (const StaticContactPoint& pt : s.contacts()[0].points())
    if (pt.active) {
      EXPECT_TRUE(pt.slipping);
    }
}

// A law of the sliding speed in a static step (Radioss Ifric 1, seed 004): mu = Fric + C2 V with
// V the slip over an increment over its length in step time: 1e-6 mm per 1/60 of the step,
// V = 6e-5 mm per unit time, mu = 0.2 + 1000 V = 0.26, shear mu p A = 26 N once it slides.
TEST(StaticContact, SpeedDependentFrictionSlidesAtMuOfTheIncrementsSlipSpeed) {
  const double p = 100.0;
  DraggedBlock b(p, 6e-5, 60, [](ContactSpec& c) {
    c.friction_law = ContactSpec::FrictionLaw::Viscous;
    c.mu_static = 0.2;  // Fric
    c.friction_c = {0.0, 1000.0, 0.0, 0.0, 0.0, 0.0};
  });
  StaticSolver s(b.m, tight());
  s.run();
  std::cout << "viscous friction: shear " << b.shear(s) << " N\n";
  EXPECT_NEAR(b.shear(s), 0.26 * p, 1e-6 * 0.26 * p);
}

// Adhesion in a static step (Radioss IVIS2 = -1, seed 004 comment 12): Gap = 0.2 mm, SigMaxAdh
// = 10 MPa on A = 1 mm^2. The upper block of two_blocks(2, 2), moved as a whole (every node
// prescribed) onto the held lower one, pressed 1e-4 mm (step 1), then lifted to 0.15 mm in 25
// increments (step 2). Opened by s <= Gap/2 it is pulled back by SigMaxAdh A s / (Gap/2); beyond
// Gap/2 the bond breaks: no force.
TEST(StaticContact, AdhesionPullsBackInItsZoneThenLetsGo) {
  Model m = two_blocks(2, 2);
  add_contact(m, Discretisation::SurfaceToSurface, 10.0 * kE, 0.0);
  m.contacts.back().adhesion = Adhesion{0.2, 10.0, 0.0, 1.0};
  const std::vector<std::uint8_t> in_upper = nodes_of_part(m, 2);
  StaticStep& step1 = m.static_steps[0];
  step1.displacements.clear();
  std::vector<std::int32_t> upper;
  for (std::size_t i = 0; i < m.mesh.nodes.size(); ++i) {
    const auto node = static_cast<std::int32_t>(i);
    if (in_upper[i]) upper.push_back(node);
    for (int dof = 0; dof < 3; ++dof)
      step1.displacements.push_back({node, dof, in_upper[i] && dof == 2 ? -1e-4 : 0.0, {}, {}});
  }
  StaticStep step2 = step1;
  const int increments = 25;
  step2.initial_increment = 1.0 / increments;
  step2.max_increment = 1.0 / increments;
  for (StepDisplacement& d : step2.displacements)
    if (in_upper[d.node] && d.dof == 2) d.value = 0.15;
  m.static_steps.push_back(step2);
  StaticSolver s(m, tight());
  double worst = 0.0;
  int pulled = 0, free = 0;
  s.run([&](const StaticIncrement& inc) {
    if (inc.step != 1) return;
    const double lift = -1e-4 + (0.15 + 1e-4) * inc.step_time;  // the step time runs to 1
    double pull = 0.0;  // the supports hold the block against the pull: their reaction
    for (const std::int32_t i : upper) pull += s.reaction()[3 * i + 2];
    const double expected = lift <= 0.1 ? 10.0 * 1.0 * std::max(lift, 0.0) / 0.1 : 0.0;
    worst = std::max(worst, std::abs(pull - expected));
    (lift <= 0.1 ? pulled : free) += 1;
  });
  std::cout << "adhesion: worst |pull - SigMaxAdh A s / (Gap/2)| " << worst << " N over " << pulled
            << " increments in the zone and " << free << " beyond\n";
  EXPECT_LT(worst, 1e-6 * 10.0);
  EXPECT_GT(pulled, 10);
  EXPECT_GT(free, 5);
}

// OptiStruct GPAD (seed 003, CONTPRM: "subtracted from contact gap opening"): the blocks of
// two_blocks(2, 2) touch at z = 1; with a padding of 0.01 mm they overlap it by 0.01 mm. Both moved
// as a whole (every node prescribed), the upper one lifted by s in 20 increments to 0.02 mm: the
// pressure is pfac (0.01 - s) while s < 0.01 and 0 beyond, on A = 1 mm^2, so the supports of the
// upper block pull it down by pfac (0.01 - s) A (every initial penetration pushes: FORCE).
TEST(StaticContact, PaddingMakesTheSurfacesTouchAtItsDistance) {
  const double pfac = 1000.0, pad = 0.01;
  Model m = two_blocks(2, 2);
  add_contact(m, Discretisation::SurfaceToSurface, pfac, 0.0);
  m.contacts.back().gaps.padding = pad;
  m.contacts.back().initial_penetration = InitialPenetration::Force;
  const std::vector<std::uint8_t> in_upper = nodes_of_part(m, 2);
  StaticStep& step = m.static_steps[0];
  step.displacements.clear();
  std::vector<std::int32_t> upper;
  for (std::size_t i = 0; i < m.mesh.nodes.size(); ++i) {
    const auto node = static_cast<std::int32_t>(i);
    if (in_upper[i]) upper.push_back(node);
    for (int dof = 0; dof < 3; ++dof)
      step.displacements.push_back({node, dof, in_upper[i] && dof == 2 ? 2.0 * pad : 0.0, {}, {}});
  }
  step.initial_increment = step.max_increment = 1.0 / 20;
  StaticSolver s(m, tight());
  double worst = 0.0;
  int pressed = 0, open = 0;
  s.run([&](const StaticIncrement& inc) {
    const double lift = 2.0 * pad * inc.step_time;
    double push = 0.0;  // the supports' reaction on the upper block, against the contact
    for (const std::int32_t i : upper) push -= s.reaction()[3 * i + 2];
    const double expected = pfac * std::max(pad - lift, 0.0) * 1.0;
    worst = std::max(worst, std::abs(push - expected));
    (lift < pad ? pressed : open) += 1;
  });
  std::cout << "padding: worst |force - pfac (pad - s) A| " << worst << " N over " << pressed
            << " pressed increments and " << open << " open\n";
  EXPECT_LT(worst, 1e-9 * pfac * pad);
  EXPECT_GT(pressed, 5);
  EXPECT_GT(open, 5);
}

}  // namespace
}  // namespace abut
