#pragma once
// Reader of decks in IMPETUS keyword syntax (docs/deck-reference.md lists every keyword and
// field abut accepts). The reader validates everything it reads: an unknown keyword, a bad
// number, a missing id or a value out of range is an InputError naming file, line, keyword
// and field; a known keyword or option that abut does not implement yet is an InputError
// saying so. Nothing is skipped silently.
#include <string>
#include <vector>

#include "abut/model/model.hpp"

namespace abut {

// A model and the plain-English notes the reader has for the user (what *CHANGE_P-ORDER and
// *SMOOTH_MESH did to the mesh, parts without elements, ...). The CLI prints the notes.
struct DeckResult {
  Model model;
  std::vector<std::string> notes;
};

// Reads a deck file; *INCLUDE paths are relative to the including file. A file whose name ends
// in .inp (any case) is read as an Abaqus/CalculiX input file (read_inp_with_notes).
DeckResult read_deck_with_notes(const std::string& path);
// Reads a deck held in memory; `name` stands for the file in messages and *INCLUDE paths are
// relative to the current directory.
DeckResult read_deck_string_with_notes(const std::string& text,
                                       const std::string& name = "<string>");

// Reads an Abaqus/CalculiX input file (.inp; docs/inp-reference.md lists the keywords and what
// each becomes in the model, static steps included). Errors are InputErrors naming file and line.
DeckResult read_inp_with_notes(const std::string& path);
// The same for a text held in memory; `name` stands for the file in messages and *INCLUDE paths
// are relative to the current directory.
DeckResult read_inp_string_with_notes(const std::string& text,
                                      const std::string& name = "<string>.inp");

// The same without the notes.
Model read_deck(const std::string& path);
Model read_deck_string(const std::string& text, const std::string& name = "<string>");

}  // namespace abut
