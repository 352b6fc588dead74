#pragma once
// Cell-wise segment-to-segment integration of surface-to-surface contact (issue 27, item 3).
//
// An integration point of a facet stands for a cell of it: the integration cells tile the facet
// (integration.hpp, FacetPoint's cell). Its traction is taken constant over the cell (explicit
// runs; static steps integrate the normal law point by point, CellSample below), and the
// cell is integrated over its overlap with the facets of the other surface that it faces, in the
// manner of mortar methods with a piecewise constant multiplier (Puso & Laursen 2004, "A mortar
// segment-to-segment contact method for large deformation solid mechanics", CMAME 193:601;
// CalculiX's face-to-face contact, Dhondt's manual "Contact"; Tribol's mortar method): the cell
// and each facet are projected along the cell's normal onto its plane, the cell's polygon is
// clipped against each facet's (Sutherland & Hodgman 1974, "Reentrant polygon clipping", CACM
// 17:32), and on every overlap polygon the shape functions of both facets are integrated exactly
// for parallelogram facets (a rule exact for quadratics on each triangle of the polygon, the
// reference coordinates being affine in the plane there). The facets of one surface do not
// overlap, so the polygons add up to the part of the cell that lies over the other surface:
//   area       = |cell ∩ other surface|,
//   own[a]     = int over it of N_a (the point's own facet),
//   target[k]b = int over cell ∩ facet k of N_b (facet k of the other surface).
// A uniform pressure p then loads every node of both surfaces with p times its consistent share
// of the true contact area, whatever the two meshes: the contact patch test (Taylor &
// Papadopoulos 1991; Crisfield 2000) holds to round-off. Areas are measured in the projection
// plane and scaled by the cell's own area over its projected area (a cell tilted against its
// partner keeps its own area when fully covered).
//
// The mean gap over the cell is measured along the cell's normal n, but the covered facets of a
// curved surface slope against n: moving the two surfaces apart along the cell's plane changes
// the gap by the mean slope. The elastic force that derives from the cell's energy 1/2 k g^2 A
// therefore pushes along push = sum_k A_k m_k / (m_k . n) / A, with A_k the projected area over
// facet k and m_k its outward normal (for a plane h(y) over the projection plane,
// n - grad h = m / (m . n)); A_k m_k / (m_k . n) is the facet part's area vector. Along n alone,
// a flat cell pressed by a faceted sphere gains energy at every facet it passes (the seed deck's
// block-to-sphere contact: +2.6%).
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "abut/contact/facet_parent.hpp"
#include "abut/contact/quad.hpp"

