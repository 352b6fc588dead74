#pragma once
// Shared by the deck tests: read a deck held in a string, catch the error it must raise.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "abut/io/deck.hpp"
#include "abut/solver/simulation.hpp"

namespace abut::testing {

// The smallest complete model: one 2x2x1 box of elastic steel, SI units.
inline const char* kBoxModel = R"(*UNIT_SYSTEM
SI
*TIME
1.0e-3
*COMPONENT_BOX
1, 1, 2, 2, 1
0.0, 0.0, 0.0, 2.0, 2.0, 1.0
*MAT_ELASTIC
1, 7800.0, 210.0e9, 0.3
*PART
"block"
1, 1
)";

// The box model with `extra` keywords after it.
inline std::string with_box(const std::string& extra) { return std::string(kBoxModel) + extra; }

// The box model in contact with itself, *CONTACT 5 between part 1 and part 1 (enough for the
// reader of the contact keywords), with `extra` keywords after it.
inline std::string with_contact(const std::string& extra) {
  return std::string(kBoxModel) + "*CONTACT\n5\nP, 1, P, 1\n" + extra;
}

inline DeckResult read(const std::string& text) { return read_deck_string_with_notes(text, "t.k"); }
inline Model model_of(const std::string& text) { return read_deck_string(text, "t.k"); }

// The InputError that reading `text` raises (a test failure if there is none).
inline InputError error_of(const std::string& text) {
  try {
    read_deck_string(text, "t.k");
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "expected an InputError for:\n" << text;
  return InputError("no error");
}

// An explicit run of `deck` refusing the keyword on its last line (one that acts in static steps
// only): an InputError at that line whose message has `text`.
inline void expect_explicit_refusal(const std::string& deck, const std::string& text) {
  const Model m = read_deck_string(deck, "t.k");
  try {
    Simulation sim(m);
    ADD_FAILURE() << "an explicit run took:\n" << deck;
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, static_cast<std::size_t>(std::count(deck.begin(), deck.end(), '\n')))
        << e.what();
    EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
  }
}

inline std::string deck_path(const std::string& name) {
  return std::string(ABUT_SOURCE_DIR) + "/tests/io/decks/" + name;
}

}  // namespace abut::testing
