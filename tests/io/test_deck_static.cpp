// *STATIC in a .k deck (abut's own keyword): the steps it makes, its errors (each with file:line),
// what *NODE constraints, *BC_MOTION, *LOAD_PRESSURE and *LOAD_GRAVITY become in the steps, the
// commands a static deck refuses, *PART_SOLID, and a block in uniaxial compression solved from the
// .k deck and from the same model written as .inp.
#include <gmock/gmock.h>

#include <cmath>
#include <map>
#include <sstream>
#include <string>

#include "abut/solver/static_solver.hpp"
#include "test_deck_helpers.hpp"

namespace abut {
namespace {

using testing::error_of;
using ::testing::HasSubstr;
using testing::model_of;

// A 2 x 2 x 2 block of elastic hexes, 1 x 1 x 2 (mass 7800 x 2), and a ramp curve; no *TIME (a
// static deck has none).
const std::string kBlock = R"(*COMPONENT_BOX
1, 1, 2, 2, 2
0.0, 0.0, 0.0, 1.0, 1.0, 2.0
*MAT_ELASTIC
1, 7800.0, 1000.0, 0.3
*PART
"block"
1, 1
*CURVE
1
0.0, 0.0
1.0, 1.0
)";

// Its faces x = 0, y = 0, z = 0 and z = 2 as geometries 1 to 4.
const std::string kFaces = R"(*GEOMETRY_BOX
1
-0.01, -1.0, -1.0, 0.01, 2.0, 3.0
*GEOMETRY_BOX
2
-1.0, -0.01, -1.0, 2.0, 0.01, 3.0
*GEOMETRY_BOX
3
-1.0, -1.0, -0.01, 2.0, 2.0, 0.01
*GEOMETRY_BOX
4
-1.0, -1.0, 1.99, 2.0, 2.0, 2.01
)";

// The line of `text` on which the last occurrence of `needle` is (1-based).
std::size_t line_of(const std::string& text, const std::string& needle) {
  const std::size_t at = text.rfind(needle);
  EXPECT_NE(at, std::string::npos) << needle;
  std::size_t line = 1;
  for (std::size_t i = 0; i < at && i < text.size(); ++i) line += text[i] == '\n';
  return line;
}

// The error of `deck`: in t.k, on the line of the last `needle`, field `field` (when given), and
// `message` in its text.
void expect_error(const std::string& deck, const std::string& needle, const std::string& message,
                  const std::string& field = "") {
  const InputError e = error_of(deck);
  EXPECT_EQ(e.where().file, "t.k") << e.what();
  EXPECT_EQ(e.where().line, line_of(deck, needle)) << e.what();
  if (!field.empty()) {
    EXPECT_EQ(e.where().field, field) << e.what();
  }
  EXPECT_THAT(e.what(), HasSubstr(message));
}

// A step's prescribed displacements by (user node id, dof).
std::map<std::pair<std::int64_t, int>, const StepDisplacement*> displacements(const Model& m,
                                                                              std::size_t step) {
  std::map<std::pair<std::int64_t, int>, const StepDisplacement*> out;
  for (const StepDisplacement& d : m.static_steps.at(step).displacements)
    out[{m.mesh.nodes.id[static_cast<std::size_t>(d.node)], d.dof}] = &d;
  return out;
}

TEST(DeckStatic, Defaults) {
  const std::string deck = kBlock + "*STATIC\n2.0\n";
  const Model m = model_of(deck);
  ASSERT_EQ(m.static_steps.size(), 1u);
  const StaticStep& s = m.static_steps[0];
  EXPECT_EQ(s.title, "");
  EXPECT_DOUBLE_EQ(s.period, 2.0);
  EXPECT_DOUBLE_EQ(s.initial_increment, 2.0);  // the whole step
  EXPECT_DOUBLE_EQ(s.min_increment, 2e-5);     // 1e-5 of the step
  EXPECT_DOUBLE_EQ(s.max_increment, 2.0);      // the step
  EXPECT_TRUE(s.nonlinear_geometry);           // large displacements, as the explicit solver
  EXPECT_EQ(s.max_increments, 100);
  EXPECT_FALSE(s.fixed_increments);
  // The Newton controls stay those of StaticControls (0.005, 0.02, 16).
  EXPECT_FALSE(s.force_tolerance.has_value());
  EXPECT_FALSE(s.displacement_tolerance.has_value());
  EXPECT_FALSE(s.max_iterations.has_value());
  EXPECT_TRUE(s.prints.empty());
  EXPECT_EQ(s.where.file, "t.k");
  EXPECT_EQ(s.where.line, line_of(deck, "*STATIC"));
  EXPECT_DOUBLE_EQ(m.time.end_time, 2.0);
  // A smaller dt_max makes the default initial increment smaller too.
  const Model m2 = model_of(kBlock + "*STATIC\n2.0, , , 0.5\n");
  EXPECT_DOUBLE_EQ(m2.static_steps[0].initial_increment, 0.5);
  EXPECT_DOUBLE_EQ(m2.static_steps[0].max_increment, 0.5);
  // An initial increment below 1e-5 of the step lowers the default dt_min to it.
  const Model m3 = model_of(kBlock + "*STATIC\n1.0, 1e-7\n");
  EXPECT_DOUBLE_EQ(m3.static_steps[0].min_increment, 1e-7);
}

