#pragma once
// Files for the tests that run and write: a scratch directory per test and process, removed
// first, a file's whole content, and a CSV history read back as numbers.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace abut::testing {

// <temp>/<name>_<pid>, removed if it exists (not created: the run under test creates it).
inline std::filesystem::path fresh_dir(const std::string& name) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / (name + "_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  return dir;
}

inline std::string file_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

inline void write_text(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
}

// A CSV file as its header and rows of numbers (energy.csv, nodes.csv, ...).
struct Csv {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  // The value of column `name` in row `row`.
  double at(std::size_t row, const std::string& name) const {
    for (std::size_t c = 0; c < columns.size(); ++c)
      if (columns[c] == name) return rows.at(row).at(c);
    throw std::runtime_error("no column " + name);
  }
};

inline Csv read_csv(const std::filesystem::path& path) {
  std::istringstream in(file_text(path));
  Csv csv;
  std::string line;
  std::getline(in, line);
  std::stringstream header(line);
  for (std::string f; std::getline(header, f, ',');) csv.columns.push_back(f);
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream fields(line);
    for (std::string f; std::getline(fields, f, ',');) row.push_back(std::stod(f));
    csv.rows.push_back(row);
  }
  return csv;
}

}  // namespace abut::testing
