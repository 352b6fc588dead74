// Restart (issue 13; state_archive.hpp, simulation_restart.cpp, restart_file.hpp, run.cpp): a
// simulation that loads the state another saved at cycle k continues bitwise identically to the
// run that saved it, whatever the features (friction history, wear, plasticity and damage,
// erosion of contact facets, rigid bodies, shells, edge contact, heat through contact); and a run
// interrupted and restarted leaves the same output files as one that was not.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "abut/core/error.hpp"
#include "abut/core/state_archive.hpp"
#include "abut/io/deck.hpp"
#include "abut/io/run.hpp"
#include "abut/solver/simulation.hpp"
#include "test_files.hpp"

namespace abut {
namespace {

namespace fs = std::filesystem;
using testing::file_text;
using testing::fresh_dir;

// A metal block sliding with Coulomb friction and wear over an elastic plate, both free.
const char* const kFrictionSlide = R"(*UNIT_SYSTEM
SI
*TIME
1.0
*COMPONENT_BOX
1, 1, 4, 4, 1
0.0, 0.0, 0.0, 0.04, 0.04, 0.01
*COMPONENT_BOX
2, 2, 2, 2, 2
0.01, 0.01, 0.01, 0.03, 0.03, 0.03
*MAT_ELASTIC
1, 7800.0, 210.0e9, 0.3
*MAT_METAL
2, 2700.0, 70.0e9, 0.33
7
*FUNCTION
7
1.0e8 + 4.0e8*epsp
*PART
1, 1
2, 2
*INITIAL_VELOCITY
P, 2, 20.0, 5.0, -30.0
*CONTACT
3
P, 1, P, 2, 0.3
0, 0.1
8, 8
*FUNCTION
8
1.0e-12*pres*vtang
*END
)";

// A rigid block crushing a metal block that fails (Johnson-Cook damage) and erodes, its exposed
// faces joining the contact; node-to-surface with a Coulomb law of static and dynamic friction.
const char* const kErodingImpact = R"(*UNIT_SYSTEM
SI
*TIME
1.0
*COMPONENT_BOX
1, 1, 3, 3, 3
0.0, 0.0, 0.0, 0.03, 0.03, 0.03
*COMPONENT_BOX
2, 2, 2, 2, 1
0.005, 0.005, 0.03, 0.025, 0.025, 0.04
*MAT_JC
1, 7800.0, 210.0e9, 0.3, 4
3.0e8, 5.0e8, 0.5
*PROP_DAMAGE_JC
4, 0.02
*MAT_RIGID
2, 7800.0
*PART
1, 1
2, 2
*INITIAL_VELOCITY
P, 2, 0.0, 3.0, -150.0
*CONTACT
3
ALL, 0, ALL, 0
*CONTACT_DISCRETIZATION
3, N2S
*CONTACT_FRICTION
3, COULOMB, 0.4, 0.2
*END
)";

// Two crossing shell plates in self contact with edge-to-edge contact.
const char* const kShellEdges = R"(*UNIT_SYSTEM
SI
*TIME
1.0
*COMPONENT_SHELL_PLATE
1, 1, 4, 4
0.0, 0.0, 0.0, 0.04, 0.0, 0.0
0.0, 0.04, 0.0
*COMPONENT_SHELL_PLATE
2, 2, 4, 2
0.02, -0.01, 0.0015, 0.02, 0.05, 0.0015
0.02, -0.01, 0.02
*MAT_METAL
1, 7800.0, 210.0e9, 0.3
7
*FUNCTION
7
2.0e8 + 5.0e8*epsp
*PART
1, 1, , 0.001
2, 1, , 0.001
*INITIAL_VELOCITY
P, 2, 1.0, 0.0, -40.0
*CONTACT
3
ALL, 0, ALL, 0, 0.2
*CONTACT_EDGE
3, ALL
*END
)";

