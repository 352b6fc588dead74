// Decks that used to run to a silent wrong result or fail without a location (issue 13): each is
// now an InputError at the file and line that causes it.
#include <gmock/gmock.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

#include "abut/solver/simulation.hpp"
#include "../../src/io/memory_budget.hpp"
#include "test_deck_helpers.hpp"

namespace abut {
namespace {

using testing::error_of;
using ::testing::HasSubstr;
using testing::kBoxModel;
using testing::read;

// One hex whose top face (nodes 5-8) lies below its bottom face: inside out. Line 13 is the
// *ELEMENT_SOLID row.
std::string inverted_hex(const char* material) {
  return std::string(
             "*TIME\n1\n*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n3, 1, 1, 0\n4, 0, 1, 0\n"
             "5, 0, 0, -1\n6, 1, 0, -1\n7, 1, 1, -1\n8, 0, 1, -1\n*ELEMENT_SOLID\n"
             "12, 1, 1, 2, 3, 4, 5, 6, 7, 8\n") +
         material + "*PART\n1, 1\n";
}

InputError simulation_error(const std::string& text) {
  try {
    const Model m = testing::model_of(text);
    const Simulation sim(m);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "expected an InputError for:\n" << text;
  return InputError("no error");
}

TEST(DeckReliability, InvertedHexOfARigidPartIsLocated) {
  const InputError e = error_of(inverted_hex("*MAT_RIGID\n1, 7800\n"));
  EXPECT_EQ(e.where().file, "t.k");
  EXPECT_EQ(e.where().line, 13u);
  EXPECT_EQ(e.where().keyword, "*ELEMENT_SOLID");
  EXPECT_THAT(e.message(), HasSubstr("element 12 (nodes 1, 2, 3, 4, 5, 6, 7, 8)"));
  EXPECT_THAT(e.message(), HasSubstr("inverted"));
  EXPECT_THAT(e.message(), HasSubstr("n1-n4"));
}

TEST(DeckReliability, InvertedHexOfADeformablePartNamesTheUsersIds) {
  const InputError e = error_of(inverted_hex("*MAT_ELASTIC\n1, 7800, 2e11, 0.3\n"));
  EXPECT_EQ(e.where().line, 13u);
  EXPECT_THAT(e.message(), HasSubstr("element 12 (nodes 1, 2, 3, 4, 5, 6, 7, 8)"));
  EXPECT_THAT(e.message(), ::testing::Not(HasSubstr("index")));
}

TEST(DeckReliability, FlatHexIsLocated) {
  // Nodes 5-8 on top of 1-4: no volume.
  const std::string deck =
      "*TIME\n1\n*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n3, 1, 1, 0\n4, 0, 1, 0\n"
      "5, 0, 0, 0\n6, 1, 0, 0\n7, 1, 1, 0\n8, 0, 1, 0\n*ELEMENT_SOLID\n"
      "3, 1, 1, 2, 3, 4, 5, 6, 7, 8\n*MAT_RIGID\n1, 7800\n*PART\n1, 1\n";
  const InputError e = error_of(deck);
  EXPECT_EQ(e.where().line, 13u);
  EXPECT_THAT(e.message(), HasSubstr("element 3"));
  EXPECT_THAT(e.message(), HasSubstr("degenerate"));
}

TEST(DeckReliability, DensityThatOverflowsTheMassIsLocatedAtThePart) {
  std::string deck(kBoxModel);
  deck.replace(deck.find("7800.0"), 6, "1e308");
  const InputError e = simulation_error(deck);
  EXPECT_EQ(e.where().line, 12u);  // the *PART row
  EXPECT_THAT(e.message(), HasSubstr("part 1"));
  EXPECT_THAT(e.message(), HasSubstr("density 1e+308 of material 1 at t.k:9"));
}

// A Young's modulus whose wave speed overflows (issue 28): no finite element step, so the run
// would take one step of dt_max and end "completed" with infinities.
TEST(DeckReliability, ModulusWhoseWaveSpeedOverflowsIsLocatedAtThePart) {
  std::string deck(kBoxModel);
  deck.replace(deck.find("210.0e9"), 7, "1.5e308");
  const InputError e = simulation_error(deck);
  EXPECT_EQ(e.where().line, 12u);  // the *PART row
  EXPECT_THAT(e.message(), HasSubstr("part 1 has no finite element stable time step"));
  EXPECT_THAT(e.message(), HasSubstr("material 1 at t.k:9"));
}

TEST(DeckReliability, RigidPartWithAnOverflowingMassIsLocated) {
  std::string deck(kBoxModel);
  const std::string elastic = "*MAT_ELASTIC\n1, 7800.0, 210.0e9, 0.3";
  deck.replace(deck.find(elastic), elastic.size(), "*MAT_RIGID\n1, 1e308");
  const InputError e = simulation_error(deck);
  EXPECT_EQ(e.where().line, 12u);
  EXPECT_THAT(e.message(), HasSubstr("rigid mass"));
}

// A rigid block of negligible density pressed on by contact: its contact spring has no mass,
// so the step is 0 and the run would end at once.
TEST(DeckReliability, ZeroInitialStepIsAnInputErrorNamingTheContact) {
  const std::string deck = R"(*UNIT_SYSTEM
SI
*TIME
1.0e-3
*COMPONENT_BOX
1, 1, 2, 2, 1
0.0, 0.0, 0.0, 2.0, 2.0, 1.0
*COMPONENT_BOX
2, 2, 1, 1, 1
0.0, 0.0, 1.0, 1.0, 1.0, 2.0
*MAT_ELASTIC
1, 7800.0, 210.0e9, 0.3
*MAT_RIGID
2, 1e-320
*PART
1, 1
2, 2
*CONTACT
3
P, 1, P, 2
)";
  const InputError e = simulation_error(deck);
  EXPECT_THAT(e.what(), HasSubstr("t.k:"));
  EXPECT_THAT(e.message(), HasSubstr("initial stable time step"));
}

TEST(DeckReliability, NonFiniteInitialVelocityFromAFunctionIsLocated) {
  for (const char* expression : {"acos(2)", "1/0"}) {
    const std::string deck = std::string(kBoxModel) + "*FUNCTION\n4\n" + expression +
                             "\n*INITIAL_VELOCITY\nP, 1, 0, fcn(4), 0\n";
    const InputError e = error_of(deck);
    EXPECT_EQ(e.where().line, 17u) << expression;
    EXPECT_EQ(e.where().keyword, "*INITIAL_VELOCITY");
    EXPECT_EQ(e.where().field, "v_y0");
    EXPECT_THAT(e.message(), HasSubstr("function 4 gives an initial velocity of "));
  }
}

TEST(DeckReliability, AbsurdInitialVelocityIsLocated) {
  // Finite, but the first strain rates overflow (found by deck_fuzz).
  const InputError e = error_of(std::string(kBoxModel) + "*INITIAL_VELOCITY\nP, 1, 0, 0, 1e308\n");
  EXPECT_EQ(e.where().line, 14u);
  EXPECT_EQ(e.where().field, "v_z0");
  EXPECT_THAT(e.message(), HasSubstr("the value gives an initial velocity of 1e+308"));
}

TEST(DeckReliability, IncludeIdOffsetThatOverflowsIsLocated) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "abut_test_include_offset";
  std::filesystem::create_directories(dir);
  {
    std::ofstream part(dir / "part.k");
    part << "*NODE\n1, 0, 0, 0\n";
  }
  {
    std::ofstream main(dir / "main.k");
    main << "*TIME\n1\n*INCLUDE\npart.k\n1, 1, 1, 9223372036854775807\n";
  }
  try {
    read_deck((dir / "main.k").string());
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, (dir / "part.k").string());
    EXPECT_EQ(e.where().line, 2u);
    EXPECT_EQ(e.where().field, "nid");
    EXPECT_THAT(e.message(), HasSubstr("exceeds the largest id"));
  }
  {
    // Nested includes add their offsets: the sum overflows at the inner *INCLUDE.
    std::ofstream middle(dir / "middle.k");
    middle << "*INCLUDE\npart.k\n1, 1, 1, 9223372036854775000\n";
    std::ofstream main(dir / "main.k");
    main << "*TIME\n1\n*INCLUDE\nmiddle.k\n1, 1, 1, 1000\n";
  }
  try {
    read_deck((dir / "main.k").string());
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, (dir / "middle.k").string());
    EXPECT_EQ(e.where().line, 3u);
    EXPECT_EQ(e.where().field, "nid_offset");
  }
  {
    // A *FUNCTION's fcn(id) is shifted too: past 2^63-1 it is an error at the expression.
    std::ofstream part(dir / "part.k");
    part << "*FUNCTION\n1\nfcn(9223372036854775800) + 1\n";
    std::ofstream main(dir / "main.k");
    main << "*TIME\n1\n*INCLUDE\npart.k\n1, 1, 1, 0, 0, 0, 0, 1000\n";
  }
  try {
    read_deck((dir / "main.k").string());
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, (dir / "part.k").string());
    EXPECT_EQ(e.where().line, 3u);
    EXPECT_EQ(e.where().field, "expression");
    EXPECT_THAT(e.message(), HasSubstr("exceeds the largest id"));
  }
  std::filesystem::remove_all(dir);
}

