#pragma once
// Initial adjustment of secondary nodes onto a main surface (OptiStruct CONTACT, ADJUST, seed 003):
// before the analysis starts, every given node whose closest point on the surface lies inside a
// facet and within `depth` of it (on either side) is moved onto that point. The caller applies it
// to its reference configuration, so the move creates no stress.
#include <cstddef>
#include <cstdint>
#include <span>

#include "abut/contact/surface.hpp"

namespace abut {

// Moves the nodes in x, y, z; a node of a facet is never moved onto that facet. Returns the
// number of nodes moved. `depth` > 0.
std::size_t adjust_onto_surface(const ContactSurface& surface, std::span<const std::int32_t> nodes,
                                std::span<double> x, std::span<double> y, std::span<double> z,
                                double depth);

// The mean edge length of a surface's facets (OptiStruct's ADJUST = AUTO takes 5% of it).
double mean_edge_length(const ContactSurface& surface, std::span<const double> x,
                        std::span<const double> y, std::span<const double> z);

}  // namespace abut
