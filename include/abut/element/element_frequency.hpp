#pragma once
// The largest eigenfrequency of one solid cell with a lumped mass: the explicit solver's stable
// step bound dt <= 2 / omega_max (the element eigenvalue inequality: the assembled mesh's largest
// frequency is at most its elements' largest with the same lumped masses; Hughes, The Finite
// Element Method, 1987/2000, section 9.3).
#include <span>

#include "abut/mesh/topology.hpp"

namespace abut {

// omega_max of the isotropic elastic cell (Lame constants lambda, mu) with coordinates X (3 per
// node) and nodal masses `masses` (> 0), integrated by its full rule: the largest eigenvalue of
// M^-1/2 K M^-1/2 by power iteration, stopped when the residual |A x - rho x| falls below 1e-6 of
// the Rayleigh quotient rho; it returns sqrt(rho + |residual|), which bounds the top eigenvalue
// from above once the iteration has found it (an eigenvalue lies within the residual of rho).
double largest_element_frequency(CellType type, std::span<const double> X,
                                 std::span<const double> masses, double lambda, double mu);

// The critical step 2 / omega_max of the cell with its HRZ lumped mass (lumped_mass.hpp) at
// density rho.
double cell_critical_step(CellType type, std::span<const double> X, double density, double lambda,
                          double mu);

}  // namespace abut
