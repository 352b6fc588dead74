// *CURVE, *FUNCTION.
#include <cctype>
#include <charconv>
#include <limits>

#include "deck_reader.hpp"

namespace abut::deck {
namespace {

bool is_one_of(const std::string& word, std::initializer_list<const char*> options) {
  for (const char* o : options) {
    if (word == o) return true;
  }
  return false;
}

// Curve and function types serve unit conversion in IMPETUS; abut checks the word only.
void check_type(const Row& r, std::size_t i, bool abscissa_of_function) {
  if (!r.given(i)) return;
  const std::string t = r.word(i);
  if (abscissa_of_function) {
    r.require(is_one_of(t, {"TIME", "STRAIN", "NONE"}), i, "expected time, strain or none");
    return;
  }
  r.require(is_one_of(t, {"TIME", "LENGTH", "DISP", "VELO", "ACC", "FORCE", "STRESS", "STRAIN",
                          "PRESSURE", "TEMP", "ENERGY", "NONE"}),
            i,
            "expected time, length, disp, velo, acc, force, stress, strain, pressure, temp, energy "
            "or none");
}

// Adds the include's id offset to the literal ids of crv(cid, ...), fcn(fid, ...) and dfcn(fid).
std::string offset_references(const std::string& expression, std::int64_t offset,
                              const SourceLocation& where) {
  if (offset == 0) return expression;
  std::string out;
  std::size_t i = 0;
  while (i < expression.size()) {
    const bool word_start =
        i == 0 || (std::isalnum(static_cast<unsigned char>(expression[i - 1])) == 0 &&
                   expression[i - 1] != '_');
    std::size_t name_end = i;
    while (name_end < expression.size() &&
           std::isalpha(static_cast<unsigned char>(expression[name_end])) != 0) {
      ++name_end;
    }
    const std::string name = upper(expression.substr(i, name_end - i));
    if (word_start && (name == "CRV" || name == "FCN" || name == "DFCN")) {
      std::size_t j = name_end;
      while (j < expression.size() && expression[j] == ' ') ++j;
      if (j < expression.size() && expression[j] == '(') {
        std::size_t k = j + 1;
        while (k < expression.size() && expression[k] == ' ') ++k;
        std::size_t digits_end = k;
        while (digits_end < expression.size() &&
               std::isdigit(static_cast<unsigned char>(expression[digits_end])) != 0) {
          ++digits_end;
        }
        if (digits_end > k) {
          out += expression.substr(i, k - i);
          // An id too long for 64 bits, or pushed past them by the offset, would wrap.
          std::int64_t id = 0, shifted = 0;
          const char* first = expression.data() + k;
          const char* last = expression.data() + digits_end;
          const auto [ptr, ec] = std::from_chars(first, last, id);
          if (ec != std::errc() || ptr != last || __builtin_add_overflow(id, offset, &shifted))
            throw InputError(where, "the id " + expression.substr(k, digits_end - k) +
                                        " plus the *INCLUDE id offset " + std::to_string(offset) +
                                        " exceeds the largest id " +
                                        std::to_string(std::numeric_limits<std::int64_t>::max()));
          out += std::to_string(shifted);
          i = digits_end;
          continue;
        }
      }
    }
    if (name_end > i) {
      out += expression.substr(i, name_end - i);
      i = name_end;
    } else {
      out += expression[i++];
    }
  }
  return out;
}

}  // namespace

void read_curve(DeckReader& d, Block& b) {
  b.title();
  const Row head = b.row({"cid", "sf_x", "sf_y", "type_x", "type_y"});
  const std::int64_t id = d.other_id(head, 0);
  const double sf_x = head.number_or(1, 1.0);
  head.require(sf_x > 0.0, 1, "expected a scale factor > 0");
  const double sf_y = head.number_or(2, 1.0);
  check_type(head, 3, false);
  check_type(head, 4, false);
  Curve curve;
  if (b.done())
    throw InputError(b.where(), "missing data line: expected the first x, y point of the curve");
  while (!b.done()) {
    const Row p = b.row({"x", "y"});
    const double x = sf_x * p.number(0);
    if (!curve.x.empty())
      p.require(x > curve.x.back(), 0, "expected abscissas in strictly increasing order");
    curve.x.push_back(x);
    curve.y.push_back(sf_y * p.number(1));
  }
  d.model.functions.add_curve(id, std::move(curve), head.where(0));
}

void read_function(DeckReader& d, Block& b) {
  b.title();
  const Row head = b.row({"fid", "derivative", "f0", "fdot0", "type_x", "type_y"});
  const std::int64_t id = d.other_id(head, 0);
  const std::int64_t derivative = head.integer_or(1, 0);
  head.require(derivative >= 0 && derivative <= 2, 1, "expected 0, 1 or 2");
  if (derivative > 0)
    head.fail(1,
              "functions given by their derivative (derivative > 0) are not supported yet by abut");
  for (std::size_t i : {2, 3}) {
    head.require(!head.given(i) || parse_number(head.text(i)) == 0.0, i,
                 "initial values apply only when derivative > 0: leave the field empty");
  }
  check_type(head, 4, true);
  check_type(head, 5, false);
  const std::string text = b.text_line("the expression");
  SourceLocation where = b.last_where();
  where.field = "expression";
  const std::string expression = offset_references(text, d.frame().offsets.other, where);
  if (trim(expression).empty()) throw InputError(where, "empty expression");
  d.model.functions.add_function(id, expression, where);
}

}  // namespace abut::deck
