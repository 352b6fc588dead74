#include "abut/core/error.hpp"

namespace abut {
namespace {
std::string format_location(const SourceLocation& w, const std::string& message) {
  std::string s;
  if (!w.file.empty()) {
    s += w.file;
    if (w.line > 0) s += ":" + std::to_string(w.line);
    s += ": ";
  }
  if (!w.keyword.empty()) s += w.keyword;
  if (!w.field.empty()) s += (w.keyword.empty() ? "" : ", ") + std::string("field '") + w.field + "'";
  if (!w.keyword.empty() || !w.field.empty()) s += ": ";
  return s + message;
}
}  // namespace

InputError::InputError(const std::string& message) : std::runtime_error(message), message_(message) {}
InputError::InputError(const SourceLocation& where, const std::string& message)
    : std::runtime_error(format_location(where, message)), where_(where), message_(message) {}

}  // namespace abut