// A hot block sliding on a cold one: conductance through the contact and friction heat (a
// conductivity 10^6 times steel's, so that the heat takes a step every few cycles).
const char* const kThermalContact = R"(*UNIT_SYSTEM
SI, C
*TIME
1.0
*COMPONENT_BOX
1, 1, 3, 3, 1
0.0, 0.0, 0.0, 0.03, 0.03, 0.01
*COMPONENT_BOX
2, 2, 2, 2, 1
0.005, 0.005, 0.01, 0.025, 0.025, 0.02
*MAT_ELASTIC
1, 7800.0, 210.0e9, 0.3, 0, 1
*PROP_THERMAL
1, 460.0, 4.5e7
*PART
1, 1
2, 1
*INITIAL_TEMPERATURE
P, 1, 20.0
P, 2, 300.0
*INITIAL_VELOCITY
P, 2, 10.0, 0.0, -5.0
*CONTACT
3
P, 1, P, 2, 0.3
0, 0.1
0, 0, 9, , , , , 1
*FUNCTION
9
1.0e5 + 0.01*pres
*END
)";

// An elastic block held in z on a roller (*CONTACT_TOOL CYLINDER) that rises into it, translates
// and spins, with Coulomb friction: the tool's pose, work and the friction history of its nodes.
const char* const kRollerTool = R"(*UNIT_SYSTEM
SI
*TIME
1.0
*COMPONENT_BOX
1, 1, 2, 2, 1
-0.01, -0.01, 0.0, 0.01, 0.01, 0.005
*MAT_ELASTIC
1, 7800.0, 210.0e9, 0.3
*PART
1, 1
*BC_MOTION
P, 1, Z
*CURVE
1
0.0, 0.5
1.0, 0.5
*CONTACT_TOOL
7, CYLINDER
0, -1, -0.02, 0, 1, 0, 0.02
1, 1.0, , , 1, 0.1, 1, 40.0
*CONTACT
3
P, 1, TOOL, 7, 0.3
*END
)";

