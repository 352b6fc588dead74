#include "inp_lines.hpp"

#include <cctype>
#include <fstream>
#include <sstream>

#include "abut/io/gmsh_mesh.hpp"

namespace abut::inp {
namespace fs = std::filesystem;

namespace {

constexpr int kMaxIncludeDepth = 16;

bool blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && blank(s.back())) s.remove_suffix(1);
  return s;
}

// Commas outside double quotes separate the fields of a keyword line.
std::vector<std::string_view> split_keyword_fields(std::string_view line) {
  std::vector<std::string_view> fields;
  bool quoted = false;
  std::size_t start = 0;
  for (std::size_t i = 0; i < line.size(); ++i) {
    if (line[i] == '"') quoted = !quoted;
    if (line[i] == ',' && !quoted) {
      fields.push_back(trimmed(line.substr(start, i - start)));
      start = i + 1;
    }
  }
  fields.push_back(trimmed(line.substr(start)));
  return fields;
}

std::string unquoted(std::string_view s) {
  s = trimmed(s);
  if (s.size() >= 2 && s.front() == '"' && s.back() == '"') s = s.substr(1, s.size() - 2);
  return std::string(s);
}

}  // namespace

std::string lookup_key(std::string_view name) {
  std::string key;
  key.reserve(name.size());
  for (const char c : name)
    if (!blank(c)) key += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return key;
}

std::string display_name(std::string_view name) {
  std::string out;
  bool gap = false;
  for (const char c : trimmed(name)) {
    if (blank(c)) {
      gap = true;
      continue;
    }
    if (gap && !out.empty()) out += ' ';
    gap = false;
    out += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  }
  return out;
}

Card parse_keyword_line(std::string_view text, std::uint32_t file, std::uint32_t line,
                        const std::string& file_name) {
  Card card;
  card.file = file;
  card.line = line;
  const std::vector<std::string_view> fields = split_keyword_fields(text);
  card.keyword = display_name(fields.front());
  card.key = lookup_key(card.keyword);
  if (card.key == "*") {
    throw InputError(SourceLocation{file_name, line, "", ""},
                     "a keyword line needs a keyword name after '*'");
  }
  for (std::size_t i = 1; i < fields.size(); ++i) {
    if (fields[i].empty()) continue;  // `*NODE,` or `A=1,,B=2`
    Parameter p;
    const std::size_t eq = fields[i].find('=');
    p.name = display_name(fields[i].substr(0, eq));
    p.key = lookup_key(p.name);
    if (eq != std::string_view::npos) {
      p.has_value = true;
      p.value = unquoted(fields[i].substr(eq + 1));
    }
    if (p.key.empty()) {
      throw InputError(SourceLocation{file_name, line, card.keyword, ""},
                       "a parameter name is missing before '='");
    }
    for (const Parameter& q : card.parameters) {
      if (q.key == p.key) {
        throw InputError(SourceLocation{file_name, line, card.keyword, p.name},
                         "the parameter is given twice: give it once");
      }
    }
    card.parameters.push_back(std::move(p));
  }
  return card;
}

void InpLines::read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot open input file '" + path.string() + "'");
  std::ostringstream text;
  text << in.rdbuf();
  files_.push_back(path.string());
  std::error_code ec;
  include_stack_.push_back(fs::weakly_canonical(path, ec).string());
  read_lines(text.str(), static_cast<std::uint32_t>(files_.size() - 1), path.parent_path(), 0);
  include_stack_.pop_back();
  flush();
}

void InpLines::read_text(const std::string& text, const std::string& name,
                         const fs::path& directory) {
  files_.push_back(name);
  read_lines(text, static_cast<std::uint32_t>(files_.size() - 1), directory, 0);
  flush();
}

void InpLines::flush() {
  if (!has_current_) return;
  has_current_ = false;
  Card card = std::move(current_);
  current_ = Card{};
  handler_(card);
}

