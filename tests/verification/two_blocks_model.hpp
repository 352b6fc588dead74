#pragma once
// The two blocks of the static contact-heat tests (issue 11, test_static_contact_heat.cpp; and
// what static thermal runs write, tests/io/test_run_static_heat.cpp): block 1, x in [0, 0.05],
// 5 x 2 x 2 hexahedra, k_1 = 100 W/(m K); block 2, x in [0.05, 0.1], 4 x 3 x 3 hexahedra
// (non-matching at the interface), k_2 = 50 W/(m K); both 0.02 x 0.02 m, steel otherwise,
// Poisson's ratio 0; geometry box 1 holds the face x = 0, box 2 the face x = 0.1. The materials,
// parts and boxes only: each test adds its supports, temperatures, contact and step.

namespace abut::verification {

inline constexpr const char* kTwoBlocksModel = R"(*UNIT_SYSTEM
SI, C
*COMPONENT_BOX
1, 1, 5, 2, 2
0.0, 0.0, 0.0, 0.05, 0.02, 0.02
*COMPONENT_BOX
2, 2, 4, 3, 3
0.05, 0.0, 0.0, 0.1, 0.02, 0.02
*MAT_ELASTIC
1, 7800.0, 2.0e11, 0.0, 0, 1
*MAT_ELASTIC
2, 7800.0, 2.0e11, 0.0, 0, 2
*PROP_THERMAL
1, 460.0, 100.0
2, 460.0, 50.0
*PART
"hot block"
1, 1
"cold block"
2, 2
*GEOMETRY_BOX
1
-0.001, -1.0, -1.0, 0.001, 1.0, 1.0
*GEOMETRY_BOX
2
0.099, -1.0, -1.0, 0.101, 1.0, 1.0
)";

}  // namespace abut::verification
