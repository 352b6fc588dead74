#pragma once
// A small JSON writer (RFC 8259) for summary.json: objects, arrays, strings, numbers, booleans and
// null, written in order into an indented text. Reals are written with the shortest text that
// reads back to the same double. JSON has no NaN or infinity: such values are written as null.
//
//   JsonWriter json;
//   json.begin_object().member("cycles", 1234).key("energy").begin_array();
//   ...
//   json.end_array().end_object();
//   json.write_file("summary.json");
//
// Misuse (a value in an object without a key, unbalanced ends, ...) throws std::logic_error.
#include <array>
#include <charconv>
#include <concepts>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace abut {

class JsonWriter {
 public:
  JsonWriter& begin_object();
  JsonWriter& end_object();
  JsonWriter& begin_array();
  JsonWriter& end_array();
  JsonWriter& key(std::string_view name);

  JsonWriter& value(std::string_view text);
  JsonWriter& value(const char* text) { return value(std::string_view(text)); }
  JsonWriter& value(bool flag);
  JsonWriter& value(double number);
  template <std::integral T>
  requires(!std::same_as<T, bool>) JsonWriter& value(T number) {
    std::array<char, 24> buffer{};
    const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), number);
    return scalar(std::string_view(buffer.data(), result.ptr));
  }
  JsonWriter& null();

  // key(name).value(v)
  template <class T>
  JsonWriter& member(std::string_view name, const T& v) {
    return key(name).value(v);
  }

  // True once exactly one top-level value is finished.
  bool complete() const { return stack_.empty() && done_; }
  // The document; throws std::logic_error while it is not complete.
  const std::string& text() const;
  // Writes text() to `path` through a temporary file and an atomic rename.
  void write_file(const std::filesystem::path& path) const;

  // `text` as a quoted JSON string, with '"', '\' and control characters escaped.
  static std::string quoted(std::string_view text);

 private:
  struct Level {
    bool object;
    std::size_t count = 0;
    bool has_key = false;
  };
  void before_value();
  JsonWriter& scalar(std::string_view token);
  JsonWriter& open(bool object);
  JsonWriter& close(bool object);
  void newline_and_indent(std::size_t depth);

  std::string text_;
  std::vector<Level> stack_;
  bool done_ = false;
};

}  // namespace abut
