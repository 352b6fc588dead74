// Node-to-surface contact at a convex edge of the other surface (issue 27): a plate's node right
// under a block's bottom edge, pressed by the block, lies nanometres beside or inside the block's
// side wall as the block breathes. Its nearest facet is then that wall, edge-on to the node's own
// surface, which pushes with almost none of the node's area; the node must press through the
// bottom it faces instead, with the part of its area under the block (ContactInterface::
// node_cover), whatever side of the wall it lies on. (A wall exactly upright is never a partner:
// it does not face the node at all. One leaning out by a micro-radian, as an elastic block's
// does, was.) The reference: pfac times the penetration
// times the node's area under the block, half of it here (the seed 000 penalty law on the covered
// area); it must not jump as the wall passes the node.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <tuple>

#include "abut/contact/interface.hpp"
#include "fixtures.hpp"

namespace abut {
namespace {

using testing::add_plate;
using testing::World;

// A closed box [x0, x0 + a] x [y0, y0 + a] x [z0, z0 + a] of n x n facets per face, normals
// outward, nodes shared along its edges; its two x walls lean out by `lean` per unit height (as
// the walls of a block pressed on a plate bulge above its bottom), so that their normals point a
// little down.
ContactSurface add_box(World& w, int n, double x0, double y0, double z0, double a, double pfac,
                       double lean) {
  std::map<std::tuple<int, int, int>, std::int32_t> ids;
  auto node = [&](int i, int j, int k) {
    const auto key = std::make_tuple(i, j, k);
    const auto found = ids.find(key);
    if (found != ids.end()) return found->second;
    const double h = a / n;
    const double out = lean * k * h * (2.0 * i / n - 1.0);
    const std::int32_t id = w.add_node(x0 + i * h + out, y0 + j * h, z0 + k * h, 1.0);
    ids.emplace(key, id);
    return id;
  };
  ContactSurface s;
  // Each face as (u, v) over a grid, its corners counter-clockwise seen from outside.
  auto face = [&](auto at) {
    for (int v = 0; v < n; ++v)
      for (int u = 0; u < n; ++u)
        s.add({at(u, v), at(u + 1, v), at(u + 1, v + 1), at(u, v + 1)}, 2, pfac, a);
  };
  face([&](int u, int v) { return node(v, u, 0); });  // bottom, normal -z
  face([&](int u, int v) { return node(u, v, n); });  // top, +z
  face([&](int u, int v) { return node(u, 0, v); });  // y = y0, -y
  face([&](int u, int v) { return node(v, n, u); });  // y = y0 + a, +y
  face([&](int u, int v) { return node(0, v, u); });  // x = x0, -x
  face([&](int u, int v) { return node(n, u, v); });  // x = x0 + a, +x
  return s;
}

TEST(NodeToSurfaceBorder, NodeUnderABlocksEdgePressesWithItsCoveredHalfOnEitherSideOfTheWall) {
  const double pfac = 1e9, d = 1e-6;
  // Walls nanometres either side of the node, and a little further than the penetration (where
  // the bottom is the nearest facet whichever rule is used).
  for (const double s : {-2e-6, -1e-9, 1e-12, 1e-9, 2e-6}) {
    World w;
    // The plate: 8 x 2 facets of 0.5 x 0.25 over [-1, 3] x [0.25, 0.75] at z = 0, facing up;
    // its nodes at x = 1 lie under the block's edge at x = 1 + s.
    const ContactSurface plate = add_plate(w, 8, 2, -1.0, 0.25, 4.0, 0.5, 0.0, true, pfac);
    const auto block_first = static_cast<std::int32_t>(w.x.size());
    const ContactSurface block = add_box(w, 2, s, 0.0, -d, 1.0, pfac, 1e-6);
    ContactSettings settings;
    settings.discretisation = Discretisation::NodeToSurface;
    settings.one_way = true;
    settings.damping = 0.0;
    ContactInterface contact(settings, plate, block, w.mass, w.input());
    ContactForces out = w.forces();
    contact.apply(w.input(0.0, 1e-7), out);
    // The plate's nodes at x = 1 (their areas: a quarter of each of their facets).
    double fz = 0.0, fx = 0.0, area = 0.0;
    for (std::int32_t i = 0; i < block_first; ++i)
      if (w.x[i] == 1.0) {
        fz += w.fz[i];
        fx += w.fx[i];
        area += (w.y[i] == 0.5 ? 2.0 : 1.0) * 0.5 * 0.25 / 2.0;
      }
    const double covered = (0.25 + s) / 0.5;  // of each node's quadrants along x
    EXPECT_NEAR(fz, -pfac * d * area * covered, 1e-6 * pfac * d * area) << "wall at 1 + " << s;
    EXPECT_NEAR(fx, 0.0, 1e-9 * pfac * d * area) << "wall at 1 + " << s;
  }
}

}  // namespace
}  // namespace abut
