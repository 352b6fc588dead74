// Static Hertz line contact: an elastic cylinder pressed on a (much stiffer) elastic plane, plane
// strain, frictionless. Reference (Hertz 1882; Johnson, "Contact Mechanics", 1985, chapter 4,
// two-dimensional contact of cylindrical bodies, pp. 99-104): under a load P per unit length,
//   p(x) = p0 sqrt(1 - x^2 / b^2),   b = sqrt(4 P R / (pi E*)),   p0 = 2 P / (pi b),
//   1/E* = (1 - nu1^2) / E1 + (1 - nu2^2) / E2.
// (P = pi b p0 / 2 is the integral of the ellipse; the half-space condition p0 = b E* / (2 R)
// then gives b.)
//
// Model (mm, N, MPa; small strain):
//  - Part 1, the cylinder, R = 100, steel: its lower part, x in [0, 50] (symmetry plane x = 0,
//    u_x = 0 there) below z = 50, with the bottom on the circle that touches z = 0 at x = 0. A
//    mapped mesh: columns of h1 = 0.1 up to x = 3 (the contact half-width is 1.68, so 17
//    elements across it, 34 Gauss points of the surface-to-surface contact), then growing by
//    1.3 per element to x = 50; rows likewise from the curved bottom up. Hertz needs only the
//    curvature at the contact and bodies large against b (here 30 b): the rest of the cylinder
//    is left out.
//  - Part 2, the plane: a block x in [0, 50], z in [-50, 0], E2 = 1000 E (its compliance still
//    enters E*), bottom held in z, meshed with h2 = 0.35 near the contact (not matching part 1),
//    growing by 1.3.
//  - Plane strain: one element (thickness t = h1) in y, u_y = 0 at every node.
//  - Load: the top of the cylinder (z = 50) moved down by 0.06 in one increment. P is measured:
//    the reactions of the top nodes, times 2 (half model), per unit length.
//  - Contact: cylinder bottom (secondary) on the block top (main), frictionless, linear penalty
//    100 E / h1 (penetration at the peak p0 / k = 9e-6 mm: 5e-6 of b; penalties from 3 to
//    1000 E / h1 give b and p0 within 1% of Hertz, so the penalty is not what is measured).
//    Also 10 E / h1 (CalculiX's advice) for the profile, below.
//
// A stiff plane, not one of the cylinder's material: on an interface that stays curved (equal
// materials: radius 2 R) two non-matching piecewise linear surfaces differ by up to the chord
// sagitta h^2 / (16 R), about 6e-6 mm here, of the order of the penetration; the point-wise
// penalty turns that into a pressure ripple of +-70% (S2S, 100 E / h) from point to point. The
// stiff plane stays flat, so the cylinder's facets can lie on it exactly.
//
// What is measured, from the contact points of the last state (StaticContact::points(): current
// position x, pressure p, active):
//  - the peak pressure: the largest point pressure (the nearest point is at most 0.013 b from
//    the centre, where the ellipse is within 1e-4 of p0);
//  - the half-width: the least-squares fit of p^2 = p0^2 (1 - x^2 / b^2), linear in x^2, over all
//    points with p > 0 (the element across the edge of contact is not resolved point by point,
//    the fit averages it out);
//  - also checked: the pressure at every point more than three elements (3 h1 = 0.18 b) inside
//    the Hertz edge is the ellipse to 3% of p0 (two elements with the softer penalty), the last
//    point with p > 0 is within 2 h1 of b, and the contact force equals the reactions.
// Both discretisations (surface-to-surface Gauss points, node-to-surface) are held to 3%. With
// the other mesh sizes tried, b and p0 stayed within 1% (h1 = b / 34: within 0.6%; box 100 x 100
// instead of 50 x 50: 0.7%; b / R = 0.009: 0.3%, 0.033: 1.2%); with h1 = b / 8.4, S2S's b was
// 2.2% off.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <map>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "abut/solver/static_solver.hpp"