TEST(DeckReliability, ByteOrderMarkAndOldLineEndsAreAccepted) {
  std::string crlf, cr;
  for (const char c : std::string(kBoxModel)) {
    crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    cr += c == '\n' ? '\r' : c;
  }
  for (const std::string& text : {"\xEF\xBB\xBF" + std::string(kBoxModel), crlf, cr}) {
    const Model m = read(text).model;
    EXPECT_EQ(m.mesh.hex_count(), 4u);
  }
  // Lines are counted the same way with every line end: the error is on line 13.
  for (const std::string ending : {"\r\n", "\r"}) {
    std::string deck;
    for (const char c : std::string(kBoxModel) + "*COMPONENT_BXO\n")
      deck += c == '\n' ? ending : std::string(1, c);
    const InputError e = error_of("\xEF\xBB\xBF" + deck);
    EXPECT_EQ(e.where().line, 13u);
    EXPECT_EQ(e.message(), "unknown keyword *COMPONENT_BXO; did you mean *COMPONENT_BOX?");
  }
}

TEST(DeckReliability, OverlongLineIsRefusedWithoutEchoingIt) {
  const std::string line(100000, 'A');
  const InputError e = error_of("*TIME\n1\n*" + line + "\n");
  EXPECT_EQ(e.where().line, 3u);
  EXPECT_THAT(e.message(), HasSubstr("at most 65536 characters"));
  EXPECT_LT(std::string(e.what()).size(), 200u);
}

