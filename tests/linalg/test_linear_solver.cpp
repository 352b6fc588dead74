#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <tuple>
#include <vector>

#include "abut/linalg/linear_solver.hpp"

namespace abut {
namespace {

struct Matrix {
  SparsePattern pattern;
  std::vector<double> values;
};

// A CSR matrix from (row, column, value) entries; repeated entries are summed.
Matrix from_entries(std::int32_t n, const std::vector<std::tuple<int, int, double>>& entries) {
  std::map<std::pair<int, int>, double> sum;
  for (const auto& [i, j, v] : entries) sum[{i, j}] += v;
  Matrix m;
  m.pattern.n = n;
  m.pattern.row_start.assign(n + 1, 0);
  for (const auto& [ij, v] : sum) {
    ++m.pattern.row_start[ij.first + 1];
    m.pattern.column.push_back(ij.second);
    m.values.push_back(v);
  }
  for (int r = 0; r < n; ++r) m.pattern.row_start[r + 1] += m.pattern.row_start[r];
  return m;
}

// A stiffness matrix of springs between dofs (i, j, k); a dof -1 is fixed (the ground). Built with
// SparseAssembly, each spring one element with the matrix k [1 -1; -1 1].
struct Spring {
  int i, j;
  double k;
};
Matrix spring_matrix(std::int32_t n, const std::vector<Spring>& springs) {
  std::vector<std::int64_t> start = {0};
  std::vector<std::int32_t> dofs;
  for (const Spring& s : springs) {
    dofs.insert(dofs.end(), {s.i, s.j});
    start.push_back(static_cast<std::int64_t>(dofs.size()));
  }
  const SparseAssembly assembly(n, start, dofs);
  std::vector<double> element_values;
  for (const Spring& s : springs)
    element_values.insert(element_values.end(), {s.k, -s.k, -s.k, s.k});
  Matrix m{assembly.pattern(), {}};
  assembly.assemble(element_values, m.values);
  return m;
}

// The 5-point Laplacian of a side x side grid as springs between neighbours; the grid's outer
// neighbours are fixed. stiffness(e) gives spring e's stiffness.
template <class Stiffness>
Matrix grid_laplacian(int side, Stiffness stiffness) {
  std::vector<Spring> springs;
  const auto id = [&](int a, int b) {
    return a < 0 || b < 0 || a >= side || b >= side ? -1 : a * side + b;
  };
  for (int a = 0; a < side; ++a) {
    for (int b = 0; b < side; ++b) {
      for (const auto& [da, db] : {std::pair{1, 0}, {0, 1}, {-1, 0}, {0, -1}}) {
        const int other = id(a + da, b + db);
        if (other > id(a, b) || other < 0) {
          springs.push_back({id(a, b), other, stiffness(springs.size())});
        }
      }
    }
  }
  return spring_matrix(side * side, springs);
}

std::vector<double> random_vector(std::size_t n, unsigned seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<double> v(n);
  for (double& x : v) x = unit(random);
  return v;
}

// |b - A x| / |b|.
double relative_residual(const Matrix& a, const std::vector<double>& x,
                         const std::vector<double>& b) {
  std::vector<double> ax(b.size());
  multiply(a.pattern, a.values, x, ax);
  double r = 0.0, nb = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    r += (b[i] - ax[i]) * (b[i] - ax[i]);
    nb += b[i] * b[i];
  }
  return std::sqrt(r / nb);
}

std::vector<double> solve(LinearSolver& solver, const Matrix& a, const std::vector<double>& b) {
  solver.factorize(a.pattern, a.values);
  std::vector<double> x(b.size());
  solver.solve(b, x);
  return x;
}

TEST(LinearSolver, FactoryGivesCholmodAndUmfpack) {
  EXPECT_STREQ(make_linear_solver(MatrixKind::SymmetricPositiveDefinite)->name(),
               "CHOLMOD (supernodal Cholesky)");
  EXPECT_STREQ(make_linear_solver(MatrixKind::General)->name(), "UMFPACK (multifrontal LU)");
}

TEST(Cholmod, Solves1DLaplacianToRoundOff) {
  // A backward-stable solve leaves |b - A x| / |b| of about eps |A| |x| / |b| <= eps cond(A), and
  // cond(A) is about 4 n^2 / pi^2 here: n = 200 keeps that near 1e-12 / 100 (at n = 1000 round-off
  // alone reaches 1e-12).
  const int n = 200;
  std::vector<Spring> springs = {{-1, 0, 1.0}, {n - 1, -1, 1.0}};
  for (int i = 0; i + 1 < n; ++i) springs.push_back({i, i + 1, 1.0});
  const Matrix a = spring_matrix(n, springs);
  const auto b = random_vector(n, 1);
  auto solver = make_linear_solver(MatrixKind::SymmetricPositiveDefinite);
  EXPECT_LT(relative_residual(a, solve(*solver, a, b), b), 1e-12);
}

TEST(Cholmod, Solves2DLaplacianToRoundOff) {
  const Matrix a = grid_laplacian(60, [](std::size_t) { return 1.0; });
  const auto b = random_vector(a.pattern.n, 2);
  auto solver = make_linear_solver(MatrixKind::SymmetricPositiveDefinite);
  EXPECT_LT(relative_residual(a, solve(*solver, a, b), b), 1e-12);
  EXPECT_EQ(solver->analysis_count(), 1);
}

TEST(Cholmod, NewValuesOnTheSamePatternReuseTheAnalysis) {
  const Matrix a = grid_laplacian(40, [](std::size_t) { return 1.0; });
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> stiffness(0.5, 2.0);
  const Matrix a2 = grid_laplacian(40, [&](std::size_t) { return stiffness(random); });
  ASSERT_EQ(a.pattern, a2.pattern);
  const auto b = random_vector(a.pattern.n, 4);
  auto solver = make_linear_solver(MatrixKind::SymmetricPositiveDefinite);
  const auto x1 = solve(*solver, a, b);
  const auto x2 = solve(*solver, a2, b);  // a2.pattern: an equal copy, not the same object
  EXPECT_EQ(solver->analysis_count(), 1);
  EXPECT_LT(relative_residual(a2, x2, b), 1e-12);
  EXPECT_GT(relative_residual(a, x2, b), 1e-3);  // the new values were used
  // rhs and x may be the same array.
  std::vector<double> in_place = b;
  solver->solve(in_place, in_place);
  EXPECT_EQ(in_place, x2);
  // A new pattern is analysed anew, and the old one again after it.
  const Matrix small = grid_laplacian(10, [](std::size_t) { return 1.0; });
  const auto bs = random_vector(small.pattern.n, 5);
  EXPECT_LT(relative_residual(small, solve(*solver, small, bs), bs), 1e-12);
  EXPECT_EQ(solver->analysis_count(), 2);
  EXPECT_EQ(solve(*solver, a, b), x1);
  EXPECT_EQ(solver->analysis_count(), 3);
}

TEST(Cholmod, FreeFloatingSpringChainIsSingular) {
  // Unit springs and no support: a rigid-body mode. With unit stiffness the elimination is exact
  // in floating point and the last pivot is exactly 0.
  const int n = 10;
  std::vector<Spring> springs;
  for (int i = 0; i + 1 < n; ++i) springs.push_back({i, i + 1, 1.0});
  Matrix a = spring_matrix(n, springs);
  auto solver = make_linear_solver(MatrixKind::SymmetricPositiveDefinite);
  try {
    solver->factorize(a.pattern, a.values);
    ADD_FAILURE() << "a singular matrix was factorised";
  } catch (const SingularMatrixError& e) {
    EXPECT_GE(e.equation(), 0);
    EXPECT_LT(e.equation(), n);
    EXPECT_THAT(e.what(), testing::HasSubstr("equation " + std::to_string(e.equation())));
  }
  std::vector<double> x(n);
  EXPECT_THROW(solver->solve(std::vector<double>(n, 1.0), x), std::logic_error);
  // Supporting node 3 (same pattern) makes it solvable again with the same analysis.
  a.values[a.pattern.row_start[3] + 1] += 1.0;  // row 3 holds columns 2, 3, 4
  const auto b = random_vector(n, 6);
  EXPECT_LT(relative_residual(a, solve(*solver, a, b), b), 1e-12);
  EXPECT_EQ(solver->analysis_count(), 1);
}

// With non-integer stiffnesses the last pivot of a floating chain is round-off, not 0: the
// factorisation may pass, but the pivot ratio shows it (~1e-16 against > 1e-6 once supported).
TEST(LinearSolver, RoundOffSingularityShowsInThePivotRatio) {
  for (const MatrixKind kind : {MatrixKind::SymmetricPositiveDefinite, MatrixKind::General}) {
    for (unsigned seed = 1; seed <= 5; ++seed) {
      const int n = 50;
      const auto k = random_vector(n, seed);
      std::vector<Spring> springs;
      for (int i = 0; i + 1 < n; ++i) springs.push_back({i, i + 1, 2e11 * (1.5 + 0.5 * k[i])});
      const Matrix floating = spring_matrix(n, springs);
      auto solver = make_linear_solver(kind);
      try {
        solver->factorize(floating.pattern, floating.values);
        EXPECT_LT(solver->reciprocal_condition(), 1e-13) << solver->name() << " seed " << seed;
      } catch (const SingularMatrixError&) {
        // caught exactly: fine
      }
      springs.push_back({0, -1, 2e11});
      const Matrix held = spring_matrix(n, springs);
      solver->factorize(held.pattern, held.values);
      EXPECT_GT(solver->reciprocal_condition(), 1e-6) << solver->name();
    }
  }
}

// The SingularMatrixError of a Cholesky factorisation must name the equation of A, not the column
// of the reordered matrix where the pivot failed.
void expect_not_positive_definite_at(const Matrix& a, std::int64_t equation) {
  auto solver = make_linear_solver(MatrixKind::SymmetricPositiveDefinite);
  try {
    solver->factorize(a.pattern, a.values);
    ADD_FAILURE() << "factorised a matrix that is not positive definite";
  } catch (const SingularMatrixError& e) {
    EXPECT_EQ(e.equation(), equation) << e.what();
  }
}

TEST(Cholmod, NamesTheEquationWithoutStiffness) {
  // Two supported chains, dofs 0-3 and 5-8, and dof 4 on its own with a zero (then negative)
  // diagonal.
  for (const double diagonal : {0.0, -1.0}) {
    std::vector<std::tuple<int, int, double>> entries = {{4, 4, diagonal}};
    for (const int first : {0, 5}) {
      for (int i = first; i < first + 4; ++i) {
        entries.push_back({i, i, 2.0});
        if (i + 1 < first + 4) entries.insert(entries.end(), {{i, i + 1, -1.0}, {i + 1, i, -1.0}});
      }
    }
    expect_not_positive_definite_at(from_entries(9, entries), 4);
  }
  // A star: hub 0 without stiffness of its own, coupled to leaves 1-8. A fill-reducing ordering
  // eliminates the leaves first and the hub last, where its pivot is 0 - 8 / 2 < 0: the failure
  // is in the last column of L but at equation 0.
  std::vector<std::tuple<int, int, double>> star = {{0, 0, 0.0}};
  for (int i = 1; i <= 8; ++i) star.insert(star.end(), {{i, i, 2.0}, {0, i, -1.0}, {i, 0, -1.0}});
  expect_not_positive_definite_at(from_entries(9, star), 0);
}

// Central differences of -u'' + c u' on a side x side grid with cell Peclet number 0.4 in both
// directions: an unsymmetric M-matrix.
Matrix convection_diffusion(int side) {
  std::vector<std::tuple<int, int, double>> entries;
  const double peclet = 0.4;
  for (int a = 0; a < side; ++a) {
    for (int b = 0; b < side; ++b) {
      const int i = a * side + b;
      entries.push_back({i, i, 4.0});
      if (b + 1 < side) entries.push_back({i, i + 1, -1.0 + peclet});
      if (b > 0) entries.push_back({i, i - 1, -1.0 - peclet});
      if (a + 1 < side) entries.push_back({i, i + side, -1.0 + peclet});
      if (a > 0) entries.push_back({i, i - side, -1.0 - peclet});
    }
  }
  return from_entries(side * side, entries);
}

TEST(Umfpack, SolvesConvectionDiffusionToRoundOff) {
  const Matrix a = convection_diffusion(60);
  // Entry (0, 1) is values[1], (1, 0) the first of row 1: A is not A^T, so solving A^T x = b by
  // mistake would leave a large residual.
  ASSERT_EQ(a.pattern.column[1], 1);
  ASSERT_EQ(a.pattern.column[a.pattern.row_start[1]], 0);
  ASSERT_GT(std::abs(a.values[1] - a.values[a.pattern.row_start[1]]), 0.5);
  const auto b = random_vector(a.pattern.n, 7);
  auto solver = make_linear_solver(MatrixKind::General);
  const auto x = solve(*solver, a, b);
  EXPECT_LT(relative_residual(a, x, b), 1e-12);
  // New values on the same pattern reuse the analysis.
  Matrix a2 = a;
  for (double& v : a2.values) v *= 3.0;
  const auto x2 = solve(*solver, a2, b);
  EXPECT_LT(relative_residual(a2, x2, b), 1e-12);
  EXPECT_NEAR(x2[100] * 3.0, x[100], 1e-12 * std::abs(x[100]));
  EXPECT_EQ(solver->analysis_count(), 1);
  std::vector<double> in_place = b;
  solver->solve(in_place, in_place);
  EXPECT_EQ(in_place, x2);
}

TEST(Umfpack, SingularMatrixNamesTheEquation) {
  Matrix a = convection_diffusion(5);
  for (auto k = a.pattern.row_start[7]; k < a.pattern.row_start[8]; ++k) a.values[k] = 0.0;
  auto solver = make_linear_solver(MatrixKind::General);
  try {
    solver->factorize(a.pattern, a.values);
    ADD_FAILURE() << "a matrix with a zero row was factorised";
  } catch (const SingularMatrixError& e) {
    EXPECT_EQ(e.equation(), 7) << e.what();
  }
  std::vector<double> x(25);
  EXPECT_THROW(solver->solve(std::vector<double>(25, 1.0), x), std::logic_error);
  // Dependent equations: row 1 = 2 row 0.
  const Matrix dependent = from_entries(3, {{0, 0, 1.0},
                                            {0, 1, 2.0},
                                            {0, 2, 3.0},
                                            {1, 0, 2.0},
                                            {1, 1, 4.0},
                                            {1, 2, 6.0},
                                            {2, 0, 1.0},
                                            {2, 2, 1.0}});
  EXPECT_THROW(solver->factorize(dependent.pattern, dependent.values), SingularMatrixError);
}

TEST(LinearSolver, RejectsBadInput) {
  for (const MatrixKind kind : {MatrixKind::SymmetricPositiveDefinite, MatrixKind::General}) {
    auto solver = make_linear_solver(kind);
    SCOPED_TRACE(solver->name());
    std::vector<double> x(3);
    EXPECT_THROW(solver->solve(std::vector<double>(3, 1.0), x), std::logic_error);
    Matrix a = from_entries(3, {{0, 0, 2.0}, {1, 1, 2.0}, {2, 2, 2.0}, {0, 2, 1.0}, {2, 0, 1.0}});
    EXPECT_THROW(solver->factorize(a.pattern, std::vector<double>(4, 1.0)), std::invalid_argument);
    a.values[1] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(solver->factorize(a.pattern, a.values), std::invalid_argument);
    a.values[1] = 1.0;
    solver->factorize(a.pattern, a.values);
    std::vector<double> short_x(2);
    EXPECT_THROW(solver->solve(std::vector<double>(3, 1.0), short_x), std::invalid_argument);
    SparsePattern unsorted = a.pattern;
    std::swap(unsorted.column[0], unsorted.column[1]);
    EXPECT_THROW(solver->factorize(unsorted, a.values), std::invalid_argument);
    // More nonzeros than a 32-bit index reaches: refused before anything is read or allocated.
    SparsePattern huge;
    huge.n = 1;
    huge.row_start = {0, std::int64_t{3} << 30};
    EXPECT_THROW(solver->factorize(huge, {}), std::runtime_error);
  }
}

}  // namespace
}  // namespace abut
