#pragma once
// *CURVE and *FUNCTION: tabulated curves and compiled expressions, looked up by id.
// Expression syntax (IMPETUS reference, §8): + - * / ^, && || == != < <= > >=, parentheses,
// numbers in E-notation, built-in values, math intrinsics (trig in degrees, *r variants in
// radians), crv(cid, x), fcn(fid) and fcn(fid, x).
//
// Details chosen where the reference is silent (src/core/expression_eval.cpp has the list):
// - Precedence, loosest first: ||, &&, comparisons, + -, * /, unary sign, ^ (right-associative;
//   -2^2 = -4, 2^3^2 = 512). Comparisons and logicals give 1 or 0.
// - R = sqrt(x^2 + y^2); theta = atan2(y, x) in degrees. Names are case-sensitive (x current,
//   X initial; t time, T temperature). ln and log are both the natural logarithm.
// - H(x) = 1 for x >= 0 (H(0) = 1), else 0; sign(0) = 0; d(i, j) = 1 if i == j, else 0;
//   mod(a, b) has the sign of a (std::fmod); round() rounds halves away from zero.
// - min(...) and max(...) take 1 to 10 arguments. NaN propagates through every operation.
// - crv(cid, x) needs a *CURVE; fcn(fid) evaluates a *FUNCTION with the same variables, or a
//   *CURVE at t; fcn(fid, a) does the same with t replaced by a. Ids are literal integers.
// - smooth_d/v/a, model feedback (xn, dxp, fc, ...), table, dfcn, norminv, lognorminv and rnd
//   are rejected with "not supported yet".
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "abut/core/error.hpp"

namespace abut {

// The values an expression may read. A use site fills what it knows (e.g. the contact fills
// pres and vtang); everything else stays 0.
struct Variables {
  double t = 0.0;      // time
  double dt = 0.0;     // time step
  double term = 0.0;   // termination time
  double x = 0.0, y = 0.0, z = 0.0;  // current coordinates
  double X = 0.0, Y = 0.0, Z = 0.0;  // initial coordinates
  double vx = 0.0, vy = 0.0, vz = 0.0;
  double xnorm = 0.0, ynorm = 0.0, znorm = 0.0;  // surface normal
  double pres = 0.0;   // contact pressure
  double gap = 0.0;    // contact gap (open > 0, penetrating < 0)
  double vtang = 0.0;  // tangential sliding speed
  double T = 0.0;      // temperature
  double epsp = 0.0, sigy0 = 0.0, dmg = 0.0, eint = 0.0;
  double wi = 0.0, we = 0.0, wk = 0.0;  // internal, external, kinetic energy
};

// A tabulated curve y(x): linear interpolation, constant beyond the first and last points.
struct Curve {
  std::vector<double> x, y;  // abscissas strictly increasing, scale factors already applied
  double value(double at) const;
};

// Opaque handle to a curve or function in a FunctionTable (cheap to copy, fast to evaluate).
struct FunctionRef {
  std::int32_t index = -1;
  bool valid() const { return index >= 0; }
};

class FunctionTable {
 public:
  FunctionTable();
  ~FunctionTable();
  FunctionTable(FunctionTable&&) noexcept;
  FunctionTable& operator=(FunctionTable&&) noexcept;

  // Registration while reading the deck. A duplicate id (curve and function share one id
  // space) is an InputError at `where`. Expressions are compiled here: a syntax error or an
  // unsupported name is an InputError at `where`.
  void add_curve(std::int64_t id, Curve curve, const SourceLocation& where);
  void add_function(std::int64_t id, const std::string& expression, const SourceLocation& where);

  // Checks that every crv()/fcn() reference exists and that functions do not call themselves
  // recursively; errors name the function's own location.
  void resolve();

  bool contains(std::int64_t id) const;
  // The handle for an id; InputError at `where` if there is none.
  FunctionRef find(std::int64_t id, const SourceLocation& where) const;
  bool is_curve(FunctionRef ref) const;
  // The abscissas of a curve, where its slope may change (a caller steps over them, not across
  // them); empty for a function.
  std::span<const double> breakpoints(FunctionRef ref) const;
  // Does the expression read this variable name (e.g. "pres")? False for curves.
  // Includes the names read by the functions it calls through fcn() (conservative).
  bool uses(FunctionRef ref, const std::string& variable) const;

  // A curve is evaluated at `abscissa`; a function evaluates its expression with `vars`
  // (its own abscissa being t, x or whichever variable it names; `abscissa` is not used).
  // Needs resolve() first when the expression calls crv()/fcn(). Allocates nothing.
  double value(FunctionRef ref, double abscissa, const Variables& vars) const;
  // Convenience for time-dependent use: curves at vars.t.
  double value(FunctionRef ref, const Variables& vars) const { return value(ref, vars.t, vars); }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Evaluates a constant expression (no variables), used for `[expression]` in decks and
// *PARAMETER. Throws InputError (without location; the caller adds it) on any error,
// including the use of a variable (t, x, ...) or of crv()/fcn(). %parameters must already be
// substituted.
double evaluate_constant_expression(const std::string& expression);

}  // namespace abut