TEST(DeckReliability, LongUnknownKeywordIsQuickAndTruncated) {
  const std::string keyword = "*" + std::string(60000, 'B');
  const auto start = std::chrono::steady_clock::now();
  const InputError e = error_of("*TIME\n1\n" + keyword + "\n");
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 1.0);
  EXPECT_THAT(e.message(), HasSubstr("(60001 characters)"));
  EXPECT_LT(std::string(e.what()).size(), 200u);
  // A long field is echoed in part.
  const InputError f = error_of("*TIME\n" + std::string(5000, '7') + "x\n");
  EXPECT_LT(std::string(f.what()).size(), 300u);
}

TEST(DeckReliability, DeviceIsNotADeck) {
  try {
    read_deck("/dev/zero");
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_THAT(e.message(), HasSubstr("not a regular file"));
  }
}

TEST(DeckReliability, SlenderAndFarComponentsKeepTheirNodes) {
  // 10 000 km long, 1 cm square: the merge tolerance follows the 5 mm spacing, not the length.
  const Model bar = read(
      "*TIME\n1\n*COMPONENT_BOX\n1, 1, 10, 2, 2\n0, 0, 0, 1e7, 0.01, 0.01\n"
      "*MAT_ELASTIC\n1, 7800, 2e11, 0.3\n*PART\n1, 1\n")
                        .model;
  EXPECT_EQ(bar.mesh.nodes.size(), 99u);
  // A 1 cm sphere 100 km up has the nodes of the same sphere at the origin.
  const std::string sphere = "*TIME\n1\n*COMPONENT_SPHERE\n1, 1, 4\n0, 0, %z, 0.01\n"
                             "*MAT_ELASTIC\n1, 7800, 2e11, 0.3\n*PART\n1, 1\n";
  std::string near = sphere, far = sphere;
  near.replace(near.find("%z"), 2, "0");
  far.replace(far.find("%z"), 2, "1e5");
  EXPECT_EQ(read(far).model.mesh.nodes.size(), read(near).model.mesh.nodes.size());
}

