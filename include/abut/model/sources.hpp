#pragma once
// Where the input gave each setting of the model, and the input's words for the settings a
// message asks the user to give. The reader fills both as it reads; the solvers name a setting by
// the model's name (below) and take its place and words from here, so that an error found while
// running points at the user's file, line, keyword and field, in the input language, without the
// solver knowing any deck field (docs/architecture.md, "The model layer").
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <tuple>

#include "abut/core/error.hpp"

namespace abut {

// The entities whose settings have places of their own (one per id).
enum class SourceEntity : std::uint8_t {
  Contact,  // ContactSpec, by id
  Tie,      // TieSpec, by id
  Time,     // the run's time control (id 0)
};

// The settings' names are the model's: for a contact, the contact library's (ContactSettings
// members and the names of its ContactSetupError) and the model's own (sources.cpp lists them
// all, and a name outside the list is a programming error).
class Sources {
 public:
  // Records where the input gave `setting` of entity `id`; a later record replaces an earlier one.
  void set(SourceEntity entity, std::int64_t id, std::string_view setting, SourceLocation where);
  // Whether the input gave the setting (its card or keyword is in the input).
  bool given(SourceEntity entity, std::int64_t id, std::string_view setting) const;
  // Where the input gave the setting; `otherwise` (usually the entity's own card) if it did not.
  SourceLocation of(SourceEntity entity, std::int64_t id, std::string_view setting,
                    const SourceLocation& otherwise = {}) const;

  // The settings' names an entity has (sources.cpp lists them once), and whether `setting` is one.
  static std::span<const std::string_view> settings(SourceEntity entity);
  static bool has_setting(SourceEntity entity, std::string_view setting);

  // The input's words for a concept that a message asks for (the keys of the model's words in
  // sources.cpp), such as "min_step": "dt_min of *TIME" in the .k dialect. A reader names the
  // concepts its language has; the others keep the model's words ("the minimum time step").
  void name(std::string_view concept_name, std::string words);
  std::string words(std::string_view concept_name) const;

 private:
  // Looked up on errors and while reading only: a key string per look-up costs nothing that
  // matters (a heterogeneous look-up of tuples compiles with GCC but not with clang).
  std::map<std::tuple<SourceEntity, std::int64_t, std::string>, SourceLocation> places_;
  std::map<std::string, std::string, std::less<>> words_;
};

}  // namespace abut
