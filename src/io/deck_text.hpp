#pragma once
// Deck text: splitting lines into fields and reading fields as typed values, every error
// carrying the file, line, keyword and field name it belongs to.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "abut/core/error.hpp"

namespace abut::deck {

// The longest deck line abut reads (docs/deck-reference.md); a longer line is an InputError.
inline constexpr std::size_t kMaxLineLength = 65536;

std::string trim(std::string_view s);
// Text of the deck quoted in a message: at most `limit` characters, then "... (N characters)".
std::string excerpt(std::string_view s, std::size_t limit = 80);
std::string upper(std::string_view s);
bool is_quoted(std::string_view s);       // "..." (after trimming)
std::string unquote(std::string_view s);  // strips one pair of double quotes, if any

// Splits a data line at commas that are outside double quotes, parentheses and brackets
// (so `[max(%a, 2)]` and `fcn(3)` stay whole). Fields are trimmed; an empty field is "".
std::vector<std::string> split_fields(std::string_view line);

// Whole-field parses: the entire (trimmed) text must be the number. Reals must be finite;
// an integer may be written as a real with no fractional part (`2.0`).
std::optional<double> parse_number(std::string_view s);
std::optional<std::int64_t> parse_integer(std::string_view s);
// Shortest text that reads back to the same double (used for %param substitution).
std::string format_number(double v);
// Levenshtein distance (insertions, deletions, substitutions), for "did you mean" suggestions.
std::size_t edit_distance(std::string_view a, std::string_view b);

// One data line of a keyword, split into fields that have names (for messages).
class Row {
 public:
  // Throws if the line has more fields than `names`.
  Row(std::vector<std::string> fields, SourceLocation line, std::vector<std::string> names);

  std::size_t size() const { return fields_.size(); }
  bool given(std::size_t i) const { return i < fields_.size() && !fields_[i].empty(); }
  const std::string& text(std::size_t i) const;  // "" when absent
  const SourceLocation& where() const { return line_; }
  SourceLocation where(std::size_t i) const;  // the line plus the field's name
  [[noreturn]] void fail(std::size_t i, const std::string& message) const;
  // fail(i, expectation + ", got <text>") unless ok.
  void require(bool ok, std::size_t i, const std::string& expectation) const;

  double number(std::size_t i) const;  // required
  double number_or(std::size_t i, double fallback) const;
  std::int64_t integer(std::size_t i) const;  // required
  std::int64_t integer_or(std::size_t i, std::int64_t fallback) const;
  std::int64_t id(std::size_t i) const;  // required, > 0
  // An optional reference: empty or 0 means none, otherwise a positive id.
  std::optional<std::int64_t> optional_id(std::size_t i) const;
  std::string word(std::size_t i) const;  // required; upper case
  bool flag(std::size_t i) const;         // 0 (default) or 1

  // A number or `fcn(fid)` (fields whose options are "constant, fcn").
  struct NumberOrFunction {
    double value = 0.0;
    std::optional<std::int64_t> function_id;
  };
  NumberOrFunction number_or_function(std::size_t i, double fallback) const;

  // A field of an option abut does not implement: an error unless it is empty or `off`.
  void unsupported_unless(std::size_t i, double off, const std::string& what) const;
  // A field of an option abut does not implement, whatever its value: an error if given.
  void unsupported(std::size_t i, const std::string& what) const;
  // A local coordinate system id: only empty or 0 (global) is supported.
  void global_coordinates_only(std::size_t i) const;

 private:
  std::vector<std::string> fields_;
  SourceLocation line_;
  std::vector<std::string> names_;
};

}  // namespace abut::deck
