#include "deck_block.hpp"

namespace abut::deck {

Block::Block(std::string keyword, std::string file, std::size_t line, std::vector<Line> lines,
             const Parameters& parameters)
    : keyword_(std::move(keyword)),
      file_(std::move(file)),
      line_(line),
      lines_(std::move(lines)),
      parameters_(parameters) {}

SourceLocation Block::where() const { return {file_, line_, keyword_, ""}; }

SourceLocation Block::where(const Line& l) const { return {file_, l.number, keyword_, ""}; }

bool Block::next_is_title() const { return !done() && lines_[next_].text.front() == '"'; }

std::vector<std::string> Block::peek_fields() const {
  return done() ? std::vector<std::string>{} : split_fields(lines_[next_].text);
}

std::optional<std::string> Block::title() {
  if (!next_is_title()) return std::nullopt;
  const Line& l = lines_[next_++];
  if (!is_quoted(l.text))
    throw InputError(where(l), "a title line must be one quoted string, got " + l.text);
  return unquote(l.text);
}

Row Block::row(std::vector<std::string> names) {
  std::string list;
  for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
  if (done()) throw InputError(where(), "missing data line: expected " + list);
  const Line& l = lines_[next_++];
  if (l.text.front() == '"') {
    throw InputError(where(l), "unexpected title line " + l.text + ": expected " + list);
  }
  std::vector<std::string> fields = split_fields(l.text);
  for (auto& f : fields) {
    if (!is_quoted(f)) f = parameters_.substitute(f, where(l));
  }
  return Row(std::move(fields), where(l), std::move(names));
}

std::optional<Row> Block::optional_row(std::vector<std::string> names) {
  if (done() || next_is_title()) return std::nullopt;
  return row(std::move(names));
}

std::string Block::text_line(const std::string& what) {
  const Line l = raw_line(what);
  return parameters_.substitute(l.text, where(l), true);
}

Line Block::raw_line(const std::string& what) {
  if (done()) throw InputError(where(), "missing data line: expected " + what);
  return lines_[next_++];
}

SourceLocation Block::last_where() const { return next_ == 0 ? where() : where(lines_[next_ - 1]); }

void Block::finish() const {
  if (!done()) {
    const Line& l = lines_[next_];
    throw InputError(where(l), "unexpected extra line '" + l.text + "' (" + keyword_ +
                                   " takes no more data here)");
  }
}

}  // namespace abut::deck
