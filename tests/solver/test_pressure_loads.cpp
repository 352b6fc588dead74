// *LOAD_PRESSURE nodal forces (pressure_loads.hpp): the forces on a face sum to -p A n, with A n
// the face's vector area (for a warped quad the vector area of its boundary polygon, the sum of
// the vector areas of the two triangles on either diagonal); on a closed solid they point
// inward (compression) and sum to zero; they follow the pressure's curve in time and the face's
// current orientation.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "abut/io/deck.hpp"
#include "abut/solver/pressure_loads.hpp"

namespace abut {
namespace {

constexpr double kP = 2.0e5;  // pressure of the shell tests [Pa]

// A model of shells of part 1 with a constant pressure kP (curve 1) on P 1.
Model shell_model(const std::vector<Vec3>& points, const std::vector<Quad4>& shells) {
  Model m;
  for (const Vec3& p : points) m.mesh.nodes.add(m.mesh.next_node_id(), p);
  for (const Quad4& q : shells) m.mesh.add_shell(m.mesh.next_shell_id(), 1, q);
  Part part;
  part.id = 1;
  m.parts.push_back(part);
  m.functions.add_curve(1, Curve{{0.0, 1.0}, {kP, kP}}, SourceLocation{});
  PressureLoad load;
  load.entity = {EntityType::Part, 1, {}};
  load.curve = m.functions.find(1, SourceLocation{});
  m.pressures.push_back(load);
  return m;
}

struct Forces {
  std::vector<double> x, y, z;
  Vec3 at(std::size_t i) const { return {x[i], y[i], z[i]}; }
  Vec3 sum() const {
    Vec3 s;
    for (std::size_t i = 0; i < x.size(); ++i) s += at(i);
    return s;
  }
};

Forces forces_at(const Model& m, double t, const Nodes& nodes) {
  PressureLoads loads(m);
  Forces f{std::vector<double>(nodes.size(), 0.0), std::vector<double>(nodes.size(), 0.0),
           std::vector<double>(nodes.size(), 0.0)};
  loads.add_forces(t, nodes.x, nodes.y, nodes.z, f.x, f.y, f.z);
  return f;
}
Forces forces_at(const Model& m, double t) { return forces_at(m, t, m.mesh.nodes); }

void expect_near(const Vec3& a, const Vec3& b, double tolerance) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(PressureLoads, FlatQuadShellPushesAgainstItsNormal) {
  // A 0.2 x 0.1 rectangle counter-clockwise about +z: n = +z, A = 0.02.
  const Model m = shell_model({{0, 0, 0}, {0.2, 0, 0}, {0.2, 0.1, 0}, {0, 0.1, 0}}, {{0, 1, 2, 3}});
  const Forces f = forces_at(m, 0.5);
  for (std::size_t a = 0; a < 4; ++a) expect_near(f.at(a), {0, 0, -kP * 0.02 / 4}, 1e-9);
  expect_near(f.sum(), {0, 0, -kP * 0.02}, 1e-9);
}

TEST(PressureLoads, TriangleShellSharesItsForceInThirds) {
  // Right triangle in the y-z plane, counter-clockwise about +x: A = 0.3 * 0.4 / 2.
  const Model m = shell_model({{1, 0, 0}, {1, 0.3, 0}, {1, 0, 0.4}}, {{0, 1, 2, 2}});
  const Forces f = forces_at(m, 0.5);
  const double area = 0.5 * 0.3 * 0.4;
  for (std::size_t a = 0; a < 3; ++a) expect_near(f.at(a), {-kP * area / 3, 0, 0}, 1e-9);
  expect_near(f.sum(), {-kP * area, 0, 0}, 1e-9);
}

TEST(PressureLoads, WarpedQuadSumsToTheVectorAreaOfItsBoundary) {
  const std::vector<Vec3> p = {{0, 0, 0.02}, {1.1, 0, -0.05}, {1.0, 0.9, 0.1}, {-0.1, 1.0, -0.03}};
  const Model m = shell_model(p, {{0, 1, 2, 3}});
  const Forces f = forces_at(m, 0.5);
  // Independent reference: the two triangles on the diagonal 1-3, and on the diagonal 2-4.
  const Vec3 a13 = 0.5 * cross(p[1] - p[0], p[2] - p[0]) + 0.5 * cross(p[2] - p[0], p[3] - p[0]);
  const Vec3 a24 = 0.5 * cross(p[2] - p[1], p[3] - p[1]) + 0.5 * cross(p[3] - p[1], p[0] - p[1]);
  expect_near(a13, a24, 1e-14);
  expect_near(f.sum(), -kP * a13, 1e-9);
  for (std::size_t a = 0; a < 4; ++a) expect_near(f.at(a), -kP / 4 * a13, 1e-9);
}

TEST(PressureLoads, FollowsTheFaceAsItTurns) {
  // The same square turned by 90 degrees about x: the force turns with it (follower load).
  const Model m = shell_model({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2, 3}});
  Nodes turned = m.mesh.nodes;
  for (std::size_t i = 0; i < turned.size(); ++i) {
    turned.z[i] = turned.y[i];
    turned.y[i] = 0.0;
  }
  // Turned about x by +90 degrees, the normal +z becomes -y.
  expect_near(forces_at(m, 0.5, turned).sum(), {0, kP, 0}, 1e-9);
}

const char* kCube = R"(*UNIT_SYSTEM
SI
*TIME
1.0
*COMPONENT_BOX
1, 1, 1, 1, 1
0.0, 0.0, 0.0, 1.0, 1.0, 1.0
*MAT_ELASTIC
1, 7800.0, 210.0e9, 0.3
*PART
"cube"
1, 1
*CURVE
1
0.0, 0.0
1.0, 4.0e6
*LOAD_PRESSURE
P, 1, 1, 0.5
)";