TEST(DeckStatic, EveryField) {
  const Model m = model_of(kBlock + R"(*STATIC
"load"
1.0, 0.1, 0.001, 0.25, 0, 40
0.001, 0.01, 8
)");
  const StaticStep& s = m.static_steps.at(0);
  EXPECT_EQ(s.title, "load");
  EXPECT_DOUBLE_EQ(s.period, 1.0);
  EXPECT_DOUBLE_EQ(s.initial_increment, 0.1);
  EXPECT_DOUBLE_EQ(s.min_increment, 0.001);
  EXPECT_DOUBLE_EQ(s.max_increment, 0.25);
  EXPECT_FALSE(s.nonlinear_geometry);
  EXPECT_EQ(s.max_increments, 40);
  EXPECT_EQ(s.force_tolerance, 0.001);
  EXPECT_EQ(s.displacement_tolerance, 0.01);
  EXPECT_EQ(s.max_iterations, 8);
  // Line 2 may give some of its fields only.
  const Model m2 = model_of(kBlock + "*STATIC\n1.0\n, , 30\n");
  EXPECT_FALSE(m2.static_steps[0].force_tolerance.has_value());
  EXPECT_FALSE(m2.static_steps[0].displacement_tolerance.has_value());
  EXPECT_EQ(m2.static_steps[0].max_iterations, 30);
}

TEST(DeckStatic, ConsecutiveSteps) {
  const Model m = model_of(kBlock + R"(*STATIC
"first"
1.0, , , , 0
*STATIC
"second"
3.0, 0.5, , , 1
*STATIC
3.5
)");
  ASSERT_EQ(m.static_steps.size(), 3u);
  EXPECT_EQ(m.static_steps[0].title, "first");
  EXPECT_EQ(m.static_steps[1].title, "second");
  EXPECT_DOUBLE_EQ(m.static_steps[0].period, 1.0);
  EXPECT_DOUBLE_EQ(m.static_steps[1].period, 2.0);  // from t = 1 to 3
  EXPECT_DOUBLE_EQ(m.static_steps[1].initial_increment, 0.5);
  EXPECT_DOUBLE_EQ(m.static_steps[1].max_increment, 2.0);
  EXPECT_DOUBLE_EQ(m.static_steps[2].period, 0.5);
  EXPECT_FALSE(m.static_steps[0].nonlinear_geometry);
  EXPECT_TRUE(m.static_steps[1].nonlinear_geometry);
  EXPECT_TRUE(m.static_steps[2].nonlinear_geometry);
  EXPECT_DOUBLE_EQ(m.time.end_time, 3.5);
}

