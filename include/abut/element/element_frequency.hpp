#pragma once
// The largest eigenfrequency of one solid cell with a lumped mass: the explicit solver's stable
// step bound dt <= 2 / omega_max (the element eigenvalue inequality: the assembled mesh's largest
// frequency is at most its elements' largest with the same lumped masses; Hughes, The Finite
// Element Method, 1987/2000, section 9.3).
#include <cstddef>
#include <span>
#include <vector>

#include "abut/mesh/topology.hpp"

namespace abut {

// omega_max of the isotropic elastic cell (Lame constants lambda, mu) with coordinates X (3 per
// node) and nodal masses `masses` (> 0), integrated by its full rule: the square root of the
// largest eigenvalue of M^-1/2 K M^-1/2 (largest_symmetric_eigenvalue).
double largest_element_frequency(CellType type, std::span<const double> X,
                                 std::span<const double> masses, double lambda, double mu);

// The largest eigenvalue of the symmetric n x n matrix a (row-major; overwritten): Householder
// reduction to tridiagonal form, then bisection on the Sturm sequence (Golub & Van Loan, Matrix
// Computations, 8.3 and 8.4), to round-off and from above. A direct method: its cost, 4/3 n^3,
// does not depend on how close the top eigenvalues lie, as a power iteration's does.
double largest_symmetric_eigenvalue(std::vector<double>& a, std::size_t n);

// The critical step 2 / omega_max of the cell with its HRZ lumped mass (lumped_mass.hpp) at
// density rho.
double cell_critical_step(CellType type, std::span<const double> X, double density, double lambda,
                          double mu);

}  // namespace abut
