// *FUNCTION expression syntax and intrinsics (IMPETUS keyword reference §8, summarized in
// /work/shared/reference/impetus-keywords.md), through the public FunctionTable interface.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "abut/core/functions.hpp"

namespace abut {
namespace {

using ::testing::HasSubstr;

double eval(const std::string& text, const Variables& vars = {}) {
  FunctionTable table;
  const SourceLocation where{"deck.k", 12, "*FUNCTION", "expression"};
  table.add_function(1, text, where);
  table.resolve();
  return table.value(table.find(1, where), vars);
}

// The message of the InputError that compiling `text` throws (empty if it does not throw).
std::string error_of(const std::string& text) {
  try {
    FunctionTable table;
    table.add_function(1, text, SourceLocation{"deck.k", 12, "*FUNCTION", "expression"});
  } catch (const InputError& e) {
    return e.what();
  }
  return {};
}

TEST(Expression, PrecedenceAndAssociativity) {
  // Expected values worked by hand from the precedence rules in functions.hpp: || loosest,
  // then &&, comparisons, + -, * /, unary sign, and ^ binding tightest (right-associative).
  const std::vector<std::pair<std::string, double>> cases = {
      {"1+2*3", 7.0},
      {"(1+2)*3", 9.0},
      {"10-4-3", 3.0},
      {"8/4/2", 1.0},
      {"2*3^2", 18.0},
      {"2^3^2", 512.0},
      {"-2^2", -4.0},
      {"(-2)^2", 4.0},
      {"2^-1", 0.5},
      {"-2^-2", -0.25},
      {"2*-3", -6.0},
      {"--2", 2.0},
      {"+-+2", -2.0},
      {"-3 < -2", 1.0},
      {"1+2 == 3", 1.0},
      {"3 > 2 > 1", 0.0},
      {"1 < 2 == 1", 1.0},
      {"1 || 0 && 0", 1.0},
      {"0 && 1 || 1", 1.0},
      {"2<3 && 3<2", 0.0},
      {"7 != 7", 0.0},
      {"7 >= 7", 1.0},
      {"7 <= 6", 0.0},
      {"6 < 7", 1.0},
      {"7 > 7", 0.0},
      {"2 == 2", 1.0},
      {"3 && 0.5", 1.0},
      {"0 || 0", 0.0},
      {"4 - 2 * 3 ^ 2 / 6", 1.0},
      {" ( 1 + 1 ) ^ ( 1 + 2 ) ", 8.0},
  };
  for (const auto& [text, expected] : cases) EXPECT_EQ(eval(text), expected) << text;
}

TEST(Expression, NumberFormats) {
  EXPECT_EQ(eval("3"), 3.0);
  EXPECT_EQ(eval("3.0e9"), 3.0e9);
  EXPECT_EQ(eval(".5"), 0.5);
  EXPECT_EQ(eval("1E-3"), 1e-3);
  EXPECT_EQ(eval("2."), 2.0);
  EXPECT_EQ(eval("5e+2"), 500.0);
  EXPECT_EQ(eval("167.0e6 + 415.0e6 * 0"), 167.0e6);
}

TEST(Expression, ReadsEveryVariableByItsCaseSensitiveName) {
  const std::vector<std::pair<std::string, double Variables::*>> fields = {
      {"t", &Variables::t},         {"dt", &Variables::dt},       {"term", &Variables::term},
      {"x", &Variables::x},         {"y", &Variables::y},         {"z", &Variables::z},
      {"X", &Variables::X},         {"Y", &Variables::Y},         {"Z", &Variables::Z},
      {"vx", &Variables::vx},       {"vy", &Variables::vy},       {"vz", &Variables::vz},
      {"xnorm", &Variables::xnorm}, {"ynorm", &Variables::ynorm}, {"znorm", &Variables::znorm},
      {"pres", &Variables::pres},   {"vtang", &Variables::vtang}, {"T", &Variables::T},
      {"epsp", &Variables::epsp},   {"sigy0", &Variables::sigy0}, {"dmg", &Variables::dmg},
      {"eint", &Variables::eint},   {"wi", &Variables::wi},       {"we", &Variables::we},
      {"wk", &Variables::wk},
  };
  Variables vars;
  double distinct = 1.0;
  for (const auto& field : fields) vars.*field.second = (distinct += 1.0);
  for (const auto& [name, member] : fields) EXPECT_EQ(eval(name, vars), vars.*member) << name;
}

TEST(Expression, CylindricalCoordinates) {
  Variables vars;
  vars.x = 3.0;
  vars.y = 4.0;
  EXPECT_DOUBLE_EQ(eval("R", vars), 5.0);  // 3-4-5 triangle
  // theta = atan2(4, 3) = 53.13010235415598 degrees (tan 53.13° = 4/3).
  EXPECT_NEAR(eval("theta", vars), 53.13010235415598, 1e-12);
  vars.x = -1.0;
  vars.y = 0.0;
  EXPECT_DOUBLE_EQ(eval("theta", vars), 180.0);
  vars.x = 0.0;
  vars.y = -2.0;
  EXPECT_DOUBLE_EQ(eval("theta", vars), -90.0);
  EXPECT_EQ(eval("pi"), std::numbers::pi);
}

TEST(Expression, TrigonometryInDegreesAndRadians) {
  // Exact values of the unit circle: sin 30° = cos 60° = 1/2, tan 45° = 1.
  EXPECT_NEAR(eval("sin(30)"), 0.5, 1e-15);
  EXPECT_NEAR(eval("cos(60)"), 0.5, 1e-15);
  EXPECT_NEAR(eval("tan(45)"), 1.0, 1e-15);
  EXPECT_NEAR(eval("asin(0.5)"), 30.0, 1e-13);
  EXPECT_NEAR(eval("acos(0.5)"), 60.0, 1e-13);
  EXPECT_NEAR(eval("atan(1)"), 45.0, 1e-13);
  EXPECT_NEAR(eval("sinr(pi/6)"), 0.5, 1e-15);
  EXPECT_NEAR(eval("cosr(pi/3)"), 0.5, 1e-15);
  EXPECT_NEAR(eval("tanr(pi/4)"), 1.0, 1e-15);
  EXPECT_NEAR(eval("asinr(0.5)"), std::numbers::pi / 6, 1e-15);
  EXPECT_NEAR(eval("acosr(0.5)"), std::numbers::pi / 3, 1e-15);
  EXPECT_NEAR(eval("atanr(1)"), std::numbers::pi / 4, 1e-15);
  // Radian variants are the <cmath> functions themselves.
  for (double a : {-2.3, -0.4, 0.0, 0.7, 1.9}) {
    Variables vars;
    vars.x = a;
    EXPECT_EQ(eval("sinr(x)", vars), std::sin(a));
    EXPECT_EQ(eval("cosr(x)", vars), std::cos(a));
    EXPECT_EQ(eval("tanr(x)", vars), std::tan(a));
    EXPECT_EQ(eval("atanr(x)", vars), std::atan(a));
    EXPECT_EQ(eval("tanh(x)", vars), std::tanh(a));
    EXPECT_EQ(eval("exp(x)", vars), std::exp(a));
    EXPECT_EQ(eval("erf(x)", vars), std::erf(a));
  }
}

TEST(Expression, OtherIntrinsicsAgainstKnownValues) {
  EXPECT_NEAR(eval("exp(1)"), std::numbers::e, 1e-15);
  EXPECT_NEAR(eval("ln(exp(2))"), 2.0, 1e-15);
  EXPECT_EQ(eval("log(10)"), std::log(10.0));  // log is natural, as ln
  EXPECT_NEAR(eval("log10(1000)"), 3.0, 1e-15);
  EXPECT_EQ(eval("sqrt(2)"), std::numbers::sqrt2);
  EXPECT_NEAR(eval("tanh(1)"), 0.7615941559557649, 1e-15);  // (e^2-1)/(e^2+1)
  // erf(0.5) = 0.5204998778130465 (Abramowitz & Stegun, Table 7.1).
  EXPECT_NEAR(eval("erf(0.5)"), 0.5204998778130465, 1e-15);
  EXPECT_EQ(eval("abs(-2.5)"), 2.5);
  EXPECT_EQ(eval("sign(-3)"), -1.0);
  EXPECT_EQ(eval("sign(0)"), 0.0);
  EXPECT_EQ(eval("sign(0.2)"), 1.0);
  EXPECT_EQ(eval("floor(-1.5)"), -2.0);
  EXPECT_EQ(eval("ceil(-1.5)"), -1.0);
  EXPECT_EQ(eval("round(2.5)"), 3.0);
  EXPECT_EQ(eval("round(-2.5)"), -3.0);
  EXPECT_EQ(eval("mod(7, 3)"), 1.0);
  EXPECT_EQ(eval("mod(-7, 3)"), -1.0);  // sign of the dividend, as Fortran MOD
  EXPECT_EQ(eval("mod(7.5, 2)"), 1.5);
  EXPECT_EQ(eval("d(2, 2)"), 1.0);
  EXPECT_EQ(eval("d(2, 3)"), 0.0);
  EXPECT_EQ(eval("H(-1)"), 0.0);
  EXPECT_EQ(eval("H(0)"), 1.0);
  EXPECT_EQ(eval("H(2)"), 1.0);
  EXPECT_EQ(eval("min(3)"), 3.0);
  EXPECT_EQ(eval("min(4, 2, 8)"), 2.0);
  EXPECT_EQ(eval("max(4, 2, 8)"), 8.0);
  EXPECT_EQ(eval("max(1,2,3,4,5,6,7,8,9,10)"), 10.0);
  EXPECT_EQ(eval("min(10,9,8,7,6,5,4,3,2,1)"), 1.0);
}

TEST(Expression, NaNPropagatesInsteadOfBecomingZeroOrOne) {
  for (const char* text : {"sqrt(-1)", "sqrt(-1) < 1", "sqrt(-1) == sqrt(-1)", "1 && sqrt(-1)",
                           "H(sqrt(-1))", "sign(sqrt(-1))", "d(sqrt(-1), 1)", "min(1, sqrt(-1))",
                           "max(sqrt(-1), 1)", "max(1, 2, sqrt(-1), 3)"}) {
    EXPECT_TRUE(std::isnan(eval(text))) << text;
  }
}

TEST(Expression, FunctionOfVariablesMatchesHandComputation) {
  // Pressure- and velocity-dependent friction: 0.1 + 0.05 exp(-1) * 2 at pres = 2e6, vtang = 10.
  Variables vars;
  vars.pres = 2e6;
  vars.vtang = 10.0;
  EXPECT_NEAR(eval("0.1+0.05*exp(-vtang/10)*pres/1e6", vars), 0.13678794411714423, 1e-16);
  // Ludwik hardening, the reference's example; 0.1^0.3 = 10^-0.3 = 0.5011872336272722.
  vars.epsp = 0.1;
  EXPECT_NEAR(eval("167.0e6 + 415.0e6 * epsp^0.3", vars), 167.0e6 + 415.0e6 * 0.5011872336272722,
              1e-6);
}

TEST(Expression, SyntaxErrorsPointAtTheColumn) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"1 + * 2", "column 5"}, {"2x", "column 2"},    {"sin(30", "column 7"}, {"1 = 2", "column 3"},
      {"1)", "column 2"},      {"(((1)", "column 6"}, {"1e", "column 2"},     {"2 & 3", "column 3"},
      {"2 | 3", "column 3"},   {"!1", "column 1"},    {"%a*2", "column 1"},   {"1 + $", "column 5"},
      {"", "column 1"},        {"3 +", "column 4"},   {"sin()", "column 1"},  {"1e999", "column 1"},
      {"1..2", "column 3"},
  };
  for (const auto& [text, column] : cases) {
    const std::string message = error_of(text);
    EXPECT_THAT(message, HasSubstr(column)) << "'" << text << "': " << message;
    EXPECT_THAT(message, HasSubstr("'" + text + "'")) << text;
    EXPECT_THAT(message, HasSubstr("deck.k:12: *FUNCTION")) << text;
  }
  EXPECT_THAT(error_of("1 + * 2"), HasSubstr("\n  1 + * 2\n      ^"));  // caret under '*'
  EXPECT_THAT(error_of("1 = 2"), HasSubstr("=="));
  EXPECT_THAT(error_of("%a*2"), HasSubstr("substituted"));
}

