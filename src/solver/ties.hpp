#pragma once
// The exact ties of an explicit run (tie_search.hpp): each tied node s follows its facet,
// x_s = sum_a N_a x_a + offset, as a constraint, with no spring and no bound on the stable step.
// Central differences enforce it kinematically, the constrained tied interface of explicit codes
// (LS-DYNA Theory Manual, "Tied interfaces" / *CONTACT_TIED_..._CONSTRAINED; Belytschko, Liu &
// Moran, Nonlinear Finite Elements for Continua and Structures, 2000, section 10.3 (constraints
// by elimination of the dependent velocities)):
//   1. the tied node's lumped mass and force go to its facet's nodes with the weights N_a:
//        M_a = m_a + sum_s N_a m_s,   F_a = f_a + sum_s N_a f_s;
//   2. the facet nodes are kicked with them, v_a += dt F_a / M_a (then their boundary motions);
//   3. the tied node takes the velocity of its facet point, v_s = sum_a N_a v_a, and its position
//      is set to x_s = sum_a N_a x_a + offset after every drift (round-off does not accumulate).
// Linear momentum is conserved exactly: the total is sum_a M_a v_a (sum_a N_a = 1), whose change
// is dt sum F_a = dt sum f. Energy: the facet nodes carry the lumped mass N_a m_s (as element
// masses are lumped), not the consistent m_s N_a N_b, so the run integrates the tied system with
// the diagonal masses M_a, whose energy central differences conserve as any other's; the solver
// books that system's kinetic energy, sum (1/2) M_a v_a^2. It exceeds the nodes' own,
// sum (1/2) m v^2, by (1/2) m_s (sum_a N_a v_a^2 - (sum_a N_a v_a)^2), the variance of the
// facet's velocities, which vanishes where a facet moves rigidly.
#include <cstdint>
#include <span>
#include <vector>

#include "abut/model/model.hpp"
#include "boundary_conditions.hpp"
#include "tie_search.hpp"

namespace abut {

class KinematicTies {
 public:
  KinematicTies() = default;
  // InputError at the tie for a tied node that is a rigid part's, has a *NODE bc or a *BC_MOTION,
  // or starts with a velocity other than its facet point's, and for a facet node of a rigid part.
  KinematicTies(const Model& model, std::vector<TiedNode> tied, std::span<const double> mass,
                std::span<const std::int32_t> rigid_body_of_node,
                std::span<const std::uint8_t> node_fixed, const BoundaryConditions& bc,
                std::span<const double> vx, std::span<const double> vy, std::span<const double> vz);

  bool empty() const { return tied_.empty(); }
  std::size_t size() const { return tied_.size(); }
  // Step 2: the facet nodes' v^{n+1/2} from v^{n-1/2} (old) with the transferred mass and force
  // (f: the nodes' own forces at t^n). Keeps the transferred forces for the external work.
  void kick(double dt_avg, std::span<const double> mass, std::span<const double> ox,
            std::span<const double> oy, std::span<const double> oz, std::span<const double> fx,
            std::span<const double> fy, std::span<const double> fz, std::span<double> vx,
            std::span<double> vy, std::span<double> vz);
  // Step 3: the tied nodes' velocities from their facets' (after the boundary motions).
  void follow(std::span<double> vx, std::span<double> vy, std::span<double> vz) const;
  // Step 3: the tied nodes' positions from their facets' (after every drift).
  void place(std::span<double> x, std::span<double> y, std::span<double> z) const;

  // The mass and force the facet nodes took from their tied nodes (0 elsewhere) and whether a node
  // is tied: the external work of the kick is that of the tied system (simulation.cpp).
  bool tied(std::size_t node) const { return role_[node] == kTied; }
  double added_mass(std::size_t node) const { return added_mass_[node]; }
  double added_force(std::size_t node, int d) const { return added_force_[3 * node + d]; }

  std::span<const TiedNode> nodes() const { return tied_; }

 private:
  enum Role : std::uint8_t { kFree, kMain, kTied };
  std::vector<TiedNode> tied_;
  std::vector<std::int32_t> main_nodes_;  // every facet node of a tie, sorted
  std::vector<std::uint8_t> role_;
  std::vector<double> added_mass_, added_force_;  // per node (force: x, y, z interleaved)
};

}  // namespace abut