void InpLines::read_lines(const std::string& text, std::uint32_t file, const fs::path& directory,
                          int depth) {
  const std::string_view all(text);
  std::size_t pos = all.starts_with("\xEF\xBB\xBF") ? 3 : 0;  // a UTF-8 byte order mark
  std::uint32_t number = 0;
  // The next line, with its number; false at the end of the text.
  const auto next_line = [&](std::string_view& out) {
    if (pos >= all.size()) return false;
    std::size_t end = all.find('\n', pos);
    if (end == std::string_view::npos) end = all.size();
    out = trimmed(all.substr(pos, end - pos));
    pos = end + 1;
    ++number;
    return true;
  };
  std::string_view line;
  while (next_line(line)) {
    if (line.empty() || line.starts_with("**")) continue;
    if (line.front() != '*') {
      if (!has_current_) {
        throw InputError(SourceLocation{files_[file], number, "", ""},
                         "data line before the first keyword: '" + std::string(line) +
                             "' (keyword lines start with '*', comment lines with '**')");
      }
      current_.data.push_back({std::string(line), file, number});
      continue;
    }
    // A keyword line; a trailing comma continues it on the next line.
    const std::uint32_t keyword_line = number;
    std::string keyword_text(line);
    while (!keyword_text.empty() && keyword_text.back() == ',') {
      std::string_view more;
      if (!next_line(more)) break;
      if (more.empty() || more.starts_with("**")) continue;
      keyword_text += more;
    }
    Card card = parse_keyword_line(keyword_text, file, keyword_line, files_[file]);
    if (card.key == "*INCLUDE") {
      include(card, directory, depth);
      continue;
    }
    flush();
    current_ = std::move(card);
    has_current_ = true;
  }
}

void InpLines::include(const Card& card, const fs::path& directory, int depth) {
  const SourceLocation here{files_[card.file], card.line, "*INCLUDE", ""};
  std::string input;
  for (const Parameter& p : card.parameters)
    if (p.key == "INPUT") input = p.value;
  // A Gmsh mesh, or a file Gmsh meshes: a card of its own for the reader (inp_gmsh.cpp), with
  // the path resolved and the file listed for the locations of its nodes and elements.
  if (!input.empty() && gmsh::gmsh_file_kind(input)) {
    const fs::path path = directory / fs::path(input);
    std::error_code ec;
    if (!fs::is_regular_file(path, ec))
      throw InputError(SourceLocation{files_[card.file], card.line, "*INCLUDE", "INPUT"},
                       "cannot open the included file '" + path.string() +
                           "' (paths are relative to the including file)");
    flush();
    Card gmsh_card = card;
    for (Parameter& p : gmsh_card.parameters)
      if (p.key == "INPUT") p.value = path.string();
    files_.push_back(path.string());
    current_ = std::move(gmsh_card);
    has_current_ = true;
    flush();
    return;
  }
  for (const Parameter& p : card.parameters) {
    if (p.key != "INPUT") {
      throw InputError(here, "unknown parameter " + p.name + " (*INCLUDE takes INPUT=file)");
    }
  }
  if (input.empty()) {
    throw InputError(here, "INPUT=file is missing: give the file to include");
  }
  const fs::path path = directory / fs::path(input);
  std::error_code ec;
  std::ifstream in(path, std::ios::binary);
  if (!fs::is_regular_file(path, ec) || !in) {
    throw InputError(SourceLocation{files_[card.file], card.line, "*INCLUDE", "INPUT"},
                     "cannot open the included file '" + path.string() +
                         "' (paths are relative to the including file)");
  }
  const std::string canonical = fs::weakly_canonical(path, ec).string();
  for (const std::string& open : include_stack_) {
    if (open == canonical) {
      throw InputError(here, "'" + path.string() + "' includes itself (include cycle)");
    }
  }
  if (depth + 1 > kMaxIncludeDepth) {
    throw InputError(here,
                     "includes nested deeper than " + std::to_string(kMaxIncludeDepth) + " levels");
  }
  std::ostringstream text;
  text << in.rdbuf();
  files_.push_back(path.string());
  include_stack_.push_back(canonical);
  read_lines(text.str(), static_cast<std::uint32_t>(files_.size() - 1), path.parent_path(),
             depth + 1);
  include_stack_.pop_back();
}

}  // namespace abut::inp
