#pragma once
// Flat plates and closed tubes of 4-node shells (*COMPONENT_SHELL_PLATE, *COMPONENT_SHELL_TUBE),
// and the area vector of a shell. Each generator appends nodes (user ids from
// mesh.next_node_id()) and shells numbered after the largest hex and shell id, so that an element
// id in a message names one element. Nodes are not merged with other components.
// Throws InputError (no location; the deck reader adds it) on invalid dimensions or counts.
#include <cstdint>

#include "abut/core/vec3.hpp"
#include "abut/mesh/mesh.hpp"

namespace abut {

// Half the cross product of the diagonals, (x3 - x1) x (x4 - x2) / 2: the shell normal times the
// area of the quad projected on its mean plane (exact for a flat quad and for a triangle n4 == n3).
Vec3 shell_area_vector(const Nodes& nodes, const Quad4& shell);

// A parallelogram with corners p0, p1, p1 + p2 - p0, p2: n1 elements along p0 -> p1, n2 along
// p0 -> p2, nodes counter-clockwise about the normal (p1 - p0) x (p2 - p0).
struct ShellPlateComponent {
  std::int64_t part_id = 0;
  int n1 = 1, n2 = 1;
  Vec3 p0, p1, p2;
};

enum class TubeSection { Round, Square };

// A tube closed around its axis from end1 to end2 (centres of the end sections), normals outward.
// Round: a circle of mid-surface radius `radius` (n_circ >= 3 flat facets). Square: a square of
// side 2 radius (n_circ a multiple of 4, a node at every corner). The section lies in the frame
// e1, e2 with e1 x e2 along the axis: e1 is `side_direction` made normal to the axis, or, when
// that is zero, the global axis least aligned with the tube axis made normal to it (as
// *COMPONENT_CYLINDER). The first node of a section is at radius * e1 (Round) or at the corner
// radius * (e1 - e2) (Square); the square's sides face +-e1 and +-e2.
struct ShellTubeComponent {
  std::int64_t part_id = 0;
  int n_axial = 1, n_circ = 4;
  TubeSection section = TubeSection::Round;
  Vec3 end1, end2;
  double radius = 0.0;
  Vec3 side_direction;
};

// The e1 of a tube section: `hint` made normal to the unit `axis`, or, when that is zero, the
// global axis least aligned with `axis` made normal to it.
Vec3 tube_side_direction(const Vec3& axis, const Vec3& hint);

void generate_shell_plate(Mesh& mesh, const ShellPlateComponent& c);
void generate_shell_tube(Mesh& mesh, const ShellTubeComponent& c);

}  // namespace abut