TEST(DeckStatic, FieldErrors) {
  const std::string d = kBlock + "*STATIC\n";
  expect_error(d + "-1.0\n", "-1.0", "expected a step end time > 0", "t_end");
  expect_error(d + "2.0\n*STATIC\n1.5\n", "1.5",
               "expected a step end time greater than 2, the t_end of the previous *STATIC",
               "t_end");
  expect_error(d + "2.0\n*STATIC\n2.0\n", "2.0", "greater than 2", "t_end");
  expect_error(d + "1.0, 2.0\n", "1.0, 2.0", "expected an initial increment in (0, 1]", "dt_0");
  expect_error(d + "1.0, 0.0\n", "1.0, 0.0", "expected an initial increment in (0, 1]", "dt_0");
  expect_error(d + "1.0, 0.1, 0.2\n", "1.0, 0.1, 0.2",
               "expected a smallest increment in (0, dt_0 = 0.1]", "dt_min");
  expect_error(d + "1.0, 0.5, , 0.25\n", "1.0, 0.5", "expected a largest increment >= dt_0 (0.5)",
               "dt_max");
  expect_error(d + "1.0, , , -1.0\n", "-1.0", "expected a largest increment > 0", "dt_max");
  expect_error(d + "1.0, , , , 2\n", "1.0, , , , 2", "expected 0 (small displacements) or 1",
               "nlgeom");
  expect_error(d + "1.0\n*STATIC\n2.0, , , , 0\n", "2.0, , , , 0",
               "large displacements stay on once a step has them", "nlgeom");
  expect_error(d + "1.0, , , , 1, 0\n", "1.0, , , , 1, 0",
               "expected a largest number of increments >= 1", "n_inc");
  expect_error(d + "1.0, , , , 1, 2.5\n", "1.0, , , , 1, 2.5", "", "n_inc");
  expect_error(d + "1.0\n0.0, 0.02, 16\n", "0.0, 0.02", "expected a residual tolerance in (0, 1)",
               "tol_R");
  expect_error(d + "1.0\n0.005, 1.5\n", "0.005, 1.5", "expected a correction tolerance in (0, 1)",
               "tol_C");
  expect_error(d + "1.0\n0.005, 0.02, 0\n", "0.005, 0.02, 0",
               "expected a number of Newton iterations in [1, 1000]", "n_iter");
  expect_error(d + "1.0, a\n", "1.0, a", "expected a number", "dt_0");
  expect_error(d + "1.0, , , , , , 7\n", "1.0, , , , , , 7", "");
  // One step per *STATIC: a further line is an error that says so.
  expect_error(d + "1.0\n0.005\n2.0\n", "2.0", "a *STATIC holds one step");
  expect_error(d, "*STATIC", "missing data line: expected t_end, dt_0");
}

TEST(DeckStatic, ExplicitOnlyCommandsAreRefused) {
  const std::string step = "*STATIC\n1.0\n";
  expect_error(kBlock + "*TIME\n1.0\n" + step, "*TIME", "remove *TIME");
  expect_error(kBlock + "*OUTPUT\n0.1\n" + step, "*OUTPUT", "remove *OUTPUT");
  expect_error(kBlock + "*INITIAL_VELOCITY\nP, 1, 2.0\n" + step, "P, 1, 2.0",
               "remove *INITIAL_VELOCITY");
  std::string eroding = kBlock;
  eroding.replace(eroding.find("1, 1\n*CURVE"), 4, "1, 1, , , , 1e-9");
  expect_error(eroding + step, "1, 1, , , , 1e-9",
               "element erosion (dt_erode, eps_geo_erode, eps_v_erode of part 1) is not supported "
               "in static steps yet");
  // Without *STATIC the deck still needs *TIME, and says how to make it static.
  EXPECT_THAT(error_of(kBlock).what(), HasSubstr("or *STATIC steps for a static analysis"));
}

TEST(DeckStatic, BoundaryConditionErrors) {
  const std::string step = "*STATIC\n1.0\n";
  expect_error(kBlock + "*BC_MOTION\nN, 1\nV, Z, 1, 2.0\n" + step, "V, Z",
               "a prescribed velocity (V) has no meaning in a static step: give the displacement "
               "(pmeth D",
               "pmeth");
  expect_error(kBlock + "*BC_MOTION\nN, 1\nA, X, 1\n" + step, "A, X",
               "a prescribed acceleration (A) has no meaning in a static step", "pmeth");
  expect_error(kBlock + "*BC_MOTION\nN, 1\nD, Z, 1, 1.0, 1\n" + step, "D, Z",
               "an activation function (fid) is not supported in static steps yet", "fid");
  // A dof given two different conditions in one step.
  expect_error(kBlock + "*BC_MOTION\nN, 1, Z\nN, 1\nD, Z, 1, 0.5\n" + step, "D, Z",
               "node 1, direction z already has a condition in static step 1 from *BC_MOTION at "
               "t.k:" +
                   std::to_string(line_of(kBlock + "*BC_MOTION\n", "*BC_MOTION") + 1));
  expect_error(kBlock + "*NODE\n100, 5.0, 5.0, 5.0, Z\n*BC_MOTION\nN, 100\nD, Z, 1, 0.5\n" + step,
               "D, Z", "from the bc field of *NODE");
  // The same condition twice is harmless.
  EXPECT_NO_THROW(model_of(kBlock + "*BC_MOTION\nN, 1, Z\nN, 1, XZ\n" + step));

  // Rigid parts and rotations.
  const std::string rigid = kBlock + R"(*COMPONENT_BOX
2, 2, 1, 1, 1
0.0, 0.0, 3.0, 1.0, 1.0, 4.0
*MAT_RIGID
2, 7800.0
*PART
2, 2
)";
  expect_error(rigid + "*BC_MOTION\nP, 2, XYZ\n" + step, "P, 2, XYZ",
               "part 2 is rigid: rigid parts are not supported in static steps yet");
  expect_error(rigid + "*BC_MOTION\nP, 2, 0, XYZ\n" + step, "P, 2, 0, XYZ",
               "fixed rotations (bc_rot) are not supported in static steps yet", "bc_rot");
  expect_error(rigid + "*BC_MOTION\nP, 2\nV, RZ, 1\n" + step, "V, RZ",
               "prescribed rotations (RX, RY, RZ) are not supported in static steps yet", "direc");
}