TEST(Expression, NamesAreCheckedWithHelpfulMessages) {
  EXPECT_THAT(error_of("foo + 1"), HasSubstr("unknown name 'foo'"));
  EXPECT_THAT(error_of("foo + 1"), HasSubstr("accepted values: pi R theta t dt"));
  EXPECT_THAT(error_of("foo + 1"), HasSubstr("sinr()"));
  EXPECT_THAT(error_of("2*Sin(30)"), HasSubstr("did you mean 'sin'"));
  EXPECT_THAT(error_of("2*Sin(30)"), HasSubstr("column 3"));
  EXPECT_THAT(error_of("Pres"), HasSubstr("did you mean 'pres'"));
  EXPECT_THAT(error_of("t(3)"), HasSubstr("'t' is a value, not a function"));
  EXPECT_THAT(error_of("sin + 1"), HasSubstr("'sin' is a function"));
  EXPECT_THAT(error_of("sin(1, 2)"), HasSubstr("sin() takes 1 argument, not 2"));
  EXPECT_THAT(error_of("mod(1)"), HasSubstr("mod() takes 2 arguments, not 1"));
  EXPECT_THAT(error_of("max(1,2,3,4,5,6,7,8,9,10,11)"), HasSubstr("1 to 10 arguments, not 11"));
  EXPECT_THAT(error_of("crv(x, 2)"), HasSubstr("needs the id of a *CURVE"));
  EXPECT_THAT(error_of("crv(2.5, 2)"), HasSubstr("needs the id of a *CURVE"));
  EXPECT_THAT(error_of("crv(3)"), HasSubstr("crv() takes two arguments"));
  EXPECT_THAT(error_of("fcn(0)"), HasSubstr("needs the id of a *FUNCTION"));
}

