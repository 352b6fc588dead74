#pragma once
// *CHANGE_P-ORDER and *SMOOTH_MESH. Raising the order of a hex to p places the nodes of the
// equispaced (p + 1)^3 lattice in it and makes it one Lagrange hexahedron of order p on them
// (hex27, hex64 of mesh/topology.hpp: IMPETUS's higher-order elements), or splits it into
// p x p x p linear hexes on the same nodes (the nodal resolution of an order-p element, with the
// one-point hexahedra of the explicit solver). New nodes on the exterior follow the exact shape
// of generated components and, where *SMOOTH_MESH applies, a smooth surface through the
// original exterior nodes.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "abut/core/error.hpp"
#include "abut/mesh/generators.hpp"
#include "abut/mesh/geometry.hpp"
#include "abut/mesh/mesh.hpp"

namespace abut {

struct OrderChange {          // one line of *CHANGE_P-ORDER, resolved
  std::vector<std::int64_t> parts;
  int order = 1;              // 1, 2 or 3
  std::optional<Geometry> region;  // gid: only hexes whose centroid is inside
  SourceLocation where;            // the deck line, for errors (empty: the message says the keyword)
};

struct SurfaceSmoothing {     // *SMOOTH_MESH, or the alpha_max of *PART, resolved
  std::vector<std::int64_t> parts;
  double max_angle = 0.0;     // degrees: smooth across edges whose face normals differ less
  bool internal = false;
  std::optional<Geometry> region;
  SourceLocation where;  // the deck line, for errors (empty: the message says the keyword)
};

// Called once the order of every hex is known and before anything is built: `added` is what the
// split will add (p^3 - 1 hexes and about as many nodes per hex of order p), `where` the
// *CHANGE_P-ORDER line that asked for the highest order. It may throw to refuse a refinement that
// would not fit in memory (the deck reader's memory budget).
using RefinementCheck = std::function<void(const MeshSize& added, const SourceLocation& where)>;

enum class POrderForm { lagrange, split };

// Applies all smoothing and order changes of the deck to the mesh (node and hex ids of new
// entities continue after the largest existing ones). Returns one plain-English note per
// action for the user (e.g. "part 1: 189 hexes split 3x3x3 into 5103 (order 3 ...)"). A
// Lagrange hexahedron keeps its hex's id and part.
std::vector<std::string> refine_and_smooth(Mesh& mesh, const std::vector<OrderChange>& orders,
                                           const std::vector<SurfaceSmoothing>& smoothing,
                                           const RefinementCheck& check = {},
                                           POrderForm form = POrderForm::split);

}  // namespace abut
