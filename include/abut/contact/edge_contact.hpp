#pragma once
// Edge-to-edge contact (Radioss /INTER/TYPE25 Iedge, seed 004, comments 5 and 6): edges that cross
// each other are pushed apart, which a point-to-facet contact misses (two plates meeting edge to
// edge, a shell border sliding over a sharp solid edge).
//
// Each edge is a capsule of radius r (a shell edge: its gap, half the thickness by default; a
// solid edge: 0). For a pair of non-parallel edges with closest points p1 = x1(s), p2 = x2(t)
// (segment-segment closest points, Ericson 2005, Real-Time Collision Detection, 5.1.9) the
// separation is measured along c = e1 x e2 / |e1 x e2|, with the side each edge was on when the
// pair was first found (so that thin edges that cross within one step are pushed back, not
// through): delta = sigma c . (p1 - p2), penetration p = r1 + r2 - delta. The force
// F = (k p - c_d v_n) sigma c (never a pull; c_d = 2 xi sqrt(k m), m the reduced mass of the two
// closest points) acts on edge 1 with weights (1 - s, s) and against edge 2 with (1 - t, t).
// k = min(k1, k2), each edge's spring [force / length] given by the caller. Friction is not
// included (seed 004). Nearly parallel pairs are left to the point-to-facet contact.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "abut/contact/broad_phase.hpp"

namespace abut {

struct ContactEdges {
  std::vector<std::array<std::int32_t, 2>> nodes;
  std::vector<double> radius;     // [length], >= 0
  std::vector<double> stiffness;  // [force / length], > 0
  std::size_t size() const { return nodes.size(); }
  void add(std::int32_t a, std::int32_t b, double r, double k) {
    nodes.push_back({a, b});
    radius.push_back(r);
    stiffness.push_back(k);
  }
};

struct EdgeContactResult {
  double elastic_energy = 0.0;  // in the springs now
  double normal_force = 0.0;    // sum of the pair forces
  double max_penetration = 0.0;
  double omega2 = 0.0;                     // stiffest spring over its reduced mass (stable step)
  std::array<double, 3> force_on_first{};  // total force on the first edges
  std::size_t active_pairs = 0;
};

class EdgeContact {
 public:
  // `self`: the edges of `edges1` against each other (each pair once), else edges1 against
  // edges2. `margin`: the broad phase's Verlet margin (the caller rebuilds when nodes moved more
  // than half of it).
  EdgeContact(ContactEdges edges1, ContactEdges edges2, bool self, double damping, double margin);

  void rebuild(std::span<const double> x, std::span<const double> y, std::span<const double> z);
  // Adds the pair forces to f, and their damping parts also to d (whose work the caller books
  // over the step, as it books its points'), and returns the step's statistics; `mass` per node.
  EdgeContactResult apply(std::span<const double> x, std::span<const double> y,
                          std::span<const double> z, std::span<const double> vx,
                          std::span<const double> vy, std::span<const double> vz,
                          std::span<const double> mass, std::span<double> fx, std::span<double> fy,
                          std::span<double> fz, std::span<double> dx, std::span<double> dy,
                          std::span<double> dz);

  std::size_t edge_count() const { return first_.size() + (self_ ? 0 : second_.size()); }

 private:
  struct Hit {  // one pair of the current step
    std::int32_t other = -1;
    std::int8_t side = 0;  // sigma
    double s = 0.0, t = 0.0, force = 0.0, damping = 0.0;  // damping: part of force
    std::array<double, 3> direction{};
  };
  ContactEdges first_, second_;
  bool self_ = false;
  double damping_ = 0.0, margin_ = 0.0;
  BucketGrid grid_;
  CandidateList candidates_;
  std::vector<double> mx_, my_, mz_;               // midpoints of the first edges (queries)
  std::vector<std::vector<Hit>> hits_, previous_;  // per first edge
  std::vector<EdgeContactResult> partial_;         // per first edge, this step

 public:
  // The pairs in contact and the broad phase, for a restart (state_archive.hpp).
  void archive(StateArchive& a) {
    a.mark("edge contact");
    a.values(grid_, candidates_, mx_, my_, mz_, hits_, previous_, partial_);
  }
};

}  // namespace abut
