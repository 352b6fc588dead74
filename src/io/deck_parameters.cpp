#include "deck_parameters.hpp"

#include <cctype>

#include "abut/core/functions.hpp"
#include "deck_text.hpp"

namespace abut::deck {
namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

bool is_name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }

}  // namespace

bool is_parameter_name(std::string_view name) {
  if (name.empty() || std::isdigit(static_cast<unsigned char>(name.front())) != 0) return false;
  for (const char c : name) {
    if (!is_name_char(c)) return false;
  }
  return true;
}

bool Parameters::contains(const std::string& name) const { return values_.count(lower(name)) > 0; }

void Parameters::define(const std::string& name, double value, const SourceLocation& where) {
  const auto [it, inserted] = values_.emplace(lower(name), Entry{value, where});
  if (!inserted) {
    throw InputError(where, "parameter %" + name + " is already defined at " +
                                it->second.where.file + ":" +
                                std::to_string(it->second.where.line));
  }
}

double Parameters::value(const std::string& name, const SourceLocation& where) const {
  const auto it = values_.find(lower(name));
  if (it != values_.end()) return it->second.value;
  std::string defined;
  for (const auto& [n, e] : values_) defined += (defined.empty() ? "%" : ", %") + n;
  throw InputError(
      where,
      "parameter %" + name + " is not defined" +
          (defined.empty() ? std::string(" (the deck defines no *PARAMETER before this line)")
                           : " (defined so far: " + defined + ")"));
}

std::string Parameters::substitute_names(std::string_view text, const SourceLocation& where,
                                         bool in_expression) const {
  std::string out;
  bool quoted = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '"') quoted = !quoted;
    if (c != '%' || quoted) {
      out += c;
      continue;
    }
    std::size_t end = i + 1;
    while (end < text.size() && is_name_char(text[end])) ++end;
    const std::string name(text.substr(i + 1, end - i - 1));
    if (!is_parameter_name(name)) {
      throw InputError(where, "'%' must be followed by a parameter name, got '" +
                                  std::string(text.substr(i, end - i + 1)) + "'");
    }
    const double v = value(name, where);
    // Inside an expression a negative value is bracketed so that `-%a` stays well formed.
    out += (in_expression && v < 0.0) ? std::string("(").append(format_number(v)).append(")")
                                      : format_number(v);
    i = end - 1;
  }
  return out;
}

std::string Parameters::substitute(std::string_view text, const SourceLocation& where,
                                   bool in_expression) const {
  std::string out;
  bool quoted = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '"') quoted = !quoted;
    if (c != '[' || quoted) {
      out += c;
      continue;
    }
    int depth = 1;
    std::size_t end = i + 1;
    for (; end < text.size() && depth > 0; ++end) {
      if (text[end] == '[') ++depth;
      if (text[end] == ']') --depth;
    }
    if (depth != 0)
      throw InputError(where, "'[' without a matching ']' in '" + std::string(text) + "'");
    const std::string inner = substitute_names(text.substr(i + 1, end - i - 2), where, true);
    try {
      out += format_number(evaluate_constant_expression(inner));
    } catch (const InputError& e) {
      throw InputError(where, "cannot evaluate [" + inner + "]: " + e.message());
    }
    i = end - 1;
  }
  return substitute_names(out, where, in_expression);
}

}  // namespace abut::deck
