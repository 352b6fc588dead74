#include "abut/io/csv_history.hpp"

#include <array>
#include <charconv>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string_view>

#include "abut/core/state_archive.hpp"
#include "io/output_file.hpp"

namespace abut {
namespace {

constexpr int kSignificantDigits = 10;

// A header field, quoted if it contains a separator, quote or line break (RFC 4180, section 2).
void append_name(std::string& line, std::string_view name) {
  if (name.find_first_of(",\"\r\n") == std::string_view::npos) {
    line += name;
    return;
  }
  line += '"';
  for (const char c : name) {
    if (c == '"') line += '"';
    line += c;
  }
  line += '"';
}

void append_number(std::string& line, double value, bool exact) {
  std::array<char, 32> buffer{};
  const auto result = exact ? std::to_chars(buffer.data(), buffer.data() + buffer.size(), value)
                            : std::to_chars(buffer.data(), buffer.data() + buffer.size(), value,
                                            std::chars_format::general, kSignificantDigits);
  line.append(buffer.data(), result.ptr);
}

void append_value(std::string& line, const CsvHistory::Value& value) {
  if (const auto* integer = std::get_if<std::int64_t>(&value)) {
    line += std::to_string(*integer);
  } else {
    append_number(line, std::get<double>(value), false);
  }
}

}  // namespace

CsvHistory::CsvHistory(std::filesystem::path path, std::vector<std::string> columns)
    : path_(std::move(path)), columns_(std::move(columns)), out_(output_file::open(path_)) {
  out_ << header() << std::flush;
  output_file::check(out_, path_);
}

std::string CsvHistory::header() const {
  std::string line = "time";
  for (const std::string& name : columns_) {
    line += ',';
    append_name(line, name);
  }
  return line + '\n';
}

void CsvHistory::write_row(double time, std::span<const Value> values) {
  if (values.size() != columns_.size()) {
    throw std::invalid_argument("CsvHistory '" + path_.string() + "': row has " +
                                std::to_string(values.size()) + " values for " +
                                std::to_string(columns_.size()) + " columns");
  }
  line_.clear();
  append_number(line_, time, true);
  for (const Value& value : values) {
    line_ += ',';
    append_value(line_, value);
  }
  line_ += '\n';
  out_ << line_ << std::flush;
  output_file::check(out_, path_);
}

void CsvHistory::archive(StateArchive& a) {
  const std::string header_line = header();
  std::string text;
  if (a.saving()) {
    out_.flush();
    std::ifstream in(path_, std::ios::binary);
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  a.value(text);
  if (a.saving()) return;
  if (text.compare(0, header_line.size(), header_line) != 0)
    a.fail("the columns of " + path_.filename().string() + " differ from the restart file's");
  out_.close();
  out_ = output_file::open(path_);
  out_ << text << std::flush;
  output_file::check(out_, path_);
}

}  // namespace abut
