// Recursive-descent compiler for *FUNCTION expressions (IMPETUS keyword reference §8) into
// postfix code. Grammar, loosest binding first:
//
//   or         := and { "||" and }
//   and        := comparison { "&&" comparison }
//   comparison := sum { ("==" | "!=" | "<" | "<=" | ">" | ">=") sum }
//   sum        := product { ("+" | "-") product }
//   product    := unary { ("*" | "/") unary }
//   unary      := ("-" | "+") unary | power
//   power      := primary [ "^" unary ]          right-associative; -2^2 = -(2^2) = -4
//   primary    := number | name | name "(" [ or { "," or } ] ")" | "(" or ")"
//
// Subexpressions whose operands are all constants are folded while compiling.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <numbers>
#include <string>
#include <system_error>

#include "core/expression.hpp"

namespace abut::expression {
namespace {

// clang-format off
enum class Symbol {
  Number, Name, Plus, Minus, Star, Slash, Caret,
  Equal, NotEqual, Less, LessEqual, Greater, GreaterEqual, And, Or,
  LeftParen, RightParen, Comma, End,
};
// clang-format on

struct Token {
  Symbol symbol = Symbol::End;
  std::string_view text;
  std::size_t column = 0;  // 1-based
  double number = 0.0;
};

struct Intrinsic {
  std::string_view name;
  Op op;
  int min_args, max_args;
};
constexpr Intrinsic kIntrinsics[] = {
    {"sin", Op::Sin, 1, 1},     {"cos", Op::Cos, 1, 1},     {"tan", Op::Tan, 1, 1},
    {"asin", Op::Asin, 1, 1},   {"acos", Op::Acos, 1, 1},   {"atan", Op::Atan, 1, 1},
    {"sinr", Op::SinR, 1, 1},   {"cosr", Op::CosR, 1, 1},   {"tanr", Op::TanR, 1, 1},
    {"asinr", Op::AsinR, 1, 1}, {"acosr", Op::AcosR, 1, 1}, {"atanr", Op::AtanR, 1, 1},
    {"tanh", Op::Tanh, 1, 1},   {"exp", Op::Exp, 1, 1},     {"ln", Op::Log, 1, 1},
    {"log", Op::Log, 1, 1},     {"log10", Op::Log10, 1, 1}, {"sqrt", Op::Sqrt, 1, 1},
    {"abs", Op::Abs, 1, 1},     {"sign", Op::Sign, 1, 1},   {"floor", Op::Floor, 1, 1},
    {"ceil", Op::Ceil, 1, 1},   {"round", Op::Round, 1, 1}, {"erf", Op::Erf, 1, 1},
    {"H", Op::Heaviside, 1, 1}, {"mod", Op::Mod, 2, 2},     {"d", Op::Kronecker, 2, 2},
    {"min", Op::Min, 1, 10},    {"max", Op::Max, 1, 10},
};

// Names of the reference that abut does not evaluate yet: model feedback, statistics, tables,
// random numbers, and the smooth ramps whose exact definition we have not confirmed.
// clang-format off
constexpr std::string_view kNotSupported[] = {
    "xn", "yn", "zn", "vxn", "vyn", "vzn", "dxp", "dyp", "dzp", "vxp", "vyp", "vzp", "wkp",
    "mpp", "xs", "ps", "fxc", "fyc", "fzc", "fc", "fxr", "fyr", "fzr", "fr", "vol_geo",
    "table", "dfcn", "norminv", "lognorminv", "rnd", "smooth_d", "smooth_v", "smooth_a",
};
// clang-format on

constexpr int kMaxNesting = 100;  // parentheses and calls; bounds the parser's recursion

bool is_name_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool is_name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

const Intrinsic* find_intrinsic(std::string_view name) {
  for (const Intrinsic& f : kIntrinsics)
    if (f.name == name) return &f;
  return nullptr;
}
int find_variable(std::string_view name) {
  for (std::size_t i = 0; i < std::size(kVariableFields); ++i)
    if (kVariableFields[i].name == name) return static_cast<int>(i);
  return -1;
}
bool is_not_supported(std::string_view name) {
  return std::find(std::begin(kNotSupported), std::end(kNotSupported), name) !=
         std::end(kNotSupported);
}
bool is_pure(Op op) {
  return op != Op::Load && op != Op::LoadR && op != Op::LoadTheta && op != Op::Curve &&
         op != Op::Function && op != Op::FunctionAt;
}

std::string accepted_names() {
  std::string s = "values: pi R theta";
  for (const VariableField& v : kVariableFields) s += " " + std::string(v.name);
  s += "; functions:";
  for (const Intrinsic& f : kIntrinsics) s += " " + std::string(f.name) + "()";
  return s + " crv(cid, x) fcn(fid) fcn(fid, t)";
}

class Parser {
 public:
  explicit Parser(std::string_view text) : text_(text) { program_.text = std::string(text); }

