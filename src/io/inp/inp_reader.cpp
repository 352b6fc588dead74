// Reading an Abaqus/CalculiX input file: the entry points, the dispatch of each card to its
// keyword's reader (with the checks of where a keyword may stand), and the helpers the keyword
// readers share for parameters and data fields.
#include "inp_reader.hpp"

#include <cctype>

#include "../deck_text.hpp"

namespace abut::inp {

std::string upper_name(std::string_view name) { return deck::upper(deck::trim(name)); }

SourceLocation Reader::where(const Card& c, const std::string& field) const {
  return {files_[c.file], c.line, c.keyword, field};
}

SourceLocation Reader::where(Loc at, const std::string& keyword, const std::string& field) const {
  return {files_[at.file], at.line, keyword, field};
}

std::string Reader::at(Loc l) const { return files_[l.file] + ":" + std::to_string(l.line); }

void Reader::note(const Card& c, const std::string& message) {
  notes.push_back(at(loc(c)) + ": " + message);
}

std::uint32_t Reader::file_index(const std::string& name) const {
  for (std::size_t k = files_.size(); k-- > 0;)
    if (files_[k] == name) return static_cast<std::uint32_t>(k);
  return 0;
}

IdSet& Reader::node_set(const std::string& name, Loc at) {
  const auto [it, inserted] = node_set_names.emplace(upper_name(name), node_sets.size());
  if (inserted) node_sets.push_back({name, {}, {}, at, {}, 0});
  return node_sets[it->second];
}

IdSet& Reader::element_set(const std::string& name, Loc at) {
  const auto [it, inserted] = element_set_names.emplace(upper_name(name), element_sets.size());
  if (inserted) element_sets.push_back({name, {}, {}, at, {}, 0});
  return element_sets[it->second];
}

void Reader::read(const Card& c) {
  // Messages that start with the keyword name the line only.
  const SourceLocation line{files_[c.file], c.line, "", ""};
  last_card = loc(c);
  if (change_friction && c.key != "*FRICTION") {
    throw InputError(where(step().changes.back().where, "*CHANGE FRICTION"),
                     "*CHANGE FRICTION must be followed by a *FRICTION card with the new friction "
                     "coefficient and stick slope (found " +
                         c.keyword + " at " + at(loc(c)) + ")");
  }
  if (change_behaviour && c.key != "*SURFACEBEHAVIOR") {
    throw InputError(where(step().changes.back().where, "*CHANGE SURFACE BEHAVIOR"),
                     "*CHANGE SURFACE BEHAVIOR must be followed by a *SURFACE BEHAVIOR card with "
                     "the new pressure-overclosure law (found " +
                         c.keyword + " at " + at(loc(c)) + ")");
  }
  if (c.key == "*STEP" && in_step) {
    throw InputError(line, "a new *STEP inside the step of " + at(step().where) +
                               ": close that step with *END STEP first");
  }
  const KeywordEntry* entry = find_keyword(c.key);
  if (!entry) {
    material.reset();
    interaction.reset();
    if (const auto why = output_only_keyword(c.key)) {
      note(c, c.keyword + " " + std::string(*why));
      return;
    }
    if (const auto why = unsupported_keyword(c.key)) {
      throw InputError(line, c.keyword + " " + std::string(*why));
    }
    std::string message = "unknown keyword " + c.keyword;
    const std::vector<std::string> close = closest_keywords(c.key);
    for (std::size_t i = 0; i < close.size(); ++i)
      message += (i == 0 ? "; did you mean " : i + 1 == close.size() ? " or " : ", ") + close[i];
    message += close.empty() ? " (docs/inp-reference.md lists the keywords abut reads)" : "?";
    throw InputError(line, message);
  }
  if (entry->family == Family::Material && !material) {
    throw InputError(line, c.keyword +
                               " defines a property of a material: put it right after the "
                               "*MATERIAL card (or after another property of that material)");
  }
  const bool new_friction = c.key == "*FRICTION" && change_friction;
  const bool new_behaviour = c.key == "*SURFACEBEHAVIOR" && change_behaviour;
  if (entry->family == Family::Interaction && !interaction && !new_friction && !new_behaviour) {
    throw InputError(
        line, c.keyword +
                  " defines a property of a surface interaction: put it right "
                  "after the *SURFACE INTERACTION card" +
                  (c.key == "*FRICTION" ? std::string(" (or, in a step, after *CHANGE FRICTION)")
                   : c.key == "*SURFACEBEHAVIOR"
                       ? std::string(" (or, in a step, after *CHANGE SURFACE BEHAVIOR)")
                       : std::string()));
  }
  if (entry->family != Family::Material) material.reset();
  if (entry->family != Family::Interaction) interaction.reset();
  if (entry->scope == Scope::Model && in_step) {
    throw InputError(line, c.keyword +
                               " is model data: put it before the first *STEP (found inside "
                               "the step of " +
                               at(step().where) + ")");
  }
  if (entry->scope == Scope::Step && !in_step) {
    throw InputError(line, c.keyword + " belongs to a step: put it between *STEP and *END STEP");
  }
  entry->reader(*this, c);
}

// ---- parameters ----

const Parameter* find_parameter(const Card& c, std::string_view name) {
  const std::string key = lookup_key(name);
  for (const Parameter& p : c.parameters)
    if (p.key == key) return &p;
  return nullptr;
}

std::optional<std::string> parameter_value(const Card& c, std::string_view key) {
  const Parameter* p = find_parameter(c, key);
  if (!p || !p->has_value) return std::nullopt;
  return p->value;
}

bool has_parameter(const Card& c, std::string_view key) { return find_parameter(c, key); }

std::string required_parameter(const Reader& r, const Card& c, std::string_view key) {
  const Parameter* p = find_parameter(c, key);
  if (!p) {
    throw InputError(r.where(c),
                     "the parameter " + std::string(key) + "= is missing: it is required");
  }
  return p->value;
}

void check_parameters(Reader& r, const Card& c, std::span<const ParameterRule> rules) {
  using Kind = ParameterRule::Kind;
  for (const Parameter& p : c.parameters) {
    const ParameterRule* rule = nullptr;
    for (const ParameterRule& candidate : rules)
      if (lookup_key(candidate.name) == p.key) rule = &candidate;
    if (!rule) {
      std::string accepted;
      for (const ParameterRule& candidate : rules) {
        if (candidate.kind == Kind::Unsupported || candidate.kind == Kind::Ignored) continue;
        accepted += (accepted.empty() ? "" : ", ") + std::string(candidate.name);
      }
      throw InputError(r.where(c, p.name), "unknown parameter " + p.name + " of " + c.keyword +
                                               (accepted.empty() ? " (it takes no parameters)"
                                                                 : " (it takes " + accepted + ")"));
    }
    switch (rule->kind) {
      case Kind::Value:
        if (!p.has_value || p.value.empty()) {
          throw InputError(r.where(c, p.name), "the parameter needs a value: " + p.name + "=...");
        }
        break;
      case Kind::Flag:
        if (p.has_value) {
          throw InputError(r.where(c, p.name),
                           "the parameter takes no value: write " + p.name + " alone");
        }
        break;
      case Kind::FlagOrValue:
        break;
      case Kind::Unsupported:
        throw InputError(r.where(c, p.name),
                         "the parameter " + p.name + " is not supported yet by abut" +
                             (rule->why.empty() ? "" : ": " + std::string(rule->why)));
      case Kind::Ignored:
        r.note(c, "parameter " + p.name + " of " + c.keyword + " " + std::string(rule->why));
        break;
    }
  }
}

std::string parameter_choice(const Reader& r, const Card& c, std::string_view key,
                             std::initializer_list<std::string_view> choices,
                             std::string_view fallback) {
  const Parameter* p = find_parameter(c, key);
  if (!p) return std::string(fallback);
  const std::string value = lookup_key(p->value);
  std::string expected;
  for (const std::string_view choice : choices) {
    if (lookup_key(choice) == value) return std::string(choice);
    expected += (expected.empty() ? "" : ", ") + std::string(choice);
  }
  throw InputError(r.where(c, p->name),
                   "expected " + p->name + "= one of " + expected + ", got '" + p->value + "'");
}

void no_data(const Reader& r, const Card& c, const std::string& why) {
  if (c.data.empty()) return;
  const DataLine& l = c.data.front();
  throw InputError(r.where(Reader::loc(l), c.keyword), "unexpected data line '" + l.text +
                                                           "': " + c.keyword + " takes none" +
                                                           (why.empty() ? "" : " (" + why + ")"));
}

// ---- data fields ----

std::optional<double> inp_number(std::string_view text) {
  if (const auto v = deck::parse_number(text)) return v;
  std::string t(text);
  bool fortran = false;
  for (char& ch : t) {
    if (ch == 'd' || ch == 'D') {
      ch = 'e';
      fortran = true;
    }
  }
  return fortran ? deck::parse_number(t) : std::nullopt;
}

Fields::Fields(const Reader& r, const Card& c, const DataLine& l)
    : reader_(r), card_(c), line_(l), fields_(deck::split_fields(l.text)) {}

const std::string& Fields::text(std::size_t i) const {
  static const std::string empty;
  return i < fields_.size() ? fields_[i] : empty;
}

SourceLocation Fields::where(const std::string& field) const {
  return reader_.where(loc(), card_.keyword, field);
}

void Fields::fail(const std::string& field, const std::string& message) const {
  throw InputError(where(field), message);
}

double Fields::number(std::size_t i, const std::string& field) const {
  if (!given(i)) fail(field, "a number is missing here (line '" + line_.text + "')");
  const auto v = inp_number(text(i));
  if (!v) fail(field, "expected a number, got '" + text(i) + "'");
  return *v;
}

double Fields::number_or(std::size_t i, const std::string& field, double fallback) const {
  return given(i) ? number(i, field) : fallback;
}

std::int64_t Fields::integer(std::size_t i, const std::string& field) const {
  if (!given(i)) fail(field, "an integer is missing here (line '" + line_.text + "')");
  const auto v = deck::parse_integer(text(i));
  if (!v) fail(field, "expected an integer, got '" + text(i) + "'");
  return *v;
}

Item Fields::item(std::size_t i, const std::string& field) const {
  if (!given(i)) fail(field, "a number or a set name is missing here (line '" + line_.text + "')");
  Item item;
  item.where = loc();
  const std::string& t = text(i);
  if (const auto id = deck::parse_integer(t)) {
    if (*id <= 0) fail(field, "expected a positive number, got '" + t + "'");
    item.id = *id;
    return item;
  }
  const unsigned char first = static_cast<unsigned char>(t.front());
  if (std::isdigit(first) || first == '-' || first == '+' || first == '.') {
    fail(field, "expected a positive integer or a set name, got '" + t + "'");
  }
  item.name = deck::unquote(t);
  return item;
}

void Fields::at_most(std::size_t n, const std::string& what) const {
  for (std::size_t i = n; i < fields_.size(); ++i) {
    if (!fields_[i].empty()) {
      fail("", "too many fields on the line '" + line_.text + "': expected " + what);
    }
  }
}

}  // namespace abut::inp

namespace abut {

namespace {

template <class Read>
DeckResult read_inp(const std::string& deck_path, Read&& read) {
  inp::Reader* reader_ptr = nullptr;
  inp::InpLines lines([&reader_ptr](inp::Card& c) { reader_ptr->read(c); });
  inp::Reader reader(lines.files());
  reader_ptr = &reader;
  reader.model.deck_path = deck_path;
  read(lines);
  return reader.finish();
}

}  // namespace

DeckResult read_inp_with_notes(const std::string& path) {
  return read_inp(path, [&](inp::InpLines& lines) { lines.read_file(path); });
}

DeckResult read_inp_string_with_notes(const std::string& text, const std::string& name) {
  return read_inp(name, [&](inp::InpLines& lines) { lines.read_text(text, name, {}); });
}

}  // namespace abut
