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

// The FunctionTable entry a crv()/fcn() instruction calls.
FunctionRef target_of(const Program& program, const Instruction& in, const FunctionTable* table) {
  const FunctionRef ref{program.references[static_cast<std::size_t>(in.slot)].target};
  if (table == nullptr || !ref.valid()) {
    throw std::logic_error("expression '" + program.text +
                           "' evaluated before FunctionTable::resolve()");
  }
  return ref;
}

}  // namespace

double evaluate(const Program& program, const Variables& vars, const FunctionTable* table) {
  double stack[kMaxStack];
  double* top = stack - 1;  // points at the topmost value
  for (const Instruction& in : program.code) {
    switch (in.op) {
      case Op::Constant: *++top = in.value; break;
      case Op::Load: *++top = vars.*kVariableFields[in.slot].member; break;
      case Op::LoadR: *++top = std::sqrt(vars.x * vars.x + vars.y * vars.y); break;
      case Op::LoadTheta: *++top = std::atan2(vars.y, vars.x) * kDegreesPerRadian; break;

      case Op::Negate: *top = -*top; break;
      case Op::Add: --top; *top = top[0] + top[1]; break;
      case Op::Subtract: --top; *top = top[0] - top[1]; break;
      case Op::Multiply: --top; *top = top[0] * top[1]; break;
      case Op::Divide: --top; *top = top[0] / top[1]; break;
      case Op::Power: --top; *top = std::pow(top[0], top[1]); break;
      case Op::Equal: --top; *top = truth(top[0] == top[1], top[0], top[1]); break;
      case Op::NotEqual: --top; *top = truth(top[0] != top[1], top[0], top[1]); break;
      case Op::Less: --top; *top = truth(top[0] < top[1], top[0], top[1]); break;
      case Op::LessEqual: --top; *top = truth(top[0] <= top[1], top[0], top[1]); break;
      case Op::Greater: --top; *top = truth(top[0] > top[1], top[0], top[1]); break;
      case Op::GreaterEqual: --top; *top = truth(top[0] >= top[1], top[0], top[1]); break;
      case Op::And: --top; *top = truth(top[0] != 0.0 && top[1] != 0.0, top[0], top[1]); break;
      case Op::Or: --top; *top = truth(top[0] != 0.0 || top[1] != 0.0, top[0], top[1]); break;

      case Op::Sin: *top = std::sin(*top * kRadiansPerDegree); break;
      case Op::Cos: *top = std::cos(*top * kRadiansPerDegree); break;
      case Op::Tan: *top = std::tan(*top * kRadiansPerDegree); break;
      case Op::Asin: *top = std::asin(*top) * kDegreesPerRadian; break;
      case Op::Acos: *top = std::acos(*top) * kDegreesPerRadian; break;
      case Op::Atan: *top = std::atan(*top) * kDegreesPerRadian; break;
      case Op::SinR: *top = std::sin(*top); break;
      case Op::CosR: *top = std::cos(*top); break;
      case Op::TanR: *top = std::tan(*top); break;
      case Op::AsinR: *top = std::asin(*top); break;
      case Op::AcosR: *top = std::acos(*top); break;
      case Op::AtanR: *top = std::atan(*top); break;
      case Op::Tanh: *top = std::tanh(*top); break;
      case Op::Exp: *top = std::exp(*top); break;
      case Op::Log: *top = std::log(*top); break;
      case Op::Log10: *top = std::log10(*top); break;
      case Op::Sqrt: *top = std::sqrt(*top); break;
      case Op::Abs: *top = std::fabs(*top); break;
      case Op::Sign: *top = sign(*top); break;
      case Op::Floor: *top = std::floor(*top); break;
      case Op::Ceil: *top = std::ceil(*top); break;
      case Op::Round: *top = std::round(*top); break;
      case Op::Erf: *top = std::erf(*top); break;
      case Op::Heaviside: *top = heaviside(*top); break;

      case Op::Mod: --top; *top = std::fmod(top[0], top[1]); break;
      case Op::Kronecker: --top; *top = truth(top[0] == top[1], top[0], top[1]); break;
      case Op::Min:
        for (int k = 1; k < in.argc; ++k, --top) top[-1] = minimum(top[-1], top[0]);
        break;
      case Op::Max:
        for (int k = 1; k < in.argc; ++k, --top) top[-1] = maximum(top[-1], top[0]);
        break;

      case Op::Curve: {
        const FunctionRef ref = target_of(program, in, table);
        *top = table->value(ref, *top, vars);
        break;
      }
      case Op::Function: {
        const FunctionRef ref = target_of(program, in, table);
        *++top = table->value(ref, vars.t, vars);
        break;
      }
      case Op::FunctionAt: {
        const FunctionRef ref = target_of(program, in, table);
        Variables at = vars;
        at.t = *top;
        *top = table->value(ref, at.t, at);
        break;
      }
    }
  }
  return stack[0];
}

}  // namespace abut::expression
