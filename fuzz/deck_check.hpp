#pragma once
// What `abut check` does with a deck, as one call for the fuzz harnesses (fuzz/README.md): read
// it, then set up the solver it asks for (explicit or static), and sort the outcome.
#include <string>
#include <string_view>

namespace abut::fuzz {

enum class DeckFormat { keyword, inp, msh };  // IMPETUS-style .k, Abaqus/CalculiX .inp, Gmsh .msh

enum class Verdict {
  accepted,            // read and set up
  rejected_located,    // InputError naming file and line: what a user should get
  rejected_unlocated,  // InputError without a line: a defect to fix (issue 13)
  too_large,           // std::bad_alloc: the model did not fit the harness's memory limit
  unexpected,          // any other exception (InstabilityError at set-up, std::logic_error...)
};

struct Outcome {
  Verdict verdict = Verdict::accepted;
  std::string message;  // what() of the exception, empty when accepted
};

// How far check_deck goes: the reader alone (read, parse, finalize into a Model: fast enough for
// a million coverage-guided inputs), or what `abut check` does (the reader, then the set-up of the
// explicit or static solver the deck asks for).
enum class Stage { read, set_up };

// Never throws. Deck text is read as if it were the file "fuzz.k" (or "fuzz.inp"). A .msh file
// is read by the Gmsh reader alone (gmsh_mesh.hpp), whatever the stage: its rejections are
// located by line (ASCII) or byte offset (binary).
Outcome check_deck(std::string_view text, DeckFormat format, Stage stage = Stage::set_up);

const char* verdict_name(Verdict v);

}  // namespace abut::fuzz
