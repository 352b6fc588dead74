#pragma once
// The lumped (diagonal) mass of a solid cell of any type (mesh/topology.hpp), as each node's share
// of the cell's volume (its mass is density times the share).
//
// Row sums of the consistent mass give the corner nodes of quadratic cells zero or negative mass
// (a 10-node tetrahedron's corners -1/20 of the volume each), which an explicit solver cannot
// divide by. The HRZ rule (Hinton, Rock & Zienkiewicz, "A note on mass lumping and related
// processes in the finite element method", Earthquake Engineering and Structural Dynamics 4,
// 1976) keeps the diagonal of the consistent mass, m_aa = int N_a^2 dV, scaled so that the shares
// add up to the volume:  share_a = V m_aa / sum_b m_bb.  Every share is positive; for straight
// cells of the linear types it is the row sum (V/8 on a parallelepiped, V/4 on a tetrahedron).
// Shares on undistorted cells: tet10 corners V/36, midside nodes 4V/27; hex20 corners 7V/248,
// midside nodes 2V/31 (the integrals of N_a^2 by hand; tests/element/test_lumped_mass.cpp).
#include <span>

#include "abut/mesh/topology.hpp"

namespace abut {

// shares[a] for the cell with coordinates X (3 per node); returns the volume. The integrals are
// exact for straight-edged cells: Gauss rules of degree >= 2p per direction (hexahedra, wedges)
// and a collapsed 4 x 4 x 4 Gauss product on tetrahedra (Stroud's conical product: the Duffy map
// of the cube adds degree 2, so it integrates degree 5 exactly).
double lumped_volume_shares(CellType type, std::span<const double> X, std::span<double> shares);

}  // namespace abut
