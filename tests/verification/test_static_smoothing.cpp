// Contact surface smoothing in static steps (*CONTACT_SMOOTHING, OptiStruct SMOOTH / SMSIDE, seed
// 003; Nagata patches, smoothing.hpp): a shaft turning in a coarsely faceted bearing.
//
// The bearing is a ring 10 <= r <= 13 mm, 1 mm long, 40 elements round (9 degrees each), held;
// the shaft a ring 6 <= r <= 10 mm, 48 or 34 elements round (meshes that do not match), stiff
// (E = 2e7 MPa) against the contact's linear penalty k = 100 MPa/mm, every node held in z (plane
// strain). Its inner nodes are driven as a rigid body: step 1 lowers it by delta = 5e-3 mm, step
// 2 turns it by 30 degrees about the bearing's axis (3.3 bearing facets) with Coulomb friction
// mu = 0.3. Both surfaces are smoothed (the shaft's own chords lie up to 0.021 mm inside its
// circle). Reference (closed form, a rigid shaft on a Winkler foundation of stiffness k): the
// overlap of two circles of radius R offset by delta is delta cos(theta) + O(delta^2 / R) at the
// angle theta from the bottom, so p = k delta cos(theta) over the lower half and the upper half
// opens:
//   W = k delta R L pi / 2 = 7.854 N          (the vertical force),
//   N = int p dA = 2 k delta R L = 10 N       (the normal force's sum),
//   T = mu R N = 30 N mm                      (the friction torque while it turns),
// the same at every angle: a smooth bearing has no facets for the friction to catch on. Errors
// expected: delta / (2 R) = 2.5e-4 from the overlap's second order, the bodies' compliance k t / E
// ~ 1e-5, and the Nagata curves' bulge over the circle, R phi^4 / 8 at an edge's middle (phi half
// the facet angle: 4.7e-5 mm on the bearing, 2.3e-5 mm on the shaft of 48, 0.9% and 0.5% of
// delta; their means over an edge half that, and of opposite sign on the two sides): W, N and T to
// 1% at every increment of step 2.
// Cells: surface to surface symmetric and one way, each with both shaft meshes. Node to surface
// is refused (smoothing is for S2S contact, seed 003); the held bearing is the rigid partner.
// Rings, not half rings: where the smoothed surface ends (a free border, or a crease such as a
// half ring's cut), a node's normal comes from the facets on its side alone, so the last edge
// follows its chord (docs/contact.md); a half bearing's ends would press into the shaft by up to
// its chords' sag, six times delta.
// Without smoothing the same model does not converge in its first increment (printed).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <sstream>
#include <string>

#include "abut/io/deck.hpp"
#include "abut/solver/static_solver.hpp"
#include "ring_mesh.hpp"
#include "skin_face_set.hpp"

namespace abut {
namespace {

using verification::Ring;
using verification::write_ring;
constexpr double kPi = verification::kRingPi, kL = verification::kRingLength;
constexpr double kR = 10.0, kDelta = 5e-3, kPenalty = 100.0, kMu = 0.3, kTurn = 30.0;
constexpr int kBearingElements = 40;

std::string bearing_deck(int shaft_elements, const std::string& contact_keywords) {
  const Ring bearing{0, kBearingElements, kR, 13.0};
  const Ring shaft{1000, shaft_elements, 6.0, kR};
  std::ostringstream nodes, hexes, drive;
  nodes.precision(17);
  write_ring(nodes, hexes, bearing, 1, 0);
  write_ring(nodes, hexes, shaft, 2, 1000);
  // The shaft's inner nodes: lowered by delta over t in [0, 1], turned by kTurn degrees about the
  // axis over [1, 2] (trigonometry in degrees).
  int fid = 100;
  const std::string down = std::to_string(kDelta) + "*min(t, 1)";
  const std::string angle = std::to_string(kTurn) + "*max(t - 1, 0)";
  std::ostringstream functions;
  functions.precision(17);
  for (int iz = 0; iz < 2; ++iz)
    for (int it = 0; it < shaft.around; ++it) {
      const double a = shaft.angle(it);
      const double x = shaft.r0 * std::cos(a), y = shaft.r0 * std::sin(a);
      functions << "*FUNCTION\n"
                << ++fid << "\n"
                << x << "*(cos(" << angle << ") - 1) - (" << y << ")*sin(" << angle << ")\n";
      functions << "*FUNCTION\n"
                << ++fid << "\n"
                << x << "*sin(" << angle << ") + (" << y << ")*(cos(" << angle << ") - 1) - "
                << down << "\n";
      drive << "N, " << shaft.id(0, it, iz) << "\nD, X, " << fid - 1 << "\nD, Y, " << fid << "\n";
    }
  return "*UNIT_SYSTEM\nMMTONS\n*NODE\n" + nodes.str() + "*ELEMENT_SOLID\n" + hexes.str() +
         R"(*MAT_ELASTIC
1, 7.85e-9, 2.0e7, 0.3
*PART
"bearing"
1, 1
"shaft"
2, 1
*PART_SOLID
1, FULL
2, FULL
*BC_MOTION
P, 1, XYZ
P, 2, Z
)" + drive.str() +
         functions.str() + "*CONTACT\n\"shaft in bearing\"\n1\nP, 2, P, 1, " + std::to_string(kMu) +
         ", " + std::to_string(kPenalty) + "\n" + contact_keywords + R"(*STATIC
"lower"
1.0, 0.25, , , 1
*STATIC
"turn"
2.0, 0.1, , 0.1, 1
*END
)";
}

struct History {
  double worst_w = 0.0, worst_n = 0.0, worst_t = 0.0;  // largest relative errors in step 2
  double t_min = 1e300, t_max = -1e300;
  int increments = 0;
};

