// The C interface (abut/abut_contact.h): the same forces, statistics and state as the C++
// interface it wraps, and errors as statuses with the setting they concern, never exceptions.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "abut/abut_contact.h"
#include "abut/contact/interface.hpp"
#include "fixtures.hpp"

namespace abut {
namespace {

using testing::add_plate;
using testing::World;

// A 3 x 3 plate facing down, 10 mm into a 4 x 4 plate facing up (non-matching), sliding over
// it: both the normal and the friction law act.
struct Sliding {
  World w;
  ContactSurface lower, upper;
  std::int32_t upper_first = 0;
  Sliding() {
    lower = add_plate(w, 4, 4, -0.5, -0.5, 2.0, 2.0, 0.0, true, 2e6, 1.0, 1.0, 2);
    upper_first = static_cast<std::int32_t>(w.x.size());
    upper = add_plate(w, 3, 3, 0.0, 0.0, 1.0, 1.0, -0.01, false, 1e6, 1.0, 0.5, 1);
    for (std::size_t n = upper_first; n < w.x.size(); ++n) {
      w.vx[n] = 0.5;
      w.vz[n] = -0.02;
    }
  }
  // Moves the upper plate by its velocity over dt.
  void advance(double dt) {
    for (std::size_t n = upper_first; n < w.x.size(); ++n) {
      w.x[n] += w.vx[n] * dt;
      w.z[n] += w.vz[n] * dt;
    }
  }
};

// The C surface of a C++ one built with one part, penalty and thickness.
abut_surface* c_surface(const ContactSurface& s) {
  std::vector<std::int32_t> nodes;
  for (const auto& f : s.facets) nodes.insert(nodes.end(), f.begin(), f.end());
  abut_surface* c = abut_surface_create();
  EXPECT_EQ(
      abut_surface_add_facets(c, s.size(), nodes.data(), s.part[0], s.penalty[0], s.thickness[0]),
      ABUT_OK);
  return c;
}

struct CContact {
  abut_contact_settings* settings = abut_contact_settings_create();
  abut_surface *s1 = nullptr, *s2 = nullptr;
  abut_contact* contact = nullptr;
  CContact(const Sliding& m, double mu) {
    EXPECT_EQ(abut_contact_settings_set(settings, "friction", mu), ABUT_OK);
    s1 = c_surface(m.upper);
    s2 = c_surface(m.lower);
    contact = abut_contact_create(settings, s1, s2, m.w.x.size(), m.w.mass.data(), m.w.x.data(),
                                  m.w.y.data(), m.w.z.data(), 0, nullptr);
    EXPECT_NE(contact, nullptr) << abut_last_error();
  }
  ~CContact() {
    abut_contact_destroy(contact);
    abut_surface_destroy(s1);
    abut_surface_destroy(s2);
    abut_contact_settings_destroy(settings);
  }
  std::vector<double> apply(World& w, double t, double dt) {
    w.clear_forces();
    EXPECT_EQ(abut_contact_apply(contact, t, dt, w.x.data(), w.y.data(), w.z.data(), w.vx.data(),
                                 w.vy.data(), w.vz.data(), w.fx.data(), w.fy.data(), w.fz.data()),
              ABUT_OK)
        << abut_last_error();
    std::vector<double> f = w.fx;
    f.insert(f.end(), w.fz.begin(), w.fz.end());
    return f;
  }
};

// Identical arithmetic: the C interface only moves arguments, so every force and statistic is
// bitwise the C++ interface's.
TEST(CApi, ForcesAndStatisticsAreTheCppInterfaceBitwise) {
  Sliding m;
  ContactSettings s;
  Coulomb coulomb;
  coulomb.mu_static = coulomb.mu_dynamic = 0.3;
  s.tangential_law = coulomb;
  ContactInterface cpp(s, m.upper, m.lower, m.w.mass, m.w.input());
  CContact c(m, 0.3);
  const double dt = 1e-3;
  for (int step = 0; step < 40; ++step) {
    const double t = step * dt;
    const std::vector<double> from_c = c.apply(m.w, t, dt);
    m.w.clear_forces();
    ContactForces out = m.w.forces();
    cpp.apply(m.w.input(t, dt), out);
    std::vector<double> from_cpp = m.w.fx;
    from_cpp.insert(from_cpp.end(), m.w.fz.begin(), m.w.fz.end());
    ASSERT_EQ(from_c, from_cpp) << "step " << step;
    abut_contact_stats cs{};
    ASSERT_EQ(abut_contact_get_stats(c.contact, &cs), ABUT_OK);
    const ContactStats& ps = cpp.stats();
    EXPECT_EQ(cs.normal_force, ps.normal_force);
    EXPECT_EQ(cs.tangential_force, ps.tangential_force);
    EXPECT_EQ(cs.elastic_energy, ps.elastic_energy);
    EXPECT_EQ(cs.friction_energy, ps.friction_energy);
    EXPECT_EQ(cs.force[2], ps.force.z);
    EXPECT_EQ(abut_contact_stable_step(c.contact),
              std::min({ps.stable_step, ps.approach_step, ps.kink_step}));
    m.advance(dt);
  }
  // The contact did act: pressed and sliding (mu N of friction once sliding).
  abut_contact_stats cs{};
  abut_contact_get_stats(c.contact, &cs);
  EXPECT_GT(cs.normal_force, 0.0);
  EXPECT_NEAR(cs.tangential_force, 0.3 * cs.normal_force, 1e-9 * cs.normal_force);
}

// A restart: the state saved after 20 steps, loaded into a new interface of the same model,
// gives the next 20 steps bitwise as the uninterrupted run does.
TEST(CApi, SavedStateContinuesTheRunBitwise) {
  const double dt = 1e-3;
  Sliding m;
  CContact first(m, 0.3);
  for (int step = 0; step < 20; ++step, m.advance(dt)) first.apply(m.w, step * dt, dt);
  const std::size_t size = abut_contact_save(first.contact, nullptr, 0);
  ASSERT_GT(size, 0u);
  std::vector<char> state(size);
  ASSERT_EQ(abut_contact_save(first.contact, state.data(), state.size()), size);
  const World at_save = m.w;

  std::vector<std::vector<double>> uninterrupted;
  for (int step = 20; step < 40; ++step, m.advance(dt))
    uninterrupted.push_back(first.apply(m.w, step * dt, dt));

  Sliding again;
  CContact second(again, 0.3);
  again.w = at_save;
  ASSERT_EQ(abut_contact_restore(second.contact, state.data(), state.size()), ABUT_OK)
      << abut_last_error();
  for (int step = 20; step < 40; ++step, again.advance(dt))
    ASSERT_EQ(second.apply(again.w, step * dt, dt), uninterrupted[step - 20]) << "step " << step;

  // Bytes that are not this interface's state are refused with a message.
  std::vector<char> damaged(state.begin(), state.begin() + state.size() / 2);
  EXPECT_EQ(abut_contact_restore(second.contact, damaged.data(), damaged.size()), ABUT_ERROR);
  EXPECT_STRNE(abut_last_error(), "");
}

TEST(CApi, ErrorsAreStatusesWithTheSettingAndAMessage) {
  abut_contact_settings* s = abut_contact_settings_create();
  EXPECT_EQ(abut_contact_settings_set(s, "frction", 0.3), ABUT_ERROR);
  EXPECT_STREQ(abut_last_error_setting(), "frction");
  EXPECT_NE(std::string(abut_last_error()).find("unknown setting 'frction'"), std::string::npos);
  EXPECT_NE(std::string(abut_last_error()).find("friction"), std::string::npos);  // the known
  EXPECT_EQ(abut_contact_settings_set(s, "damping", std::nan("")), ABUT_ERROR);

  abut_surface* bad = abut_surface_create();
  const std::int32_t nodes[4] = {0, 1, 2, 3};
  EXPECT_EQ(abut_surface_add_facets(bad, 1, nodes, 1, -5.0, 1.0), ABUT_ERROR);  // penalty
  EXPECT_EQ(abut_surface_add_facets(bad, 1, nullptr, 1, 1e6, 1.0), ABUT_ERROR);
  EXPECT_EQ(abut_surface_facet_count(bad), 0u);
  const std::int32_t beyond[4] = {0, 1, 2, 99};  // node 99 of 8
  ASSERT_EQ(abut_surface_add_facets(bad, 1, beyond, 1, 1e6, 1.0), ABUT_OK);
  abut_surface* good = abut_surface_create();
  const std::int32_t other[4] = {4, 5, 6, 7};
  ASSERT_EQ(abut_surface_add_facets(good, 1, other, 2, 1e6, 1.0), ABUT_OK);
  const std::vector<double> mass(8, 1.0), coordinate(8, 0.0);
  // An interface that cannot be made: no handle, and the surface named.
  EXPECT_EQ(abut_contact_create(s, bad, good, 8, mass.data(), coordinate.data(), coordinate.data(),
                                coordinate.data(), 0, nullptr),
            nullptr);
  EXPECT_STREQ(abut_last_error_setting(), "surface1");
  EXPECT_EQ(abut_contact_create(s, nullptr, good, 8, mass.data(), coordinate.data(),
                                coordinate.data(), coordinate.data(), 0, nullptr),
            nullptr);
  EXPECT_EQ(abut_contact_apply(nullptr, 0, 0, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr,
                               nullptr, nullptr, nullptr),
            ABUT_ERROR);
  abut_surface_destroy(bad);
  abut_surface_destroy(good);
  abut_contact_settings_destroy(s);
}

}  // namespace
}  // namespace abut
