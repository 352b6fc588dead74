// Which edges take part in edge-to-edge contact (Radioss Iedge, seed 004, comment 6), with the
// radius and spring of each (edge_contact.hpp).
//   Iedge 1   both sides: the free borders of shells
//   Iedge 11  secondary (surface 1): sharp solid edges (facets meeting at an angle below
//             Edge_angle) and shell borders; main (surface 2): every exterior solid edge and the
//             shell borders
//   Iedge 13  as 11, the main side with every shell edge
//   Iedge 22  both sides: every exterior solid edge and every shell edge
// An edge's radius is its shell's gap (0 on solids); its spring is the largest of its facets'
// springs on one node: pfac A / 4 (facet penalty rule) or K_m (Radioss rules).
#include <algorithm>
#include <map>
#include <utility>

#include "abut/contact/integration.hpp"
#include "abut/contact/quad.hpp"
#include "interface_impl.hpp"

namespace abut {
namespace {

enum class Take { Borders, SharpSolidAndBorders, AllSolidAndBorders, AllSolidAndAllShell };

}  // namespace

void InterfaceImpl::build_edges(const ContactInput& in) {
  const EdgeSelection selection = settings_.edges.selection;
  if (selection == EdgeSelection::None) return;
  auto collect = [&](const Side& side, Take take) {
    const ContactSurface& surface = side.surface;
    // Solid edges meeting at an angle below Edge_angle turn their normals by more than
    // 180 - Edge_angle.
    const std::vector<std::uint8_t> sharp =
        sharp_edges(surface, in.x, in.y, in.z, 180.0 - settings_.edges.angle);
    std::map<std::pair<std::int32_t, std::int32_t>, std::pair<double, double>> edges;
    for (std::size_t f = 0; f < surface.size(); ++f) {
      const bool shell = surface.twin[f] >= 0;
      const QuadCorners c = quad_corners(surface.facets[f], in.x, in.y, in.z);
      const double spring = settings_.stiffness.rule == StiffnessRule::FacetPenalty
                                ? surface.penalty[f] * 0.125 * norm(cross(c[2] - c[0], c[3] - c[1]))
                                : side.facet_km[f];
      for (int e = 0; e < 4; ++e) {
        const std::int32_t a = surface.facets[f][e], b = surface.facets[f][(e + 1) % 4];
        if (a == b) continue;
        const bool border = shell && (side.free_edges[f] & (1u << e));
        bool wanted = false;
        switch (take) {
          case Take::Borders:
            wanted = border;
            break;
          case Take::SharpSolidAndBorders:
            wanted = border || (!shell && (sharp[f] & (1u << e)));
            break;
          case Take::AllSolidAndBorders:
            wanted = border || !shell;
            break;
          case Take::AllSolidAndAllShell:
            wanted = true;
            break;
        }
        if (!wanted) continue;
        auto& [radius, k] = edges[{std::min(a, b), std::max(a, b)}];
        radius = std::max(radius, side.facet_gap[f]);
        k = std::max(k, spring);
      }
    }
    ContactEdges out;
    for (const auto& [nodes, value] : edges)
      out.add(nodes.first, nodes.second, value.first, value.second);
    return out;
  };
  Take secondary = Take::Borders, main = Take::Borders;
  switch (selection) {
    case EdgeSelection::None:
    case EdgeSelection::ShellBorders:
      break;
    case EdgeSelection::SharpSolidEdges:
      secondary = Take::SharpSolidAndBorders;
      main = Take::AllSolidAndBorders;
      break;
    case EdgeSelection::SharpSolidAllShells:
      secondary = Take::SharpSolidAndBorders;
      main = Take::AllSolidAndAllShell;
      break;
    case EdgeSelection::AllEdges:
      secondary = main = Take::AllSolidAndAllShell;
      break;
  }
  const bool self = self_contact();
  ContactEdges first = collect(sides_[0], secondary);
  ContactEdges second = self ? ContactEdges{} : collect(sides_[1], main);
  edges_.emplace(std::move(first), std::move(second), self, settings_.damping, margin_);
}

}  // namespace abut
