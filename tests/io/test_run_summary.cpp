// The contacts of summary.json and of the log in the model's words (issue 33): the same text
// whatever the input language, from the contact library's description of its settings
// (contact/describe.hpp), never the deck's fields (pfac, Istf, Igap) or keywords (COULOMB, MEAN).
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "abut/io/deck.hpp"
#include "abut/io/run.hpp"
#include "test_files.hpp"

namespace abut {
namespace {

using testing::file_text;
using testing::fresh_dir;

// A block resting on a plate, with a friction law, a stiffness rule and a gap rule of their own.
const char* const kDeck = R"(*UNIT_SYSTEM
SI
*TIME
1.0e-6
*COMPONENT_BOX
1, 1, 2, 2, 1
0.0, 0.0, 0.0, 0.02, 0.02, 0.01
*COMPONENT_BOX
2, 2, 1, 1, 1
0.005, 0.005, 0.01, 0.015, 0.015, 0.02
*MAT_ELASTIC
1, 7800.0, 210.0e9, 0.3
*PART
1, 1
2, 1
*CONTACT
1
P, 2, P, 1
*CONTACT_FRICTION
1, COULOMB, 0.3, 0.2
*CONTACT_STIFFNESS
1, MEAN, 2
*CONTACT_GAP
1, 3, 1, 0.25
*END
)";

TEST(RunSummary, ContactLawsInTheModelsWords) {
  const std::filesystem::path dir = fresh_dir("abut_test_run_summary");
  const Model model = read_deck_string(kDeck, "summary.k");
  std::ostringstream log;
  const RunReport report = run_simulation(model, RunOptions{dir, 1, false}, log);
  ASSERT_TRUE(report.stable) << report.message;
  const std::string summary = file_text(dir / "summary.json");
  for (const char* member :
       {R"("discretisation": "surface-to-surface (accuracy level 2), symmetric")",
        R"("normal_law": "linear penalty, positive side")",
        R"("tangential_law": "Coulomb, mu_static = 0.3, mu_dynamic = 0.2")",
        R"("stiffness_rule": "mean of both sides, scale = 2")",
        R"("gap_rule": "shell gaps x 1, at most 0.25 of the mesh size")",
        R"("erosion": "eroded facets removed, free nodes kept, faces that erosion exposes join")",
        R"("edge_contact": "none")"})
    EXPECT_NE(summary.find(member), std::string::npos) << member << "\n" << summary;
  for (const char* deck_word : {"COULOMB", "MEAN", "Istf", "Igap", "pfac"}) {
    EXPECT_EQ(summary.find(deck_word), std::string::npos) << deck_word;
    EXPECT_EQ(log.str().find(deck_word), std::string::npos) << deck_word << "\n" << log.str();
  }
  EXPECT_NE(log.str().find("(surface-to-surface (accuracy level 2), symmetric; linear penalty, "
                           "positive side; Coulomb, mu_static = 0.3, mu_dynamic = 0.2; mean of "
                           "both sides, scale = 2)"),
            std::string::npos)
      << log.str();
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace abut
