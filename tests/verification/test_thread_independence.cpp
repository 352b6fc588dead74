// Forces are summed node by node in a fixed order, so a run is bitwise identical for any
// number of threads (issue 3). Mooney-Rivlin sphere and a spinning elastic box, 60 cycles.
#include <gtest/gtest.h>
#include <omp.h>

#include <vector>

#include "run_to.hpp"

namespace abut {
namespace {

const char* kDeck = R"(
*UNIT_SYSTEM
SI
*TIME
1.0
*COMPONENT_SPHERE
1, 1, 3
0.0, 0.0, 0.03, 0.01
*COMPONENT_BOX
2, 2, 4, 4, 2
-0.03, -0.03, -0.05, 0.03, 0.03, -0.03
*MAT_MOONEY_RIVLIN
1, 1500.0, 3.0e9
1.0e6, 0, 1.0e2
*MAT_ELASTIC
2, 7800.0, 210.0e9, 0.3
*PART
"rubber"
1, 1
"steel"
2, 2
*INITIAL_VELOCITY
P, 1, 0.0, 3.0, -100.0, 1000.0, 0.0, 0.0
0.0, 0.0, 0.03
*INITIAL_VELOCITY
P, 2, 0.0, 0.0, 0.0, 0.0, 0.0, 500.0
0.0, 0.0, -0.04
*END
)";

// A square steel tube of 2560 Johnson-Cook shells (above the parallel threshold) crushed at its
// top at 20 m/s: shell forces and moments, plastic returns, rotations.
const char* kShellDeck = R"(
*UNIT_SYSTEM
SI
*TIME
1.0e-3
*COMPONENT_SHELL_TUBE
1, 1, 40, 64, SQUARE
0.0, 0.0, 0.0, 0.0, 0.0, 0.2
0.025
*MAT_JC
1, 7800.0, 210.0e9, 0.3
300e6, 500e6, 0.5
*PART
"tube"
1, 1, , 0.0015
*GEOMETRY_BOX
1
-1.0, -1.0, -0.001, 1.0, 1.0, 0.001
*GEOMETRY_BOX
2
-1.0, -1.0, 0.199, 1.0, 1.0, 0.201
*BC_MOTION
G, 1, XYZ, XYZ
*BC_MOTION
G, 2, XY, XYZ
V, Z, 3
*CURVE
3
0.0, 0.0
1e-4, -20.0
1.0, -20.0
*END
)";

// Shell contact (issue 9): two elastic shell plates, one tilted, colliding face to face.
const char* kShellContactDeck = R"(
*UNIT_SYSTEM
SI
*TIME
1.0e-3
*COMPONENT_SHELL_PLATE
1, 1, 10, 10
0.0, 0.0, 0.0, 0.05, 0.0, 0.0
0.0, 0.05, 0.0
*COMPONENT_SHELL_PLATE
2, 2, 10, 10
0.01, 0.01, 0.0018, 0.06, 0.01, 0.0025
0.01, 0.06, 0.0018
*MAT_ELASTIC
1, 7850.0, 210.0e9, 0.3
*PART
1, 1, , 0.0015
2, 1, , 0.0015
*INITIAL_VELOCITY
P, 1, 0.0, 0.0, 10.0
*INITIAL_VELOCITY
P, 2, 0.0, 0.0, -10.0
*CONTACT
1
P, 1, P, 2, 0.3
*END
)";

std::vector<double> positions_after(int threads, int cycles, const char* deck = kDeck) {
  omp_set_num_threads(threads);
  const Model model = read_deck_string(deck, "threads.k");
  Simulation sim(model);
  for (int i = 0; i < cycles; ++i) sim.advance();
  std::vector<double> out = sim.x();
  out.insert(out.end(), sim.y().begin(), sim.y().end());
  out.insert(out.end(), sim.z().begin(), sim.z().end());
  out.push_back(sim.energies().internal);
  out.push_back(sim.energies().hourglass);
  return out;
}

TEST(ThreadIndependence, OneAndTwoThreadsGiveBitwiseIdenticalResults) {
  const int saved = omp_get_max_threads();
  const std::vector<double> one = positions_after(1, 60);
  const std::vector<double> two = positions_after(2, 60);
  omp_set_num_threads(saved);
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t i = 0; i < one.size(); ++i) ASSERT_EQ(one[i], two[i]) << "entry " << i;
}

TEST(ThreadIndependence, ShellsGiveBitwiseIdenticalResults) {
  const int saved = omp_get_max_threads();
  const std::vector<double> one = positions_after(1, 150, kShellDeck);
  const std::vector<double> two = positions_after(2, 150, kShellDeck);
  omp_set_num_threads(saved);
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t i = 0; i < one.size(); ++i) ASSERT_EQ(one[i], two[i]) << "entry " << i;
}

TEST(ThreadIndependence, ShellContactGivesBitwiseIdenticalResults) {
  const int saved = omp_get_max_threads();
  const std::vector<double> one = positions_after(1, 200, kShellContactDeck);
  const std::vector<double> two = positions_after(2, 200, kShellContactDeck);
  omp_set_num_threads(saved);
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t i = 0; i < one.size(); ++i) ASSERT_EQ(one[i], two[i]) << "entry " << i;
}

}  // namespace
}  // namespace abut
