#pragma once
// Dunavant's 6-point rule of degree 4 on a triangle (D. A. Dunavant, "High degree efficient
// symmetrical Gaussian quadrature rules for the triangle", IJNME 21, 1985, table of degree 4):
// area coordinates (l1, l2; l0 = 1 - l1 - l2) and weights that sum to 1 (times the triangle's
// area). Face loads of quadratic triangles (mesh/shape_functions.cpp) and the integrals of curved
// faces' shape functions over contact overlaps (contact/mortar.cpp) use it.
#include <array>

namespace abut {

struct TrianglePoint {
  double l1, l2, weight;
};

inline constexpr double kDunavantA = 0.445948490915965, kDunavantB = 0.091576213509771;
inline constexpr double kDunavantWa = 0.223381589678011, kDunavantWb = 0.109951743655322;
inline constexpr std::array<TrianglePoint, 6> kTriangleDegree4 = {
    {{kDunavantA, kDunavantA, kDunavantWa},
     {1.0 - 2.0 * kDunavantA, kDunavantA, kDunavantWa},
     {kDunavantA, 1.0 - 2.0 * kDunavantA, kDunavantWa},
     {kDunavantB, kDunavantB, kDunavantWb},
     {1.0 - 2.0 * kDunavantB, kDunavantB, kDunavantWb},
     {kDunavantB, 1.0 - 2.0 * kDunavantB, kDunavantWb}}};

}  // namespace abut