  Program parse() {
    tokenize();
    if (peek().symbol == Symbol::End) fail(1, "the expression is empty");
    parse_or();
    if (peek().symbol != Symbol::End) {
      fail(peek().column, "unexpected '" + std::string(peek().text) +
                              "'; expected an operator or the end of the expression");
    }
    return std::move(program_);
  }

 private:
  [[noreturn]] void fail(std::size_t column, const std::string& message) const {
    throw InputError(describe_at(text_, column, message));
  }

  // ---- tokens ----

  void tokenize() {
    std::size_t i = 0;
    while (i < text_.size()) {
      const char c = text_[i];
      const std::size_t start = i;
      if (std::isspace(static_cast<unsigned char>(c))) {
        ++i;
        continue;
      }
      Token token{Symbol::End, {}, start + 1, 0.0};
      if (is_digit(c) || (c == '.' && i + 1 < text_.size() && is_digit(text_[i + 1]))) {
        i = scan_number(i, token);
      } else if (is_name_start(c)) {
        while (i < text_.size() && is_name_char(text_[i])) ++i;
        token.symbol = Symbol::Name;
      } else {
        i = scan_operator(i, token.symbol);
      }
      token.text = text_.substr(start, i - start);
      tokens_.push_back(token);
    }
    tokens_.push_back(Token{Symbol::End, "end of expression", text_.size() + 1, 0.0});
  }

  // digits [. digits] [(e|E) [+|-] digits], or . digits [exponent]
  std::size_t scan_number(std::size_t i, Token& token) const {
    const std::size_t start = i;
    while (i < text_.size() && is_digit(text_[i])) ++i;
    if (i < text_.size() && text_[i] == '.') ++i;
    while (i < text_.size() && is_digit(text_[i])) ++i;
    if (i < text_.size() && (text_[i] == 'e' || text_[i] == 'E')) {
      std::size_t j = i + 1;
      if (j < text_.size() && (text_[j] == '+' || text_[j] == '-')) ++j;
      if (j >= text_.size() || !is_digit(text_[j])) {
        fail(i + 1, "the exponent of a number needs digits (e.g. 3.0e9)");
      }
      while (j < text_.size() && is_digit(text_[j])) ++j;
      i = j;
    }
    if (i < text_.size() && (is_name_char(text_[i]) || text_[i] == '.')) {
      fail(i + 1, "unexpected '" + std::string(1, text_[i]) +
                      "' after a number; write an operator between them (e.g. 2*x)");
    }
    const auto [end, error] = std::from_chars(text_.data() + start, text_.data() + i, token.number);
    if (error == std::errc::result_out_of_range) {
      fail(start + 1, "the number '" + std::string(text_.substr(start, i - start)) +
                          "' is out of the range of double precision");
    }
    if (error != std::errc() || end != text_.data() + i) fail(start + 1, "malformed number");
    token.symbol = Symbol::Number;
    return i;
  }