TEST(DeckStatic, BoundaryConditionWindowMustCoverWholeSteps) {
  const std::string steps = "*STATIC\n1.0\n*STATIC\n\"second\"\n2.0\n";
  expect_error(kBlock + "*BC_MOTION\nN, 1, XYZ, , , , 0.0, 0.5\n" + steps, "N, 1, XYZ",
               "the boundary condition acts from t_beg = 0 to t_end = 0.5, which covers only part "
               "of static step 1 (t = 0 to 1, *STATIC at t.k:" +
                   std::to_string(line_of(kBlock + "*BC_MOTION\nN\n*STATIC", "*STATIC")) +
                   "): in static steps a boundary condition acts during whole steps",
               "t_end");
  expect_error(kBlock + "*BC_MOTION\nN, 1, XYZ, , , , 1.5\n" + steps, "N, 1, XYZ",
               "covers only part of static step 2 (t = 1 to 2", "t_beg");

  // Windows on step ends: the condition is in the steps it covers.
  const Model m = model_of(kBlock + "*BC_MOTION\nN, 1, XYZ, , , , 0.0, 1.0\nN, 2, Z, , , , 1.0\n" +
                           steps + "*STATIC\n3.0\n");
  const auto s1 = displacements(m, 0), s2 = displacements(m, 1), s3 = displacements(m, 2);
  EXPECT_EQ(s1.size(), 3u);
  EXPECT_TRUE(s1.count({1, 0}) && s1.count({1, 1}) && s1.count({1, 2}));
  EXPECT_EQ(s2.size(), 1u);
  EXPECT_TRUE(s2.count({2, 2}));
  EXPECT_EQ(s3.size(), 1u);
  EXPECT_TRUE(s3.count({2, 2}));
  // A condition that acts in no step is reported.
  const DeckResult r = testing::read(kBlock + "*BC_MOTION\nN, 1, XYZ, , , , 5.0\n" + steps);
  EXPECT_THAT(r.notes, ::testing::Contains(HasSubstr("acts in no static step")));
}

TEST(DeckStatic, BoundaryConditionsBecomeStepDisplacements) {
  const Model m = model_of(kBlock + kFaces + R"(*NODE
100, 5.0, 5.0, 5.0, XY
*BC_MOTION
G, 1, X
G, 2, Y
G, 3, Z
G, 4
D, Z, 1, -0.002
*STATIC
1.0
*STATIC
2.0
)");
  EXPECT_TRUE(m.motions.empty());  // translated: the static solver does not see them
  for (std::size_t s = 0; s < 2; ++s) {
    const auto d = displacements(m, s);
    // 9 nodes on each face, and node 100's x and y.
    EXPECT_EQ(d.size(), 4u * 9u + 2u);
    for (const auto& [key, p] : d) {
      const auto node = static_cast<std::size_t>(p->node);
      EXPECT_EQ(p->where.file, key.first == 100 ? "" : "t.k");
      if (m.mesh.nodes.z[node] == 2.0 && key.second == 2) {
        EXPECT_DOUBLE_EQ(p->value, -0.002);
        EXPECT_TRUE(p->amplitude.curve.valid());
        EXPECT_TRUE(p->amplitude.total_time);
        EXPECT_DOUBLE_EQ(m.functions.value(p->amplitude.curve, 0.5, {}), 0.5);
      } else {
        EXPECT_DOUBLE_EQ(p->value, 0.0);
        EXPECT_FALSE(p->amplitude.curve.valid());
      }
    }
    EXPECT_TRUE(d.count({100, 0}) && d.count({100, 1}) && !d.count({100, 2}));
  }
}