struct Case {
  const char* name;
  const char* deck;
  int before, after;  // cycles before the state is saved and after
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

// Every value a state file or history shows, and the nodal state, bit for bit.
void expect_identical(const Simulation& a, const Simulation& b) {
  const auto same = [](const std::vector<double>& u, const std::vector<double>& v) {
    // memcmp must not get the null data() of an empty vector, even for 0 bytes
    return u.size() == v.size() &&
           (u.empty() || std::memcmp(u.data(), v.data(), u.size() * sizeof(double)) == 0);
  };
  EXPECT_EQ(a.cycle(), b.cycle());
  EXPECT_EQ(a.time(), b.time());
  EXPECT_EQ(a.time_step(), b.time_step());
  for (const auto field : {&Simulation::x, &Simulation::y, &Simulation::z, &Simulation::vx,
                           &Simulation::vy, &Simulation::vz})
    EXPECT_TRUE(same((a.*field)(), (b.*field)()));
  std::vector<double> u, v;
  for (const auto field :
       {&Simulation::von_mises_stress, &Simulation::plastic_strain,
        &Simulation::shell_von_mises_stress, &Simulation::shell_plastic_strain}) {
    (a.*field)(u);
    (b.*field)(v);
    EXPECT_TRUE(same(u, v));
  }
  EXPECT_EQ(a.eroded_solids(), b.eroded_solids());
  const Energies ea = a.energies(), eb = b.energies();
  EXPECT_EQ(std::memcmp(&ea, &eb, sizeof ea), 0);
  std::vector<double> fa, pa, wa, fb, pb, wb;
  a.contact_fields(fa, pa, wa);
  b.contact_fields(fb, pb, wb);
  EXPECT_TRUE(same(fa, fb));
  EXPECT_TRUE(same(pa, pb));
  EXPECT_TRUE(same(wa, wb));
  const std::vector<double> ta(a.temperature().begin(), a.temperature().end());
  const std::vector<double> tb(b.temperature().begin(), b.temperature().end());
  EXPECT_TRUE(same(ta, tb));
}

class RestartOf : public ::testing::TestWithParam<Case> {};

TEST_P(RestartOf, ContinuesBitwiseIdentically) {
  const Case c = GetParam();
  const Model model = read_deck_string(c.deck, "t.k");
  Simulation first(model);
  for (int i = 0; i < c.before; ++i) first.advance();
  StateArchive saved = StateArchive::for_saving();
  first.archive(saved);
  for (int i = 0; i < c.after; ++i) first.advance();

  Simulation second(model);
  StateArchive loading = StateArchive::for_loading(saved.bytes());
  second.archive(loading);
  EXPECT_TRUE(loading.exhausted());
  EXPECT_EQ(second.cycle(), c.before);
  for (int i = 0; i < c.after; ++i) second.advance();
  expect_identical(first, second);
}

// What each case must exercise at the moment of the save, so that a change of the decks cannot
// quietly make the test pass without the history it is about.
TEST(Restart, TheCasesExerciseTheirFeatures) {
  {
    const Model model = read_deck_string(kRollerTool, "t.k");
    Simulation sim(model);
    for (int i = 0; i < 300; ++i) sim.advance();
    EXPECT_GT(sim.energies().friction, 0.0);
    EXPECT_GT(sim.contact_reports().at(0).stats.active_points, 0u);
    EXPECT_NE(sim.energies().external_work, 0.0);
  }
  {
    const Model model = read_deck_string(kFrictionSlide, "t.k");
    Simulation sim(model);
    for (int i = 0; i < 300; ++i) sim.advance();
    EXPECT_GT(sim.energies().friction, 0.0);
    std::vector<double> u;
    sim.plastic_strain(u);
    EXPECT_GT(*std::max_element(u.begin(), u.end()), 0.0);
    std::vector<double> f, p, w;
    sim.contact_fields(f, p, w);
    EXPECT_GT(*std::max_element(w.begin(), w.end()), 0.0);
  }
  {
    const Model model = read_deck_string(kErodingImpact, "t.k");
    Simulation sim(model);
    for (int i = 0; i < 400; ++i) sim.advance();
    const std::vector<std::uint8_t> eroded = sim.eroded_solids();
    EXPECT_GT(std::count(eroded.begin(), eroded.end(), std::uint8_t{1}), 0);
    EXPECT_GT(sim.energies().friction, 0.0);
  }
  {
    const Model model = read_deck_string(kShellEdges, "t.k");
    Simulation sim(model);
    for (int i = 0; i < 300; ++i) sim.advance();
    EXPECT_GT(sim.energies().contact, 0.0);
  }
  {
    const Model model = read_deck_string(kThermalContact, "t.k");
    Simulation sim(model);
    for (int i = 0; i < 300; ++i) sim.advance();
    EXPECT_GT(sim.energies().friction, 0.0);
    EXPECT_GT(sim.thermal_steps(), 0);
  }
}

INSTANTIATE_TEST_SUITE_P(Restart, RestartOf,
                         ::testing::Values(Case{"friction_slide", kFrictionSlide, 300, 300},
                                           Case{"eroding_impact", kErodingImpact, 400, 400},
                                           Case{"shell_edges", kShellEdges, 300, 300},
                                           Case{"thermal_contact", kThermalContact, 300, 300},
                                           Case{"roller_tool", kRollerTool, 300, 300}),
                         [](const auto& param_info) { return std::string(param_info.param.name); });

// ---------------------------------------------------------------------------------------------

// The run stops after `cycles` cycles (as at a SIGINT), writing restart.abr.
RunOptions stopping_after(const fs::path& dir, int cycles) {
  RunOptions options{dir, 1, false};
  auto count = std::make_shared<int>(0);
  options.stop_requested = [count, cycles] { return ++*count > cycles; };
  return options;
}

// The friction slide, shortened to about 700 cycles with 20 states, and `extra` keywords.
std::string short_slide(const std::string& extra = "") {
  std::string deck = kFrictionSlide;
  const std::string time = "*TIME\n1.0\n";
  deck.replace(deck.find(time), time.size(), "*TIME\n6.0e-4\n*OUTPUT\n3.0e-5, 4.0e-6\n");
  deck.insert(deck.find("*END"), extra);
  return deck;
}

TEST(Restart, AnInterruptedAndRestartedRunWritesTheSameFiles) {
  // The sliding block's nodes are followed in nodes.csv, which the restart must continue too.
  const Model model = read_deck_string(short_slide("*OUTPUT_NODE_HISTORY\nP, 2\n"), "t.k");
  std::ostringstream log;
  const fs::path whole = fresh_dir("abut_restart_whole");
  const RunReport reference = run_simulation(model, {whole, 1, false}, log);
  ASSERT_TRUE(reference.stable);

  const fs::path dir = fresh_dir("abut_restart_split");
  const RunReport stopped = run_simulation(model, stopping_after(dir, 300), log);
  ASSERT_TRUE(stopped.interrupted);
  ASSERT_TRUE(fs::exists(dir / "restart.abr"));
  RunOptions again{dir, 2, false};  // another thread count: still the same bits
  again.restart_from = dir / "restart.abr";
  const RunReport resumed = run_simulation(model, again, log);
  ASSERT_TRUE(resumed.stable);
  EXPECT_EQ(resumed.cycles, reference.cycles);

  for (const char* name : {"energy.csv", "parts.csv", "contact.csv", "nodes.csv", "results.pvd"})
    EXPECT_EQ(file_text(whole / name), file_text(dir / name)) << name;
  EXPECT_GT(file_text(whole / "nodes.csv").size(), 1000u);
  std::size_t states = 0;
  for (const auto& entry : fs::directory_iterator(whole / "states")) {
    ++states;
    EXPECT_EQ(file_text(entry.path()), file_text(dir / "states" / entry.path().filename()))
        << entry.path().filename();
  }
  EXPECT_GE(states, 20u);
  std::size_t resumed_states = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir / "states"))
    ++resumed_states;
  EXPECT_EQ(resumed_states, states);  // the interrupted run's extra final state is gone
  fs::remove_all(whole);
  fs::remove_all(dir);
}