  std::size_t scan_operator(std::size_t i, Symbol& symbol) const {
    const char c = text_[i];
    const char next = i + 1 < text_.size() ? text_[i + 1] : '\0';
    // clang-format off
    auto two = [&](Symbol s) { symbol = s; return i + 2; };
    auto one = [&](Symbol s) { symbol = s; return i + 1; };
    switch (c) {
      case '+': return one(Symbol::Plus);
      case '-': return one(Symbol::Minus);
      case '*': return one(Symbol::Star);
      case '/': return one(Symbol::Slash);
      case '^': return one(Symbol::Caret);
      case '(': return one(Symbol::LeftParen);
      case ')': return one(Symbol::RightParen);
      case ',': return one(Symbol::Comma);
      case '<': return next == '=' ? two(Symbol::LessEqual) : one(Symbol::Less);
      case '>': return next == '=' ? two(Symbol::GreaterEqual) : one(Symbol::Greater);
      case '=':
        if (next == '=') return two(Symbol::Equal);
        fail(i + 1, "'=' is not an operator; compare with '=='");
      case '!':
        if (next == '=') return two(Symbol::NotEqual);
        fail(i + 1, "'!' is not an operator; use '!=' to compare or '== 0' to negate");
      case '&':
        if (next == '&') return two(Symbol::And);
        fail(i + 1, "'&' is not an operator; the logical and is '&&'");
      case '|':
        if (next == '|') return two(Symbol::Or);
        fail(i + 1, "'|' is not an operator; the logical or is '||'");
      case '%':
        fail(i + 1, "parameter '%...' was not substituted; parameters are replaced before the "
                    "expression is compiled");
      default:
        fail(i + 1, "unexpected character '" + std::string(1, c) + "'");
    }
    // clang-format on
  }

  const Token& peek() const { return tokens_[next_]; }
  const Token& take() { return tokens_[next_++]; }
  bool accept(Symbol s) {
    if (peek().symbol != s) return false;
    ++next_;
    return true;
  }
  void expect(Symbol s, std::string_view what) {
    if (accept(s)) return;
    fail(peek().column,
         "expected " + std::string(what) + " but found '" + std::string(peek().text) + "'");
  }

  // ---- code generation ----

  // Appends `in`, which pops `operands` values and pushes one. Pure operations on constants
  // are run now (by the evaluator itself) and replaced by their value.
  void emit(Instruction in, int operands, std::size_t column) {
    std::vector<Instruction>& code = program_.code;
    const auto n = static_cast<std::size_t>(operands);
    const bool on_constants =
        operands > 0 && is_pure(in.op) &&
        std::all_of(code.end() - static_cast<std::ptrdiff_t>(n), code.end(),
                    [](const Instruction& c) { return c.op == Op::Constant; });
    if (on_constants) {
      Program folded;
      folded.code.assign(code.end() - static_cast<std::ptrdiff_t>(n), code.end());
      folded.code.push_back(in);
      const double value = evaluate(folded, Variables{}, nullptr);
      code.resize(code.size() - n);
      in = Instruction{Op::Constant, 0, 0, value};
    }
    code.push_back(in);
    depth_ += 1 - operands;
    if (depth_ > kMaxStack) {
      fail(column, "the expression needs more than " + std::to_string(kMaxStack) +
                       " intermediate values; split it into several *FUNCTIONs");
    }
  }

  void emit_binary(Op op, std::size_t column) { emit(Instruction{op, 0, 0, 0.0}, 2, column); }

  void note_name(std::string_view name, std::size_t column) {
    for (const NameUse& use : program_.names)
      if (use.name == name) return;
    program_.names.push_back(NameUse{std::string(name), column});
  }

  // ---- grammar ----

  void parse_or() {
    parse_and();
    while (peek().symbol == Symbol::Or) {
      const std::size_t column = take().column;
      parse_and();
      emit_binary(Op::Or, column);
    }
  }

  void parse_and() {
    parse_comparison();
    while (peek().symbol == Symbol::And) {
      const std::size_t column = take().column;
      parse_comparison();
      emit_binary(Op::And, column);
    }
  }

