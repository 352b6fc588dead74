// Contact interface: penalty, damping, friction, activation, initial penetration, sticking,
// self contact, wear, regions, thread independence. References in each test.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstring>
#include <numbers>

#include "abut/contact/interface.hpp"
#include "fixtures.hpp"

namespace abut {
namespace {

using testing::add_plate;
using testing::World;

double sum(const std::vector<double>& f, std::int32_t first, std::int32_t last) {
  double s = 0.0;
  for (std::int32_t i = first; i < last; ++i) s += f[i];
  return s;
}

// Surface 2: a 1x1 facet (or a larger plate) at z = 0 facing up; surface 1: a 1x1 facet
// over [0,1]^2 facing down, created at z = `upper_z`. Upper nodes are [upper, end).
struct Pair {
  World w;
  ContactSurface lower, upper;
  std::int32_t upper_first = 0, end = 0;
  Pair(double upper_z, double pfac_upper, double pfac_lower, bool big_lower = false,
       double m_upper = 1.0, double m_lower = 1.0) {
    lower = big_lower ? add_plate(w, 3, 3, -1, -1, 3, 3, 0.0, true, pfac_lower, 1.0, m_lower, 2)
                      : add_plate(w, 1, 1, 0, 0, 1, 1, 0.0, true, pfac_lower, 1.0, m_lower, 2);
    upper_first = static_cast<std::int32_t>(w.x.size());
    upper = add_plate(w, 1, 1, 0, 0, 1, 1, upper_z, false, pfac_upper, 1.0, m_upper, 1);
    end = static_cast<std::int32_t>(w.x.size());
  }
  ContactInterface make(ContactSettings s) {
    return ContactInterface(std::move(s), upper, lower, w.mass, w.input());
  }
  void move_upper(double dx, double dy, double dz) { w.shift(upper_first, end, dx, dy, dz); }
  Vec3 force_on_upper() const {
    return {sum(w.fx, upper_first, end), sum(w.fy, upper_first, end), sum(w.fz, upper_first, end)};
  }
};

ContactSettings undamped(int level = 2) {
  ContactSettings s;
  s.accuracy_level = level;
  s.damping = 0.0;
  return s;
}

// Penalty law of seed 000: pressure = pfac * penetration with pfac = min(pfac_A, pfac_B), so two
// flat facets of area A overlapping by d carry F = min(pfac) * A * d, and the spring stores
// E = k d^2 / 2 with k = min(pfac) A. Points of the big lower plate outside the upper facet lie
// beyond its free (sharp) edges and must not add force.
TEST(ContactInterface, PressedFacetsCarryPenaltyTimesAreaTimesPenetration) {
  const double d = 0.01, pfac = 3e6;
  for (int level : {1, 2, 3})
    for (bool one_way : {false, true}) {
      Pair pair(0.1, 5e6, pfac, true);
      ContactSettings s = undamped(level);
      s.one_way = one_way;
      ContactInterface contact = pair.make(s);
      pair.move_upper(0, 0, -0.1 - d);
      ContactForces out = pair.w.forces();
      contact.apply(pair.w.input(0.0, 1e-6), out);
      const Vec3 f = pair.force_on_upper();
      EXPECT_NEAR(f.z, pfac * 1.0 * d, 1e-9 * pfac * d)
          << "level " << level << " one_way " << one_way;
      EXPECT_NEAR(f.x, 0.0, 1e-9);
      EXPECT_NEAR(contact.stats().force.z, pfac * d, 1e-9 * pfac * d);
      // Action = reaction: the nodal forces of both surfaces add up to zero.
      EXPECT_NEAR(sum(pair.w.fz, 0, pair.end), 0.0, 1e-12 * pfac * d);
      EXPECT_NEAR(contact.stats().elastic_energy, 0.5 * pfac * d * d, 1e-9 * pfac * d * d);
      EXPECT_NEAR(contact.stats().max_penetration, d, 1e-12);
      EXPECT_NEAR(contact.stats().normal_force, pfac * d, 1e-9 * pfac * d);
    }
}

// Seed 000: with one_way = 1 "all forces will then be perfectly perpendicular to Surface 2"
// (no friction). Surface 2 is a plane tilted by 15 degrees; surface 1 a horizontal facet
// cutting through it. The symmetric treatment, which also uses surface 1's normal, does not
// give a force along n2 here: the check can tell the two apart.
TEST(ContactInterface, OneWayForceIsNormalToSurface2) {
  for (bool one_way : {true, false}) {
    World w;
    const double a = 15.0 * std::numbers::pi / 180.0;
    ContactSurface tilted = add_plate(w, 1, 1, -2, -2, 4, 4, 0.0, true, 1e6, 1.0, 1.0, 2);
    for (std::int32_t i = 0; i < 4; ++i) w.z[i] = w.x[i] * std::tan(a);
    const Vec3 n2{-std::sin(a), 0.0, std::cos(a)};
    const auto first = static_cast<std::int32_t>(w.x.size());
    ContactSurface flat = add_plate(w, 1, 1, -0.5, -0.5, 1, 1, 1.0, false, 1e6, 1.0, 1.0, 1);
    ContactSettings s = undamped(3);
    s.one_way = one_way;
    s.initial_max = 1.0;
    ContactInterface contact(s, flat, tilted, w.mass, w.input());
    w.shift(first, first + 4, 0, 0, -1.05);
    ContactForces out = w.forces();
    contact.apply(w.input(0.0, 1e-6), out);
    const Vec3 f = contact.stats().force;
    ASSERT_GT(norm(f), 0.0);
    const double off_normal = norm(cross(f, n2)) / norm(f);
    if (one_way)
      EXPECT_LT(off_normal, 1e-12);
    else
      EXPECT_GT(off_normal, 1e-3);
  }
}

// Damping: fraction xi of the critical damping 2 sqrt(k m) of the contact spring, with the
// two facets' masses in series, m = M1 M2 / (M1 + M2) (two-body oscillator). Approaching at
// speed v with penetration d: F = k d + 2 xi sqrt(k m) v. Its work over a step of motion at v is
// booked as the mean of the damping forces at the step's two ends times the motion
// (ContactStats::damping_energy): after the first evaluation the half of its force that acts
// over the step to come, c v^2 dt / 2; after a second one at the same speed, c v^2 dt more.
// Stable step of the damped spring: (2 / omega)(sqrt(1 + xi^2) - xi) (Belytschko, Liu & Moran
// 2000, section 6.2).
TEST(ContactInterface, DampingIsAFractionOfCriticalOfTheContactSpring) {
  const double d = 0.002, pfac = 2e6, v = 3.0, xi = 0.1, dt = 1e-5;
  const double m1 = 0.5, m2 = 2.0;  // per node
  for (int level : {1, 2}) {
    Pair pair(0.1, pfac, pfac, false, m1, m2);
    ContactSettings s = undamped(level);
    s.damping = xi;
    ContactInterface contact = pair.make(s);
    pair.move_upper(0, 0, -0.1 - d);
    for (std::int32_t i = pair.upper_first; i < pair.end; ++i) pair.w.vz[i] = -v;
    ContactForces out = pair.w.forces();
    contact.apply(pair.w.input(0.0, dt), out);
    const double k = pfac * 1.0, M1 = 4 * m1, M2 = 4 * m2, m = M1 * M2 / (M1 + M2);
    const double c = 2.0 * xi * std::sqrt(k * m);
    EXPECT_NEAR(pair.force_on_upper().z, k * d + c * v, 1e-10 * k * d) << "level " << level;
    EXPECT_NEAR(contact.stats().damping_energy, 0.5 * c * v * v * dt, 1e-10 * c * v * v * dt);
    // Stable step of the spring between the two masses: omega^2 = k/m, damped at xi.
    EXPECT_NEAR(contact.stats().stable_step,
                2.0 / std::sqrt(k / m) * (std::sqrt(1.0 + xi * xi) - xi), 1e-10);
    ContactForces again = pair.w.forces();
    contact.apply(pair.w.input(0.0, dt), again);
    EXPECT_NEAR(contact.stats().damping_energy, 1.5 * c * v * v * dt, 1e-10 * c * v * v * dt);
  }
}

// Coulomb friction with an elastic predictor and return to the cone (seed 004): a block pressed
// by N and pulled by T sticks (elastic tangential spring, |x| <= 2T/k) when T < mu N and slides
// with acceleration (T - mu N)/M when T > mu N (Newton's second law with kinetic friction).
// The pull starts suddenly, so the sticking block oscillates up to 2T: T = 0.45 mu N keeps
// that below mu N. One-way contact keeps the integration points of the block over the plate
// (the symmetric pass would add the plate's points entering and leaving the block's footprint).
TEST(ContactInterface, CoulombBlockSticksBelowAndSlidesAboveMuN) {
  const double pfac = 1e6, d = 1e-3, mu = 0.3, m = 0.25, dt = 2e-5;
  const double k = pfac, N = k * d, M = 4 * m;
  for (double ratio : {0.45, 1.5}) {
    Pair pair(0.1, pfac, pfac, true, m, 1e9);
    ContactSettings s = undamped(2);
    s.tangential_law = Coulomb{mu, mu, {}, {}, {}, {}};
    s.one_way = true;
    ContactInterface contact = pair.make(s);
    pair.move_upper(0, 0, -0.1 - d);
    const double T = ratio * mu * N;
    double x0 = pair.w.x[pair.upper_first], max_shift = 0.0, v_mid = 0.0;
    const int steps = 2000;
    for (int step = 0; step < steps; ++step) {
      pair.w.clear_forces();
      ContactForces out = pair.w.forces();
      contact.apply(pair.w.input(step * dt, dt), out);
      EXPECT_LE(std::abs(contact.stats().force.x), mu * contact.stats().normal_force * (1 + 1e-12));
      for (std::int32_t i = pair.upper_first; i < pair.end; ++i) {
        pair.w.vx[i] += (pair.w.fx[i] + T / 4) / m * dt;  // semi-implicit Euler
        pair.w.x[i] += pair.w.vx[i] * dt;
      }
      max_shift = std::max(max_shift, std::abs(pair.w.x[pair.upper_first] - x0));
      if (step == steps / 2) v_mid = pair.w.vx[pair.upper_first];
    }
    EXPECT_NEAR(contact.stats().normal_force, N, 1e-9 * N);
    if (ratio < 1.0) {
      EXPECT_GT(max_shift, 0.5 * T / k);
      EXPECT_LE(max_shift, 2.0 * T / k * 1.01);
    } else {
      const double a = (pair.w.vx[pair.upper_first] - v_mid) / ((steps - 1 - steps / 2) * dt);
      EXPECT_NEAR(a, (T - mu * N) / M, 0.01 * (T - mu * N) / M);
      // Dissipation: mu N times the slip (the sliding distance less the elastic stretch).
      const double slip = pair.w.x[pair.upper_first] - x0 - mu * N / k;
      EXPECT_NEAR(contact.stats().friction_energy, mu * N * slip, 0.02 * mu * N * slip);
    }
  }
}

// Radioss /FRICTION (seed 004, fric_ID; comment 7): the law of a part pair replaces the
// interface's. The block of the test above (part 1) slides on the plate (part 2) under a pull
// above mu N: once sliding, the friction force is the pair's mu times N. Interface frictionless;
// pairs: (1, 2) mu 0.3 -> 0.3; (2, 2) mu 0.3 covers no pair that meets -> 0; (1, 2) mu 0.1 then
// every pair mu 0.25 -> the last wins, 0.25.
TEST(ContactInterface, APartPairsFrictionReplacesTheInterfacesLaw) {
  const double pfac = 1e6, d = 1e-3, m = 0.25, dt = 2e-5;
  const double N = pfac * d, T = 0.6 * N;
  auto coulomb = [](double mu) { return Coulomb{mu, mu, {}, {}, {}, {}}; };
  struct Case {
    std::vector<PairFriction> pairs;
    double mu;
  };
  const Case cases[] = {
      {{PairFriction{{1}, {2}, coulomb(0.3), {}}}, 0.3},
      {{PairFriction{{2}, {}, coulomb(0.3), {}}}, 0.0},
      {{PairFriction{{1}, {2}, coulomb(0.1), {}}, PairFriction{{}, {}, coulomb(0.25), {}}}, 0.25},
  };
  for (const Case& c : cases) {
    Pair pair(0.1, pfac, pfac, true, m, 1e9);
    ContactSettings s = undamped(2);
    s.one_way = true;
    s.pair_frictions = c.pairs;
    ContactInterface contact = pair.make(s);
    pair.move_upper(0, 0, -0.1 - d);
    for (int step = 0; step < 1000; ++step) {
      pair.w.clear_forces();
      ContactForces out = pair.w.forces();
      contact.apply(pair.w.input(step * dt, dt), out);
      for (std::int32_t i = pair.upper_first; i < pair.end; ++i) {
        pair.w.vx[i] += (pair.w.fx[i] + T / 4) / m * dt;
        pair.w.x[i] += pair.w.vx[i] * dt;
      }
    }
    EXPECT_GT(pair.w.vx[pair.upper_first], 0.0);  // sliding
    EXPECT_NEAR(std::abs(contact.stats().force.x), c.mu * contact.stats().normal_force, 1e-9 * N)
        << "mu " << c.mu;
  }
}

// Seed 000: contact acts between t_beg and t_end only.
TEST(ContactInterface, ActsOnlyBetweenBeginAndEndTime) {
  Pair pair(0.1, 1e6, 1e6);
  ContactSettings s = undamped();
  s.begin_time = 1.0;
  s.end_time = 2.0;
  ContactInterface contact = pair.make(s);
  pair.move_upper(0, 0, -0.11);
  for (double t : {0.5, 1.5, 2.5}) {
    pair.w.clear_forces();
    ContactForces out = pair.w.forces();
    contact.apply(pair.w.input(t, 1e-6), out);
    EXPECT_NEAR(pair.force_on_upper().z, (t > 1.0 && t < 2.0) ? 1e6 * 0.01 : 0.0, 1e-6)
        << "t = " << t;
  }
}

// Seed 000, delta0_offset: faces in contact at time zero get their initial penetration (up to
// the offset) subtracted, so there is no force jump at t = 0; further penetration acts fully.
TEST(ContactInterface, InitialOffsetRemovesTheForceJump) {
  const double d0 = 0.01, e = 0.004, pfac = 1e6;
  for (double offset : {0.0, 0.02}) {
    Pair pair(-d0, pfac, pfac);
    ContactSettings s = undamped();
    s.initial_offset = offset;
    ContactInterface contact = pair.make(s);
    ContactForces out = pair.w.forces();
    contact.apply(pair.w.input(0.0, 1e-6), out);
    EXPECT_NEAR(pair.force_on_upper().z, offset > 0 ? 0.0 : pfac * d0, 1e-6);
    pair.w.clear_forces();
    pair.move_upper(0, 0, -e);
    contact.apply(pair.w.input(1e-6, 1e-6), out);
    EXPECT_NEAR(pair.force_on_upper().z, pfac * (offset > 0 ? e : d0 + e), 1e-6);
  }
}

// Seed 000, delta0_max (default 4% of the element thickness): points penetrating deeper at
// time zero are released and never act.
TEST(ContactInterface, DeepInitialPenetrationIsReleased) {
  const double pfac = 1e6, d0 = 0.05;  // thickness 1: the default limit is 0.04
  {
    Pair pair(-d0, pfac, pfac);
    ContactInterface contact = pair.make(undamped());
    EXPECT_EQ(contact.released_points(), contact.point_count());
    pair.move_upper(0, 0, -0.05);
    ContactForces out = pair.w.forces();
    contact.apply(pair.w.input(0.0, 1e-6), out);
    EXPECT_EQ(pair.force_on_upper().z, 0.0);
    EXPECT_EQ(contact.stats().active_points, 0u);
  }
  {
    Pair pair(-d0, pfac, pfac);
    ContactSettings s = undamped();
    s.initial_max = 0.06;
    ContactInterface contact = pair.make(s);
    EXPECT_EQ(contact.released_points(), 0u);
    ContactForces out = pair.w.forces();
    contact.apply(pair.w.input(0.0, 1e-6), out);
    EXPECT_NEAR(pair.force_on_upper().z, pfac * d0, 1e-6);
  }
}

// Seed 000, sigma_stick: sticking contact holds in tension and shear like a spring of
// stiffness pfac*A until the traction exceeds sigma_stick; then it is ordinary contact.
TEST(ContactInterface, StickingContactHoldsUntilItsFailureStress) {
  const double pfac = 1e6, sigma = pfac * 0.002;
  Pair pair(0.0, pfac, pfac);
  ContactSettings s = undamped();
  s.stick_stress = sigma;
  ContactInterface contact = pair.make(s);
  ContactForces out = pair.w.forces();
  auto step = [&](double dx, double dz) {
    pair.move_upper(dx, 0, dz);
    pair.w.clear_forces();
    contact.apply(pair.w.input(0.0, 1e-6), out);
    return pair.force_on_upper();
  };
  EXPECT_NEAR(norm(step(0, 0)), 0.0, 1e-9);                   // touching: tied, no force
  EXPECT_NEAR(step(0, 0.001).z, -pfac * 0.001, 1e-6);         // tension below sigma
  EXPECT_NEAR(step(0.0005, -0.001).x, -pfac * 0.0005, 1e-6);  // shear
  EXPECT_NEAR(step(-0.0005, 0.0).z, 0.0, 1e-6);
  EXPECT_EQ(norm(step(0, 0.003)), 0.0);                // 3e-3 * pfac > sigma: fails
  EXPECT_EQ(norm(step(0, -0.001)), 0.0);               // failed: no tension any more
  EXPECT_NEAR(step(0, -0.003).z, pfac * 0.001, 1e-6);  // ordinary contact
  EXPECT_NEAR(step(0, 0.002).z, 0.0, 1e-6);
}

// Self contact (entity ALL): a point never contacts its own facet or a facet sharing a node
// with it. A folds onto B (sharing an edge, B lies just under A) and C is a separate facet
// under A: only the A-C pair acts, with pfac * A * d.
TEST(ContactInterface, SelfContactSkipsFacetsSharingANode) {
  World w;
  const double pfac = 1e6, d = 0.01;
  ContactSurface all;
  const auto n0 = w.add_node(0, 0, 0, 1), n1 = w.add_node(1, 0, 0, 1), n2 = w.add_node(1, 1, 0, 1),
             n3 = w.add_node(0, 1, 0, 1);
  all.add({n0, n1, n2, n3}, 1, pfac, 1.0);  // A, facing up
  const auto b2 = w.add_node(1, 1, -0.02, 1), b3 = w.add_node(0, 1, -0.02, 1);
  all.add({n0, b3, b2, n1}, 1, pfac, 1.0);  // B, facing down, hinged on A's edge y = 0
  ContactSurface c = add_plate(w, 1, 1, 0, 0, 1, 1, -d, false, pfac);
  all.add(c.facets[0], 1, pfac, 1.0);  // C, facing down
  ContactInterface contact(undamped(), all, all, w.mass, w.input());
  EXPECT_TRUE(contact.self_contact());
  ContactForces out = w.forces();
  contact.apply(w.input(0.0, 1e-6), out);
  // A's body lies below it and C's above C: the overlap pushes A down.
  EXPECT_NEAR(w.fz[n0] + w.fz[n1] + w.fz[n2] + w.fz[n3], -pfac * d, 1e-9 * pfac * d);
  EXPECT_EQ(w.fz[b2], 0.0);
  EXPECT_EQ(w.fz[b3], 0.0);
}

// Seed 000, wear: rate(pressure, speed) integrated per node; here as the rate averaged over
// each node's tributary area. The upper facet is fully in contact (wear = rate dt); a centre
// node of the 3x3 lower plate touches over a quarter of its area (wear = rate dt / 4).
TEST(ContactInterface, WearIsTheAreaAveragedRateIntegratedInTime) {
  const double pfac = 1e6, d = 0.01, dt = 0.1;
  Pair pair(0.1, pfac, pfac, true);
  ContactSettings s = undamped();
  s.wear_rate1 = [&](double pres, double) { return 2.0 * pres / (pfac * d); };
  s.wear_rate2 = [](double, double) { return 4.0; };
  ContactInterface contact = pair.make(s);
  pair.move_upper(0, 0, -0.1 - d);
  ContactForces out = pair.w.forces();
  contact.apply(pair.w.input(0.0, dt), out);
  for (std::int32_t i = pair.upper_first; i < pair.end; ++i) {
    EXPECT_NEAR(contact.wear()[i], 2.0 * dt, 1e-12);
    EXPECT_NEAR(contact.nodal_pressure()[i], pfac * d, 1e-6);
  }
  const std::int32_t centre = 1 * 4 + 1;  // lower plate node (1,1) at (0,0)
  EXPECT_NEAR(contact.wear()[centre], 4.0 * dt / 4.0, 1e-12);
  EXPECT_NEAR(contact.nodal_pressure()[centre], pfac * d / 4.0, 1e-6);
}

// gid_0 excludes facets outside the region at t = 0; gid_1 deactivates facets that leave it.
TEST(ContactInterface, RegionsExcludeAndDeactivateFacets) {
  const double pfac = 1e6, d = 0.01;
  World w;
  ContactSurface lower = add_plate(w, 2, 1, 0, 0, 2, 1, 0.0, true, pfac);
  const auto first = static_cast<std::int32_t>(w.x.size());
  ContactSurface upper = add_plate(w, 2, 1, 0, 0, 2, 1, 0.1, false, pfac);
  const auto end = static_cast<std::int32_t>(w.x.size());
  ContactSettings s = undamped();
  s.initial_region = [](double x, double, double) { return x > 1.0; };
  s.moving_region = [](double x, double, double) { return x < 5.0; };
  ContactInterface contact(s, upper, lower, w.mass, w.input());
  w.shift(first, end, 0, 0, -0.1 - d);
  ContactForces out = w.forces();
  contact.apply(w.input(0.0, 1e-6), out);
  EXPECT_NEAR(contact.stats().force.z, pfac * 1.0 * d, 1e-6);  // only the right half
  w.shift(first, end, 10.0, 0, 0);
  contact.apply(w.input(0.0, 1e-6), out);
  w.shift(first, end, -10.0, 0, 0);
  contact.apply(w.input(0.0, 1e-6), out);
  EXPECT_EQ(contact.stats().active_points, 0u);
}

TEST(ContactInterface, InconsistentSettingsAreInputErrors) {
  Pair pair(0.1, 1e6, 1e6);
  ContactSettings s;
  s.one_way = true;
  EXPECT_THROW(ContactInterface(s, pair.upper, pair.upper, pair.w.mass, pair.w.input()),
               ContactSetupError);
  s = ContactSettings{};
  s.tangential_law = Coulomb{-0.1, -0.1, {}, {}, {}, {}};
  try {
    pair.make(s);
    ADD_FAILURE() << "a negative friction coefficient was accepted";
  } catch (const ContactSetupError& e) {
    EXPECT_EQ(e.setting(), "tangential_law");  // the library's own name, not a deck field
  }
  ContactSurface bad = pair.upper;
  bad.penalty[0] = 0.0;
  EXPECT_THROW(ContactInterface(ContactSettings{}, bad, pair.lower, pair.w.mass, pair.w.input()),
               ContactSetupError);
}

// A stiff block (four nodal masses) dropped on a fixed facet with an undamped penalty spring
// bounces elastically: rebound speed = impact speed (energy conservation), here within 1%.
TEST(ContactInterface, UndampedBounceReturnsTheImpactSpeed) {
  const double pfac = 1e6, v0 = 1.0, m = 1.0;
  Pair pair(0.001, pfac, pfac, false, m, 1e12);
  ContactSettings s = undamped(2);
  ContactInterface contact = pair.make(s);
  const double M = 4 * m, k = pfac;
  const double dt = 0.02 * 2.0 * std::sqrt(M / k);
  for (std::int32_t i = pair.upper_first; i < pair.end; ++i) pair.w.vz[i] = -v0;
  bool touched = false;
  double time = 0.0, dt_seen = 1e300;
  for (int step = 0; step < 100000; ++step) {
    pair.w.clear_forces();
    ContactForces out = pair.w.forces();
    contact.apply(pair.w.input(time, dt), out);
    if (contact.stats().active_points > 0) {
      touched = true;
      dt_seen = std::min(dt_seen, contact.stats().stable_step);
    }
    for (std::int32_t i = pair.upper_first; i < pair.end; ++i) {  // central difference
      pair.w.vz[i] += pair.w.fz[i] / m * dt;
      pair.w.z[i] += pair.w.vz[i] * dt;
    }
    time += dt;
    if (touched && pair.w.z[pair.upper_first] > 0.001) break;
  }
  ASSERT_TRUE(touched);
  for (std::int32_t i = pair.upper_first; i < pair.end; ++i)
    EXPECT_NEAR(pair.w.vz[i], v0, 0.01 * v0);
  // The contact step limit is that of the block on its spring: 2/omega, omega^2 = k/M.
  EXPECT_NEAR(dt_seen, 2.0 * std::sqrt(M / k), 1e-6 * 2.0 * std::sqrt(M / k));
  EXPECT_LT(contact.initial_stable_step(), dt_seen);  // the bound before contact is conservative
}

// A normal penalty f(t) times pfac (Metafor PEN_NORMALE TM, laws/dependency.hpp) stiffens every
// spring by f: the block on its spring then has the bound 2/omega with omega^2 = f k/M, and the
// bounds made before contact (at a factor 1) shrink by sqrt(f), so that they stay below it.
TEST(ContactInterface, ATimeFactorOnThePenaltyShrinksTheStepBounds) {
  const double pfac = 1e6, v0 = 1.0, m = 1.0, f = 4.0;
  Pair plain_pair(0.001, pfac, pfac, false, m, 1e12), pair(0.001, pfac, pfac, false, m, 1e12);
  const ContactInterface plain = plain_pair.make(undamped(2));
  ContactSettings s = undamped(2);
  s.normal_in_time = {[f](double) { return f; }};
  ContactInterface contact = pair.make(s);
  EXPECT_DOUBLE_EQ(contact.initial_stable_step(), plain.initial_stable_step() / std::sqrt(f));
  const double M = 4 * m, k = f * pfac, bound = 2.0 * std::sqrt(M / k);
  const double dt = 0.02 * bound;
  for (std::int32_t i = pair.upper_first; i < pair.end; ++i) pair.w.vz[i] = -v0;
  double time = 0.0, dt_seen = 1e300, approach = 1e300;
  for (int step = 0; step < 100000; ++step) {
    pair.w.clear_forces();
    ContactForces out = pair.w.forces();
    contact.apply(pair.w.input(time, dt), out);
    approach = std::min(approach, contact.stats().approach_step);
    if (contact.stats().active_points > 0) dt_seen = std::min(dt_seen, contact.stats().stable_step);
    for (std::int32_t i = pair.upper_first; i < pair.end; ++i) {
      pair.w.vz[i] += pair.w.fz[i] / m * dt;
      pair.w.z[i] += pair.w.vz[i] * dt;
    }
    time += dt;
    if (dt_seen < 1e300 && pair.w.z[pair.upper_first] > 0.001) break;
  }
  EXPECT_NEAR(dt_seen, bound, 1e-6 * bound);
  EXPECT_LT(approach, dt_seen);  // before contact the bound was already below the stiff spring's
}

// The bound before touching limits the step only where a spring may act in the next step (issue
// 12): while the surfaces are further apart than the search margin the step only keeps the nodes
// from crossing a quarter of the margin (at rest, with no speed to judge by, the bound holds);
// near a facet the bound holds; the springs that touch give stable_step as before.
TEST(ContactInterface, TheApproachBoundActsOnlyNearAFacet) {
  Pair pair(10.0, 1e6, 1e6, false, 1.0, 1.0);
  ContactInterface contact = pair.make(undamped(2));
  const double margin = contact.search_margin();
  ASSERT_LT(margin, 5.0);
  ContactForces out = pair.w.forces();
  contact.apply(pair.w.input(0.0, 1e-6), out);
  EXPECT_EQ(contact.stats().approach_step, contact.initial_stable_step());  // at rest
  const double v = 0.01 * margin / contact.initial_stable_step();  // slow: a long step is safe
  for (std::int32_t i = pair.upper_first; i < pair.end; ++i) pair.w.vz[i] = -v;
  contact.apply(pair.w.input(0.0, 1e-6), out);
  EXPECT_DOUBLE_EQ(contact.stats().approach_step, 0.25 * margin / v);
  EXPECT_EQ(contact.stats().stable_step, std::numeric_limits<double>::infinity());
  pair.move_upper(0, 0, -10.0 + 0.25 * contact.search_margin());  // near, open
  out = pair.w.forces();
  contact.apply(pair.w.input(0.0, 1e-6), out);
  EXPECT_EQ(contact.stats().active_points, 0u);
  EXPECT_DOUBLE_EQ(contact.stats().approach_step, contact.initial_stable_step());
  EXPECT_EQ(contact.stats().stable_step, std::numeric_limits<double>::infinity());
  pair.move_upper(0, 0, -0.25 * contact.search_margin() - 0.001);  // touching
  pair.w.clear_forces();
  out = pair.w.forces();
  contact.apply(pair.w.input(0.0, 1e-6), out);
  EXPECT_GT(contact.stats().active_points, 0u);
  EXPECT_DOUBLE_EQ(contact.stats().approach_step, contact.initial_stable_step());
  EXPECT_GT(contact.stats().stable_step, contact.initial_stable_step());
}

// While the surfaces move, a point near a facet holds the step to the bound only once it may come
// within the narrow phase's reach in the next step (open_points.cpp, approach_limit): a plate
// closing in at constant speed, stepped at min(approach_step, stable_step, a long element step),
// steps longer than the bound near the other plate, and is at the bound when it first touches.
// (The rule is on while the caller's step is at least half the bound, as here.)
TEST(ContactInterface, TheApproachBoundHoldsFromJustBeforeTheFirstTouch) {
  Pair pair(10.0, 1e6, 1e6, false, 1.0, 1.0);
  ContactInterface contact = pair.make(undamped(2));
  const double margin = contact.search_margin();
  const double bound = contact.initial_stable_step();
  const double v = 0.01 * margin / bound;
  for (std::int32_t i = pair.upper_first; i < pair.end; ++i) pair.w.vz[i] = -v;
  const double element_step = 50.0 * bound;
  int long_steps_near = 0;
  double last_dt = bound;  // the caller's step, which the contact is told
  for (int step = 0; step < 100000; ++step) {
    pair.w.clear_forces();
    ContactForces out = pair.w.forces();
    contact.apply(pair.w.input(0.0, last_dt), out);
    if (contact.stats().active_points > 0) {
      // The move into contact was taken at the bound (or shorter).
      EXPECT_LE(last_dt, bound * (1.0 + 1e-12)) << "step " << step;
      EXPECT_GT(long_steps_near, 0);  // and the rule was of use before
      return;
    }
    const double dt =
        std::min({contact.stats().approach_step, contact.stats().stable_step, element_step});
    // Near: some point has a candidate facet, so the step is below the far points' rule.
    const bool near = contact.stats().approach_step < 0.25 * margin / v;
    if (near && dt > 1.01 * bound) ++long_steps_near;
    pair.move_upper(0, 0, -v * dt);
    last_dt = dt;
  }
  ADD_FAILURE() << "the plates never touched";
}

// OpenMP over points with per-point results and a serial scatter: bitwise the same forces and
// energies with 1 and 2 threads.
// One step of 1e-4 s; appends the nodal forces, the energies and, last, the active points.
void apply_and_trace(ContactInterface& contact, World& w, int step, std::vector<double>& trace) {
  w.clear_forces();
  ContactForces out = w.forces();
  contact.apply(w.input(step * 1e-4, 1e-4), out);
  trace.insert(trace.end(), w.fx.begin(), w.fx.end());
  trace.insert(trace.end(), w.fz.begin(), w.fz.end());
  trace.push_back(contact.stats().elastic_energy);
  trace.push_back(contact.stats().friction_energy);
  trace.push_back(contact.stats().damping_energy);
  trace.push_back(static_cast<double>(contact.stats().active_points));
}

TEST(ContactInterface, BitwiseIdenticalForOneAndTwoThreads) {
  auto run = [](int threads) {
    omp_set_num_threads(threads);
    World w;
    ContactSurface lower = add_plate(w, 16, 16, 0, 0, 1, 1, 0.0, true, 1e6, 0.2, 0.01, 2);
    const auto first = static_cast<std::int32_t>(w.x.size());
    ContactSurface upper =
        add_plate(w, 13, 13, 0.03, 0.02, 0.95, 0.95, 0.05, false, 2e6, 0.2, 0.01, 1);
    for (std::size_t i = 0; i < w.x.size(); ++i)
      w.z[i] += 0.004 * std::sin(7 * w.x[i]) * std::cos(5 * w.y[i]);
    ContactSettings s;
    s.accuracy_level = 3;
    s.accuracy_edge = true;
    Coulomb coulomb;
    coulomb.function = [](double pres, double vt, double, double x, double, double) {
      return 0.2 + 1e-9 * pres + 0.01 * vt + 0.01 * x;
    };
    s.tangential_law = coulomb;
    ContactInterface contact(s, upper, lower, w.mass, w.input());
    for (std::size_t i = first; i < w.x.size(); ++i) {
      w.vx[i] = 0.3 * std::sin(3.0 * static_cast<double>(i));
      w.vz[i] = -1.0;
    }
    std::vector<double> trace;
    for (int step = 0; step < 5; ++step) {
      w.shift(first, static_cast<std::int32_t>(w.x.size()), 0.001, 0.0005, -0.012);
      apply_and_trace(contact, w, step, trace);
    }
    return trace;
  };
  const int saved = omp_get_max_threads();
  const auto one = run(1);
  const auto two = run(2);
  omp_set_num_threads(saved);
  ASSERT_EQ(one.size(), two.size());
  EXPECT_GT(one[one.size() - 1], 100.0);  // many active points
  EXPECT_EQ(std::memcmp(one.data(), two.data(), one.size() * sizeof(double)), 0);
}

// Skipping the points that are surely open (open_points.cpp) is for speed only: wavy, warped
// plates that approach, touch, slide and part give bitwise the same forces and energies with it
// and without it, surface-to-surface and node-to-surface.
TEST(ContactInterface, SkippingOpenPointsChangesNothing) {
  auto run = [](bool skip, Discretisation discretisation) {
    World w;
    ContactSurface lower = add_plate(w, 16, 16, 0, 0, 1, 1, 0.0, true, 1e6, 0.2, 0.01, 2);
    const auto first = static_cast<std::int32_t>(w.x.size());
    ContactSurface upper =
        add_plate(w, 13, 13, 0.03, 0.02, 0.95, 0.95, 0.03, false, 2e6, 0.2, 0.01, 1);
    for (std::size_t i = 0; i < w.x.size(); ++i)
      w.z[i] += 0.01 * std::sin(7 * w.x[i]) * std::cos(5 * w.y[i]) + 0.002 * std::sin(40 * w.x[i]);
    ContactSettings s;
    s.discretisation = discretisation;
    s.skip_open_points = skip;
    s.tangential_law = Coulomb{0.3, 0.3, {}, {}, {}, {}};
    ContactInterface contact(s, upper, lower, w.mass, w.input());
    for (std::size_t i = first; i < w.x.size(); ++i) w.vx[i] = 0.5, w.vz[i] = -1.0;
    std::vector<double> trace;
    for (int step = 0; step < 60; ++step) {  // down 24 mm and up again, sliding and tilting
      const double down = step < 30 ? -0.0008 : 0.0008;
      for (std::int32_t i = first; i < static_cast<std::int32_t>(w.x.size()); ++i) {
        w.x[i] += 0.0004;
        w.z[i] += down * (1.0 + 0.3 * w.x[i]);
      }
      apply_and_trace(contact, w, step, trace);
    }
    return trace;
  };
  for (const auto d : {Discretisation::SurfaceToSurface, Discretisation::NodeToSurface}) {
    const auto with = run(true, d);
    const auto without = run(false, d);
    ASSERT_EQ(with.size(), without.size());
    double most_active = 0.0;  // the approach, the contact and the parting all happen
    const std::size_t per_step = with.size() / 60;
    for (std::size_t k = per_step - 1; k < with.size(); k += per_step)
      most_active = std::max(most_active, with[k]);
    EXPECT_GT(most_active, 50.0);
    EXPECT_EQ(with[per_step - 1], 0.0);
    EXPECT_EQ(with.back(), 0.0);
    EXPECT_EQ(std::memcmp(with.data(), without.data(), with.size() * sizeof(double)), 0);
  }
}

}  // namespace
}  // namespace abut
