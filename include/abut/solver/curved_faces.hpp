#pragma once
// Contact on the curved faces of quadratic solids (docs/contact.md, "Curved faces"): each
// quadratic face of a contact surface becomes n x n facets whose corners lie on the true face,
// at the face's shape functions; a corner that is not a node of the face is a dependent node of
// the contact library (dependent_nodes.hpp), x_v = sum_a N_a(xi_v) x_a, and the forces on it go
// to the face's nodes with the same N_a(xi_v). Corners on an edge are shared by the faces on both
// sides (they depend on that edge's nodes alone), so the surface stays closed. Each facet also
// knows its face (facet_parent.hpp): the static contact integrates the face's own shape functions
// over the overlaps of surface-to-surface cells, so that its loads are the face's consistent ones.
#include <array>
#include <cstdint>
#include <map>
#include <span>
#include <vector>

#include "abut/contact/dependent_nodes.hpp"
#include "abut/mesh/mesh.hpp"
#include "abut/mesh/skin.hpp"

namespace abut {

// Facets per edge of a quadratic face.
inline constexpr int kCurvedFaceDivisions = 4;

class CurvedFaces {
 public:
  explicit CurvedFaces(const Mesh& mesh, int divisions = kCurvedFaceDivisions);
  // `faces` (the skin's facets; those of one quadratic face come together) with every quadratic
  // face replaced by its subdivision. Linear faces pass unchanged. With `parents`, one entry per
  // facet returned: its face (facet_parent.hpp) for a subdivided face, a plain one otherwise.
  std::vector<SkinFace> facets(std::span<const SkinFace> faces,
                               std::vector<FacetParent>* parents = nullptr);
  // The dependent nodes made so far (indices from the mesh's node count on).
  const DependentNodes& dependents() const { return dependents_; }

 private:
  std::int32_t corner(std::span<const std::int32_t> nodes, std::span<const double> weights);

  const Mesh& mesh_;
  int divisions_;
  DependentNodes dependents_;
  // A dependent node by its terms (host node, weight in units of 2^-40), so that the two faces of
  // an edge name the same corner.
  std::map<std::vector<std::pair<std::int32_t, std::int64_t>>, std::int32_t> index_;
};

}  // namespace abut
