#pragma once
// The gap of a contact pair: how far from the facets' geometric surfaces the contact surfaces lie.
// Solids have none; a shell's contact surfaces lie on either side of its mid-surface (surface.hpp).
//
// Radioss /INTER/TYPE25 variable gap (seed 004, comment 3; decoded in seeds/README.md):
//     main facet          g_m = Gap_scale * t / 2 on shells, 0 on solids
//     secondary point     g_s = Gap_scale * t / 2, t the largest thickness of the shells at the
//                         node (0 for nodes of solids only; 0 on a free shell edge with Igap0 = 1)
//     pair (Igap 1)       g = min(g_s, Gap_max_s) + min(g_m, Gap_max_m)
//     pair (Igap 3)       g = min(that, %mesh_size * (g_s_l + g_m_l))
// with g_m_l the shortest edge of the main facet and g_s_l the shortest edge of the main-surface
// facets at the secondary node if that node belongs to the main surface (self contact), else
// unbounded. abut's integration points (S2S) take their own facet's g_s.
#include <algorithm>
#include <limits>
#include <optional>

namespace abut {

struct GapSettings {
  double scale = 1.0;                                              // Gap_scale
  double max_secondary = std::numeric_limits<double>::infinity();  // Gap_max_s
  double max_main = std::numeric_limits<double>::infinity();       // Gap_max_m
  std::optional<double> mesh_fraction;                             // %mesh_size: Igap 3 when set
  // Igap 2, self contact: a point does not meet facets that lay within twice the pair's gap of it
  // in the initial configuration (seed 004: curvilinear distance below 2 Gap).
  bool skip_close = false;
  bool zero_at_free_edges = false;  // Igap0 = 1 (node-to-surface points only)
  // OptiStruct GPAD (seed 003, CONTPRM/PCONT): a layer of this thickness on the main surface,
  // solid or shell, added to every pair's gap after the caps: the surfaces touch at this distance.
  double padding = 0.0;
  // Radioss Ishape (seed 004, comment 4): what a shell surface's free border is to a point that
  // carries a gap of its own (g_s > 0). Cut: the surface ends at the border. Square (Ishape 1):
  // the point's gap reaches up to g_s over the border, the gap and the push along the facet's
  // normal as on the facet. Round (Ishape 2): the facet's slab (its gap g - g_s) cut square at
  // the border, widened by a ball of radius g_s: beyond the border the push points away from the
  // slab's edge. Either way the gap never reaches further than g_s beyond the border.
  enum class Border { Cut, Square, Round } border = Border::Cut;

  bool operator==(const GapSettings&) const = default;
};

// The gap a shell of thickness t contributes on one side, before the caps.
inline double shell_gap(const GapSettings& s, double thickness) {
  return s.scale * 0.5 * thickness;
}

// The gap of a pair from the capped gaps of its two sides and their shortest edges.
inline double pair_gap(double g_secondary, double g_main, double edge_secondary, double edge_main,
                       double mesh_fraction) {
  return std::min(g_secondary + g_main, mesh_fraction * (edge_secondary + edge_main));
}

}  // namespace abut
