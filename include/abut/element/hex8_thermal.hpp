#pragma once
// Heat conduction in the trilinear hexahedron: the conductance matrix of Fourier's law
// (2 x 2 x 2 Gauss points; one point would leave checkerboard temperature modes without
// resistance, as the hourglass modes of the one-point mechanical element), the lumped heat
// capacity, and the element's bound on the stable step of explicit (forward Euler) time
// integration. Node order and Gauss points as hex8_full.hpp / hex8_gauss.hpp.
//
// Semi-discrete heat equation (e.g. Lewis, Nithiarasu & Seetharamu, Fundamentals of the Finite
// Element Method for Heat and Fluid Flow, 2004, chapter 7): C dT/dt + K T = Q, with
//   K_ab = int k grad N_a . grad N_b dV,   C_a = rho c V / 8 (row-sum lumping),
// so that the heat flowing into node a from the element is -(K T)_a.
// Stable step of forward Euler: dt <= 2 / lambda_max(C^-1 K). The element's Gershgorin bound
// lambda_e = max_a sum_b |K_ab| / C_a bounds the assembled lambda_max (Irons' element eigenvalue
// theorem: lambda_max of the mesh <= the largest element lambda_max), so dt_e = 2 / lambda_e is
// safe for the mesh.
namespace abut {

struct Hex8Conduction {
  double conductance[64];  // K, row-major, symmetric, rows summing to 0 [power / temperature]
  double capacity[8];      // C_a [energy / temperature]
  double volume;
  double stable_step;  // 2 / lambda_e [time]
};

// X: node coordinates; conductivity k [power / (length temperature)]; volumetric heat capacity
// rho c [energy / (volume temperature)]. Preconditions: a valid (positive Jacobian) element,
// k >= 0, rho c > 0.
void hex8_conduction(const double X[8][3], double conductivity, double volumetric_capacity,
                     Hex8Conduction& out);

}  // namespace abut
