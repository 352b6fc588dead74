// General (unsymmetric or indefinite) solves with UMFPACK's multifrontal LU factorisation
// P R A Q = L U (T. A. Davis, UMFPACK User Guide, SuiteSparse 5.12; the conventions relied on are
// quoted from the comments of umfpack_*.h, which the guide reproduces in its reference section).
#include <fmt/format.h>
#include <umfpack.h>

#include <algorithm>
#include <array>
#include <memory>
#include <vector>

#include "linalg/solver_support.hpp"

namespace abut::linalg_detail {
namespace {

constexpr const char* kName = "UMFPACK (multifrontal LU)";

struct FreeSymbolic {
  void operator()(void* p) const { umfpack_di_free_symbolic(&p); }
};
struct FreeNumeric {
  void operator()(void* p) const { umfpack_di_free_numeric(&p); }
};

// Why we store A^T: UMFPACK takes compressed sparse COLUMN matrices (umfpack_symbolic.h: Ap, Ai,
// Ax). Our CSR arrays of A, read as CSC, are exactly A^T, so UMFPACK factorises A^T and every solve
// asks for sys = UMFPACK_At, "A'x = b" with A' = (A^T)^T = A (umfpack.h; for real matrices A' and
// A.' are the same). This needs no transposed copy of the values at each factorisation, and
// umfpack_di_solve does its iterative refinement for UMFPACK_At as for UMFPACK_A.
class UmfpackSolver final : public LinearSolver {
 public:
  UmfpackSolver() { umfpack_di_defaults(control_.data()); }

  void factorize(const SparsePattern& a, std::span<const double> values) override {
    numeric_.reset();
    if (!symbolic_ || a != pattern_) analyse(a, values);
    check_values(pattern_, values, kName);
    // The values are kept: umfpack_di_solve reads the matrix again for iterative refinement.
    values_.assign(values.begin(), values.end());

    void* numeric = nullptr;
    const int status = umfpack_di_numeric(start_.data(), pattern_.column.data(), values_.data(),
                                          symbolic_.get(), &numeric, control_.data(), info_.data());
    std::unique_ptr<void, FreeNumeric> owned(numeric);
    // UMFPACK_WARNING_singular_matrix: "Numeric factorization was successful, but the matrix is
    // singular ... you will get a divide by zero in umfpack_*_*solve" (umfpack_numeric.h).
    if (status == UMFPACK_WARNING_singular_matrix) {
      const std::int64_t equation = zero_pivot_equation(owned.get());
      throw SingularMatrixError(
          equation,
          fmt::format("{}: the matrix is singular: zero pivot at equation {} (0-based). A dof "
                      "without stiffness (missing support, rigid-body motion) or dependent "
                      "equations.",
                      kName, equation));
    }
    if (status != UMFPACK_OK) fail("numeric factorisation", status);
    rcond_ = info_[UMFPACK_RCOND];
    numeric_ = std::move(owned);
  }

  void solve(std::span<const double> rhs, std::span<double> x) override {
    if (!numeric_) {
      throw std::logic_error(fmt::format("{}: solve() without a successful factorize()", kName));
    }
    check_solve(pattern_.n, rhs.size(), x.size(), kName);
    // A copy, so that rhs and x may be the same array (UMFPACK reads b while writing x).
    rhs_.assign(rhs.begin(), rhs.end());
    const int status =
        umfpack_di_solve(UMFPACK_At, start_.data(), pattern_.column.data(), values_.data(),
                         x.data(), rhs_.data(), numeric_.get(), control_.data(), info_.data());
    if (status != UMFPACK_OK) fail("solve", status);
  }

  const char* name() const override { return kName; }
  std::int64_t analysis_count() const override { return analyses_; }
  double reciprocal_condition() const override { return numeric_ ? rcond_ : 0.0; }

 private:
  // Column pre-ordering (COLAMD or AMD, chosen by UMFPACK's strategy) and symbolic analysis.
  void analyse(const SparsePattern& a, std::span<const double> values) {
    symbolic_.reset();
    check_pattern(a, kName);
    check_values(a, values, kName);
    pattern_ = a;
    // UMFPACK's _di_ interface indexes with int (check_pattern ensured nnz fits).
    start_.assign(a.row_start.begin(), a.row_start.end());
    void* symbolic = nullptr;
    // The values only guide the strategy here; the analysis holds for any values on this pattern.
    const int status = umfpack_di_symbolic(a.n, a.n, start_.data(), pattern_.column.data(),
                                           values.data(), &symbolic, control_.data(), info_.data());
    symbolic_.reset(symbolic);
    if (status != UMFPACK_OK) fail("symbolic analysis", status);
    ++analyses_;
  }

  // UMFPACK reports singularity but not where. The k-th pivot U(k, k) is zero for column Q[k] of
  // the factorised matrix (umfpack_get_numeric.h: Q[k] = j, Dx = diag(U)); a column of A^T is a
  // row of A, that is an equation.
  std::int64_t zero_pivot_equation(void* numeric) const {
    const std::int32_t n = pattern_.n;
    std::vector<int> q(n);
    std::vector<double> diagonal(n);
    const int status =
        umfpack_di_get_numeric(nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr,
                               q.data(), diagonal.data(), nullptr, nullptr, numeric);
    if (status != UMFPACK_OK) fail("reading the singular factorisation", status);
    const auto zero = std::find(diagonal.begin(), diagonal.end(), 0.0);
    return zero == diagonal.end() ? -1 : q[zero - diagonal.begin()];
  }

  [[noreturn]] static void fail(const char* what, int status) {
    const char* text = status == UMFPACK_ERROR_out_of_memory ? "out of memory"
                       : status == UMFPACK_ERROR_invalid_matrix
                           ? "invalid matrix"
                           : "error (see umfpack.h for the status code)";
    throw std::runtime_error(
        fmt::format("{}: {} failed: {} (status {})", kName, what, text, status));
  }

  std::array<double, UMFPACK_CONTROL> control_{};
  std::array<double, UMFPACK_INFO> info_{};
  SparsePattern pattern_;   // the analysed pattern: its arrays are A^T in CSC for UMFPACK
  std::vector<int> start_;  // pattern_.row_start as int, for the _di_ interface
  std::vector<double> values_;
  std::vector<double> rhs_;
  std::unique_ptr<void, FreeSymbolic> symbolic_;
  std::unique_ptr<void, FreeNumeric> numeric_;
  double rcond_ = 0.0;
  std::int64_t analyses_ = 0;
};

}  // namespace

std::unique_ptr<LinearSolver> make_umfpack_solver() { return std::make_unique<UmfpackSolver>(); }

}  // namespace abut::linalg_detail