TEST(DeckReliability, MeshTooLargeForTheMemoryIsRefusedBeforeAllocating) {
  const InputError e = error_of(
      "*TIME\n1\n*COMPONENT_SPHERE\n1, 1, 100000\n0, 0, 0, 0.01\n"
      "*MAT_ELASTIC\n1, 7800, 2e11, 0.3\n*PART\n1, 1\n");
  EXPECT_EQ(e.where().line, 3u);
  EXPECT_EQ(e.where().keyword, "*COMPONENT_SPHERE");
  EXPECT_THAT(e.message(), HasSubstr("elements"));
  EXPECT_THAT(e.message(), HasSubstr("GB of memory"));
  EXPECT_THAT(e.message(), HasSubstr("available"));
}

TEST(DeckReliability, MemoryBudgetComparesTheRunWithWhatIsAvailable) {
  const SourceLocation where{"t.k", 5, "*COMPONENT_BOX", ""};
  const MeshSize million{1e6, 1e6};
  EXPECT_NO_THROW(deck::require_memory(million, 1e12, where));
  EXPECT_NO_THROW(deck::require_memory(million, std::nullopt, where));  // unknown: no refusal
  try {
    deck::require_memory(million, 1e8, where);
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 5u);
    EXPECT_THAT(e.message(), HasSubstr("1000000 elements"));
    EXPECT_THAT(e.message(), HasSubstr("only 0.1 GB are available"));
  }
  EXPECT_TRUE(deck::available_memory().has_value());  // Linux: /proc/meminfo
  // A deck file is read whole: one larger than a third of the available memory is refused.
  EXPECT_NO_THROW(deck::require_readable("big.k", 1e9, 4e9));
  EXPECT_THROW(deck::require_readable("big.k", 2e9, 4e9), InputError);
}

TEST(DeckReliability, RefinementErrorsAreAtTheirLine) {
  // Two boxes joined by *MERGE_DUPLICATED_NODES; refining one alone leaves hanging nodes.
  const std::string joined =
      "*TIME\n1\n*COMPONENT_BOX\n1, 1, 1, 1, 1\n0, 0, 0, 1, 1, 1\n"
      "*COMPONENT_BOX\n2, 2, 1, 1, 1\n0, 0, 1, 1, 1, 2\n*MAT_ELASTIC\n1, 7800, 2e11, 0.3\n"
      "*PART\n1, 1\n2, 1\n*MERGE_DUPLICATED_NODES\nP, 2, P, 1\n";
  const InputError e = error_of(joined + "*CHANGE_P-ORDER\nP, 2, 1\nP, 1, 2\n");
  EXPECT_EQ(e.where().line, 18u);
  EXPECT_EQ(e.where().keyword, "*CHANGE_P-ORDER");
  EXPECT_THAT(e.message(), HasSubstr("parts 1 and 2 share nodes"));
  const InputError s = error_of(joined + "*SMOOTH_MESH\nP, 1, 45, 1\n");
  EXPECT_EQ(s.where().line, 17u);
  EXPECT_THAT(s.message(), HasSubstr("internal = 1"));
}

