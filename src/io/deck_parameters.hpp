#pragma once
// *PARAMETER values and their substitution into deck text: `%name` is replaced by the value,
// `[expression]` by the value of the expression (evaluated once, when the line is read).
#include <map>
#include <string>
#include <string_view>

#include "abut/core/error.hpp"

namespace abut::deck {

class Parameters {
 public:
  // Names are given without '%' and compared case-insensitively.
  bool contains(const std::string& name) const;
  // A name may be defined once; a second definition is an InputError at `where`.
  void define(const std::string& name, double value, const SourceLocation& where);
  double value(const std::string& name, const SourceLocation& where) const;

  // Replaces every `[expression]` (after substituting %names inside it) and every bare
  // `%name` in `text`; text in double quotes is left alone. Errors are located at `where`.
  // With `in_expression`, negative values of %names are written in parentheses.
  std::string substitute(std::string_view text, const SourceLocation& where,
                         bool in_expression = false) const;

 private:
  std::string substitute_names(std::string_view text, const SourceLocation& where,
                               bool in_expression) const;
  struct Entry {
    double value = 0.0;
    SourceLocation where;
  };
  std::map<std::string, Entry> values_;
};

// A valid parameter name: a letter or '_' then letters, digits or '_'.
bool is_parameter_name(std::string_view name);

}  // namespace abut::deck