TEST(DeckStatic, PressureBecomesStepPressures) {
  const Model m = model_of(kBlock + R"(*CURVE
2
0.0, 1.0
9.0, 1.0
*LOAD_PRESSURE
P, 1, 1, 3.0
ALL, 0, 1, 2.0
*STATIC
1.0
)");
  EXPECT_TRUE(m.pressures.empty());
  const StaticStep& s = m.static_steps[0];
  ASSERT_EQ(s.pressures.size(), 24u);  // 4 faces on each side of the block
  for (const StepPressure& p : s.pressures) {
    EXPECT_DOUBLE_EQ(p.value, 5.0);  // two loads of one curve add up
    EXPECT_TRUE(p.amplitude.total_time);
    // An exterior face: its centre lies on the block's boundary.
    const Hex8& hex = m.mesh.hexes[static_cast<std::size_t>(p.face.solid)];
    double c[3] = {0, 0, 0};
    for (const int a : kHexFaces[p.face.face]) {
      const Vec3 x = m.mesh.nodes.position(static_cast<std::size_t>(hex[a]));
      for (int k = 0; k < 3; ++k) c[k] += x[k] / 4.0;
    }
    const bool boundary =
        c[0] == 0.0 || c[0] == 1.0 || c[1] == 0.0 || c[1] == 1.0 || c[2] == 0.0 || c[2] == 2.0;
    EXPECT_TRUE(boundary) << c[0] << " " << c[1] << " " << c[2];
  }
  // Loads of different curves on one face cannot be one step load.
  const std::string two_curves = kBlock + R"(*CURVE
2
0.0, 1.0
9.0, 1.0
*LOAD_PRESSURE
P, 1, 1, 3.0
P, 1, 2, 2.0
*STATIC
1.0
)";
  expect_error(two_curves, "P, 1, 2, 2.0",
               "already carries a load of another curve from *LOAD_PRESSURE at t.k:" +
                   std::to_string(line_of(two_curves, "P, 1, 1, 3.0")));
}

TEST(DeckStatic, GravityBecomesNodalWeights) {
  const Model m = model_of(kBlock + "*LOAD_GRAVITY\nZ, 1, , , -9.81\n*STATIC\n1.0\n");
  EXPECT_TRUE(m.gravity.empty());
  const StaticStep& s = m.static_steps[0];
  ASSERT_EQ(s.forces.size(), 27u);  // every node, along z
  double total = 0.0;
  for (const StepForce& f : s.forces) {
    EXPECT_EQ(f.dof, 2);
    EXPECT_TRUE(f.amplitude.curve.valid());
    EXPECT_TRUE(f.amplitude.total_time);
    total += f.value;
  }
  EXPECT_NEAR(total, -9.81 * 7800.0 * 2.0, 1e-9 * 9.81 * 7800.0 * 2.0);  // weight of rho V
  // A corner node carries 1/8 of one hex (0.5 x 0.5 x 1).
  EXPECT_NEAR(s.forces.front().value, -9.81 * 7800.0 * 0.25 / 8.0, 1e-9);

  const std::string shells = kBlock + R"(*COMPONENT_SHELL_PLATE
2, 2, 1, 1
0.0, 0.0, 5.0, 1.0, 0.0, 5.0
0.0, 1.0, 5.0
*PART
2, 1, , 0.01
)";
  expect_error(shells + "*LOAD_GRAVITY\nZ, 1\n*STATIC\n1.0\n", "Z, 1",
               "gravity on shells (part 2) is not supported in static steps yet");
  expect_error(shells + "*LOAD_PRESSURE\nP, 2, 1\n*STATIC\n1.0\n", "P, 2, 1",
               "a pressure on shells (part 2) is not supported in static steps yet");
}