namespace abut {

// Facets of the other surface one cell may be integrated against: more are folded into the
// partner facet's slot (extrapolated shape functions: the force and its moment stay, only the
// split between the nodes of the two facets is lost).
inline constexpr int kMaxOverlaps = 8;

// A cell of a facet in its reference square: [xi0, xi1] x [eta0, eta1].
struct CellBounds {
  double xi0 = -1.0, xi1 = 1.0, eta0 = -1.0, eta1 = 1.0;
};

struct CellOverlap {
  double area = 0.0;            // covered area of the cell
  Vec3 push;                    // direction of the elastic force on the cell (its n part is 1)
  Vec3 normal;                  // n: the direction of projection, from the other surface
  std::array<double, 4> own{};  // int of the own facet's N_a over the covered part
  int count = 0;                // facets of the other surface overlapped (at most kMaxOverlaps)
  std::array<std::int32_t, kMaxOverlaps> facet{};
  std::array<std::array<double, 4>, kMaxOverlaps> target{};  // int of facet k's N_b over its part
  // Facets of curved faces (facet_parent.hpp): the same integrals of the face's own shape
  // functions, over the face's nodes (Dunavant's degree-4 rule on each triangle of the polygon,
  // exact for the serendipity quad8's cubic terms where the facet's reference coordinates are
  // affine). Filled only for the sides that have a parent.
  const FacetParent* own_parent = nullptr;
  std::array<double, FacetParent::kMaxNodes> own_face{};
  std::array<const FacetParent*, kMaxOverlaps> target_parent{};
  std::array<std::array<double, FacetParent::kMaxNodes>, kMaxOverlaps> target_face{};
};

// A point of a cell's overlap, for integrating a traction that varies over the cell (static
// steps): the gap is not constant over a cell, and p(mean gap) times the integrals of N misses the
// integral of p(g) N by a term of the order of the cell's size squared (CalculiX's contact4, a
// C3D20 cube pressed into another's face: U 5.0e-4 with 8 x 8 cells per face, 1.1e-4 with 16 x
// 16, exactly as the cells' size, whatever the faces' facets). Dunavant's degree-4 rule on every
// triangle of each overlap polygon, as CalculiX integrates its clipped polygons point by point.
struct CellSample {
  double area = 0.0;                      // its share of the covered area (true, not projected)
  int slot = 0;                           // the overlap's slot in CellOverlap (facet, face)
  std::array<double, 2> own{}, target{};  // reference coordinates in the own and slot's facets
};

// The cell `cell` of facet `own`, projected along `normal` (unit) onto a plane, against the
// facets `ids` of the other surface with corners `corners` (same order; the first is the
// point's partner, into whose slot overflowing facets fold). Facets whose projection is
// degenerate are passed over.
// `own_parent`, `parents` (parallel to `ids`, or empty): the curved faces the facets are part of
// (null: none). `samples`: when given, the overlap's points are appended to it.
CellOverlap overlap_cell(const QuadCorners& own, const CellBounds& cell, const Vec3& normal,
                         std::span<const std::int32_t> ids, std::span<const QuadCorners> corners,
                         const FacetParent* own_parent = nullptr,
                         std::span<const FacetParent* const> parents = {},
                         std::vector<CellSample>* samples = nullptr);

// The most facets one cell is clipped against (further candidates are passed over).
inline constexpr std::size_t kMaxCoverFacets = 64;

// A facet turned further than about 84 degrees from a cell's normal is a wall to it, not cover.
inline constexpr double kCoverMinCos = 0.1;

// The facets of the other surface, as a cell's cover sees them.
struct CoverFacets {
  std::span<const std::array<std::int32_t, 4>> facets;
  std::span<const std::uint8_t> active;  // empty: every facet is active
  std::span<const std::int32_t> twin;  // a shell's facets (twin >= 0) are passed over; empty: none
  std::span<const double> x, y, z;
  std::span<const FacetParent> parent;  // the curved faces of the facets; empty: none
};

// The cell `cell` of the facet with nodes `own` against the facets of the other surface that it
// may cover: `partner` first, then `candidates` (the broad phase's), each once, never the own
// facet or one sharing a node with it (self contact), and only those that face the cell
// (m . n >= kCoverMinCos). `normal` (unit) points from the other surface towards the cell: minus
// the cell's own normal. The cell and the facets are projected along it, so a facet turning
// towards edge-on covers a vanishing area and none enters or leaves the cover with a jump: the
// other surface, seen from the cell, is a height field over the cell's plane.
CellOverlap cover_cell(const std::array<std::int32_t, 4>& own, const CellBounds& cell,
                       const Vec3& normal, std::int32_t partner,
                       std::span<const std::int32_t> candidates, const CoverFacets& other,
                       const FacetParent* own_parent = nullptr,
                       std::vector<CellSample>* samples = nullptr);

// The mean gap over the covered part of a cell, along o.normal: the own side's centroid less the
// other side's, both weighted by the integrals of the overlap (positive: open); a side on a
// curved face by its face's integrals and nodes, the centroid of the true face's part.
double cell_mean_gap(const std::array<std::int32_t, 4>& own, const CellOverlap& o,
                     const CoverFacets& other);

// The area of a convex polygon clipped against a convex one (both counter-clockwise), for tests.
double clipped_area(std::span<const std::array<double, 2>> subject,
                    std::span<const std::array<double, 2>> clip);

}  // namespace abut