namespace abut {
namespace {

constexpr double kE = 210000.0, kNu = 0.3;  // MPa
constexpr double kStiff = 1000.0;           // E2 / E1
constexpr double kR = 100.0;                // cylinder radius [mm]
constexpr double kWidth = 50.0, kHeight = 50.0;
constexpr double kH1 = 0.1, kH2 = 0.35;  // element sizes at the contact: cylinder, plane
constexpr double kFine = 3.0;            // extent of the uniform elements from the contact point
constexpr double kGrowth = 1.3;          // element size ratio beyond it
constexpr double kT = kH1;               // thickness (y)
constexpr double kDelta = 0.06;          // prescribed approach of the cylinder's top

// Positions 0 = s_0 < s_1 < ... < s_n = total: steps of h up to `fine`, then steps growing by
// `growth` (scaled to end at `total`).
std::vector<double> graded(double h, double fine, double growth, double total) {
  std::vector<double> s{0.0};
  while (s.back() + 0.5 * h < fine) s.push_back(s.back() + h);
  const double start = s.back();
  std::vector<double> steps;
  double step = h, sum = 0.0;
  while (sum < total - start) {
    step *= growth;
    steps.push_back(step);
    sum += step;
  }
  const double scale = (total - start) / sum;
  for (const double d : steps) s.push_back(s.back() + d * scale);
  s.back() = total;
  return s;
}

// A mapped block of hexes one element thick in y (0..kT): columns at xs, and in column x the rows
// z = bottom(x) + f_j (top(x) - bottom(x)), f from 0 to 1. Hexes column by column, bottom up, so
// hex (i, j) is first + i (f.size() - 1) + j; local face 0 is the bottom (z-), 1 the top (z+).
template <class Bottom, class Top>
void add_block(Mesh& mesh, std::int64_t part, const std::vector<double>& xs,
               const std::vector<double>& f, Bottom bottom, Top top) {
  const std::size_t nx = xs.size(), nz = f.size();
  std::vector<std::int32_t> node(nx * nz * 2);
  auto at = [&](std::size_t i, std::size_t j, std::size_t k) { return node[(i * nz + j) * 2 + k]; };
  for (std::size_t i = 0; i < nx; ++i) {
    const double zb = bottom(xs[i]), zt = top(xs[i]);
    for (std::size_t j = 0; j < nz; ++j)
      for (std::size_t k = 0; k < 2; ++k)
        node[(i * nz + j) * 2 + k] = mesh.nodes.add(
            mesh.next_node_id(), {xs[i], static_cast<double>(k) * kT, zb + f[j] * (zt - zb)});
  }
  for (std::size_t i = 0; i + 1 < nx; ++i)
    for (std::size_t j = 0; j + 1 < nz; ++j)
      mesh.add_hex(mesh.next_hex_id(), part,
                   {at(i, j, 0), at(i + 1, j, 0), at(i + 1, j, 1), at(i, j, 1), at(i, j + 1, 0),
                    at(i + 1, j + 1, 0), at(i + 1, j + 1, 1), at(i, j + 1, 1)});
}

// The same mapped block as cells of `type` (hex20, hex27 or tet10) of twice the size: each cell
// spans two columns and two rows of (xs, f), whose in-between values are its lattice of edge,
// face and centre nodes (so curved edges follow bottom(x)); a tet10 is one of the 6 tetrahedra
// around the diagonal 0-6 of such a cell, its midside nodes on that lattice too. Only the nodes
// the cells use are made. Returns, per cell, whether each node lies on the bottom (lattice row 0)
// through `on_bottom` (indexed by node).
template <class Bottom, class Top>
void add_cells(Mesh& mesh, std::int64_t part, CellType type, const std::vector<double>& xs,
               const std::vector<double>& f, Bottom bottom, Top top,
               std::vector<std::uint8_t>& on_bottom) {
  const std::size_t nx = xs.size(), nz = f.size();  // odd: 2 cells' lattice + 1
  std::map<std::array<std::size_t, 3>, std::int32_t> made;
  const auto node = [&](std::size_t i, std::size_t j, std::size_t k) {
    const auto it = made.find({i, j, k});
    if (it != made.end()) return it->second;
    const double zb = bottom(xs[i]), zt = top(xs[i]);
    const std::int32_t n = mesh.nodes.add(
        mesh.next_node_id(), {xs[i], 0.5 * static_cast<double>(k) * kT, zb + f[j] * (zt - zb)});
    on_bottom.resize(mesh.nodes.size(), 0);
    on_bottom[static_cast<std::size_t>(n)] = j == 0;
    made.emplace(std::array<std::size_t, 3>{i, j, k}, n);
    return n;
  };
  // The cell's natural (xi, eta, zeta) run along x, y, z: lattice (2i + xi + 1, 2j + zeta + 1,
  // eta + 1).
  const auto lattice = [](double xi) { return static_cast<std::size_t>(std::lround(xi + 1.0)); };
  for (std::size_t i = 0; i + 2 < nx; i += 2)
    for (std::size_t j = 0; j + 2 < nz; j += 2) {
      const CellTopology& hex = topology(type == CellType::tet10 ? CellType::hex27 : type);
      std::vector<std::array<std::size_t, 3>> place;
      for (const auto& xi : hex.natural)
        place.push_back({i + lattice(xi[0]), j + lattice(xi[2]), lattice(xi[1])});
      if (type != CellType::tet10) {
        std::vector<std::int32_t> cell;
        for (const auto& q : place) cell.push_back(node(q[0], q[1], q[2]));
        mesh.add_cell(type, 1000000 + static_cast<std::int64_t>(mesh.solid_count()), part, cell);
        continue;
      }
      constexpr int kTets[6][4] = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6},
                                   {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};
      for (const auto& tet : kTets) {
        std::array<std::array<std::size_t, 3>, 4> c = {place[tet[0]], place[tet[1]], place[tet[2]],
                                                       place[tet[3]]};
        const auto at = [&](int a) { return mesh.nodes.position(node(c[a][0], c[a][1], c[a][2])); };
        if (dot(cross(at(1) - at(0), at(2) - at(0)), at(3) - at(0)) < 0.0) std::swap(c[1], c[2]);
        std::vector<std::int32_t> cell;
        for (const auto& q : c) cell.push_back(node(q[0], q[1], q[2]));
        for (const EdgeTopology& e : topology(CellType::tet10).edges)
          cell.push_back(node((c[e.a][0] + c[e.b][0]) / 2, (c[e.a][1] + c[e.b][1]) / 2,
                              (c[e.a][2] + c[e.b][2]) / 2));
        mesh.add_cell(CellType::tet10, 1000000 + static_cast<std::int64_t>(mesh.solid_count()),
                      part, cell);
      }
    }
}

struct HertzModel {
  Model model;
  std::vector<std::int32_t> top;  // the driven nodes of the cylinder
};

HertzModel cylinder_on_plane(Discretisation discretisation, double penalty,
                             CellType type = CellType::hex8) {
  HertzModel hm;
  Model& m = hm.model;
  // Part 1: the cylinder, fine at its bottom. Quadratic cells span two of the linear spacings, so
  // that the nodes are as far apart as the hexahedra's (an odd count of positions: cells of two).
  std::vector<double> x1 = graded(kH1, kFine, kGrowth, kWidth);
  std::vector<double> f1 = graded(kH1, kFine, kGrowth, kHeight);
  for (double& v : f1) v /= kHeight;
  const auto circle = [](double x) { return kR - std::sqrt(kR * kR - x * x); };
  std::vector<std::uint8_t> on_bottom;
  if (type == CellType::hex8) {
    add_block(m.mesh, 1, x1, f1, circle, [](double) { return kHeight; });
  } else {
    for (auto* s : {&x1, &f1})
      if (s->size() % 2 == 0) s->erase(s->end() - 2);  // merge the last two spacings
    add_cells(
        m.mesh, 1, type, x1, f1, circle, [](double) { return kHeight; }, on_bottom);
  }
  const std::size_t hexes1 = m.mesh.hex_count(), nodes1 = m.mesh.nodes.size();
  // Part 2: the plane, fine at its top.
  const std::vector<double> x2 = graded(kH2, kFine, kGrowth, kWidth);
  std::vector<double> f2;
  const std::vector<double> depth = graded(kH2, kFine, kGrowth, kHeight);
  for (auto d = depth.rbegin(); d != depth.rend(); ++d) f2.push_back(1.0 - *d / kHeight);
  add_block(
      m.mesh, 2, x2, f2, [](double) { return -kHeight; }, [](double) { return 0.0; });

  for (const auto& [id, young] : {std::pair{1, kE}, std::pair{2, kStiff * kE}}) {
    Material mat;
    mat.id = id;
    mat.params = ElasticParams{7.8e-9, young, kNu};
    m.materials.push_back(mat);
    Part p;
    p.id = id;
    p.material_id = id;
    p.solid_integration = Part::SolidIntegration::Full;
    m.parts.push_back(p);
  }

  StaticStep step;
  const Nodes& n = m.mesh.nodes;
  for (std::size_t i = 0; i < n.size(); ++i) {
    const auto node = static_cast<std::int32_t>(i);
    step.displacements.push_back({node, 1, 0.0, {}, {}});                     // plane strain
    if (n.x[i] == 0.0) step.displacements.push_back({node, 0, 0.0, {}, {}});  // symmetry
    if (i < nodes1 && n.z[i] == kHeight) {
      step.displacements.push_back({node, 2, -kDelta, {}, {}});
      hm.top.push_back(node);
    }
    if (i >= nodes1 && n.z[i] == -kHeight) step.displacements.push_back({node, 2, 0.0, {}, {}});
  }
  m.static_steps.push_back(step);
  m.time.end_time = 1.0;

  FaceSet bottom, top;  // of the cylinder (face 0 of its lowest row), of the plane (face 1)
  bottom.id = 1;
  top.id = 2;
  const std::size_t rows1 = f1.size() - 1, rows2 = f2.size() - 1;
  if (type == CellType::hex8) {
    for (std::size_t i = 0; i + 1 < x1.size(); ++i)
      bottom.faces.push_back({static_cast<std::int32_t>(i * rows1), 0});
  } else {  // the faces whose nodes all lie on the bottom; cells follow the plane's hexes
    const CellBlock& cells = m.mesh.cells.at(0);
    for (std::size_t c = 0; c < cells.size(); ++c)
      for (std::size_t k = 0; k < topology(cells.type).faces.size(); ++k) {
        const FaceTopology& face = topology(cells.type).faces[k];
        bool all = true;
        for (int a = 0; a < face.size(); ++a)
          all = all && on_bottom[static_cast<std::size_t>(cells.cell(c)[face.nodes[a]])];
        if (all)
          bottom.faces.push_back(
              {static_cast<std::int32_t>(m.mesh.hex_count() + c), static_cast<std::int8_t>(k)});
      }
  }
  for (std::size_t i = 0; i + 1 < x2.size(); ++i)
    top.faces.push_back({static_cast<std::int32_t>(hexes1 + i * rows2 + rows2 - 1), 1});
  m.face_sets.push_back(bottom);
  m.face_sets.push_back(top);
  ContactSpec c;
  c.id = 1;
  c.surface1 = {EntityType::FaceSet, 1, {}};
  c.surface2 = {EntityType::FaceSet, 2, {}};
  c.discretisation = discretisation;
  c.one_way = true;
  c.penalty = penalty;
  c.damping = 0.0;
  c.friction_law = ContactSpec::FrictionLaw::None;
  m.contacts.push_back(c);
  return hm;
}

// `edge`: the pressure is held to the ellipse at the points farther than this inside the Hertz
// edge.
void check_hertz(Discretisation discretisation, double penalty, double edge,
                 CellType type = CellType::hex8, double tolerance = 0.03) {
  const auto start = std::chrono::steady_clock::now();
  const HertzModel hm = cylinder_on_plane(discretisation, penalty, type);
  StaticControls controls;  // far below the defaults: the discretisation is measured
  controls.force_tolerance = 1e-8;
  controls.displacement_tolerance = 1e-6;
  // Surface-to-surface, every Gauss point starts open (the nearest lies 1e-6 mm above the
  // plane), so the first iteration pushes the cylinder 0.06 into the plane unopposed and the
  // active set shrinks back to the Hertz width over some 15 iterations.
  controls.max_iterations = 30;
  StaticSolver s(hm.model, controls);
  s.run([](const StaticIncrement& inc) {
    std::cout << "increment " << inc.increment << ": " << inc.attempts << " attempt(s), "
              << inc.iterations << " iterations, residual " << inc.residual << "\n";
  });

  // The load per unit length of the whole cylinder and the Hertz values for it.
  double fz = 0.0;
  for (const std::int32_t i : hm.top) fz -= s.reaction()[3 * i + 2];
  const double load = 2.0 * fz / kT;
  const double estar = 1.0 / ((1.0 - kNu * kNu) / kE + (1.0 - kNu * kNu) / (kStiff * kE));
  const double b = std::sqrt(4.0 * load * kR / (std::numbers::pi * estar));
  const double p0 = 2.0 * load / (std::numbers::pi * b);

  // Points with pressure: the peak, the fit of p^2 against x^2, the extent, the profile.
  double n = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  double peak = 0.0, extent = 0.0, profile = 0.0;
  for (const StaticContactPoint& pt : s.contacts()[0].points()) {
    if (!pt.active || pt.pressure <= 0.0) continue;
    const double x = pt.position.x, p = pt.pressure;
    n += 1.0, sx += x * x, sy += p * p, sxx += x * x * x * x, sxy += x * x * p * p;
    peak = std::max(peak, p);
    extent = std::max(extent, x);
    if (x <= b - edge)
      profile = std::max(profile, std::abs(p - p0 * std::sqrt(1.0 - x * x / (b * b))));
  }
  ASSERT_GT(n, 20.0);
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx), intercept = (sy - slope * sx) / n;
  ASSERT_LT(slope, 0.0);
  const double b_fit = std::sqrt(-intercept / slope), p0_fit = std::sqrt(intercept);
  const double contact = 2.0 * s.contacts()[0].total_force().z / kT;
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << (discretisation == Discretisation::SurfaceToSurface ? "S2S" : "N2S") << " "
            << topology(type).name << ": " << hm.model.mesh.solid_count() << " solids, "
            << s.statistics().equations << " equations, " << s.statistics().iterations
            << " iterations, " << seconds << " s\n"
            << "  P = " << load << " N/mm (contact force " << contact << "), Hertz b = " << b
            << " mm (b/R = " << b / kR << "), p0 = " << p0 << " MPa\n"
            << "  half-width (fit) " << b_fit << " (" << 100.0 * (b_fit / b - 1.0)
            << "%), peak pressure " << peak << " (" << 100.0 * (peak / p0 - 1.0)
            << "%), p0 of the fit " << p0_fit << " (" << 100.0 * (p0_fit / p0 - 1.0) << "%)\n"
            << "  last point with pressure at " << extent << " (" << 100.0 * (extent / b - 1.0)
            << "%), worst interior pressure error " << 100.0 * profile / p0 << "% of p0\n";
  EXPECT_NEAR(contact, load, 1e-6 * load);
  EXPECT_NEAR(b_fit, b, tolerance * b);
  EXPECT_NEAR(peak, p0, tolerance * p0);
  EXPECT_NEAR(p0_fit, p0, tolerance * p0);
  // The point-wise profile is held for the linear hexahedra only (see the quadratic cells' test).
  if (type == CellType::hex8) {
    EXPECT_LT(profile, 0.03 * p0);
  }
  EXPECT_NEAR(extent, b, 2.0 * kH1);  // the points resolve the edge to an element or two
}

