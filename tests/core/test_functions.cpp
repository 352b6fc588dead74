// *CURVE and *FUNCTION tables: interpolation, ids, cross references, recursion, uses().
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "abut/core/functions.hpp"

namespace abut {
namespace {

using ::testing::HasSubstr;

SourceLocation at_line(std::size_t line, const char* keyword = "*FUNCTION") {
  return SourceLocation{"deck.k", line, keyword, ""};
}

// The what() of the InputError `action` throws (empty if none).
template <class Action>
std::string input_error(Action action) {
  try {
    action();
  } catch (const InputError& e) {
    return e.what();
  }
  return {};
}

TEST(Curve, InterpolatesLinearlyAndHoldsTheEndValues) {
  // Points (0, 0), (1, 10), (3, 40): slopes 10 and 15.
  const Curve curve{{0.0, 1.0, 3.0}, {0.0, 10.0, 40.0}};
  EXPECT_EQ(curve.value(0.0), 0.0);
  EXPECT_EQ(curve.value(0.5), 5.0);
  EXPECT_EQ(curve.value(1.0), 10.0);
  EXPECT_EQ(curve.value(2.0), 25.0);
  EXPECT_EQ(curve.value(3.0), 40.0);
  EXPECT_EQ(curve.value(-7.0), 0.0);    // constant before the first point
  EXPECT_EQ(curve.value(100.0), 40.0);  // and after the last
  EXPECT_TRUE(std::isnan(curve.value(std::nan(""))));
  const Curve single{{2.0}, {5.0}};
  EXPECT_EQ(single.value(-1.0), 5.0);
  EXPECT_EQ(single.value(9.0), 5.0);
}

TEST(FunctionTable, RejectsMalformedCurves) {
  FunctionTable table;
  EXPECT_THAT(input_error([&] {
                table.add_curve(1, Curve{{0.0, 1.0}, {0.0}}, at_line(3));
              }),
              HasSubstr("2 abscissas but 1 ordinates"));
  EXPECT_THAT(input_error([&] { table.add_curve(2, Curve{}, at_line(3)); }),
              HasSubstr("has no points"));
  EXPECT_THAT(
      input_error([&] {
        table.add_curve(3, Curve{{0.0, 2.0, 2.0}, {0.0, 1.0, 2.0}}, at_line(3, "*CURVE"));
      }),
      HasSubstr("deck.k:3: *CURVE: *CURVE 3: abscissas must increase strictly, but point 3"));
  EXPECT_THAT(input_error([&] {
                table.add_curve(4, Curve{{0.0, INFINITY}, {0.0, 1.0}}, at_line(3));
              }),
              HasSubstr("point 2 is not a finite number"));
  EXPECT_FALSE(table.contains(1));
}

TEST(FunctionTable, DuplicateIdNamesBothLocations) {
  FunctionTable table;
  table.add_curve(5, Curve{{0.0, 1.0}, {0.0, 1.0}}, at_line(3, "*CURVE"));
  const std::string message = input_error([&] { table.add_function(5, "t", at_line(9)); });
  EXPECT_THAT(message, HasSubstr("deck.k:9: *FUNCTION"));
  EXPECT_THAT(message, HasSubstr("id 5 is already used by the *CURVE at deck.k:3"));
  EXPECT_THAT(input_error([&] {
                table.add_curve(5, Curve{{0.0}, {1.0}}, at_line(11));
              }),
              HasSubstr("deck.k:11"));
}

TEST(FunctionTable, CompileErrorsCarryTheLocation) {
  FunctionTable table;
  const std::string message = input_error([&] { table.add_function(7, "2*(t", at_line(20)); });
  EXPECT_THAT(message,
              HasSubstr("deck.k:20: *FUNCTION: *FUNCTION 7: in '2*(t' at column 5: expected ')'"));
  EXPECT_FALSE(table.contains(7));
}

TEST(FunctionTable, FindsEntriesById) {
  FunctionTable table;
  table.add_curve(1, Curve{{0.0, 1.0}, {0.0, 2.0}}, at_line(3));
  table.add_function(2, "3*t", at_line(6));
  table.resolve();
  EXPECT_TRUE(table.contains(1));
  EXPECT_FALSE(table.contains(3));
  const FunctionRef curve = table.find(1, at_line(40));
  const FunctionRef function = table.find(2, at_line(40));
  EXPECT_TRUE(curve.valid());
  EXPECT_TRUE(table.is_curve(curve));
  EXPECT_FALSE(table.is_curve(function));
  EXPECT_THAT(input_error([&] { table.find(3, at_line(40, "*CONTACT")); }),
              HasSubstr("deck.k:40: *CONTACT: there is no *CURVE or *FUNCTION with id 3"));
  Variables vars;
  vars.t = 0.25;
  EXPECT_EQ(table.value(curve, vars), 0.5);            // curve at t
  EXPECT_EQ(table.value(curve, 0.75, vars), 1.5);      // curve at an abscissa
  EXPECT_EQ(table.value(function, vars), 0.75);        // 3 t
  EXPECT_EQ(table.value(function, 99.0, vars), 0.75);  // a function reads its own variables
  EXPECT_THROW(table.value(FunctionRef{}, vars), std::invalid_argument);
}

TEST(FunctionTable, CrossReferencesResolveInAnyOrder) {
  FunctionTable table;
  // Referenced entries are defined after the functions that call them.
  table.add_function(1, "2*crv(10, pres)", at_line(1));
  table.add_function(2, "fcn(3) + 1", at_line(2));
  table.add_function(3, "t^2 + x", at_line(3));
  table.add_function(4, "fcn(3, t - 1)", at_line(4));
  table.add_function(5, "fcn(10) + fcn(10, 2*t)", at_line(5));
  table.add_curve(10, Curve{{0.0, 10.0}, {0.0, 100.0}}, at_line(6));
  table.resolve();
  Variables vars;
  vars.t = 3.0;
  vars.x = 1.0;
  vars.pres = 4.0;
  const auto value = [&](std::int64_t id) { return table.value(table.find(id, {}), vars); };
  EXPECT_EQ(value(1), 80.0);         // 2 * curve(4) = 2 * 40
  EXPECT_EQ(value(2), 11.0);         // (3^2 + 1) + 1
  EXPECT_EQ(value(4), 5.0);          // (3-1)^2 + 1: t replaced, x kept
  EXPECT_EQ(value(5), 30.0 + 60.0);  // curve(t = 3) + curve(6)
}

TEST(FunctionTable, ResolveReportsMissingAndMistypedTargets) {
  {
    FunctionTable table;
    table.add_function(1, "1 + fcn(8)", at_line(14));
    const std::string message = input_error([&] { table.resolve(); });
    EXPECT_THAT(message, HasSubstr("deck.k:14: *FUNCTION"));
    EXPECT_THAT(message, HasSubstr("there is no *CURVE or *FUNCTION 8"));
    EXPECT_THAT(message, HasSubstr("column 5"));
  }
  {
    FunctionTable table;
    table.add_function(1, "crv(2, t)", at_line(14));
    table.add_function(2, "t", at_line(17));
    const std::string message = input_error([&] { table.resolve(); });
    EXPECT_THAT(message, HasSubstr("2 is the *FUNCTION at deck.k:17; use fcn(2, x)"));
  }
}

TEST(FunctionTable, EvaluatingBeforeResolveIsAProgrammingError) {
  FunctionTable table;
  table.add_curve(2, Curve{{0.0}, {1.0}}, at_line(1));
  table.add_function(1, "fcn(2)", at_line(2));
  EXPECT_THROW(table.value(table.find(1, {}), Variables{}), std::logic_error);
}

TEST(FunctionTable, DetectsRecursion) {
  {
    FunctionTable table;
    table.add_function(1, "1 + fcn(1)", at_line(30));
    EXPECT_THAT(input_error([&] { table.resolve(); }),
                HasSubstr("deck.k:30: *FUNCTION: *FUNCTION 1 calls itself recursively: "
                          "fcn(1) -> fcn(1)"));
  }
  {
    FunctionTable table;
    table.add_function(1, "fcn(2)", at_line(30));
    table.add_function(2, "t + fcn(3, t)", at_line(33));
    table.add_function(3, "fcn(1)*2", at_line(36));
    EXPECT_THAT(input_error([&] { table.resolve(); }),
                HasSubstr("recursively: fcn(1) -> fcn(2) -> fcn(3) -> fcn(1)"));
  }
  {
    // A diamond (1 calls 2 and 3, 2 calls 3) is not a cycle.
    FunctionTable table;
    table.add_function(1, "fcn(2) + fcn(3)", at_line(1));
    table.add_function(2, "fcn(3)", at_line(2));
    table.add_function(3, "t", at_line(3));
    table.resolve();
    Variables vars;
    vars.t = 2.0;
    EXPECT_EQ(table.value(table.find(1, {}), vars), 4.0);
  }
}

TEST(FunctionTable, UsesReportsTheVariablesReadIncludingThroughFcn) {
  FunctionTable table;
  table.add_function(1, "0.1+0.05*exp(-vtang/10)*pres/1e6", at_line(1));
  table.add_function(2, "term*T + fcn(1)", at_line(2));
  table.add_function(3, "R", at_line(3));
  table.add_curve(4, Curve{{0.0}, {1.0}}, at_line(4));
  table.add_function(5, "crv(4, epsp)", at_line(5));
  table.resolve();
  const FunctionRef friction = table.find(1, {});
  EXPECT_TRUE(table.uses(friction, "pres"));
  EXPECT_TRUE(table.uses(friction, "vtang"));
  EXPECT_FALSE(table.uses(friction, "t"));
  const FunctionRef outer = table.find(2, {});
  EXPECT_TRUE(table.uses(outer, "pres"));  // through fcn(1)
  EXPECT_TRUE(table.uses(outer, "T"));
  EXPECT_TRUE(table.uses(outer, "term"));
  EXPECT_FALSE(table.uses(outer, "t"));
  EXPECT_TRUE(table.uses(table.find(3, {}), "x"));  // R reads x and y
  EXPECT_TRUE(table.uses(table.find(3, {}), "R"));
  EXPECT_FALSE(table.uses(table.find(3, {}), "z"));
  EXPECT_FALSE(table.uses(table.find(4, {}), "t"));  // a curve reads nothing itself
  EXPECT_TRUE(table.uses(table.find(5, {}), "epsp"));
}

TEST(FunctionTable, SurvivesAMove) {
  FunctionTable table;
  table.add_curve(2, Curve{{0.0, 1.0}, {0.0, 1.0}}, at_line(1));
  table.add_function(1, "4*fcn(2)", at_line(2));
  table.resolve();
  FunctionTable moved = std::move(table);
  Variables vars;
  vars.t = 0.5;
  EXPECT_EQ(moved.value(moved.find(1, {}), vars), 2.0);
}

}  // namespace
}  // namespace abut
