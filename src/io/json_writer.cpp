#include "abut/io/json_writer.hpp"

#include <cmath>
#include <stdexcept>

#include "io/output_file.hpp"

namespace abut {

std::string JsonWriter::quoted(std::string_view text) {
  // RFC 8259, section 7: the quotation mark, the reverse solidus and U+0000..U+001F must be
  // escaped; the two-character forms are used where they exist.
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out = "\"";
  for (const char c : text) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\b':
        out += "\\b";
        break;
      case '\f':
        out += "\\f";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\r':
        out += "\\r";
        break;
      case '\t':
        out += "\\t";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          out += "\\u00";
          out += kHex[(static_cast<unsigned char>(c) >> 4) & 0xF];
          out += kHex[static_cast<unsigned char>(c) & 0xF];
        } else {
          out += c;  // UTF-8 bytes pass through unchanged
        }
    }
  }
  out += '"';
  return out;
}

void JsonWriter::newline_and_indent(std::size_t depth) {
  text_ += '\n';
  text_.append(2 * depth, ' ');
}

void JsonWriter::before_value() {
  if (stack_.empty()) {
    if (done_) throw std::logic_error("JsonWriter: a document holds one top-level value");
    return;
  }
  Level& level = stack_.back();
  if (level.object) {
    if (!level.has_key) throw std::logic_error("JsonWriter: a value in an object needs a key");
    level.has_key = false;
  } else {
    if (level.count > 0) text_ += ',';
    newline_and_indent(stack_.size());
  }
  ++level.count;
}

JsonWriter& JsonWriter::scalar(std::string_view token) {
  before_value();
  text_ += token;
  if (stack_.empty()) done_ = true;
  return *this;
}

JsonWriter& JsonWriter::open(bool object) {
  before_value();
  text_ += object ? '{' : '[';
  stack_.push_back({object});
  return *this;
}

JsonWriter& JsonWriter::close(bool object) {
  if (stack_.empty() || stack_.back().object != object) {
    throw std::logic_error(object ? "JsonWriter: end_object() without an open object"
                                  : "JsonWriter: end_array() without an open array");
  }
  if (stack_.back().has_key) throw std::logic_error("JsonWriter: key without a value");
  const bool empty = stack_.back().count == 0;
  stack_.pop_back();
  if (!empty) newline_and_indent(stack_.size());
  text_ += object ? '}' : ']';
  if (stack_.empty()) done_ = true;
  return *this;
}

JsonWriter& JsonWriter::begin_object() { return open(true); }
JsonWriter& JsonWriter::end_object() { return close(true); }
JsonWriter& JsonWriter::begin_array() { return open(false); }
JsonWriter& JsonWriter::end_array() { return close(false); }

JsonWriter& JsonWriter::key(std::string_view name) {
  if (stack_.empty() || !stack_.back().object) {
    throw std::logic_error("JsonWriter: key '" + std::string(name) + "' outside an object");
  }
  Level& level = stack_.back();
  if (level.has_key) throw std::logic_error("JsonWriter: two keys without a value between");
  if (level.count > 0) text_ += ',';
  newline_and_indent(stack_.size());
  text_ += quoted(name);
  text_ += ": ";
  level.has_key = true;
  return *this;
}

JsonWriter& JsonWriter::value(std::string_view text) { return scalar(quoted(text)); }

JsonWriter& JsonWriter::value(bool flag) { return scalar(flag ? "true" : "false"); }

JsonWriter& JsonWriter::value(double number) {
  if (!std::isfinite(number)) return null();
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), number);
  return scalar(std::string_view(buffer.data(), result.ptr));
}

JsonWriter& JsonWriter::null() { return scalar("null"); }

const std::string& JsonWriter::text() const {
  if (!complete()) throw std::logic_error("JsonWriter: the document is not complete");
  return text_;
}

void JsonWriter::write_file(const std::filesystem::path& path) const {
  output_file::replace(path, text() + '\n');
}

}  // namespace abut
