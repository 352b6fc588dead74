#include "deck_check.hpp"

#include <exception>
#include <new>

#include "abut/core/error.hpp"
#include "abut/io/deck.hpp"
#include "abut/io/gmsh_mesh.hpp"
#include "abut/io/run.hpp"

namespace abut::fuzz {

Outcome check_deck(std::string_view text, DeckFormat format, Stage stage) {
  try {
    if (format == DeckFormat::msh) {
      gmsh::read_msh(text, "fuzz.msh");
      return {};
    }
    const std::string deck(text);
    const DeckResult result = format == DeckFormat::inp
                                  ? read_inp_string_with_notes(deck, "fuzz.inp")
                                  : read_deck_string_with_notes(deck, "fuzz.k");
    if (stage == Stage::read) return {};
    check_model(result.model);
    return {};
  } catch (const InputError& e) {
    const bool located =
        e.where().line > 0 || (format == DeckFormat::msh && !e.where().file.empty() &&
                               e.message().rfind("at byte ", 0) == 0);
    const Verdict v = located ? Verdict::rejected_located : Verdict::rejected_unlocated;
    return {v, e.what()};
  } catch (const std::bad_alloc& e) {
    return {Verdict::too_large, e.what()};
  } catch (const std::exception& e) {
    return {Verdict::unexpected, e.what()};
  }
}

const char* verdict_name(Verdict v) {
  switch (v) {
    case Verdict::accepted:
      return "accepted";
    case Verdict::rejected_located:
      return "rejected with file:line";
    case Verdict::rejected_unlocated:
      return "rejected without a line";
    case Verdict::too_large:
      return "too large (bad_alloc)";
    case Verdict::unexpected:
      return "unexpected exception";
  }
  return "?";
}

}  // namespace abut::fuzz
