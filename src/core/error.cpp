#include "abut/core/error.hpp"

namespace abut {
namespace {
std::string format_location(const SourceLocation& w, const std::string& message) {
  // Built with append(): GCC 12 warns falsely (-Wrestrict, PR 105329) on chained operator+.
  std::string s;
  if (!w.file.empty()) {
    s.append(w.file);
    if (w.line > 0) s.append(":").append(std::to_string(w.line));
    s.append(": ");
  }
  s.append(w.keyword);
  if (!w.field.empty()) {
    if (!w.keyword.empty()) s.append(", ");
    s.append("field '").append(w.field).append("'");
  }
  if (!w.keyword.empty() || !w.field.empty()) s.append(": ");
  s.append(message);
  return s;
}
}  // namespace

InputError::InputError(const std::string& message) : std::runtime_error(message), message_(message) {}
InputError::InputError(const SourceLocation& where, const std::string& message)
    : std::runtime_error(format_location(where, message)), where_(where), message_(message) {}

}  // namespace abut
