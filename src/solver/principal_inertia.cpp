#include "principal_inertia.hpp"

#include <algorithm>

#include "abut/material/sym_tensor.hpp"

namespace abut {

PrincipalInertia principal_inertia(const std::vector<Vec3>& arms,
                                   const std::vector<double>& masses) {
  Sym3 inertia;  // xx, yy, zz, xy, yz, zx
  for (std::size_t k = 0; k < arms.size(); ++k) {
    const Vec3& r = arms[k];
    const double m = masses[k];
    inertia[0] += m * (r.y * r.y + r.z * r.z);
    inertia[1] += m * (r.z * r.z + r.x * r.x);
    inertia[2] += m * (r.x * r.x + r.y * r.y);
    inertia[3] -= m * r.x * r.y;
    inertia[4] -= m * r.y * r.z;
    inertia[5] -= m * r.z * r.x;
  }
  const SymEigen eigen = eigen_symmetric(inertia);
  PrincipalInertia out;
  out.axes = eigen.vectors;
  const double largest = std::max({eigen.values[0], eigen.values[1], eigen.values[2]});
  for (int k = 0; k < 3; ++k) out.moments[k] = std::max(eigen.values[k], kInertiaFloor * largest);
  return out;
}

}  // namespace abut
