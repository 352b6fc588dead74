#pragma once
// One contact interface (one *CONTACT): surface-to-surface penalty contact between two
// surfaces, or self contact when both are the same facets. Each step:
//   broad phase (bucket grid, rebuilt only when nodes moved more than half the search margin)
//   -> narrow phase (closest-point projection of each integration point on the other surface)
//   -> enforcement (penalty + damping normal force, Coulomb friction, sticking contact)
//   -> side effects (energies, stable step, wear, statistics).
// Input and output are plain nodal arrays owned by the caller. The result is bitwise identical
// for any number of OpenMP threads: points are evaluated in parallel into per-point slots and
// their forces are added to the nodes serially in a fixed order. See docs/contact.md.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "abut/contact/broad_phase.hpp"
#include "abut/contact/settings.hpp"
#include "abut/contact/surface.hpp"
#include "abut/core/vec3.hpp"

namespace abut {

struct ContactInput {
  std::span<const double> x, y, z;     // current nodal coordinates
  std::span<const double> vx, vy, vz;  // current nodal velocities (may be empty at construction)
  double time = 0.0;
  double dt = 0.0;  // step over which friction, damping work and wear are integrated
};

// Nodal force arrays owned by the caller; the contact forces are added to them.
struct ContactForces {
  std::span<double> fx, fy, fz;
};

struct ContactStats {
  Vec3 force;                      // total contact force acting on the nodes of surface 1
  double normal_force = 0.0;       // sum of the normal forces of the active points
  double tangential_force = 0.0;   // sum of the magnitudes of their tangential forces
  double elastic_energy = 0.0;     // energy stored in the penalty springs now
  double damping_energy = 0.0;     // work of the contact damping so far
  double friction_energy = 0.0;    // energy dissipated by friction so far
  double max_penetration = 0.0;    // largest penetration beyond the initial offsets
  std::size_t active_points = 0;
  double stable_step = std::numeric_limits<double>::infinity();  // 2/omega of the stiffest spring
};

class ContactInterface {
 public:
  // `node_mass` and the coordinates of `initial` are indexed by node like the facets' nodes.
  // The initial coordinates fix sharp edges, nodal areas, gid_0 and the initial penetrations
  // (delta0_offset, delta0_max). Surfaces with identical facets give self contact.
  // InputError (at settings.where) for inconsistent settings.
  ContactInterface(ContactSettings settings, ContactSurface surface1, ContactSurface surface2,
                   std::span<const double> node_mass, const ContactInput& initial);

  // Adds the contact forces of the state `in` to `out` and updates energies and statistics.
  void apply(const ContactInput& in, ContactForces& out);

  const ContactStats& stats() const { return stats_; }
  // Stable step bound before any contact: 2 / sqrt(max over facets of 2 pfac A / m_min).
  double initial_stable_step() const { return initial_stable_step_; }
  // Accumulated wear depth and current contact pressure per node (0 away from the surfaces).
  std::span<const double> wear() const { return wear_; }
  std::span<const double> nodal_pressure() const { return pressure_; }

  bool self_contact() const { return sides_.size() == 1; }
  std::size_t point_count() const;
  std::size_t released_points() const;  // initially deeper than delta0_max
  std::size_t broad_phase_builds() const { return builds_; }
  double search_margin() const { return margin_; }

 private:
  enum PointState : std::uint8_t { kFree, kReleased, kTied, kUntied };

  struct Side {  // one contact surface and its integration points
    ContactSurface surface;
    std::vector<std::uint8_t> sharp;   // sharp-edge bits per facet
    std::vector<std::uint8_t> active;  // gid_0 / gid_1
    std::vector<double> depth;         // detection depth per facet: half its thickness
    std::vector<double> node_area;     // tributary area of each node (global index)
    std::vector<std::int32_t> point_facet;
    std::vector<double> point_xi, point_eta, point_weight;
  };

  struct Pass {  // the points of side `own` against the facets of side `target`
    int own = 0, target = 0;
    double weight = 1.0;  // 1/2 when both sides' points act (symmetric and self contact)
    BucketGrid grid;
    CandidateList candidates;
    std::vector<double> qx, qy, qz;  // point positions for the broad-phase query
    // History per point.
    std::vector<std::uint8_t> state;
    std::vector<double> offset;             // initial penetration subtracted (delta0_offset)
    std::vector<double> htx, hty, htz;      // tangential spring force (friction history)
    std::vector<std::int32_t> tie_facet;    // sticking contact: fixed partner
    std::vector<double> tie_xi, tie_eta;
    // Results of the current step, one slot per point.
    std::vector<std::uint8_t> hit;
    std::vector<std::int32_t> hit_facet;
    std::vector<double> hit_xi, hit_eta;
    std::vector<double> fx, fy, fz;          // force on the point (before `weight`)
    std::vector<double> area, pressure, slip_speed, normal_force, tangential_force;
    std::vector<double> energy, damping_work, slip_work, penetration, omega2;
  };

  struct Hit {
    std::int32_t facet = -1;
    double xi = 0.0, eta = 0.0, gap = 0.0;
  };

  void build_sides(const ContactInput& initial);
  void build_passes();
  void rebuild_broad_phase(const ContactInput& in);
  bool needs_rebuild(const ContactInput& in) const;
  Hit closest_facet(const Pass& pass, std::size_t p, const Vec3& x_p, const Vec3& n_p,
                    const ContactInput& in) const;
  void evaluate_point(Pass& pass, std::size_t p, const ContactInput& in);
  void scatter(const ContactInput& in, ContactForces& out);
  void update_moving_region(const ContactInput& in);
  void initial_penetrations(const ContactInput& in);

  ContactSettings settings_;
  std::vector<Side> sides_;
  std::vector<Pass> passes_;
  std::vector<double> mass_;
  std::vector<std::int32_t> surface_nodes_;  // union of both sides' nodes, sorted
  std::vector<double> bx_, by_, bz_;         // their positions at the last broad-phase build
  std::vector<double> wear_, pressure_;
  double margin_ = 0.0;
  double smooth_reach_ = 0.0;  // overshoot beyond a smooth edge per unit |gap|: tan(alpha_edge)
  double initial_stable_step_ = std::numeric_limits<double>::infinity();
  std::size_t builds_ = 0;
  ContactStats stats_;
};

}  // namespace abut
