// Conformance: CalculiX's own example decks (Debian package calculix-ccx-test, listed in
// deps/debian-packages.txt) read into the model with the counts read off each deck. The .gz
// decks are decompressed into a temporary directory at test time.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "abut/io/deck.hpp"

namespace abut {
namespace {

namespace fs = std::filesystem;

const fs::path kExamples = "/usr/share/doc/calculix-ccx-test/examples/test";

// The deck as a plain file: the installed .inp, or the .inp.gz decompressed into a directory of
// the test's own (removed with this object), so that tests running side by side do not share
// files. An empty path (and a test failure) when the package is missing.
class Deck {
 public:
  explicit Deck(const std::string& name) {
    if (!fs::is_directory(kExamples)) {
      ADD_FAILURE() << kExamples
                    << " is missing: install the Debian package calculix-ccx-test (it is in "
                       "deps/debian-packages.txt), whose example decks these tests read";
      return;
    }
    const fs::path plain = kExamples / (name + ".inp");
    if (fs::exists(plain)) {
      path_ = plain;
      return;
    }
    const fs::path gz = kExamples / (name + ".inp.gz");
    if (!fs::exists(gz)) {
      ADD_FAILURE() << "neither " << plain << " nor " << gz << " exists";
      return;
    }
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string unique = std::string(test->test_suite_name()) + "_" + test->name();
    for (char& c : unique)
      if (c == '/') c = '_';
    dir_ = fs::temp_directory_path() / ("abut_inp_" + unique);
    fs::create_directories(dir_);
    const fs::path out = dir_ / (name + ".inp");
    const std::string command = "gzip -dc '" + gz.string() + "' > '" + out.string() + "'";
    if (std::system(command.c_str()) != 0) {
      ADD_FAILURE() << "could not decompress " << gz << " with: " << command;
      return;
    }
    path_ = out;
  }
  ~Deck() {
    std::error_code ec;
    if (!dir_.empty()) fs::remove_all(dir_, ec);
  }
  Deck(const Deck&) = delete;
  Deck& operator=(const Deck&) = delete;
  const fs::path& path() const { return path_; }
  bool empty() const { return path_.empty(); }
  std::string string() const { return path_.string(); }