  void parse_comparison() {
    parse_sum();
    for (;;) {
      Op op;
      // clang-format off
      switch (peek().symbol) {
        case Symbol::Equal: op = Op::Equal; break;
        case Symbol::NotEqual: op = Op::NotEqual; break;
        case Symbol::Less: op = Op::Less; break;
        case Symbol::LessEqual: op = Op::LessEqual; break;
        case Symbol::Greater: op = Op::Greater; break;
        case Symbol::GreaterEqual: op = Op::GreaterEqual; break;
        default: return;
      }
      // clang-format on
      const std::size_t column = take().column;
      parse_sum();
      emit_binary(op, column);
    }
  }

  void parse_sum() {
    parse_product();
    while (peek().symbol == Symbol::Plus || peek().symbol == Symbol::Minus) {
      const Token& token = take();
      parse_product();
      emit_binary(token.symbol == Symbol::Plus ? Op::Add : Op::Subtract, token.column);
    }
  }

  void parse_product() {
    parse_unary();
    while (peek().symbol == Symbol::Star || peek().symbol == Symbol::Slash) {
      const Token& token = take();
      parse_unary();
      emit_binary(token.symbol == Symbol::Star ? Op::Multiply : Op::Divide, token.column);
    }
  }

  void parse_unary() {
    if (peek().symbol == Symbol::Minus || peek().symbol == Symbol::Plus) {
      const Token& token = take();
      enter(token.column);
      parse_unary();
      --nesting_;
      if (token.symbol == Symbol::Minus) emit(Instruction{Op::Negate, 0, 0, 0.0}, 1, token.column);
      return;
    }
    parse_power();
  }

  void parse_power() {
    parse_primary();
    if (peek().symbol == Symbol::Caret) {
      const std::size_t column = take().column;
      enter(column);
      parse_unary();  // the exponent may carry a sign and is itself a power: 2^3^2 = 2^9
      --nesting_;
      emit_binary(Op::Power, column);
    }
  }

  void enter(std::size_t column) {
    if (++nesting_ > kMaxNesting) {
      fail(column,
           "the expression is nested more than " + std::to_string(kMaxNesting) + " levels deep");
    }
  }

  void parse_primary() {
    const Token& token = take();
    switch (token.symbol) {
      case Symbol::Number:
        emit(Instruction{Op::Constant, 0, 0, token.number}, 0, token.column);
        return;
      case Symbol::LeftParen:
        enter(token.column);
        parse_or();
        expect(Symbol::RightParen, "')' closing the '(' at column " + std::to_string(token.column));
        --nesting_;
        return;
      case Symbol::Name:
        if (peek().symbol == Symbol::LeftParen) {
          parse_call(token);
        } else {
          parse_value(token);
        }
        return;
      case Symbol::End:
        fail(token.column, "the expression ends where a number, a name or '(' is expected");
      default:
        fail(token.column,
             "expected a number, a name or '(' but found '" + std::string(token.text) + "'");
    }
  }

  void parse_value(const Token& token) {
    const std::string_view name = token.text;
    if (name == "pi") {
      emit(Instruction{Op::Constant, 0, 0, std::numbers::pi}, 0, token.column);
    } else if (const int field = find_variable(name); field >= 0) {
      note_name(name, token.column);
      emit(Instruction{Op::Load, 0, field, 0.0}, 0, token.column);
    } else if (name == "R" || name == "theta") {
      note_name(name, token.column);
      note_name("x", token.column);
      note_name("y", token.column);
      emit(Instruction{name == "R" ? Op::LoadR : Op::LoadTheta, 0, 0, 0.0}, 0, token.column);
    } else if (is_not_supported(name)) {
      fail(token.column, "'" + std::string(name) + "' is not supported yet");
    } else if (find_intrinsic(name) != nullptr || name == "crv" || name == "fcn") {
      fail(token.column,
           "'" + std::string(name) + "' is a function; write " + std::string(name) + "(...)");
    } else {
      unknown_name(token);
    }
  }

