// Element erosion seen by the contact: facets of eroded elements leave, internal faces they
// expose join (IMPETUS no_internal = 0, seed 000), and nodes left without facets stay as free
// point masses (Abaqus/Explicit without nodal erosion, seed 001) or leave with them (nodal
// erosion; Radioss Idel 1 and 2, seed 004).
#include <algorithm>
#include <cmath>

#include "interface_impl.hpp"

namespace abut {

void InterfaceImpl::erode(std::span<const std::uint8_t> eroded) {
  const ErosionSettings& e = settings_.erosion;
  auto is_eroded = [&eroded](std::int32_t element) {
    return element >= 0 && static_cast<std::size_t>(element) < eroded.size() && eroded[element];
  };
  for (std::size_t side_index = 0; side_index < sides_.size(); ++side_index) {
    Side& side = sides_[side_index];
    const ContactSurface& surface = side.surface;
    std::vector<std::int32_t> touched;  // nodes of facets that eroded in this call
    for (std::size_t f = 0; f < surface.size(); ++f) {
      const std::uint8_t before = side.off[f];
      if ((before & kDormant) && is_eroded(surface.exposed_by[f])) side.off[f] &= ~kDormant;
      if (e.remove_facets && !(before & kEroded) && is_eroded(surface.element[f])) {
        side.off[f] |= kEroded;
        touched.insert(touched.end(), surface.facets[f].begin(), surface.facets[f].end());
      }
      side.active[f] = side.off[f] == 0 ? 1 : 0;
      if (side.off[f] != before) rebuild_pending_ = true;
    }
    if (touched.empty() || !e.keep_free_nodes) continue;
    std::sort(touched.begin(), touched.end());
    touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
    // A node is free once every facet around it has eroded. Node points (N2S) stay and act as
    // free nodes from now on; integration-point sides get a node point for it.
    const bool has_node_points = settings_.discretisation == Discretisation::NodeToSurface;
    const std::vector<std::uint8_t> no_free_edges(mass_.size(), 0);
    for (const std::int32_t node : touched) {
      if (side.node_free[node]) continue;
      bool free = true;
      for (std::int32_t k = side.node_facet_start[node]; k < side.node_facet_start[node + 1]; ++k)
        free = free && (side.off[side.node_facets[k]] & kEroded);
      if (!free) continue;
      side.node_free[node] = 1;
      if (has_node_points) continue;
      side.point_facet.push_back(side.node_facets[side.node_facet_start[node]]);
      side.point_node.push_back(node);
      side.point_xi.push_back(-1.0);
      side.point_eta.push_back(-1.0);
      side.point_weight.push_back(0.0);
      side.point_cell.insert(side.point_cell.end(), {-1.0, 1.0, -1.0, 1.0});
      side.point_reach.push_back(0.0);
      init_point(side, side.point_facet.size() - 1, no_free_edges, 1.0);
      for (Pass& pass : passes_)
        if (pass.own == static_cast<int>(side_index)) {
          // A freed node (its facets are gone) may touch with the interface's stiffest bound.
          const double bound = std::isfinite(initial_stable_step_)
                                   ? 4.0 / (initial_stable_step_ * initial_stable_step_)
                                   : 0.0;
          size_pass(pass, side.point_facet.size());
          pass.approach_omega2.back() = bound;
        }
    }
  }
}

}  // namespace abut
