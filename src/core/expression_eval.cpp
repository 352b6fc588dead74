// Runs a compiled expression on a fixed stack. The parser folds constant subexpressions by
// running this same code, so folded and run-time results are bitwise identical.
//
// Conventions (documented for deck authors in functions.hpp):
// - sin cos tan take degrees, asin acos atan return degrees; the *r variants use radians.
// - theta = atan2(y, x) in degrees, in (-180, 180]; R = sqrt(x^2 + y^2).
// - Comparisons and && || give 1 or 0; any nonzero operand counts as true.
// - H(x) = 1 for x >= 0, else 0 (so H(0) = 1). sign(x) is -1, 0 or 1. d(i, j) = 1 if i == j.
// - mod(a, b) = a - b*trunc(a/b) (std::fmod: the result has the sign of a, as Fortran MOD).
// - round() rounds halves away from zero (std::round).
// - NaN propagates through every operation, including comparisons, logicals, H, sign, d, min
//   and max, so a bad input reaches the solver's NaN check instead of turning into 0 or 1.
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "core/expression.hpp"

namespace abut::expression {
namespace {

constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;
constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;

// 1 or 0 for a predicate of a and b, NaN if either is NaN.
double truth(bool predicate, double a, double b) {
  if (std::isnan(a) || std::isnan(b)) return std::nan("");
  return predicate ? 1.0 : 0.0;
}

double sign(double a) { return a > 0.0 ? 1.0 : (a < 0.0 ? -1.0 : a * 0.0); }
double heaviside(double a) { return a >= 0.0 ? 1.0 : (a < 0.0 ? 0.0 : a); }
double minimum(double a, double b) { return (a < b || std::isnan(a)) ? a : b; }
double maximum(double a, double b) { return (a > b || std::isnan(a)) ? a : b; }

// crv()/fcn() need the table and a target set by FunctionTable::resolve().
[[noreturn]] void unresolved(const Program& program) {
  throw std::logic_error("expression '" + program.text +
                         "' evaluated before FunctionTable::resolve()");
}
const FunctionTable* table_of(const Program& program, const FunctionTable* table) {
  if (table == nullptr) unresolved(program);
  return table;
}
FunctionRef target_of(const Program& program, const Instruction& in) {
  const FunctionRef ref{program.references[static_cast<std::size_t>(in.slot)].target};
  if (!ref.valid()) unresolved(program);
  return ref;
}

}  // namespace

double evaluate(const Program& program, const Variables& vars, const FunctionTable* table) {
  // The topmost value lives in `top` (a register); the ones under it in `below`. The first
  // push parks the initial 0 in below[0], so a program of depth d uses d slots.
  double below[kMaxStack];
  int n = 0;
  double top = 0.0;
  const auto push = [&](double value) {
    below[n++] = top;
    top = value;
  };
  const auto pop = [&] { return below[--n]; };
  double a = 0.0;  // left operand of a binary operation
  // clang-format off
  for (const Instruction& in : program.code) {
    switch (in.op) {
      case Op::Constant: push(in.value); break;
      case Op::Load: push(vars.*kVariableFields[in.slot].member); break;
      case Op::LoadR: push(std::sqrt(vars.x * vars.x + vars.y * vars.y)); break;
      case Op::LoadTheta: push(std::atan2(vars.y, vars.x) * kDegreesPerRadian); break;

      case Op::Negate: top = -top; break;
      case Op::Add: top = pop() + top; break;
      case Op::Subtract: top = pop() - top; break;
      case Op::Multiply: top = pop() * top; break;
      case Op::Divide: top = pop() / top; break;
      case Op::Power: top = std::pow(pop(), top); break;
      case Op::Equal: a = pop(); top = truth(a == top, a, top); break;
      case Op::NotEqual: a = pop(); top = truth(a != top, a, top); break;
      case Op::Less: a = pop(); top = truth(a < top, a, top); break;
      case Op::LessEqual: a = pop(); top = truth(a <= top, a, top); break;
      case Op::Greater: a = pop(); top = truth(a > top, a, top); break;
      case Op::GreaterEqual: a = pop(); top = truth(a >= top, a, top); break;
      case Op::And: a = pop(); top = truth(a != 0.0 && top != 0.0, a, top); break;
      case Op::Or: a = pop(); top = truth(a != 0.0 || top != 0.0, a, top); break;

      case Op::Sin: top = std::sin(top * kRadiansPerDegree); break;
      case Op::Cos: top = std::cos(top * kRadiansPerDegree); break;
      case Op::Tan: top = std::tan(top * kRadiansPerDegree); break;
      case Op::Asin: top = std::asin(top) * kDegreesPerRadian; break;
      case Op::Acos: top = std::acos(top) * kDegreesPerRadian; break;
      case Op::Atan: top = std::atan(top) * kDegreesPerRadian; break;
      case Op::SinR: top = std::sin(top); break;
      case Op::CosR: top = std::cos(top); break;
      case Op::TanR: top = std::tan(top); break;
      case Op::AsinR: top = std::asin(top); break;
      case Op::AcosR: top = std::acos(top); break;
      case Op::AtanR: top = std::atan(top); break;
      case Op::Tanh: top = std::tanh(top); break;
      case Op::Exp: top = std::exp(top); break;
      case Op::Log: top = std::log(top); break;
      case Op::Log10: top = std::log10(top); break;
      case Op::Sqrt: top = std::sqrt(top); break;
      case Op::Abs: top = std::fabs(top); break;
      case Op::Sign: top = sign(top); break;
      case Op::Floor: top = std::floor(top); break;
      case Op::Ceil: top = std::ceil(top); break;
      case Op::Round: top = std::round(top); break;
      case Op::Erf: top = std::erf(top); break;
      case Op::Heaviside: top = heaviside(top); break;

      case Op::Mod: top = std::fmod(pop(), top); break;
      case Op::Kronecker: a = pop(); top = truth(a == top, a, top); break;
      case Op::Min: for (int k = 1; k < in.argc; ++k) top = minimum(pop(), top); break;
      case Op::Max: for (int k = 1; k < in.argc; ++k) top = maximum(pop(), top); break;

      case Op::Curve:
        top = table_of(program, table)->value(target_of(program, in), top, vars);
        break;
      case Op::Function:
        push(table_of(program, table)->value(target_of(program, in), vars.t, vars));
        break;
      case Op::FunctionAt: {
        Variables at = vars;
        at.t = top;
        top = table_of(program, table)->value(target_of(program, in), at.t, at);
        break;
      }
    }
  }
  // clang-format on
  return top;
}

}  // namespace abut::expression