  void parse_call(const Token& name_token) {
    const std::string_view name = name_token.text;
    if (is_not_supported(name)) {
      fail(name_token.column, "'" + std::string(name) + "' is not supported yet");
    }
    if (name == "crv" || name == "fcn") return parse_reference(name_token);
    const Intrinsic* f = find_intrinsic(name);
    if (f == nullptr) {
      if (name == "pi" || name == "R" || name == "theta" || find_variable(name) >= 0) {
        fail(name_token.column, "'" + std::string(name) + "' is a value, not a function");
      }
      unknown_name(name_token);
    }
    take();  // '('
    enter(name_token.column);
    int count = 0;
    if (peek().symbol != Symbol::RightParen) {
      do {
        parse_or();
        ++count;
      } while (accept(Symbol::Comma));
    }
    expect(Symbol::RightParen, "',' or ')' in the arguments of " + std::string(name) + "()");
    --nesting_;
    if (count < f->min_args || count > f->max_args) {
      const std::string wanted = f->min_args == f->max_args ? std::to_string(f->min_args)
                                                            : std::to_string(f->min_args) + " to " +
                                                                  std::to_string(f->max_args);
      fail(name_token.column, std::string(name) + "() takes " + wanted + " argument" +
                                  (f->max_args == 1 ? "" : "s") + ", not " + std::to_string(count));
    }
    emit(Instruction{f->op, static_cast<std::uint8_t>(count), 0, 0.0}, count, name_token.column);
  }

  // crv(cid, x), fcn(fid), fcn(fid, a): the id is a literal positive integer.
  void parse_reference(const Token& name_token) {
    const bool curve = name_token.text == "crv";
    take();  // '('
    enter(name_token.column);
    const Token& id_token = take();
    const double id = id_token.number;
    if (id_token.symbol != Symbol::Number || id < 1.0 || id != std::floor(id) || id > 9e15) {
      fail(id_token.column, std::string(name_token.text) + "() needs the id of a " +
                                (curve ? "*CURVE" : "*FUNCTION") +
                                " (a positive integer) as its first argument");
    }
    const auto slot = static_cast<std::int32_t>(program_.references.size());
    program_.references.push_back(
        Reference{curve ? Reference::Kind::Curve : Reference::Kind::Function,
                  static_cast<std::int64_t>(id), name_token.column, -1});
    int operands = 0;
    if (accept(Symbol::Comma)) {
      parse_or();
      operands = 1;
    } else if (curve) {
      fail(peek().column, "crv() takes two arguments: crv(cid, x)");
    }
    expect(Symbol::RightParen, curve ? "')' closing crv(cid, x)" : "')' closing fcn(fid[, t])");
    --nesting_;
    const Op op = curve ? Op::Curve : (operands == 1 ? Op::FunctionAt : Op::Function);
    emit(Instruction{op, 0, slot, 0.0}, operands, name_token.column);
  }

  [[noreturn]] void unknown_name(const Token& token) const {
    std::string hint;
    std::string lower(token.text);
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    for (std::string_view known : {std::string_view("pi"), std::string_view("theta")})
      if (lower == known && token.text != known) hint = known;
    for (const VariableField& v : kVariableFields)
      if (lower == v.name && token.text != v.name) hint = v.name;
    for (const Intrinsic& f : kIntrinsics)
      if (lower == f.name && token.text != f.name) hint = f.name;
    if (!hint.empty()) hint = " (names are case-sensitive: did you mean '" + hint + "'?)";
    fail(token.column, "unknown name '" + std::string(token.text) + "'" + hint + "; accepted " +
                           accepted_names());
  }

  std::string_view text_;
  std::vector<Token> tokens_;
  std::size_t next_ = 0;
  Program program_;
  int depth_ = 0;    // values on the stack after the code emitted so far
  int nesting_ = 0;  // open parentheses, calls, signs and exponents
};

}  // namespace

Program compile(std::string_view text) { return Parser(text).parse(); }

std::string describe_at(std::string_view text, std::size_t column, const std::string& message) {
  std::string caret = "  ";
  for (std::size_t i = 0; i + 1 < column && i < text.size(); ++i) {
    caret += text[i] == '\t' ? '\t' : ' ';  // keeps the caret aligned under tabs
  }
  return "in '" + std::string(text) + "' at column " + std::to_string(column) + ": " + message +
         "\n  " + std::string(text) + "\n" + caret + "^";
}

}  // namespace abut::expression
