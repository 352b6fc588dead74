#include "abut/linalg/linear_solver.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "linalg/solver_support.hpp"

namespace abut {

std::unique_ptr<LinearSolver> make_linear_solver(MatrixKind kind) {
  switch (kind) {
    case MatrixKind::SymmetricPositiveDefinite:
      return linalg_detail::make_cholmod_solver();
    case MatrixKind::General:
      return linalg_detail::make_umfpack_solver();
  }
  throw std::invalid_argument("make_linear_solver: unknown matrix kind");
}

namespace linalg_detail {

void check_pattern(const SparsePattern& a, const char* solver) {
  const std::int32_t n = a.n;
  if (n < 0 || static_cast<std::int64_t>(a.row_start.size()) != std::int64_t{n} + 1 ||
      a.row_start.front() != 0) {
    throw std::invalid_argument(
        fmt::format("{}: malformed pattern: row_start must hold n + 1 = {} offsets from 0", solver,
                    std::int64_t{n} + 1));
  }
  // SuiteSparse's int interfaces (umfpack_di_*, cholmod_* after cholmod_start) index the nonzeros
  // with int; the int64 variants (umfpack_dl_*, cholmod_l_*) would be needed beyond this.
  if (a.nonzeros() > std::numeric_limits<int>::max()) {
    throw std::runtime_error(fmt::format(
        "{}: the matrix has {} nonzeros, more than the 32-bit interface used here can index "
        "({}); use a distributed solver or the 64-bit SuiteSparse interface",
        solver, a.nonzeros(), std::numeric_limits<int>::max()));
  }
  if (static_cast<std::int64_t>(a.column.size()) != a.nonzeros()) {
    throw std::invalid_argument(fmt::format("{}: malformed pattern: {} columns for {} nonzeros",
                                            solver, a.column.size(), a.nonzeros()));
  }
  for (std::int32_t r = 0; r < n; ++r) {
    if (a.row_start[r + 1] < a.row_start[r]) {
      throw std::invalid_argument(
          fmt::format("{}: malformed pattern: row_start decreases at row {}", solver, r));
    }
    for (std::int64_t k = a.row_start[r]; k < a.row_start[r + 1]; ++k) {
      const std::int32_t c = a.column[k];
      if (c < 0 || c >= n || (k > a.row_start[r] && c <= a.column[k - 1])) {
        throw std::invalid_argument(
            fmt::format("{}: malformed pattern: row {} has column {} out of range or out of order",
                        solver, r, c));
      }
    }
  }
}

void check_values(const SparsePattern& a, std::span<const double> values, const char* solver) {
  if (static_cast<std::int64_t>(values.size()) != a.nonzeros()) {
    throw std::invalid_argument(fmt::format("{}: {} values for a pattern with {} nonzeros", solver,
                                            values.size(), a.nonzeros()));
  }
  for (std::int32_t r = 0; r < a.n; ++r) {
    for (std::int64_t k = a.row_start[r]; k < a.row_start[r + 1]; ++k) {
      if (!std::isfinite(values[k])) {
        throw std::invalid_argument(
            fmt::format("{}: the matrix entry ({}, {}) is {}", solver, r, a.column[k], values[k]));
      }
    }
  }
}

void check_solve(std::int32_t n, std::size_t rhs, std::size_t x, const char* solver) {
  if (rhs != static_cast<std::size_t>(n) || x != static_cast<std::size_t>(n)) {
    throw std::invalid_argument(fmt::format(
        "{}: right-hand side ({}) and solution ({}) must have n = {} entries", solver, rhs, x, n));
  }
}

}  // namespace linalg_detail
}  // namespace abut