TEST(DeckStatic, PartSolid) {
  const Model m = model_of(kBlock + "*PART_SOLID\n1, FULL\n*STATIC\n1.0\n");
  EXPECT_EQ(m.parts[0].solid_integration, Part::SolidIntegration::Full);
  EXPECT_EQ(model_of(kBlock + "*PART_SOLID\n1, 8\n*STATIC\n1.0\n").parts[0].solid_integration,
            Part::SolidIntegration::Full);
  EXPECT_EQ(model_of(kBlock + "*STATIC\n1.0\n").parts[0].solid_integration,
            Part::SolidIntegration::Reduced);
  EXPECT_EQ(model_of(kBlock + "*TIME\n1.0\n*PART_SOLID\n1, REDUCED\n").parts[0].solid_integration,
            Part::SolidIntegration::Reduced);
  expect_error(kBlock + "*TIME\n1.0\n*PART_SOLID\n1, FULL\n", "1, FULL",
               "fully integrated hexahedra (FULL) are for static steps (*STATIC) only",
               "integration");
  expect_error(kBlock + "*PART_SOLID\n1, HALF\n*STATIC\n1.0\n", "1, HALF",
               "expected REDUCED (or 1: one point) or FULL", "integration");
  expect_error(kBlock + "*PART_SOLID\n9, FULL\n*STATIC\n1.0\n", "9, FULL",
               "part 9 does not exist (defined parts: 1)", "pid");
  expect_error(kBlock + "*PART_SOLID\n1, FULL\n1, FULL\n*STATIC\n1.0\n", "1, FULL", "", "pid");
}

// Uniaxial compression of an elastic block with its lateral faces free: x = 0, y = 0 and z = 0
// on rollers (symmetry planes), the top z = L pushed down by delta. Small strain (nlgeom 0) and a
// linear displacement field, which the trilinear hexahedron represents exactly (patch test):
// u_z = -eps z, u_x = nu eps x, u_y = nu eps y, eps = delta / L, and the force on the top face is
// F = E A eps (Hooke's law for uniaxial stress, sigma = E eps; Timoshenko & Goodier, Theory of
// Elasticity, 3rd ed. 1970, section 3 "Hooke's law"; Gere & Timoshenko, Mechanics of Materials,
// section 1.5). The same model written as .inp (C3D8, *BOUNDARY, one *STATIC step) gives the same
// displacement field.
TEST(DeckStatic, UniaxialCompressionMatchesHookeAndTheInpModel) {
  constexpr double kE = 1000.0, kNu = 0.3, kL = 2.0, kWidth = 1.0, kDepth = 1.5, kDelta = 0.002;
  const double eps = kDelta / kL, area = kWidth * kDepth;
  const std::string deck = R"(*COMPONENT_BOX
1, 1, 2, 3, 4
0.0, 0.0, 0.0, 1.0, 1.5, 2.0
*MAT_ELASTIC
1, 7800.0, 1000.0, 0.3
*PART
"block"
1, 1
*PART_SOLID
1, FULL
*CURVE
1
0.0, 0.0
1.0, 1.0
)" + kFaces + R"(*BC_MOTION
G, 1, X
G, 2, Y
G, 3, Z
G, 4
D, Z, 1, -0.002
*STATIC
"press"
1.0, 0.5, , , 0
)";
  Model k = model_of(deck);
  StaticSolver solver(k);
  solver.run();
  const auto u = solver.displacement();
  const auto reaction = solver.reaction();
  double top_force = 0.0;
  for (std::size_t i = 0; i < k.mesh.nodes.size(); ++i) {
    const double x = k.mesh.nodes.x[i], y = k.mesh.nodes.y[i], z = k.mesh.nodes.z[i];
    EXPECT_NEAR(u[3 * i], kNu * eps * x, 1e-9 * kDelta);
    EXPECT_NEAR(u[3 * i + 1], kNu * eps * y, 1e-9 * kDelta);
    EXPECT_NEAR(u[3 * i + 2], -eps * z, 1e-9 * kDelta);
    if (z == kL) top_force += reaction[3 * i + 2];
  }
  // The block pushes back on the support that presses it: the reaction is the force the
  // elements need at the top nodes, along -z.
  EXPECT_NEAR(top_force, -kE * area * eps, 1e-6 * kE * area * eps);

  // The same model in Abaqus/CalculiX form, node and element ids as in the .k model.
  std::ostringstream inp;
  inp.precision(17);
  inp << "*NODE\n";
  for (std::size_t i = 0; i < k.mesh.nodes.size(); ++i)
    inp << k.mesh.nodes.id[i] << ", " << k.mesh.nodes.x[i] << ", " << k.mesh.nodes.y[i] << ", "
        << k.mesh.nodes.z[i] << "\n";
  inp << "*ELEMENT, TYPE=C3D8, ELSET=EALL\n";
  for (std::size_t h = 0; h < k.mesh.hex_count(); ++h) {
    inp << k.mesh.hex_id[h];
    for (const std::int32_t n : k.mesh.hexes[h]) inp << ", " << k.mesh.nodes.id[n];
    inp << "\n";
  }
  const auto node_set = [&](const std::string& name, int axis, double at) {
    inp << "*NSET, NSET=" << name << "\n";
    int count = 0;
    for (std::size_t i = 0; i < k.mesh.nodes.size(); ++i) {
      const double c[3] = {k.mesh.nodes.x[i], k.mesh.nodes.y[i], k.mesh.nodes.z[i]};
      if (c[axis] != at) continue;
      inp << (count % 8 == 0 ? "" : ", ") << k.mesh.nodes.id[i];
      if (++count % 8 == 0) inp << "\n";
    }
    if (count % 8 != 0) inp << "\n";
  };
  node_set("X0", 0, 0.0);
  node_set("Y0", 1, 0.0);
  node_set("Z0", 2, 0.0);
  node_set("TOP", 2, kL);
  inp << R"(*MATERIAL, NAME=M