 private:
  fs::path path_, dir_;
};

struct Expected {
  const char* name;
  std::size_t nodes, hexes, steps, contacts, face_sets, equations;
  std::size_t first_slave_faces;  // faces of the slave surface of contact 1 (0: node surface)
  Discretisation discretisation;
};

void PrintTo(const Expected& e, std::ostream* os) { *os << e.name; }

class Conformance : public ::testing::TestWithParam<Expected> {};

TEST_P(Conformance, ReadsWithTheDeckCounts) {
  const Expected& e = GetParam();
  const Deck path(e.name);
  if (path.empty()) return;
  const Model m = read_inp_with_notes(path.string()).model;
  EXPECT_EQ(m.mesh.nodes.size(), e.nodes);
  EXPECT_EQ(m.mesh.hex_count(), e.hexes);
  EXPECT_EQ(m.static_steps.size(), e.steps);
  ASSERT_EQ(m.contacts.size(), e.contacts);
  EXPECT_EQ(m.face_sets.size(), e.face_sets);
  EXPECT_EQ(m.equations.size(), e.equations);
  const ContactSpec& c = m.contacts.front();
  EXPECT_EQ(c.discretisation, e.discretisation);
  EXPECT_EQ(c.surface2.type, EntityType::FaceSet);
  if (e.first_slave_faces == 0) {
    EXPECT_EQ(c.surface1.type, EntityType::NodeSet);
  } else {
    ASSERT_EQ(c.surface1.type, EntityType::FaceSet);
    EXPECT_EQ(m.face_set(c.surface1).faces.size(), e.first_slave_faces);
  }
  EXPECT_EQ(m.vx0.size(), m.mesh.nodes.size());
  double total = 0.0;
  for (const StaticStep& s : m.static_steps) total += s.period;
  EXPECT_DOUBLE_EQ(m.time.end_time, total);
}

INSTANTIATE_TEST_SUITE_P(
    CalculixExamples, Conformance,
    ::testing::Values(
        Expected{"contactenergy", 16, 2, 1, 1, 2, 0, 1, Discretisation::SurfaceToSurface},
        Expected{"friction2", 16, 2, 4, 1, 2, 0, 1, Discretisation::NodeToSurface},
        Expected{"fricloop", 16, 2, 4, 1, 2, 6, 1, Discretisation::SurfaceToSurface},
        Expected{"changefric", 16, 2, 5, 1, 2, 0, 1, Discretisation::SurfaceToSurface},
        Expected{"contact3", 16, 2, 1, 1, 1, 6, 0, Discretisation::NodeToSurface},
        Expected{"contact6", 16, 2, 1, 1, 1, 6, 0, Discretisation::NodeToSurface},
        Expected{"contact1", 16, 2, 1, 1, 1, 6, 0, Discretisation::NodeToSurface},
        Expected{"cubespring", 128, 54, 1, 1, 2, 0, 9, Discretisation::NodeToSurface},
        Expected{"friction1", 250, 128, 1, 1, 2, 0, 16, Discretisation::NodeToSurface},
        Expected{"hueeber1", 17524, 8500, 1, 1, 2, 0, 60, Discretisation::SurfaceToSurface},
        Expected{"hueeber3", 17524, 8500, 1, 1, 2, 0, 60, Discretisation::SurfaceToSurface}),
    [](const ::testing::TestParamInfo<Expected>& p) { return std::string(p.param.name); });

TEST(Conformance, ContactEnergyInDetail) {
  const Deck path("contactenergy");
  if (path.empty()) return;
  const Model m = read_inp_with_notes(path.string()).model;
  const StaticStep& s = m.static_steps.at(0);
  // Nfix (4 nodes) in x, y, z and Nfixxy (4 nodes) in x, y; 4 forces of -1 in z.
  EXPECT_EQ(s.displacements.size(), 4u * 3u + 4u * 2u);
  ASSERT_EQ(s.forces.size(), 4u);
  for (const StepForce& f : s.forces) {
    EXPECT_EQ(f.dof, 2);
    EXPECT_EQ(f.value, -1.0);
  }
  EXPECT_FALSE(s.nonlinear_geometry);
  const ContactSpec& c = m.contacts.at(0);
  EXPECT_EQ(c.title, "Sslav/Smast");
  EXPECT_EQ(c.penalty, 1e7);
  EXPECT_EQ(c.friction_law, ContactSpec::FrictionLaw::None);
  // Smast = element 1, S5: nodes 3, 7, 8, 4 of the element (CalculiX face 5: 3-7-8-4).
  const FaceSet& master = m.face_set(c.surface2);
  ASSERT_EQ(master.faces.size(), 1u);
  EXPECT_EQ(master.faces[0].face, 4);
  ASSERT_EQ(s.prints.size(), 3u);  // U,RF of Nall; ELSE of Eall with totals; CELS with totals
  EXPECT_EQ(s.prints[0].members.size(), 16u);
  EXPECT_TRUE(s.prints[1].totals);
  EXPECT_EQ(s.prints[2].kind, PrintRequest::Kind::Contact);
  EXPECT_TRUE(s.prints[2].members.empty());
}

TEST(Conformance, Friction2ChangesFrictionAndReleasesBoundaries) {
  const Deck path("friction2");
  if (path.empty()) return;
  const DeckResult result = read_inp_with_notes(path.string());
  const Model& m = result.model;
  ASSERT_EQ(m.static_steps.size(), 4u);
  // Step 1: Nbigcube (8 nodes) x 3 plus Ndisp (4 nodes) x 2; steps 2-4 (OP=NEW): Nbigcube x 3
  // plus Nslav (4 nodes) in y.
  EXPECT_EQ(m.static_steps[0].displacements.size(), 8u * 3u + 4u * 2u);
  EXPECT_EQ(m.static_steps[1].displacements.size(), 8u * 3u + 4u);
  EXPECT_TRUE(m.static_steps[3].nonlinear_geometry);  // NLGEOM of step 1 stays on
  ASSERT_EQ(m.static_steps[3].contact_changes.size(), 1u);
  EXPECT_EQ(m.static_steps[3].contact_changes[0].friction, 0.1);
  EXPECT_EQ(m.static_steps[3].contact_changes[0].stick_slope, 80.0);
  // The *DLOAD with amplitude A1 (1 at step times 0 and 1) carries over at its final value.
  ASSERT_EQ(m.static_steps[1].pressures.size(), 1u);
  EXPECT_FALSE(m.static_steps[1].pressures[0].amplitude.curve.valid());
  EXPECT_EQ(m.static_steps[1].pressures[0].value, 100.0);
  const ContactSpec& c = m.contacts.at(0);
  EXPECT_EQ(c.friction_law, ContactSpec::FrictionLaw::Coulomb);
  EXPECT_EQ(c.mu_static, 0.2);
  EXPECT_EQ(c.tangential_penalty, 80.0);
  bool frequency_note = false;
  for (const std::string& n : result.notes)
    frequency_note = frequency_note || n.find("friction2.inp:36") != std::string::npos;
  EXPECT_TRUE(frequency_note) << "the note on FREQUENCY of *NSET names its line";
}

TEST(Conformance, HueeberReadsQuicklyWithItsLoads) {
  const Deck path("hueeber1");
  if (path.empty()) return;
  const auto start = std::chrono::steady_clock::now();
  const Model m = read_inp_with_notes(path.string()).model;
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("hueeber1.inp (71054 lines): read in %.3f s\n", seconds);
  const StaticStep& s = m.static_steps.at(0);
  EXPECT_EQ(s.displacements.size(), 18052u);  // distinct (node, dof) of its 18316 lines
  EXPECT_EQ(s.forces.size(), 488u);           // 244 nodes of Ncopy1_l*/r* in x and y
  EXPECT_EQ(m.parts.size(), 2u);              // Ecopy1 and Ecopy2
  EXPECT_EQ(m.contacts.at(0).penalty, 1e15);
  // The pair reads "Smast,Sslav": the surface named Smast (60 faces) is the slave.
  EXPECT_EQ(m.contacts.at(0).title, "Smast/Sslav");
  EXPECT_EQ(m.face_set(m.contacts.at(0).surface2).faces.size(), 70u);
  EXPECT_LT(seconds, 10.0);
}

// changesurfbeh.inp: a TIED pair (penalty 1e9, *FRICTION 1e-4, 1e3) becomes a LINEAR one of slope
// 1e9 in the second step, read at line 69-71.
TEST(Conformance, ChangeSurfaceBehaviorReadsAsAContactChangeOfTheSecondStep) {
  const Deck path("changesurfbeh");
  if (path.empty()) return;
  const Model m = read_inp_with_notes(path.string()).model;
  ASSERT_EQ(m.static_steps.size(), 2u);
  EXPECT_TRUE(m.static_steps[0].contact_changes.empty());
  const auto& changes = m.static_steps[1].contact_changes;
  ASSERT_EQ(changes.size(), 1u);
  ASSERT_TRUE(changes[0].overclosure.has_value());
  ASSERT_TRUE(changes[0].overclosure->slope.has_value());
  EXPECT_EQ(*changes[0].overclosure->slope, 1e9);
  EXPECT_EQ(changes[0].friction, 1e-4);
  EXPECT_EQ(changes[0].stick_slope, 1e3);
}

}  // namespace
}  // namespace abut
