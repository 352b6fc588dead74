#pragma once
// Time histories as CSV (energy.csv, parts.csv, contact.csv): one header line of column names,
// then one row per output time. The first column is always `time`, written with the shortest
// text that reads back to the same double; other reals get 10 significant digits (as printf
// "%.10g", but independent of the C locale); integers (part or interface ids) are exact.
// Each row is flushed, so the file is readable while the run goes on and complete up to the last
// row if it stops.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <span>
#include <string>
#include <variant>
#include <vector>

namespace abut {

class StateArchive;

class CsvHistory {
 public:
  using Value = std::variant<std::int64_t, double>;

  // Creates (or truncates) `path` and writes the header "time,<columns...>".
  // Throws std::runtime_error if the file cannot be written.
  CsvHistory(std::filesystem::path path, std::vector<std::string> columns);

  // One row: the time, then exactly one value per column (std::invalid_argument otherwise).
  void write_row(double time, std::span<const Value> values);
  void write_row(double time, std::initializer_list<Value> values) {
    write_row(time, std::span<const Value>(values.begin(), values.size()));
  }

  const std::vector<std::string>& columns() const { return columns_; }
  const std::filesystem::path& path() const { return path_; }
  // Restart: saving keeps the text of the file so far; loading writes it back (its header must
  // be this history's) and goes on appending to it.
  void archive(StateArchive& a);

 private:
  std::string header() const;  // "time,<columns...>\n"

  std::filesystem::path path_;
  std::vector<std::string> columns_;
  std::ofstream out_;
  std::string line_;  // reused for every row
};

}  // namespace abut
