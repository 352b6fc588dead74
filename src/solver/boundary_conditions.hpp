#pragma once
// *NODE bc and *BC_MOTION resolved for the time loop: nodal constraints and prescribed
// motions on deformable nodes, and the same on rigid bodies (translation and rotation).
#include <cstdint>
#include <vector>

#include "abut/model/model.hpp"

namespace abut {

struct NodalMotion {            // one *BC_MOTION applied to deformable nodes
  const MotionBoundary* source = nullptr;
  std::vector<std::int32_t> nodes;
  std::vector<std::int32_t> rotating_nodes;  // those with rotational degrees of freedom (shells)
};

struct RigidMotion {            // one *BC_MOTION applied to one rigid body
  const MotionBoundary* source = nullptr;
  std::size_t body = 0;         // index into the simulation's rigid bodies
};

struct BoundaryConditions {
  std::vector<NodalMotion> nodal;
  std::vector<RigidMotion> rigid;
};

// Splits every *BC_MOTION between deformable nodes and rigid bodies. `rigid_body_of_node`
// gives the body index of each node or -1; `rigid_body_of_part` maps part ids to bodies.
// Throws InputError for motions that cannot act (rotations on deformable nodes, rigid-part
// nodes addressed one by one). `rotary_inertia` (per node, empty without shells) tells which
// nodes have rotational degrees of freedom; rotations of a *BC_MOTION act on those only.
BoundaryConditions resolve_boundary_conditions(const Model& model,
                                               const std::vector<std::int32_t>& rigid_body_of_node,
                                               const std::vector<std::pair<std::int64_t, std::size_t>>& rigid_body_of_part,
                                               const std::vector<double>& rotary_inertia);

// Is the motion active at time t (window and optional activation function)?
bool motion_active(const Model& model, const MotionBoundary& m, double t);
bool prescription_active(const Model& model, const PrescribedMotion& p, double t);

}  // namespace abut
