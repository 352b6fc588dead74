#pragma once
// Two identical steel bars (E = 210 GPa, rho = 7800 kg/m^3, Poisson's ratio 0: exactly 1-D) end
// to end along x with a 0.1 mm gap, meeting head on at +v and -v: the deck shared by the bar
// impact problems (test_contact_bars.cpp, test_contact_bulk_viscosity.cpp).
#include <string>

namespace abut::verification {

struct TwoBars {
  double length = 0.2;  // of each bar [m]
  int elements = 200;   // along each bar
  double side = 0.001;  // of the square cross-section, one element across [m]
  double speed = 10.0;  // of each bar toward the other [m/s]
  double end_time = 1.2e-4;
  double pfac = 0.0;    // the contact's penalty [Pa/m]
  std::string contact;  // lines after *CONTACT's line 2, and keywords after it
};

inline std::string two_bars_deck(const TwoBars& b) {
  const std::string count = std::to_string(b.elements), side = std::to_string(b.side);
  const std::string far = std::to_string(b.length + 0.00005);
  return "*UNIT_SYSTEM\nSI\n*TIME\n" + std::to_string(b.end_time) + "\n*COMPONENT_BOX\n1, 1, " +
         count + ", 1, 1\n-" + far + ", 0.0, 0.0, -0.00005, " + side + ", " + side +
         "\n*COMPONENT_BOX\n2, 2, " + count + ", 1, 1\n0.00005, 0.0, 0.0, " + far + ", " + side +
         ", " + side + R"(
*MAT_ELASTIC
1, 7800.0, 210.0e9, 0.0
*PART
"left bar"
1, 1
"right bar"
2, 1
*INITIAL_VELOCITY
P, 1, )" +
         std::to_string(b.speed) + ", 0.0, 0.0\n*INITIAL_VELOCITY\nP, 2, " +
         std::to_string(-b.speed) + R"(, 0.0, 0.0
*CONTACT
"bar ends"
1
P, 1, P, 2, 0.0, )" +
         std::to_string(b.pfac) + "\n" + b.contact + "\n*END\n";
}

}  // namespace abut::verification
