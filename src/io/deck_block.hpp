#pragma once
// The data lines of one keyword, read front to back by the keyword's reader.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "abut/core/error.hpp"
#include "deck_parameters.hpp"
#include "deck_text.hpp"

namespace abut::deck {

// One data line (not blank, not a comment), trimmed, with its 1-based line number.
struct Line {
  std::string text;
  std::size_t number = 0;
};

class Block {
 public:
  Block(std::string keyword, std::string file, std::size_t line, std::vector<Line> lines,
        const Parameters& parameters);

  const std::string& keyword() const { return keyword_; }  // "*NAME", upper case
  const std::string& file() const { return file_; }
  SourceLocation where() const;               // the keyword line
  SourceLocation where(const Line& l) const;  // a data line of this block

  bool done() const { return next_ >= lines_.size(); }
  bool next_is_title() const;
  // The next line split into raw fields (no substitution), for deciding what it is.
  std::vector<std::string> peek_fields() const;

  // Consumes a quoted title line if one comes next.
  std::optional<std::string> title();
  // Consumes the next line as a row; `what` describes it if the line is missing.
  Row row(std::vector<std::string> names);
  // Consumes the next line as a row if there is one and it is not a title.
  std::optional<Row> optional_row(std::vector<std::string> names);
  // Consumes the next line with %name and [expression] substituted, not split (expressions).
  std::string text_line(const std::string& what);
  // Consumes the next line as it is written.
  Line raw_line(const std::string& what);
  // The location of the line consumed last.
  SourceLocation last_where() const;
  // Every line must have been read.
  void finish() const;

 private:
  std::string keyword_, file_;
  std::size_t line_;
  std::vector<Line> lines_;
  std::size_t next_ = 0;
  const Parameters& parameters_;
};

}  // namespace abut::deck
