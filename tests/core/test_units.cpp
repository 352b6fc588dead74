#include "abut/core/units.hpp"

#include <gtest/gtest.h>

namespace abut {

TEST(Units, ParsesNamesOfTheKeywordReference) {
  EXPECT_EQ(parse_unit_system("si"), UnitSystem::SI);
  EXPECT_EQ(parse_unit_system("MM/TON/S"), UnitSystem::MMTONS);
  EXPECT_FALSE(parse_unit_system("furlong").has_value());
}

TEST(Units, ConvertsSIValuesToDeckUnits) {
  // 100 m/s is 1e5 mm/s in [mm, ton, s]; 1e13 Pa/m = 1e13 N/m^3 is 1e4 N/mm^3 = 1e4 MPa/mm.
  EXPECT_DOUBLE_EQ(from_si(UnitSystem::MMTONS, 100.0, 1, 0, -1), 1e5);
  EXPECT_NEAR(from_si(UnitSystem::MMTONS, 1e13, -2, 1, -2), 1e4, 1e-9);
  // 100 m/s is 0.01 cm/us.
  EXPECT_NEAR(from_si(UnitSystem::CMGUS, 100.0, 1, 0, -1), 0.01, 1e-15);
}

}  // namespace abut