TEST(DeckReliability, RefinementOfSlenderAndFarMeshesKeepsItsNodes) {
  // Hexes of *ELEMENT_SOLID (no exact shape) split 2x2x2: the new nodes of neighbouring hexes are
  // shared, whatever the model's extent or position.
  const auto num = [](double v) {
    std::ostringstream text;
    text.precision(17);
    text << v;
    return text.str();
  };
  const auto refined_nodes = [&num](double x_end, double z0) {
    std::string deck = "*TIME\n1\n*NODE\n";
    int id = 1;
    for (int k = 0; k < 2; ++k)
      for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 3; ++i)
          deck += std::to_string(id++) + ", " + num(x_end * i / 2) + ", " + num(0.01 * j) + ", " +
                  num(z0 + 0.01 * k) + "\n";
    deck += "*ELEMENT_SOLID\n1, 1, 1, 2, 5, 4, 7, 8, 11, 10\n2, 1, 2, 3, 6, 5, 8, 9, 12, 11\n"
            "*MAT_ELASTIC\n1, 7800, 2e11, 0.3\n*PART\n1, 1\n*CHANGE_P-ORDER\nP, 1, 2\n";
    return read(deck).model.mesh.nodes.size();
  };
  const std::size_t reference = refined_nodes(0.02, 0.0);
  EXPECT_EQ(reference, 5u * 3u * 3u);
  EXPECT_EQ(refined_nodes(1e7, 0.0), reference);
  EXPECT_EQ(refined_nodes(0.02, 1e5), reference);
}

TEST(DeckReliability, MergeDefaultToleranceFollowsTheLocalSpacing) {
  // Two 10 000 km long, 1 cm square boxes side by side along their length (99 nodes each, 5 mm
  // apart across): the default tolerance of *MERGE_DUPLICATED_NODES follows the 5 mm spacing at
  // the nodes, so the 33 nodes of the common face merge and no other. It used to be 1e-6 of the
  // model's diagonal (10 m, more than the elements across): "would join two corners", at line 15.
  const std::string boxes =
      "*TIME\n1\n*COMPONENT_BOX\n1, 1, 10, 2, 2\n0, 0, 0, 1e7, 0.01, 0.01\n"
      "*COMPONENT_BOX\n2, 2, 10, 2, 2\n0, 0.01, 0, 1e7, 0.02, 0.01\n"
      "*MAT_ELASTIC\n1, 7800, 2e11, 0.3\n*PART\n1, 1\n2, 1\n*MERGE_DUPLICATED_NODES\n";
  const DeckResult r = read(boxes + "P, 2, P, 1\n");
  EXPECT_EQ(r.model.mesh.nodes.size(), 2u * 99u - 33u);
  EXPECT_THAT(r.notes, ::testing::Contains(HasSubstr("merged 33 nodes")));
  // An explicit tolerance is taken as given: within 1 cm, the nodes of box 2 one element (5 mm)
  // away from the common face would join the face nodes they share hexahedra with.
  const InputError e = error_of(boxes + "P, 2, P, 1, 0.01\n");
  EXPECT_EQ(e.where().line, 15u);
  EXPECT_THAT(e.message(), HasSubstr("would join two corners"));
}

// Sets an environment variable for the life of the object, then restores it.
class ScopedEnvironment {
 public:
  ScopedEnvironment(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    setenv(name, value, 1);
  }
  ~ScopedEnvironment() {
    if (old_) {
      setenv(name_.c_str(), old_->c_str(), 1);
    } else {
      unsetenv(name_.c_str());
    }
  }
  ScopedEnvironment(const ScopedEnvironment&) = delete;
  ScopedEnvironment& operator=(const ScopedEnvironment&) = delete;

 private:
  std::string name_;
  std::optional<std::string> old_;
};