TEST(Expression, NamesOfTheReferenceNotYetSupported) {
  for (const char* text : {"xn(3)",
                           "vxn(3)",
                           "dxp(1)",
                           "vzp(1)",
                           "wkp(1)",
                           "mpp(1)",
                           "xs(3)",
                           "ps(1)",
                           "fxc(1)",
                           "fc(1)",
                           "fxr(1)",
                           "fr(1)",
                           "vol_geo(1)",
                           "table(1,2,3)",
                           "dfcn(1)",
                           "norminv(0.5)",
                           "lognorminv(0.5)",
                           "rnd",
                           "smooth_d(1, 0, 1)",
                           "smooth_v(1, 0, 1)",
                           "smooth_a(1, 0, 1)"}) {
    const std::string message = error_of(std::string("1 + ") + text);
    const std::string name = std::string(text).substr(0, std::string(text).find('('));
    EXPECT_THAT(message, HasSubstr("'" + name + "' is not supported yet")) << text;
    EXPECT_THAT(message, HasSubstr("column 5")) << text;
  }
}

TEST(Expression, LimitsAreErrorsNotCrashes) {
  EXPECT_THAT(error_of(std::string(500, '(') + "1" + std::string(500, ')')),
              HasSubstr("nested more than"));
  EXPECT_THAT(error_of(std::string(500, '-') + "1"), HasSubstr("nested more than"));
  // x+(x+(x+...)) keeps one value per level on the stack.
  std::string deep = "x";
  for (int i = 0; i < 80; ++i) deep = "x+(" + deep + ")";
  EXPECT_THAT(error_of(deep), HasSubstr("intermediate values"));
  std::string fits = "x";
  for (int i = 0; i < 60; ++i) fits = "x+(" + fits + ")";
  Variables vars;
  vars.x = 1.0;
  EXPECT_EQ(eval(fits, vars), 61.0);
}

TEST(ConstantExpression, EvaluatesNumbersAndIntrinsics) {
  EXPECT_EQ(evaluate_constant_expression("2*pi"), 2.0 * std::numbers::pi);
  EXPECT_EQ(evaluate_constant_expression("max(1, 2^3, 7) - 1"), 7.0);
  EXPECT_NEAR(evaluate_constant_expression("sqrt(3^2 + 4^2)"), 5.0, 1e-15);
}

TEST(ConstantExpression, RejectsVariablesAndReferences) {
  const auto message = [](const std::string& text) {
    try {
      evaluate_constant_expression(text);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_THAT(message("2*t"), HasSubstr("'t' is a variable"));
  EXPECT_THAT(message("2*t"), HasSubstr("column 3"));
  EXPECT_THAT(message("1 + R"), HasSubstr("'R' is a variable"));
  EXPECT_THAT(message("crv(1, 2)"), HasSubstr("crv() and fcn() cannot be used"));
  EXPECT_THAT(message("fcn(1)"), HasSubstr("column 1"));
  EXPECT_THAT(message("2*"), HasSubstr("column 3"));
}

}  // namespace
}  // namespace abut
