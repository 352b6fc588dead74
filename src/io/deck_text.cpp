#include "deck_text.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>

namespace abut::deck {

std::string trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r\n");
  return std::string(s.substr(first, last - first + 1));
}

std::string excerpt(std::string_view s, std::size_t limit) {
  if (s.size() <= limit) return std::string(s);
  std::string out(s.substr(0, limit));
  out.append("... (").append(std::to_string(s.size())).append(" characters)");
  return out;
}

std::string upper(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return out;
}

bool is_quoted(std::string_view s) {
  const std::string t = trim(s);
  return t.size() >= 2 && t.front() == '"' && t.back() == '"';
}

std::string unquote(std::string_view s) {
  const std::string t = trim(s);
  return is_quoted(t) ? t.substr(1, t.size() - 2) : t;
}

std::vector<std::string> split_fields(std::string_view line) {
  std::vector<std::string> fields;
  std::string current;
  int depth = 0;
  bool quoted = false;
  for (const char c : line) {
    if (c == '"') quoted = !quoted;
    if (!quoted) {
      if (c == '(' || c == '[') ++depth;
      if ((c == ')' || c == ']') && depth > 0) --depth;
      if (c == ',' && depth == 0) {
        fields.push_back(trim(current));
        current.clear();
        continue;
      }
    }
    current += c;
  }
  fields.push_back(trim(current));
  return fields;
}

std::optional<double> parse_number(std::string_view s) {
  std::string t = trim(s);
  if (!t.empty() && t.front() == '+') t.erase(0, 1);
  if (t.empty()) return std::nullopt;
  double value = 0.0;
  const char* end = t.data() + t.size();
  const auto [ptr, ec] = std::from_chars(t.data(), end, value);
  if (ec != std::errc() || ptr != end || !std::isfinite(value)) return std::nullopt;
  return value;
}

std::optional<std::int64_t> parse_integer(std::string_view s) {
  std::string t = trim(s);
  if (!t.empty() && t.front() == '+') t.erase(0, 1);
  std::int64_t value = 0;
  const char* end = t.data() + t.size();
  const auto [ptr, ec] = std::from_chars(t.data(), end, value);
  if (!t.empty() && ec == std::errc() && ptr == end) return value;
  // `2.0` or `1e3`: accepted when the real has no fractional part.
  const auto real = parse_number(t);
  if (real && std::floor(*real) == *real && std::fabs(*real) < 9.0e15) {
    return static_cast<std::int64_t>(*real);
  }
  return std::nullopt;
}

std::string format_number(double v) {
  char buffer[64];
  const auto [ptr, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
  return std::string(buffer, ec == std::errc() ? ptr : buffer);
}

Row::Row(std::vector<std::string> fields, SourceLocation line, std::vector<std::string> names)
    : fields_(std::move(fields)), line_(std::move(line)), names_(std::move(names)) {
  // A trailing comma leaves an empty last field: that is "default", not an extra field.
  while (fields_.size() > names_.size() && fields_.back().empty()) fields_.pop_back();
  if (fields_.size() > names_.size()) {
    std::string list;
    for (const auto& n : names_) list += (list.empty() ? "" : ", ") + n;
    throw InputError(line_, std::string("expected at most ") + std::to_string(names_.size()) +
                                " fields (" + list + "), got " + std::to_string(fields_.size()));
  }
}

const std::string& Row::text(std::size_t i) const {
  static const std::string empty;
  return i < fields_.size() ? fields_[i] : empty;
}

SourceLocation Row::where(std::size_t i) const {
  SourceLocation w = line_;
  w.field = i < names_.size() ? names_[i] : std::string("#").append(std::to_string(i + 1));
  return w;
}

void Row::fail(std::size_t i, const std::string& message) const {
  throw InputError(where(i), message);
}

void Row::require(bool ok, std::size_t i, const std::string& expectation) const {
  if (!ok)
    fail(i, expectation + ", got " + (given(i) ? excerpt(text(i)) : std::string("nothing")));
}

double Row::number(std::size_t i) const {
  if (!given(i)) fail(i, "missing value: expected a number");
  const auto v = parse_number(text(i));
  if (!v) fail(i, "expected a number, got '" + excerpt(text(i)) + "'");
  return *v;
}

double Row::number_or(std::size_t i, double fallback) const {
  return given(i) ? number(i) : fallback;
}

std::int64_t Row::integer(std::size_t i) const {
  if (!given(i)) fail(i, "missing value: expected an integer");
  const auto v = parse_integer(text(i));
  if (!v) fail(i, "expected an integer, got '" + excerpt(text(i)) + "'");
  return *v;
}

std::int64_t Row::integer_or(std::size_t i, std::int64_t fallback) const {
  return given(i) ? integer(i) : fallback;
}

std::int64_t Row::id(std::size_t i) const {
  if (!given(i)) fail(i, "missing value: expected a positive integer id");
  const auto v = parse_integer(text(i));
  if (!v || *v <= 0) fail(i, "expected a positive integer id, got '" + excerpt(text(i)) + "'");
  return *v;
}

std::optional<std::int64_t> Row::optional_id(std::size_t i) const {
  if (!given(i)) return std::nullopt;
  const auto v = parse_integer(text(i));
  if (!v || *v < 0)
    fail(i, "expected a positive integer id (or 0 for none), got '" + excerpt(text(i)) + "'");
  if (*v == 0) return std::nullopt;
  return v;
}

std::string Row::word(std::size_t i) const {
  if (!given(i)) fail(i, "missing value");
  return upper(text(i));
}

bool Row::flag(std::size_t i) const {
  const std::int64_t v = integer_or(i, 0);
  require(v == 0 || v == 1, i, "expected 0 or 1");
  return v == 1;
}

Row::NumberOrFunction Row::number_or_function(std::size_t i, double fallback) const {
  if (!given(i)) return {fallback, std::nullopt};
  const std::string t = upper(text(i));
  if (t.rfind("FCN", 0) == 0) {
    const std::string rest = trim(std::string_view(t).substr(3));
    if (rest.size() < 3 || rest.front() != '(' || rest.back() != ')') {
      fail(i, "expected a number or fcn(fid), got '" + excerpt(text(i)) + "'");
    }
    const auto fid = parse_integer(rest.substr(1, rest.size() - 2));
    if (!fid || *fid <= 0)
      fail(i, "expected fcn(fid) with a positive function id, got '" + excerpt(text(i)) + "'");
    return {0.0, fid};
  }
  const auto v = parse_number(t);
  if (!v) fail(i, "expected a number or fcn(fid), got '" + excerpt(text(i)) + "'");
  return {*v, std::nullopt};
}

void Row::unsupported_unless(std::size_t i, double off, const std::string& what) const {
  if (!given(i)) return;
  const auto v = parse_number(text(i));
  if (v && *v == off) return;
  fail(i, what + " is not supported yet by abut (leave the field empty)");
}

void Row::unsupported(std::size_t i, const std::string& what) const {
  if (given(i)) fail(i, what + " is not supported yet by abut (leave the field empty)");
}

void Row::global_coordinates_only(std::size_t i) const {
  unsupported_unless(i, 0.0, "a local coordinate system (csysid)");
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

}  // namespace abut::deck
