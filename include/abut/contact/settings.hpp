#pragma once
// Settings of one contact interface. They mirror the solver's ContactSpec (the *CONTACT fields of
// seed 000) in plain values and callbacks, so that a host code can drive the library without the
// deck, the solver or the function table. Lengths, times and stresses are in the caller's units.
#include <functional>
#include <optional>

#include "abut/core/error.hpp"

namespace abut {

// mu(pres, vtang, t, x, y, z): friction coefficient from the contact pressure, the tangential
// sliding speed, the time and the current position of the contact point. Called once per
// active contact point per step from several threads at once: it must be thread-safe and cheap.
using FrictionFunction =
    std::function<double(double pres, double vtang, double t, double x, double y, double z)>;
// Wear rate (wear depth per unit time) from the contact pressure and the sliding speed.
// Thread-safety as for FrictionFunction (called serially today, but keep it pure).
using WearRateFunction = std::function<double(double pres, double vtang)>;
// Is the point (x, y, z) inside a region (gid_0 / gid_1)? Called serially.
using RegionPredicate = std::function<bool(double x, double y, double z)>;

struct ContactSettings {
  int accuracy_level = 2;          // 1: centre point, 2: 2x2 Gauss, >2: 3x3 Gauss per facet
  bool accuracy_edge = false;      // extra integration points in strips along sharp edges
  double friction = 0.0;           // Coulomb mu, used when friction_function is empty
  FrictionFunction friction_function;
  double begin_time = 0.0;         // t_beg
  double end_time = 1e20;          // t_end
  double damping = 0.1;            // xi: fraction of critical damping of each contact spring
  RegionPredicate initial_region;  // gid_0: facets whose centroid is outside at t=0 never contact
  RegionPredicate moving_region;   // gid_1: facets whose centroid leaves it are deactivated
  double initial_offset = 0.0;     // delta0_offset
  std::optional<double> initial_max;  // delta0_max; default 4% of the point's element thickness
  double edge_tolerance = 0.0;     // delta_edge: accepted overshoot beyond sharp edges
  WearRateFunction wear_rate1, wear_rate2;  // fid_wear1 / fid_wear2
  double edge_angle = 20.0;        // alpha_edge [degrees]
  bool one_way = false;            // only surface 2 is a contact surface
  std::optional<double> stick_stress;  // sigma_stick: tied contact until this traction
  std::optional<double> search_margin;  // broad-phase margin; default: half the smallest
                                         // detection depth (see docs/contact.md)
  SourceLocation where;            // the *CONTACT command, for error messages
};

}  // namespace abut