// *CONTROL_BULK_VISCOSITY is not in the restart file: the restarted run takes it from its deck,
// so a run without bulk viscosity, interrupted and continued, is the run in one go, and that run
// differs from the default one (the keyword acts in both halves).
TEST(Restart, TheDecksBulkViscosityActsOnBothSidesOfARestart) {
  const Model model = read_deck_string(short_slide("*CONTROL_BULK_VISCOSITY\n0, 0\n"), "t.k");
  std::ostringstream log;
  const fs::path whole = fresh_dir("abut_restart_bulk_whole");
  ASSERT_TRUE(run_simulation(model, {whole, 1, false}, log).stable);
  const fs::path dir = fresh_dir("abut_restart_bulk_split");
  ASSERT_TRUE(run_simulation(model, stopping_after(dir, 300), log).interrupted);
  RunOptions again{dir, 1, false};
  again.restart_from = dir / "restart.abr";
  ASSERT_TRUE(run_simulation(model, again, log).stable);
  for (const char* name : {"energy.csv", "parts.csv", "contact.csv"})
    EXPECT_EQ(file_text(whole / name), file_text(dir / name)) << name;
  const fs::path standard = fresh_dir("abut_restart_bulk_default");
  ASSERT_TRUE(
      run_simulation(read_deck_string(short_slide(), "t.k"), {standard, 1, false}, log).stable);
  EXPECT_NE(file_text(whole / "energy.csv"), file_text(standard / "energy.csv"));
  for (const fs::path& d : {whole, dir, standard}) fs::remove_all(d);
}

