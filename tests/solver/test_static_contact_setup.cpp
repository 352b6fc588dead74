// How the static solver takes a model's contacts (solver/static/static_contacts.hpp): one pass
// per one-way contact, two per symmetric one (the explicit interface's rule), and an error at
// the card for every contact feature that static steps do not have, rather than ignoring it.
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "abut/mesh/generators.hpp"
#include "abut/solver/simulation.hpp"
#include "abut/solver/static_solver.hpp"

namespace abut {
namespace {

// Two stacked blocks, part 1 below z = 1, part 2 above; a contact of part 2 on part 1.
Model stacked() {
  Model m;
  generate_box(m.mesh, {1, 2, 2, 1, {0, 0, 0}, {1, 1, 1}});
  generate_box(m.mesh, {2, 2, 2, 1, {0, 0, 1}, {1, 1, 2}});
  Material mat;
  mat.id = 1;
  mat.params = ElasticParams{7.8e-9, 1000.0, 0.3};
  m.materials.push_back(mat);
  for (const std::int64_t id : {1, 2}) {
    Part p;
    p.id = id;
    p.material_id = 1;
    p.solid_integration = Part::SolidIntegration::Full;
    m.parts.push_back(p);
  }
  ContactSpec c;
  c.id = 1;
  c.surface1 = {EntityType::Part, 2, {}};
  c.surface2 = {EntityType::Part, 1, {}};
  c.where = {"t.k", 7, "", ""};
  m.contacts.push_back(c);
  m.static_steps.push_back(StaticStep{});
  return m;
}

TEST(StaticContactSetup, SymmetricContactsRunBothWays) {
  Model m = stacked();
  const StaticSolver symmetric(m);
  ASSERT_EQ(symmetric.contacts().size(), 2u);
  EXPECT_EQ(symmetric.contact_of(0), 0u);
  EXPECT_EQ(symmetric.contact_of(1), 0u);
  m.contacts[0].one_way = true;
  const StaticSolver one_way(m);
  EXPECT_EQ(one_way.contacts().size(), 1u);
}

TEST(StaticContactSetup, ExplicitOnlyFeaturesAreErrorsAtTheirCard) {
  // `change` alters the contact and may say where the input gave the setting (Sources).
  const auto expect_error = [](const std::function<void(ContactSpec&, Sources&)>& change,
                               const std::string& message) {
    Model m = stacked();
    change(m.contacts[0], m.sources);
    try {
      const StaticSolver s(m);
      ADD_FAILURE() << "expected an error containing '" << message << "'";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
      EXPECT_EQ(e.where().file, "t.k") << e.what();
    }
  };
  expect_error([](ContactSpec& c, Sources&) { c.begin_time = 0.5; }, "activation window");
  expect_error([](ContactSpec& c, Sources&) { c.stick_stress = 10.0; },
               "sticking up to a failure stress");
  expect_error(
      [](ContactSpec& c, Sources& s) {
        c.friction_filter.kind = FrictionFilter::Kind::Simple;
        s.set(SourceEntity::Contact, c.id, "friction_filter", {"t.k", 9, "", ""});
      },
      "friction filtering is not supported in static steps");
  expect_error(
      [](ContactSpec& c, Sources& s) {
        c.sense = ContactSense::Bilateral;
        s.set(SourceEntity::Contact, c.id, "sense", {"t.k", 11, "", ""});
      },
      "contact sense");
  expect_error([](ContactSpec& c, Sources&) { c.surface1 = c.surface2; }, "self contact");
  expect_error(
      [](ContactSpec& c, Sources&) {
        ContactSpec::FrictionPair& pair = c.friction_pairs.emplace_back();
        pair.law = ContactSpec::FrictionLaw::Coulomb;
        pair.mu_static = pair.mu_dynamic = 0.2;
        pair.filter.kind = FrictionFilter::Kind::Simple;
        pair.where = {"t.k", 12, "", "law"};
      },
      "friction filtering is not supported in static steps");  // a pair's filter, as a contact's
}

// Small sliding (OptiStruct TRACK = SMALL) pairs points once; the explicit solver searches every
// cycle, so it refuses the option rather than ignore it.
TEST(StaticContactSetup, SmallSlidingIsAStaticOption) {
  Model m = stacked();
  m.static_steps.clear();
  m.time.end_time = 1e-3;
  m.contacts[0].penalty = 1e3;
  m.contacts[0].small_sliding = true;
  try {
    const Simulation s(m);
    ADD_FAILURE() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("small sliding"), std::string::npos) << e.what();
  }
  m.static_steps.push_back(StaticStep{});
  EXPECT_NO_THROW(StaticSolver s(m));
}

}  // namespace
}  // namespace abut