History turn(const std::string& deck) {
  const Model m = read_deck_string(deck, "bearing.k");
  StaticSolver solver(m);
  History h;
  const double w_ref = kPenalty * kDelta * kR * kL * kPi / 2.0;
  const double n_ref = 2.0 * kPenalty * kDelta * kR * kL;
  const double t_ref = kMu * kR * n_ref;
  solver.run([&](const StaticIncrement& inc) {
    if (inc.step != 1) return;
    // The drive's reactions on the shaft's inner nodes: the vertical force and the torque about
    // the axis; the normal force from the contact points (a symmetric pass halves its areas).
    const verification::DriveReaction drive =
        verification::drive_reaction(m.mesh.nodes, solver.displacement(), solver.reaction(), 6.5);
    const double w = drive.vertical, torque = drive.torque;
    const double normal = verification::normal_force(solver.contacts());
    h.worst_w = std::max(h.worst_w, std::abs(std::abs(w) - w_ref) / w_ref);
    h.worst_n = std::max(h.worst_n, std::abs(normal - n_ref) / n_ref);
    h.worst_t = std::max(h.worst_t, std::abs(std::abs(torque) - t_ref) / t_ref);
    h.t_min = std::min(h.t_min, std::abs(torque)), h.t_max = std::max(h.t_max, std::abs(torque));
    ++h.increments;
  });
  return h;
}

TEST(StaticSmoothing, AShaftTurnsInAFacetedBearingWithTheFrictionOfTheCircle) {
  struct Cell {
    const char* name;
    const char* keywords;
  };
  for (const Cell& cell :
       {Cell{"S2S symmetric", ""}, Cell{"S2S one way", "*CONTACT_DISCRETIZATION\n1, S2S, 0\n"}})
    for (const int shaft : {48, 34}) {
      const History h =
          turn(bearing_deck(shaft, std::string(cell.keywords) + "*CONTACT_SMOOTHING\n1, BOTH\n"));
      std::cout << "smoothed, shaft of " << shaft << " elements, " << cell.name << ": step 2 in "
                << h.increments << " increments, worst errors W " << h.worst_w << ", N "
                << h.worst_n << ", T " << h.worst_t << "; T from " << h.t_min << " to " << h.t_max
                << " N mm\n";
      EXPECT_GE(h.increments, 10) << cell.name << " " << shaft;
      EXPECT_LT(h.worst_w, 0.01) << cell.name << " " << shaft;
      EXPECT_LT(h.worst_n, 0.01) << cell.name << " " << shaft;
      EXPECT_LT(h.worst_t, 0.01) << cell.name << " " << shaft;
    }
  try {
    const History facets = turn(bearing_deck(48, ""));
    std::cout << "facets: worst errors W " << facets.worst_w << ", N " << facets.worst_n << ", T "
              << facets.worst_t << "; T from " << facets.t_min << " to " << facets.t_max
              << " N mm\n";
  } catch (const StaticConvergenceError& e) {
    std::cout << "facets: " << e.what() << "\n";
  }
}

TEST(StaticSmoothing, NodeToSurfaceRefusesIt) {
  const Model m = read_deck_string(
      bearing_deck(34, "*CONTACT_DISCRETIZATION\n1, N2S, 0\n*CONTACT_SMOOTHING\n1, MAIN\n"),
      "bearing.k");
  try {
    StaticSolver solver(m);
    solver.run();
    ADD_FAILURE() << "node-to-surface contact took *CONTACT_SMOOTHING";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, "bearing.k");
    EXPECT_NE(std::string(e.what()).find("surface-to-surface"), std::string::npos) << e.what();
  }
}

// A *SET_FACE of the exterior faces of `parts` of the model of `deck`, as setid 7.
std::string skin_face_set(const std::string& deck, const std::vector<std::int64_t>& parts) {
  return verification::skin_face_set(read_deck_string(deck, "bearing.k").mesh, parts, 7);
}

// The vertical drive reaction after the first increment (the run stops there).
double first_reaction(const std::string& deck) {
  const Model m = read_deck_string(deck, "bearing.k");
  StaticSolver solver(m);
  struct Stop {};
  double w = 0.0;
  try {
    solver.run([&](const StaticIncrement&) {
      w = verification::drive_reaction(m.mesh.nodes, solver.displacement(), solver.reaction(), 6.5)
              .vertical;
      throw Stop{};
    });
  } catch (const Stop&) {
  }
  return w;
}

// SMREG (OptiStruct SMREG = SURF id): a region naming every face of both sides is the whole
// sides (SMREG ALL), to round-off; a region with no face of a side it smooths is an error there.
TEST(StaticSmoothing, ARegionOfEveryFaceIsTheWholeSide) {
  const std::string all = bearing_deck(34, "*CONTACT_SMOOTHING\n1, BOTH\n");
  const std::string region =
      bearing_deck(34, skin_face_set(all, {1, 2}) + "*CONTACT_SMOOTHING\n1, BOTH, 7\n");
  const double w_all = first_reaction(all), w_region = first_reaction(region);
  EXPECT_NE(w_all, 0.0);
  EXPECT_NEAR(w_region, w_all, 1e-12 * std::abs(w_all));
  const Model bearing_only = read_deck_string(
      bearing_deck(34, skin_face_set(all, {1}) + "*CONTACT_SMOOTHING\n1, BOTH, 7\n"), "b.k");
  try {
    StaticSolver solver(bearing_only);
    ADD_FAILURE() << "a region without a face of the shaft smoothed the shaft";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("has no face of surface 1"), std::string::npos)
        << e.what();
    EXPECT_EQ(e.where().field, "region") << e.what();
  }
}

}  // namespace
}  // namespace abut