*ELASTIC
1000., 0.3
*SOLID SECTION, ELSET=EALL, MATERIAL=M
*BOUNDARY
X0, 1, 1
Y0, 2, 2
Z0, 3, 3
*STEP
*STATIC
0.5, 1.
*BOUNDARY
TOP, 3, 3, -0.002
*END STEP
)";
  Model a = read_inp_string_with_notes(inp.str(), "block.inp").model;
  ASSERT_EQ(a.mesh.nodes.size(), k.mesh.nodes.size());
  EXPECT_EQ(a.parts.at(0).solid_integration, Part::SolidIntegration::Full);
  StaticSolver inp_solver(a);
  inp_solver.run();
  std::map<std::int64_t, std::size_t> index;
  for (std::size_t i = 0; i < a.mesh.nodes.size(); ++i) index[a.mesh.nodes.id[i]] = i;
  const auto v = inp_solver.displacement();
  for (std::size_t i = 0; i < k.mesh.nodes.size(); ++i) {
    const std::size_t j = index.at(k.mesh.nodes.id[i]);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(u[3 * i + c], v[3 * j + c], 1e-9 * kDelta);
  }

  // Two increments of 0.5 with room for one: the solver's message asks for the field of each
  // dialect in its own words (Sources::words), not for both.
  const auto too_few = [](Model& m) {
    m.static_steps.at(0).max_increments = 1;
    try {
      StaticSolver(m).run();
    } catch (const StaticConvergenceError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_THAT(too_few(k), HasSubstr("more than 1 increments needed (n_inc of *STATIC)"));
  EXPECT_THAT(too_few(a), HasSubstr("more than 1 increments needed (INC of *STEP)"));
}

// The step's Newton controls reach the solver: a large-displacement step (20% compression in one
// increment) takes 3 iterations at the default tolerances. With n_iter 2 its increment cannot
// converge at any size allowed (dt_min = half the step), unless the tolerances are loose enough for
// the residual after 2 iterations.
TEST(DeckStatic, StepNewtonControlsReachTheSolver) {
  const std::string base = kBlock + kFaces + R"(*PART_SOLID
1, FULL
*BC_MOTION
G, 1, X
G, 2, Y
G, 3, Z
G, 4
D, Z, 1, -0.4
*STATIC
1.0, 1.0, 0.5
)";
  const auto iterations = [](const Model& m) {
    StaticSolver solver(m);
    solver.run();
    return solver.statistics().iterations;
  };
  EXPECT_EQ(iterations(model_of(base)), 3);
  EXPECT_EQ(iterations(model_of(base + "0.005, 0.02, 3\n")), 3);
  EXPECT_THROW(iterations(model_of(base + "0.005, 0.02, 2\n")), StaticConvergenceError);
  EXPECT_EQ(iterations(model_of(base + "0.5, 0.9, 2\n")), 2);
}

}  // namespace
}  // namespace abut