TEST(PressureLoads, PositivePressureCompressesASolid) {
  const Model m = read_deck_string(kCube, "cube.k");
  ASSERT_EQ(pressure_faces(m, m.pressures[0]).size(), 6u);
  const double p = 0.5 * 4.0e6 * 0.25;  // sf * curve(0.25)
  const Forces f = forces_at(m, 0.25);
  const Vec3 centre{0.5, 0.5, 0.5};
  for (std::size_t i = 0; i < m.mesh.nodes.size(); ++i) {
    // Each corner carries a quarter of three unit faces, each pushing inward: p/4 (1, 1, 1)
    // toward the centre.
    const Vec3 inward = centre - m.mesh.nodes.position(i);
    expect_near(f.at(i), (p / 4 / 0.5) * inward, 1e-6);
  }
  expect_near(f.sum(), {0, 0, 0}, 1e-6);
}

TEST(PressureLoads, TheCurveOfTimeIsRespected) {
  const Model m = read_deck_string(kCube, "cube.k");
  std::size_t corner = 0;  // the node at the origin: force (p/4)(1, 1, 1)
  while (dot(m.mesh.nodes.position(corner), {1, 1, 1}) > 1e-12) ++corner;
  ASSERT_LT(corner, m.mesh.nodes.size());
  for (const double t : {0.0, 0.1, 0.7, 2.0}) {
    const double p = 0.5 * 4.0e6 * std::min(t, 1.0);  // constant beyond the last point
    EXPECT_NEAR(forces_at(m, t).x[corner], p / 4, 1e-6) << "t = " << t;
  }
  // A *FUNCTION of t gives the pressure as well.
  std::string deck = kCube;
  deck.replace(deck.find("*CURVE"), deck.find("*LOAD_PRESSURE") - deck.find("*CURVE"),
               "*FUNCTION\n1\n1.0e6 * sinr(t)\n");
  const Model g = read_deck_string(deck, "cube.k");
  EXPECT_NEAR(forces_at(g, 0.3).x[corner], 0.5 * 1.0e6 * std::sin(0.3) / 4, 1e-6);
}

TEST(PressureLoads, ACollapsedHexGivesTriangles) {
  // A wedge: a unit hex whose top-back edge is pinched (nodes 2 = 3 and 6 = 7). Its bottom and
  // top faces become triangles, its eta = +1 face an edge (no area); the five remaining faces
  // close the wedge, so the forces sum to zero.
  Model m = read_deck_string(kCube, "cube.k");
  Hex8& h = m.mesh.hexes[0];
  h[3] = h[2];
  h[7] = h[6];
  const std::vector<Quad4> faces = pressure_faces(m, m.pressures[0]);
  ASSERT_EQ(faces.size(), 5u);
  int triangles = 0;
  for (const Quad4& q : faces) triangles += is_triangle(q) ? 1 : 0;
  EXPECT_EQ(triangles, 2);
  const Forces f = forces_at(m, 1.0);
  expect_near(f.sum(), {0, 0, 0}, 1e-6);
  // The bottom triangle (area 1/2, normal -z) puts (p/3)(1/2) on each of its nodes along +z.
  EXPECT_GT(f.z[h[0]], 0.0);
}

TEST(PressureLoads, AGeometryRegionSelectsTheFacesInside) {
  const Model m = read_deck_string(std::string(kCube) + R"(*COMPONENT_BOX
2, 1, 2, 2, 1
2.0, 0.0, 0.0, 3.0, 1.0, 1.0
*GEOMETRY_BOX
7
2.9, -1, -1, 3.1, 2, 2
*LOAD_PRESSURE
G, 7, 1
)",
                                   "region.k");
  // The x = 3 end of the second box: two faces of 0.5 x 1, outward normal +x.
  const PressureLoad& load = m.pressures[1];
  EXPECT_EQ(pressure_faces(m, load).size(), 2u);
  PressureLoads loads(m);
  const std::size_t n = m.mesh.nodes.size();
  std::vector<double> fx(n, 0.0), fy(n, 0.0), fz(n, 0.0);
  loads.add_forces(1.0, m.mesh.nodes.x, m.mesh.nodes.y, m.mesh.nodes.z, fx, fy, fz);
  // Both loads: the closed cube sums to zero; the end faces give -p * 1 * (+x), p = 4e6.
  double sx = 0.0;
  for (const double v : fx) sx += v;
  EXPECT_NEAR(sx, -4.0e6, 1e-6);
}

TEST(PressureLoads, PowerOverAStepUsesTheMidVelocity) {
  const Model m = shell_model({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2, 3}});
  PressureLoads loads(m);
  std::vector<double> fx(4, 0.0), fy(4, 0.0), fz(4, 0.0);
  loads.add_forces(0.5, m.mesh.nodes.x, m.mesh.nodes.y, m.mesh.nodes.z, fx, fy, fz);
  const std::vector<double> zero(4, 0.0), old_vz(4, -1.0), new_vz(4, -3.0);
  // Force -kP (z) in total, mid velocity -2 (z): power 2 kP.
  EXPECT_NEAR(loads.mid_step_power(zero, zero, old_vz, zero, zero, new_vz), 2.0 * kP, 1e-9);
}

}  // namespace
}  // namespace abut
