#pragma once
// What the linear solver implementations share (internal to the linalg layer).
#include <cstddef>
#include <memory>
#include <span>

#include "abut/linalg/linear_solver.hpp"

namespace abut::linalg_detail {

std::unique_ptr<LinearSolver> make_cholmod_solver();
std::unique_ptr<LinearSolver> make_umfpack_solver();

// Checks that the pattern is well formed (row_start of n + 1 non-decreasing offsets from 0,
// columns in range, sorted and unique in each row) and fits the 32-bit integer interfaces of
// SuiteSparse (std::runtime_error if not). Run once per new pattern: O(nnz).
void check_pattern(const SparsePattern& a, const char* solver);

// Checks that values has one finite entry per nonzero. The factorisations would not report a NaN:
// CHOLMOD's supernodal factorisation stops only at a zero or negative pivot, never at a NaN one
// (comment in CHOLMOD/Supernodal/t_cholmod_super_numeric.c), and UMFPACK tests pivots against 0.
void check_values(const SparsePattern& a, std::span<const double> values, const char* solver);

// Checks that rhs and x have n entries.
void check_solve(std::int32_t n, std::size_t rhs, std::size_t x, const char* solver);

}  // namespace abut::linalg_detail
