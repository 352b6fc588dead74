#pragma once
// A face divided into n x n facets in its natural coordinates: quadrilaterals on the grid
// xi, eta = -1 + 2i/n; triangles on the grid of area coordinates (i/n, j/n), each cell split into
// its two triangles (a triangle repeats its third corner). Corners counter-clockwise like the
// face's. The facets of a curved face (mesh/shape_functions.hpp subdivide_face) and of a smoothed
// contact surface (contact/smoothing.hpp) are made of it.
#include <array>
#include <cstdint>
#include <vector>

namespace abut {

struct FaceSubdivision {
  std::vector<std::array<double, 2>> corners;       // natural coordinates
  std::vector<std::array<std::int32_t, 4>> facets;  // indices into corners
};
FaceSubdivision subdivide_reference_face(bool quadrilateral, int n);

}  // namespace abut
