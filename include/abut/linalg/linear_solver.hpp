#pragma once
// The linear solve A x = b of the implicit solver behind one small interface, so that another
// library (PETSc, when runs go distributed) can be added as one more implementation. Today:
// CHOLMOD (supernodal Cholesky) for symmetric positive definite matrices and UMFPACK (multifrontal
// LU) for general ones, both from SuiteSparse.
//
// Matrices come as a SparsePattern (full CSR storage, sparse_matrix.hpp) plus its values. The
// expensive symbolic analysis (fill-reducing ordering, elimination tree) depends on the pattern
// only, so it is redone only when the pattern changes; each factorize() call redoes the numeric
// factorisation.
#include <cstdint>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>

#include "abut/linalg/sparse_matrix.hpp"

namespace abut {

// The factorisation broke down: the matrix is singular (to the solver's pivot test) or, for a
// Cholesky solver, not positive definite. equation() is the 0-based row of A where it happened,
// so that the caller can name the node and direction (a dof without stiffness: missing support,
// rigid-body motion, a zero-stiffness material); -1 in the unexpected case that the library
// reports singularity without a zero pivot. Only exact breakdowns are caught: a matrix singular
// to round-off (a floating part with non-integer stiffness) can leave a tiny nonzero pivot and
// factorise without error, so callers should still check their solution.
class SingularMatrixError : public std::runtime_error {
 public:
  SingularMatrixError(std::int64_t equation, const std::string& message)
      : std::runtime_error(message), equation_(equation) {}
  std::int64_t equation() const { return equation_; }

 private:
  std::int64_t equation_;
};

enum class MatrixKind { SymmetricPositiveDefinite, General };

class LinearSolver {
 public:
  LinearSolver() = default;
  LinearSolver(const LinearSolver&) = delete;
  LinearSolver& operator=(const LinearSolver&) = delete;
  virtual ~LinearSolver() = default;

  // Analyses (only when the pattern differs from the last analysed one) and factorises.
  // A symmetric solver reads the lower triangle only (the pattern still holds both).
  // Throws SingularMatrixError when the factorisation breaks down, std::invalid_argument for a
  // malformed pattern, mismatched sizes or a non-finite value, and std::runtime_error when the
  // library fails otherwise (out of memory, more than 2^31 - 1 nonzeros).
  virtual void factorize(const SparsePattern& a, std::span<const double> values) = 0;

  // x = A^-1 rhs with the last successful factorisation (std::logic_error if there is none).
  // rhs and x have n entries and may be the same array.
  virtual void solve(std::span<const double> rhs, std::span<double> x) = 0;

  // "CHOLMOD (supernodal Cholesky)", "UMFPACK (multifrontal LU)": for logs and summaries.
  virtual const char* name() const = 0;

  // Smallest over largest pivot of the last factorisation (CHOLMOD: cholmod_rcond, the square of
  // min/max diag(L) of L L^T; UMFPACK: Info[UMFPACK_RCOND], min/max |diag(U)|): a cheap estimate
  // of the reciprocal condition number. A matrix singular to round-off (a floating part) factorises
  // with pivots ~1e-16 of the others; a callers tests this against a threshold it can justify.
  virtual double reciprocal_condition() const = 0;

  // How many symbolic analyses factorize() has run (for statistics and to test the reuse).
  virtual std::int64_t analysis_count() const = 0;
};

// CHOLMOD for MatrixKind::SymmetricPositiveDefinite, UMFPACK for MatrixKind::General.
std::unique_ptr<LinearSolver> make_linear_solver(MatrixKind kind);

}  // namespace abut
