#pragma once
// OptiStruct MORIENT OVERLAP (seed 003: "Slave and master bodies overlap"): the secondary body
// starts through the main shells, and contact pushes it back out the way it came in, the reverse
// of OPENGAP (OptiStruct's user guide on contact parameters: OVERLAP is for bodies that already
// overlap and must be pushed apart, such as fitted bolts). Each shell facet then acts with one
// side, on its mid-surface (ContactSurface::add_shell_side), facing away from the secondary
// nodes that lie through it at the start.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace abut {

// For each facet (nodes counter-clockwise about its normal n; a triangle repeats its last node),
// whether its push points against n. The secondary node nearest to the facet among those whose
// normal projection falls on it (within 1e-2 of its diagonal beyond an edge) decides: a node on
// the side of n overlaps from that side and is pushed to the other, so the push is -n; a node
// behind the facet gives +n. A facet that no node projects onto takes the push of a neighbour
// across an edge (breadth first, so a patch follows the facets that see the body); a connected
// patch without any such node pushes along n.
std::vector<std::uint8_t> overlap_push_reversed(std::span<const std::array<std::int32_t, 4>> facets,
                                                std::span<const double> x,
                                                std::span<const double> y,
                                                std::span<const double> z,
                                                std::span<const std::int32_t> secondary_nodes);

}  // namespace abut
