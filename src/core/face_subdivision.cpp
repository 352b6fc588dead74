#include "abut/core/face_subdivision.hpp"

namespace abut {

FaceSubdivision subdivide_reference_face(bool quadrilateral, int n) {
  FaceSubdivision out;
  const auto at = [n](int i, int j) { return static_cast<std::int32_t>(i + (n + 1) * j); };
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double s = static_cast<double>(i) / n, t = static_cast<double>(j) / n;
      out.corners.push_back(quadrilateral ? std::array<double, 2>{-1.0 + 2.0 * s, -1.0 + 2.0 * t}
                                          : std::array<double, 2>{s, t});
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      if (quadrilateral) {
        out.facets.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
        continue;
      }
      if (i + j >= n) continue;  // beyond the hypotenuse
      out.facets.push_back({at(i, j), at(i + 1, j), at(i, j + 1), at(i, j + 1)});
      if (i + j + 1 < n)
        out.facets.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1), at(i, j + 1)});
    }
  return out;
}

}  // namespace abut
