// What a static run writes (run_static.cpp): the histories a user plots. Two unit cubes stacked,
// the lower one held at its base, the upper one pressed by a pressure p on its top face and held
// sideways, frictionless contact in between: the contact carries p x 1 (equilibrium of the upper
// cube), and for this linear problem the stored energy (elements and contact springs) is half the
// work of the load, 1/2 p u_top (Clapeyron's theorem).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "abut/io/deck.hpp"
#include "abut/io/run.hpp"

namespace abut {
namespace {

constexpr double kPressure = 5.0;

const char* const kDeck = R"(*NODE
1, 0., 0., 0.
2, 1., 0., 0.
3, 1., 1., 0.
4, 0., 1., 0.
5, 0., 0., 1.
6, 1., 0., 1.
7, 1., 1., 1.
8, 0., 1., 1.
11, 0., 0., 1.
12, 1., 0., 1.
13, 1., 1., 1.
14, 0., 1., 1.
15, 0., 0., 2.
16, 1., 0., 2.
17, 1., 1., 2.
18, 0., 1., 2.
*ELEMENT, TYPE=C3D8, ELSET=LOWER
1, 1, 2, 3, 4, 5, 6, 7, 8
*ELEMENT, TYPE=C3D8, ELSET=UPPER
2, 11, 12, 13, 14, 15, 16, 17, 18
*NSET, NSET=BASE
1, 2, 3, 4
*NSET, NSET=UPPERN
11, 12, 13, 14, 15, 16, 17, 18
*MATERIAL, NAME=M
*ELASTIC
1000., 0.
*SOLID SECTION, ELSET=LOWER, MATERIAL=M
*SOLID SECTION, ELSET=UPPER, MATERIAL=M
*SURFACE, NAME=TOPOFLOWER
LOWER, S2
*SURFACE, NAME=BOTTOMOFUPPER
UPPER, S1
*SURFACE INTERACTION, NAME=I
*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR
1.e5
*CONTACT PAIR, INTERACTION=I, TYPE=SURFACE TO SURFACE
BOTTOMOFUPPER, TOPOFLOWER
*BOUNDARY
BASE, 1, 3
UPPERN, 1, 2
*STEP
*STATIC
0.5, 1.
*DLOAD
2, P2, 5.
*END STEP
)";

std::vector<std::vector<double>> csv_rows(const std::filesystem::path& path, std::string& header) {
  std::ifstream in(path);
  std::getline(in, header);
  std::vector<std::vector<double>> rows;
  for (std::string line; std::getline(in, line);) {
    std::vector<double> row;
    std::stringstream fields(line);
    for (std::string f; std::getline(fields, f, ',');) row.push_back(std::stod(f));
    rows.push_back(row);
  }
  return rows;
}

TEST(RunStatic, EnergyAndContactHistories) {
  const Model model = read_inp_string_with_notes(kDeck, "t.inp").model;
  const auto dir = std::filesystem::temp_directory_path() / "abut_test_run_static";
  std::filesystem::remove_all(dir);
  std::ostringstream log;
  const RunReport report = run_static_analysis(model, {dir, 1, false}, log);
  ASSERT_TRUE(report.stable) << log.str();

  std::string header;
  const auto contact = csv_rows(dir / "contact.csv", header);
  EXPECT_EQ(header,
            "time,contact,fx,fy,fz,normal_force,tangential_force,energy,friction_energy,"
            "max_penetration,active_points");
  ASSERT_EQ(contact.size(), 2u);  // two increments of 0.5
  EXPECT_NEAR(contact[0][5], 0.5 * kPressure, 1e-9 * kPressure);
  EXPECT_NEAR(contact[1][5], kPressure, 1e-9 * kPressure);
  EXPECT_NEAR(contact[1][4], kPressure, 1e-9 * kPressure);  // on the upper cube, along +z
  EXPECT_EQ(contact[1][10], 4.0);                           // 2 x 2 Gauss points

  const auto energy = csv_rows(dir / "energy.csv", header);
  EXPECT_EQ(header, "time,internal,contact,friction,external_work,balance_error");
  ASSERT_EQ(energy.size(), 2u);
  // The top face's downward displacement from the contact penetration and the two cubes.
  const double u_top = kPressure / 1000.0 * 2.0 + contact[1][9];
  EXPECT_NEAR(energy[1][1] + energy[1][2], 0.5 * kPressure * u_top, 1e-9);
  EXPECT_EQ(energy[1][3], 0.0);
  // The pressure, ramped with the top's displacement, works 1/2 p A u_top (A = 1): the books
  // balance at every increment (linear steps: the trapezoidal rule is exact).
  EXPECT_NEAR(energy[1][4], 0.5 * kPressure * u_top, 1e-9);
  for (const std::vector<double>& row : energy) EXPECT_NEAR(row[5], 0.0, 1e-8);
  std::filesystem::remove_all(dir);
}

// Abaqus history output of a node set (*OUTPUT, HISTORY with *NODE OUTPUT, NSET=): nodes.csv
// follows the top face of kDeck at t = 0 and after each increment. References: the nodal force
// there is the pressure load, -p t A (A = 1); the top moves down by p t / E over the two cubes plus
// the contact's penetration (as EnergyAndContactHistories).
TEST(RunStatic, AbaqusHistoryOutputFollowsANodeSet) {
  std::string deck = kDeck;
  deck.insert(deck.find("*MATERIAL"), "*NSET, NSET=TOPN\n15, 16, 17, 18\n");
  deck.insert(deck.find("*END STEP"), "*OUTPUT, HISTORY\n*NODE OUTPUT, NSET=TOPN\nU, RF\n");
  const DeckResult read = read_inp_string_with_notes(deck, "t.inp");
  ASSERT_EQ(read.model.output.history_nodes.size(), 1u);
  EXPECT_FALSE(read.model.output.state_fields) << "a history request chooses no state fields";
  const auto dir = std::filesystem::temp_directory_path() / "abut_test_run_static_history";
  std::filesystem::remove_all(dir);
  std::ostringstream log;
  ASSERT_TRUE(run_static_analysis(read.model, {dir, 1, false}, log).stable) << log.str();
  std::string header;
  const auto contact = csv_rows(dir / "contact.csv", header);
  const auto nodes = csv_rows(dir / "nodes.csv", header);
  EXPECT_EQ(header, "time,node,x,y,z,ux,uy,uz,force_x,force_y,force_z");
  ASSERT_EQ(nodes.size(), 12u);  // 4 nodes at t = 0, 0.5, 1
  ASSERT_EQ(contact.size(), 2u);
  for (std::size_t s = 0; s < 3; ++s) {
    const double t = 0.5 * static_cast<double>(s);
    const double penetration = s == 0 ? 0.0 : contact[s - 1][9];
    const double u_top = kPressure * t / 1000.0 * 2.0 + penetration;
    double force = 0.0;
    for (std::size_t k = 0; k < 4; ++k) {
      const std::vector<double>& row = nodes[4 * s + k];
      EXPECT_EQ(row[0], t);
      EXPECT_EQ(row[1], static_cast<double>(15 + k));
      EXPECT_NEAR(row[7], -u_top, 1e-9) << "t = " << t;
      force += row[10];
    }
    EXPECT_NEAR(force, -kPressure * t, 1e-9 * kPressure) << "t = " << t;
  }
  // Without NSET the request is an error at the card.
  deck.replace(deck.find(", NSET=TOPN\nU"), 11, "");
  try {
    static_cast<void>(read_inp_string_with_notes(deck, "t.inp"));
    ADD_FAILURE() << "*NODE OUTPUT history without NSET";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("needs NSET="), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}

// With thermal properties each state carries the steady temperature of its loads: the lower
// cube held at 100 at its base (nodes 1-4), the upper one at 0 on its top (15-18); the contact
// does not conduct in static steps, so each cube takes its held temperature (and the deck needs
// no density: a steady state stores no heat).
TEST(RunStatic, SteadyTemperatureInEveryState) {
  Model model = read_inp_string_with_notes(kDeck, "t.inp").model;
  ThermalProperties p;
  p.id = 1;
  p.conductivity = 50.0;
  p.specific_heat = 400.0;
  model.thermal.properties.push_back(p);
  for (Material& m : model.materials) m.thermal_id = 1;
  model.thermal.prescribed.push_back({{0, 1, 2, 3}, {}, 100.0, {}});
  model.thermal.prescribed.push_back({{12, 13, 14, 15}, {}, 0.0, {}});
  const auto dir = std::filesystem::temp_directory_path() / "abut_test_run_static_heat";
  std::filesystem::remove_all(dir);
  std::ostringstream log;
  const RunReport report = run_static_analysis(model, {dir, 1, false}, log);
  ASSERT_TRUE(report.stable) << log.str();
  std::ifstream vtu(dir / "states" / "state_0002.vtu");
  const std::string text((std::istreambuf_iterator<char>(vtu)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("Name=\"temperature\""), std::string::npos);
  EXPECT_NE(log.str().find("steady heat conduction"), std::string::npos);

  p.expansion = 1e-5;  // not coupled in static steps: refused rather than ignored
  model.thermal.properties = {p};
  EXPECT_THROW(run_static_analysis(model, {dir, 1, false}, log), InputError);
  std::filesystem::remove_all(dir);
}

// The output cards choose the states' fields and how often they are written (CalculiX *NODE FILE
// and *EL FILE, FREQUENCY: every n-th increment; abut adds each step's last). Four fixed
// increments with FREQUENCY=3: the initial state, increment 3 and increment 4 (the step's end).
TEST(RunStatic, OutputCardsChooseTheStatesFieldsAndFrequency) {
  std::string deck = kDeck;
  const std::string step = "*STEP\n*STATIC\n0.5, 1.\n";
  deck.replace(deck.find(step), step.size(),
               "*STEP\n*STATIC, DIRECT\n0.25, 1.\n*NODE FILE, FREQUENCY=3\nU\n*EL FILE\nS, E\n");
  const DeckResult read = read_inp_string_with_notes(deck, "t.inp");
  ASSERT_EQ(read.notes.size(), 1u);
  EXPECT_NE(read.notes[0].find("*EL FILE: E not written"), std::string::npos) << read.notes[0];
  const auto dir = std::filesystem::temp_directory_path() / "abut_test_run_static_output";
  std::filesystem::remove_all(dir);
  std::ostringstream log;
  const RunReport report = run_static_analysis(read.model, {dir, 1, false}, log);
  ASSERT_TRUE(report.stable) << log.str();
  EXPECT_TRUE(std::filesystem::exists(dir / "states" / "state_0002.vtu"));
  EXPECT_FALSE(std::filesystem::exists(dir / "states" / "state_0003.vtu"));
  std::ifstream vtu(dir / "states" / "state_0002.vtu");
  const std::string text((std::istreambuf_iterator<char>(vtu)), std::istreambuf_iterator<char>());
  for (const char* field : {"displacement", "stress", "von_mises_stress", "part_id"})
    EXPECT_NE(text.find("Name=\"" + std::string(field) + "\""), std::string::npos) << field;
  for (const char* field : {"force", "plastic_strain", "strain_energy"})
    EXPECT_EQ(text.find("Name=\"" + std::string(field) + "\""), std::string::npos) << field;
  // The histories keep every increment.
  std::string header;
  EXPECT_EQ(csv_rows(dir / "energy.csv", header).size(), 4u);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace abut
