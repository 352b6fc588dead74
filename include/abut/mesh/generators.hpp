#pragma once
// Structured hexahedral meshes of *COMPONENT_BOX, *COMPONENT_SPHERE and *COMPONENT_CYLINDER.
// Each generator appends nodes (user ids from mesh.next_node_id()) and hexes (ids from
// mesh.next_hex_id()) to `mesh` and records the component's exact shape, so that later
// refinement (*CHANGE_P-ORDER) places new boundary nodes on the true geometry.
// Throws InputError (no location; the deck reader adds it) on invalid dimensions or counts.
// Shell components (*COMPONENT_SHELL_PLATE, *COMPONENT_SHELL_TUBE): shell_generators.hpp.
#include <cstdint>

#include "abut/core/vec3.hpp"
#include "abut/mesh/mesh.hpp"
#include "abut/mesh/shell_generators.hpp"

namespace abut {

struct BoxComponent {
  std::int64_t part_id = 0;
  int nx = 1, ny = 1, nz = 1;  // elements along x, y, z
  Vec3 corner1, corner2;       // opposite corners
};

struct SphereComponent {
  std::int64_t part_id = 0;
  int density = 1;             // N: mesh density parameter
  Vec3 centre;
  double inner_radius = 0.0;   // 0 = solid sphere
  double outer_radius = 0.0;
};

struct CylinderComponent {
  std::int64_t part_id = 0;
  int n_axial = 1;             // N_1: elements along the axis
  int density = 1;             // N_2: cross-section density parameter
  Vec3 end1, end2;             // centres of the end faces
  double radius1 = 0.0;        // radius at end 1
  double radius2 = 0.0;        // radius at end 2 (cone when different)
  int symmetry = 0;            // 0 full, 1 half, 2 quarter
};

// How many elements and nodes a generator would add, computed without building anything (in
// floating point: a deck may ask for more than an integer holds), so that the reader can refuse
// a mesh that cannot fit in memory before allocating it. Invalid counts or radii give 0 (the
// generator then reports them).
struct MeshSize {
  double elements = 0.0;
  double nodes = 0.0;
};
MeshSize box_size(const BoxComponent& c);
MeshSize sphere_size(const SphereComponent& c);
MeshSize cylinder_size(const CylinderComponent& c);

void generate_box(Mesh& mesh, const BoxComponent& c);
void generate_sphere(Mesh& mesh, const SphereComponent& c);
void generate_cylinder(Mesh& mesh, const CylinderComponent& c);

}  // namespace abut
