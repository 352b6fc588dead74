// The Radioss /INTER/TYPE25 stiffness rules (seed 004 = ../shared/seeds/004_5ae881f05f7a02ff
// .clean.txt, comment 2; decoded in ../shared/seeds/README.md), against references written out
// here from the seed:
//   solid main segment   K_m = Stfac B S^2 / V
//   solid secondary node K_s = Stfac B V^(1/3)
//   K_n: Istf 1000 K_m, 2 (K_m + K_s)/2, 3 max, 4 min, 5 K_m K_s / (K_m + K_s)
//   K = max(Stmin, min(Stmax, K_n)), "Stmin/Stmax ... used only when Istf > 1 and Istf < 7".
// Tolerance: round-off, 1e-12 relative.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "abut/contact/gap.hpp"
#include "abut/contact/stiffness_rule.hpp"

namespace abut {
namespace {

constexpr double kRoundOff = 1e-12;
double rel(double expected) { return kRoundOff * std::abs(expected); }

// A 2 x 3 x 1 cm solid (V = 6e-6 m^3) with a 2 x 3 cm face (S = 6e-4 m^2), B = 1e10 Pa,
// Stfac = 0.3: K_m = 0.3 * 1e10 * 3.6e-7 / 6e-6 = 1.8e8 N/m;
// K_s = 0.3 * 1e10 * (6e-6)^(1/3) = 5.4513617784964204e7 N/m (Python).
constexpr double kBulk = 1e10, kArea = 6e-4, kVolume = 6e-6, kStfac = 0.3;
constexpr double kMain = 1.8e8, kSecondary = 5.4513617784964204e7;

TEST(StiffnessRule, MainSegmentAndSecondaryNodeStiffness) {
  const double km = main_segment_stiffness(kBulk, kArea, kVolume, kStfac);
  const double ks = secondary_node_stiffness(kBulk, kVolume, kStfac);
  EXPECT_NEAR(km, kStfac * kBulk * kArea * kArea / kVolume, rel(kMain));
  EXPECT_NEAR(km, kMain, rel(kMain));
  EXPECT_NEAR(ks, kStfac * kBulk * std::pow(kVolume, 1.0 / 3.0), rel(kSecondary));
  EXPECT_NEAR(ks, kSecondary, rel(kSecondary));
  // A 2 cm cube: S^2 / V = V^(1/3) = L, the two sides agree (0.3 * 1e10 * 0.02 = 6e7).
  EXPECT_NEAR(main_segment_stiffness(kBulk, 4e-4, 8e-6, kStfac), 6e7, rel(6e7));
  EXPECT_NEAR(secondary_node_stiffness(kBulk, 8e-6, kStfac), 6e7, rel(6e7));
}

TEST(StiffnessRule, IstfCombinationsWithoutBounds) {
  StiffnessSettings s;  // Stmin 0, Stmax unbounded
  const auto k = [&](StiffnessRule rule) {
    s.rule = rule;
    return combined_stiffness(s, kMain, kSecondary);
  };
  const double mean = (kMain + kSecondary) / 2.0;
  const double series = kMain * kSecondary / (kMain + kSecondary);
  EXPECT_NEAR(k(StiffnessRule::Main), kMain, rel(kMain));                    // Istf 1000
  EXPECT_NEAR(k(StiffnessRule::Mean), mean, rel(mean));                      // Istf 2
  EXPECT_NEAR(k(StiffnessRule::Maximum), kMain, rel(kMain));                 // Istf 3
  EXPECT_NEAR(k(StiffnessRule::Minimum), kSecondary, rel(kSecondary));       // Istf 4
  EXPECT_NEAR(k(StiffnessRule::Series), series, rel(series));                // Istf 5
  EXPECT_NEAR(k(StiffnessRule::Mean), 1.1725680889248209e8, rel(1.17e8));    // by hand (Python)
  EXPECT_NEAR(k(StiffnessRule::Series), 4.1841711769126445e7, rel(4.18e7));  // by hand (Python)
  // The rules are symmetric where the seed's formula is (swap main and secondary).
  s.rule = StiffnessRule::Series;
  EXPECT_NEAR(combined_stiffness(s, kSecondary, kMain), series, rel(series));
}

TEST(StiffnessRule, StminStmaxClampIstf2To5ButNotIstf1000) {
  StiffnessSettings s;
  s.minimum = 1e8;    // Stmin: above K_s and the series value
  s.maximum = 1.5e8;  // Stmax: below K_m
  const auto k = [&](StiffnessRule rule) {
    s.rule = rule;
    return combined_stiffness(s, kMain, kSecondary);
  };
  const auto clamp = [&](double kn) { return std::max(s.minimum, std::min(s.maximum, kn)); };
  const double mean = (kMain + kSecondary) / 2.0;  // 1.17e8: inside [Stmin, Stmax]
  EXPECT_NEAR(k(StiffnessRule::Mean), clamp(mean), rel(mean));
  EXPECT_NEAR(k(StiffnessRule::Mean), mean, rel(mean));
  EXPECT_EQ(k(StiffnessRule::Maximum), 1.5e8);  // max(K_m, K_s) = 1.8e8 > Stmax
  EXPECT_EQ(k(StiffnessRule::Minimum), 1e8);    // min = 5.45e7 < Stmin
  EXPECT_EQ(k(StiffnessRule::Series), 1e8);     // 4.18e7 < Stmin
  // Istf 1000 (main side only) is outside "Istf > 1 and Istf < 7": neither bound applies.
  EXPECT_NEAR(k(StiffnessRule::Main), kMain, rel(kMain));
  s.minimum = 1e9;
  EXPECT_NEAR(k(StiffnessRule::Main), kMain, rel(kMain));
  EXPECT_EQ(k(StiffnessRule::Mean), 1e9);
}

TEST(GapRule, RadiossVariableGapOfShells) {
  // Seed 004, comment 3: g_m = g_s = Gap_scale t / 2 on shells; Igap 3 caps the sum at
  // %mesh_size (g_s_l + g_m_l).
  GapSettings s;
  s.scale = 0.8;
  EXPECT_DOUBLE_EQ(shell_gap(s, 2.0), 0.8);
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_DOUBLE_EQ(pair_gap(0.8, 0.5, inf, 4.0, inf), 1.3);  // Igap 1
  EXPECT_DOUBLE_EQ(pair_gap(0.8, 0.5, inf, 4.0, 0.4), 1.3);  // not in self contact: no cap
  EXPECT_DOUBLE_EQ(pair_gap(0.8, 0.5, 1.0, 2.0, 0.4), 1.2);  // 0.4 (1 + 2)
  EXPECT_DOUBLE_EQ(shell_segment_stiffness(210e9, 0.002, 2.0), 2.0 * 0.5 * 210e9 * 0.002);
}

}  // namespace
}  // namespace abut
