// How a run owns its output directory and stops on request (output_directory.cpp, run.cpp,
// run_static.cpp): a locked directory refuses a second run, a previous run's files are removed
// and a user's are kept, and a stopped run still leaves a final state, a valid series and a
// summary.json saying "interrupted".
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "abut/core/error.hpp"
#include "abut/io/deck.hpp"
#include "abut/io/output_directory.hpp"
#include "abut/io/run.hpp"
#include "test_files.hpp"

namespace abut {
namespace {

namespace fs = std::filesystem;
using testing::file_text;
using testing::fresh_dir;
using testing::write_text;

// A free steel cube of 2 x 2 x 2 elements moving at 1 m/s; its end time takes ~10^5 cycles.
const char* const kCube = R"(*UNIT_SYSTEM
SI
*TIME
0.1
*COMPONENT_BOX
1, 1, 2, 2, 2
0.0, 0.0, 0.0, 0.01, 0.01, 0.01
*MAT_ELASTIC
1, 7800.0, 210.0e9, 0.3
*PART
"cube"
1, 1
*INITIAL_VELOCITY
P, 1, 1.0, 0.0, 0.0
*END
)";

std::size_t count_of(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(OutputDirectory, ASecondClaimNamesTheRunThatHoldsIt) {
  const fs::path dir = fresh_dir("abut_test_lock");
  {
    const OutputDirectory first(dir);
    EXPECT_TRUE(fs::exists(dir / ".abut.lock"));
    try {
      const OutputDirectory second(dir);
      FAIL() << "a second run claimed a locked directory";
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("is in use by another run (pid " + std::to_string(getpid()) + ")"),
                std::string::npos)
          << message;
    }
  }
  EXPECT_FALSE(fs::exists(dir / ".abut.lock"));  // released with its owner
  EXPECT_NO_THROW(OutputDirectory{dir});
  fs::remove_all(dir);
}

TEST(OutputDirectory, RemovesAPreviousRunsFilesAndKeepsTheUsers) {
  const fs::path dir = fresh_dir("abut_test_clean");
  for (const char* name : {"results.pvd", "summary.json", "results.dat", "energy.csv", "parts.csv",
                           "contact.csv", "increments.csv", "states/state_0000.vtu",
                           "states/state_0099.vtu", "notes.txt", "mine.csv", "states/mine.vtu"})
    write_text(dir / name, "old\n");
  { const OutputDirectory output(dir); }
  for (const char* name :
       {"results.pvd", "summary.json", "results.dat", "energy.csv", "parts.csv", "contact.csv",
        "increments.csv", "states/state_0000.vtu", "states/state_0099.vtu"})
    EXPECT_FALSE(fs::exists(dir / name)) << name;
  for (const char* name : {"notes.txt", "mine.csv", "states/mine.vtu"})
    EXPECT_TRUE(fs::exists(dir / name)) << name;
  fs::remove_all(dir);
}

TEST(OutputDirectory, AFileInTheWaySuggestsAnotherDirectory) {
  const fs::path dir = fresh_dir("abut_test_file_in_the_way");
  write_text(dir, "not a directory\n");
  try {
    const OutputDirectory output(dir / "out");
    FAIL() << "an output directory under a file";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("-o DIR"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

TEST(RunControl, ARerunLeavesOnlyItsOwnStates) {
  const Model model = read_deck_string(kCube, "cube.k");
  const fs::path dir = fresh_dir("abut_test_rerun");
  write_text(dir / "states/state_0500.vtu", "stale\n");
  write_text(dir / "contact.csv", "stale\n");
  std::ostringstream log;
  RunOptions options{dir, 1, false};
  options.stop_requested = [calls = 0]() mutable { return ++calls > 200; };
  run_simulation(model, options, log);
  EXPECT_FALSE(fs::exists(dir / "states/state_0500.vtu"));
  EXPECT_FALSE(fs::exists(dir / "contact.csv"));  // the cube has no contact
  const std::string pvd = file_text(dir / "results.pvd");
  std::size_t files = 0;
  for (const fs::directory_entry& e : fs::directory_iterator(dir / "states")) {
    ++files;
    EXPECT_NE(pvd.find("states/" + e.path().filename().string()), std::string::npos);
  }
  EXPECT_EQ(files, count_of(pvd, "<DataSet"));
  fs::remove_all(dir);
}

TEST(RunControl, AnExplicitRunStopsAtTheEndOfACycle) {
  const Model model = read_deck_string(kCube, "cube.k");
  const fs::path dir = fresh_dir("abut_test_stop_explicit");
  std::ostringstream log;
  RunOptions options{dir, 1, false};
  options.stop_requested = [calls = 0]() mutable { return ++calls > 100; };
  const RunReport report = run_simulation(model, options, log);
  EXPECT_TRUE(report.interrupted);
  EXPECT_TRUE(report.stable);
  EXPECT_EQ(report.cycles, 100);
  EXPECT_LT(report.end_time, model.time.end_time);
  const std::string summary = file_text(dir / "summary.json");
  EXPECT_NE(summary.find("\"status\": \"interrupted\""), std::string::npos) << summary;
  // The initial state and the final one, at the time it stopped.
  const std::string pvd = file_text(dir / "results.pvd");
  EXPECT_EQ(count_of(pvd, "<DataSet"), 2u) << pvd;
  EXPECT_TRUE(fs::exists(dir / "states/state_0001.vtu"));
  EXPECT_NE(log.str().find("INTERRUPTED after 100 cycles"), std::string::npos) << log.str();
  EXPECT_FALSE(fs::exists(dir / ".abut.lock"));
  fs::remove_all(dir);
}

TEST(RunControl, AStaticRunStopsAtTheEndOfAnIncrement) {
  const fs::path deck = fs::path(ABUT_SOURCE_DIR) / "examples/static_block_press.k";
  const Model model = read_deck(deck.string());
  ASSERT_FALSE(model.static_steps.empty());
  const fs::path dir = fresh_dir("abut_test_stop_static");
  std::ostringstream log;
  RunOptions options{dir, 1, false};
  options.stop_requested = [] { return true; };
  const RunReport report = run_simulation(model, options, log);
  EXPECT_TRUE(report.interrupted);
  EXPECT_EQ(report.cycles, 1);  // one increment
  const std::string summary = file_text(dir / "summary.json");
  EXPECT_NE(summary.find("\"status\": \"interrupted\""), std::string::npos) << summary;
  EXPECT_EQ(count_of(file_text(dir / "results.pvd"), "<DataSet"), 2u);  // t = 0 and the increment
  fs::remove_all(dir);
}

}  // namespace
}  // namespace abut
