#pragma once
// A *FUNCTION expression compiled once into postfix code for a small fixed stack.
// expression_parser.cpp turns text into a Program; expression_eval.cpp runs it.
// Evaluation allocates nothing: it is called per contact point per step.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "abut/core/functions.hpp"

namespace abut::expression {

// The values of Variables an expression can load, by name (case-sensitive: x current, X initial).
struct VariableField {
  std::string_view name;
  double Variables::*member;
};
inline constexpr VariableField kVariableFields[] = {
    {"t", &Variables::t},         {"dt", &Variables::dt},       {"term", &Variables::term},
    {"x", &Variables::x},         {"y", &Variables::y},         {"z", &Variables::z},
    {"X", &Variables::X},         {"Y", &Variables::Y},         {"Z", &Variables::Z},
    {"vx", &Variables::vx},       {"vy", &Variables::vy},       {"vz", &Variables::vz},
    {"xnorm", &Variables::xnorm}, {"ynorm", &Variables::ynorm}, {"znorm", &Variables::znorm},
    {"pres", &Variables::pres},   {"vtang", &Variables::vtang}, {"T", &Variables::T},
    {"epsp", &Variables::epsp},   {"sigy0", &Variables::sigy0}, {"dmg", &Variables::dmg},
    {"eint", &Variables::eint},   {"wi", &Variables::wi},       {"we", &Variables::we},
    {"wk", &Variables::wk},       {"gap", &Variables::gap},
};

// clang-format off
enum class Op : std::uint8_t {
  // operands
  Constant,   // push value
  Load,       // push vars.*kVariableFields[slot].member
  LoadR,      // push sqrt(x^2 + y^2)
  LoadTheta,  // push atan2(y, x) in degrees
  // operators
  Negate, Add, Subtract, Multiply, Divide, Power,
  Equal, NotEqual, Less, LessEqual, Greater, GreaterEqual, And, Or,
  // one-argument intrinsics (trigonometry without suffix works in degrees)
  Sin, Cos, Tan, Asin, Acos, Atan, SinR, CosR, TanR, AsinR, AcosR, AtanR,
  Tanh, Exp, Log, Log10, Sqrt, Abs, Sign, Floor, Ceil, Round, Erf, Heaviside,
  // several arguments
  Mod, Kronecker,
  Min, Max,  // argc values
  // references to other entries of the FunctionTable (slot indexes Program::references)
  Curve,       // crv(cid, x): pops x
  Function,    // fcn(fid): pops nothing
  FunctionAt,  // fcn(fid, a): pops a, evaluates with t = a
};
// clang-format on

struct Instruction {
  Op op = Op::Constant;
  std::uint8_t argc = 0;  // Min, Max
  std::int32_t slot = 0;  // Load: index into kVariableFields; Curve/Function*: into references
  double value = 0.0;     // Constant
};

// A crv()/fcn() call; `target` is the FunctionTable index, filled by FunctionTable::resolve().
struct Reference {
  enum class Kind : std::uint8_t { Curve, Function };
  Kind kind = Kind::Function;
  std::int64_t id = 0;
  std::size_t column = 0;  // 1-based, for error messages
  std::int32_t target = -1;
};

// A name the expression reads (variables, R, theta), with the column of its first use.
struct NameUse {
  std::string name;
  std::size_t column = 0;
};

// The most values an expression may hold on the stack at once (checked when compiling).
inline constexpr int kMaxStack = 64;

struct Program {
  std::string text;
  std::vector<Instruction> code;
  std::vector<Reference> references;
  std::vector<NameUse> names;  // R and theta also list x and y, which they read
};

// Compiles `text`. Throws InputError without location on a syntax error or an unsupported
// name; the message contains the expression and the 1-based column of the fault.
Program compile(std::string_view text);

// Runs `program`. crv()/fcn() are evaluated through `table` (which must have been resolved);
// a program without references may pass nullptr.
double evaluate(const Program& program, const Variables& vars, const FunctionTable* table);

// "in '<text>' at column N: <message>" followed by the text and a caret under the fault.
std::string describe_at(std::string_view text, std::size_t column, const std::string& message);

}  // namespace abut::expression
