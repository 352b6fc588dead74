#pragma once
// A ring of hexahedra about the z axis for the static verification decks (a shaft, a bearing):
// r0 <= r <= r1 with 2 elements through the wall, `around` elements round and 1 along z (length
// kRingLength), as *NODE and *ELEMENT_SOLID rows.
#include <cmath>
#include <span>
#include <sstream>
#include <utility>

#include "abut/contact/static_contact.hpp"
#include "abut/mesh/mesh.hpp"

namespace abut::verification {

inline constexpr double kRingPi = 3.14159265358979323846;
inline constexpr double kRingLength = 1.0;

struct Ring {
  int first_node = 0;  // id of node (0, 0, 0) less 1
  int around = 0;
  double r0 = 0.0, r1 = 0.0;
  int id(int ir, int it, int iz) const {
    return first_node + 1 + ir + 3 * (it % around + around * iz);
  }
  double angle(int it) const { return 2.0 * kRingPi * it / around; }  // [radians]
};

inline void write_ring(std::ostringstream& nodes, std::ostringstream& hexes, const Ring& g,
                       int part, int first_element) {
  for (int iz = 0; iz < 2; ++iz)
    for (int it = 0; it < g.around; ++it)
      for (int ir = 0; ir < 3; ++ir) {
        const double r = g.r0 + (g.r1 - g.r0) * ir / 2.0;
        nodes << g.id(ir, it, iz) << ", " << r * std::cos(g.angle(it)) << ", "
              << r * std::sin(g.angle(it)) << ", " << iz * kRingLength << "\n";
      }
  int e = first_element;
  for (int it = 0; it < g.around; ++it)
    for (int ir = 0; ir < 2; ++ir) {
      hexes << ++e << ", " << part;
      for (int iz = 0; iz < 2; ++iz)
        for (const auto& [dr, dt] : {std::pair{0, 0}, {1, 0}, {1, 1}, {0, 1}})
          hexes << ", " << g.id(ir + dr, it + dt, iz);
      hexes << "\n";
    }
}

// What drives a ring's inner nodes (within `radius` of the axis) takes: the sum of their
// reactions along y and their torque about z, from the displacements u and reactions f (3 per
// node) of a static solver's converged state.
struct DriveReaction {
  double vertical = 0.0, torque = 0.0;
};
inline DriveReaction drive_reaction(const Nodes& x, std::span<const double> u,
                                    std::span<const double> f, double radius) {
  DriveReaction r;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (std::hypot(x.x[i], x.y[i]) > radius) continue;
    r.vertical += f[3 * i + 1];
    r.torque += (x.x[i] + u[3 * i]) * f[3 * i + 1] - (x.y[i] + u[3 * i + 1]) * f[3 * i];
  }
  return r;
}

// The normal force of the static contact passes: p A summed over their points (a symmetric
// contact's two passes each halve their areas).
inline double normal_force(std::span<const StaticContact> passes) {
  double n = 0.0;
  for (const StaticContact& c : passes)
    for (const StaticContactPoint& p : c.points()) n += p.pressure * p.area;
  return n;
}

}  // namespace abut::verification