TEST(DeckReliability, MemoryLimitOfTheEnvironmentCapsTheBudget) {
  const ScopedEnvironment limit("ABUT_MEMORY_MB", "100");
  ASSERT_TRUE(deck::available_memory().has_value());
  EXPECT_EQ(*deck::available_memory(), 100.0 * 1024 * 1024);
  {
    const ScopedEnvironment nonsense("ABUT_MEMORY_MB", "lots");  // ignored
    EXPECT_GT(*deck::available_memory(), 0.0);
  }
  // 64 000 hexes fit in 100 MB; 27 000 hexes refined to order 3 (729 000) do not: refused at the
  // *CHANGE_P-ORDER line before the refinement allocates (deck_fuzz / libFuzzer: -rss_limit_mb).
  const std::string box =
      "*TIME\n1\n*COMPONENT_BOX\n1, 1, %n, %n, %n\n0, 0, 0, 1, 1, 1\n"
      "*MAT_ELASTIC\n1, 7800, 2e11, 0.3\n*PART\n1, 1\n";
  const auto sized = [&](const char* n) {
    std::string deck = box;
    for (std::size_t at = deck.find("%n"); at != std::string::npos; at = deck.find("%n"))
      deck.replace(at, 2, n);
    return deck;
  };
  EXPECT_EQ(read(sized("40")).model.mesh.hex_count(), 64000u);
  const InputError e = error_of(sized("30") + "*CHANGE_P-ORDER\nP, 1, 3\n");
  EXPECT_EQ(e.where().line, 11u);
  EXPECT_EQ(e.where().keyword, "*CHANGE_P-ORDER");
  EXPECT_THAT(e.message(), HasSubstr("729000 elements"));
  EXPECT_THAT(e.message(), HasSubstr("available"));
}

// Issue 28: the contact points count against the memory too. A slab of 2 x 2000 x 1 hexahedra
// in S2S self contact makes 64 032 points (about 64 MB at kBytesPerPoint): within 100 MB it runs,
// within 20 MB it is refused at its *CONTACT line before the points are made. The mesh itself
// (4000 hexes, about 5 MB) fits both.
TEST(DeckReliability, ContactPointsBeyondTheMemoryAreRefusedAtTheContact) {
  const std::string slab =
      "*UNIT_SYSTEM\nSI\n*TIME\n1e-12\n*COMPONENT_BOX\n1, 1, 2, 2000, 1\n0, 0, 0, 1, 1, 1\n"
      "*MAT_ELASTIC\n1, 7800, 2e11, 0.3\n*PART\n1, 1\n*CONTACT\n\"self\"\n1\nALL, , ALL\n";
  {
    const ScopedEnvironment roomy("ABUT_MEMORY_MB", "100");
    const Model m = testing::model_of(slab);
    const Simulation sim(m);
    EXPECT_GT(sim.contact_reports().at(0).points, 60000u);
  }
  const ScopedEnvironment tight("ABUT_MEMORY_MB", "20");
  const InputError e = simulation_error(slab);
  EXPECT_EQ(e.where().keyword, "*CONTACT");
  EXPECT_EQ(e.where().line, 14u);
  EXPECT_THAT(e.message(), HasSubstr("contact points"));
  EXPECT_THAT(e.message(), HasSubstr("available"));
}

TEST(DeckReliability, InpWithoutElementsIsAnErrorAtItsLastCard) {
  // deck_libfuzzer_inp_reader: a step without a mesh was "the input has no *ELEMENT" with no line.
  try {
    read_inp_string_with_notes(
        "*BOUNDARY\n1, ENCASTRE\n2, XSYMM\n3, YASYMM\n*STEP\n*STATIC\n*END STEP\n", "t.inp");
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, "t.inp");
    EXPECT_EQ(e.where().line, 7u);  // *END STEP, the last card
    EXPECT_THAT(e.message(), HasSubstr("the input has no *ELEMENT"));
  }
}

}  // namespace
}  // namespace abut