TEST(StaticHertz, CylinderOnPlaneSurfaceToSurface) {
  check_hertz(Discretisation::SurfaceToSurface, 100.0 * kE / kH1, 3.0 * kH1);
}

TEST(StaticHertz, CylinderOnPlaneNodeToSurface) {
  check_hertz(Discretisation::NodeToSurface, 100.0 * kE / kH1, 3.0 * kH1);
}

// The pressure of the surface-to-surface points in the last elements before the edge ripples, more
// so with a stiffer penalty (worst point up to two elements inside the edge: 0.4% of p0 at
// 3 E / h1, 0.5% at 10, 1.8% at 30, 3.9% at 100, 6.2% at 1000; in the last element, 15% at 100)
// while b and p0 stay within 1%; node-to-surface stays within 0.6% at every penalty. With the
// penalty of CalculiX's advice the profile holds to 3% up to two elements from the edge.
TEST(StaticHertz, CylinderOnPlaneSurfaceToSurfaceSoftPenalty) {
  check_hertz(Discretisation::SurfaceToSurface, 10.0 * kE / kH1, 2.0 * kH1);
}

// The cylinder of quadratic and Lagrange cells, each two of the linear spacings wide (the same
// node spacing h1 = 0.1 at the contact): faces curved through their midside nodes on the
// circle, the contact on their true faces (curved_faces.hpp, 4 x 4 facets per face). The issue's
// bound for these cells, 2% on the contact half-width and the peak pressure, holds (2026-12-04:
// b +0.74 / +0.81 / +1.03%, peak +0.42 / +0.42 / +0.69% for hex20 / hex27 / tet10). The point
// pressures ripple more than the linear hexahedra's: 3.1 / 3.3 / 9.1% of p0 at worst more than
// three elements inside the edge, which is not claimed. Node-to-surface is not claimed for these
// cells either: its points are the corners of the 4 x 4 facets of each face, 25 constraints on a
// face of 8 to 9 nodes, and with this penalty their pressures alternate by up to +-35% about the
// ellipse (peak +21%, fit p0 -2.3%, though b is within 0.2% and the force is exact).
TEST(StaticHertz, QuadraticCylinderOnPlaneSurfaceToSurface) {
  for (const CellType type : {CellType::hex20, CellType::hex27, CellType::tet10}) {
    SCOPED_TRACE(std::string(topology(type).name));
    check_hertz(Discretisation::SurfaceToSurface, 100.0 * kE / kH1, 3.0 * kH1, type, 0.02);
  }
}

}  // namespace
}  // namespace abut
