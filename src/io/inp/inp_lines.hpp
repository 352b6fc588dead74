#pragma once
// The lines of an Abaqus/CalculiX input file (.inp) grouped into cards: a keyword line
// `*NAME, PARAM=VALUE, FLAG, ...` (continued on the next line when it ends with a comma) and the
// data lines that follow it. `**` starts a comment line; blank lines are ignored. *INCLUDE,
// INPUT=file is replaced by the lines of the file (relative to the including file), so that an
// included file may hold the data lines of the keyword before it, as Abaqus allows.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "abut/core/error.hpp"

namespace abut::inp {

// Keywords and parameter names compare in upper case with blanks removed ("*NODE PRINT",
// "*node print" and "*NODEPRINT" are one keyword; "SMALL SLIDING" and "SMALLSLIDING" one
// parameter); `display` keeps single blanks for messages.
std::string lookup_key(std::string_view name);
std::string display_name(std::string_view name);

struct Parameter {
  std::string name;   // display form, upper case
  std::string key;    // lookup_key(name)
  std::string value;  // as written, trimmed, without enclosing double quotes
  bool has_value = false;
};

struct DataLine {
  std::string text;  // trimmed
  std::uint32_t file = 0;
  std::uint32_t line = 0;
};

struct Card {
  std::string keyword;  // display form: "*NODE PRINT"
  std::string key;      // lookup_key(keyword): "*NODEPRINT"
  std::vector<Parameter> parameters;
  std::uint32_t file = 0;  // index into InpLines::files()
  std::uint32_t line = 0;
  std::vector<DataLine> data;
};

class InpLines {
 public:
  using Handler = std::function<void(Card&)>;
  explicit InpLines(Handler handler) : handler_(std::move(handler)) {}

  // Reads a file or a text (`name` stands for the file in messages; *INCLUDE paths are relative
  // to `directory`) and hands every card to the handler, in order. Throws InputError.
  void read_file(const std::filesystem::path& path);
  void read_text(const std::string& text, const std::string& name,
                 const std::filesystem::path& directory);

  const std::vector<std::string>& files() const { return files_; }

 private:
  void read_lines(const std::string& text, std::uint32_t file,
                  const std::filesystem::path& directory, int depth);
  void include(const Card& card, const std::filesystem::path& directory, int depth);
  void flush();

  Handler handler_;
  std::vector<std::string> files_;
  std::vector<std::string> include_stack_;  // canonical paths of the files being read
  Card current_;
  bool has_current_ = false;
};

// Splits a keyword line (without continuation) into its card: keyword and parameters.
Card parse_keyword_line(std::string_view text, std::uint32_t file, std::uint32_t line,
                        const std::string& file_name);

}  // namespace abut::inp