TEST(Restart, AnIntervalWritesRestartFilesAsTheRunGoes) {
  const Model model = read_deck_string(short_slide(), "t.k");
  std::ostringstream log;
  const fs::path dir = fresh_dir("abut_restart_interval");
  RunOptions options = stopping_after(dir, 400);
  options.restart_interval = 1.0e-4;
  run_simulation(model, options, log);
  ASSERT_TRUE(fs::exists(dir / "restart.abr"));
  // Restarting from it and running to the end again with the interval gives the end state.
  RunOptions again{dir, 1, false};
  again.restart_from = dir / "restart.abr";
  again.restart_interval = 1.0e-4;
  const RunReport end = run_simulation(model, again, log);
  EXPECT_TRUE(end.stable);
  // The final restart file is at the end time: a restart from it has nothing left to do.
  RunOptions extend{dir, 1, false};
  extend.restart_from = dir / "restart.abr";
  const RunReport nothing = run_simulation(model, extend, log);
  EXPECT_EQ(nothing.cycles, end.cycles);
  fs::remove_all(dir);
}

TEST(Restart, AFileThatDoesNotFitIsAnInputErrorNamingIt) {
  const Model model = read_deck_string(short_slide(), "t.k");
  std::ostringstream log;
  const fs::path dir = fresh_dir("abut_restart_unfit");
  run_simulation(model, stopping_after(dir, 50), log);
  const fs::path file = dir / "restart.abr";
  const std::string good = file_text(file);
  const auto error_of = [&](const Model& m, const fs::path& f) -> std::string {
    RunOptions options{fresh_dir("abut_restart_unfit_out"), 1, false};
    options.restart_from = f;
    try {
      run_simulation(m, options, log);
    } catch (const InputError& e) {
      EXPECT_EQ(e.where().file, f.string());
      return e.message();
    }
    ADD_FAILURE() << "no InputError";
    return {};
  };
  // Another mesh.
  std::string finer = short_slide();
  finer.replace(finer.find("1, 1, 4, 4, 1"), 13, "1, 1, 5, 4, 1");
  EXPECT_NE(error_of(read_deck_string(finer, "t.k"), file).find("another mesh"), std::string::npos);
  // Same mesh, another contact setting that changes the state's layout (N2S points).
  EXPECT_NE(
      error_of(read_deck_string(short_slide("*CONTACT_DISCRETIZATION\n3, N2S\n"), "t.k"), file)
          .find("does not fit"),
      std::string::npos);
  // Damaged: cut short, a byte changed, not a restart file, missing.
  const fs::path bad = dir / "bad.abr";
  std::ofstream(bad, std::ios::binary) << good.substr(0, good.size() / 2);
  EXPECT_NE(error_of(model, bad).find("incomplete or damaged"), std::string::npos);
  std::string flipped = good;
  flipped[flipped.size() / 2] ^= 1;
  std::ofstream(bad, std::ios::binary) << flipped;
  EXPECT_NE(error_of(model, bad).find("checksum"), std::string::npos);
  std::ofstream(bad, std::ios::binary) << "*KEYWORD\n";
  EXPECT_NE(error_of(model, bad).find("not an abut restart file"), std::string::npos);
  EXPECT_NE(error_of(model, dir / "none.abr").find("does not exist"), std::string::npos);
  fs::remove_all(dir);
  fs::remove_all(fresh_dir("abut_restart_unfit_out"));
}

TEST(Restart, StaticStepsRefuseRestartOptions) {
  const Model model = read_deck(std::string(ABUT_SOURCE_DIR) + "/examples/static_block_press.k");
  std::ostringstream log;
  RunOptions options{fresh_dir("abut_restart_static"), 1, false};
  options.restart_interval = 1.0;
  try {
    run_simulation(model, options, log);
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(e.message().find("explicit runs only"), std::string::npos) << e.message();
  }
}

}  // namespace
}  // namespace abut
