// Symmetric positive definite solves with CHOLMOD's supernodal Cholesky factorisation
// P A P^T = L L^T (T. A. Davis, CHOLMOD User Guide, SuiteSparse 5.12; the conventions relied on
// are quoted from the comments of cholmod_core.h, which the guide reproduces).
#include <cholmod.h>
#include <fmt/format.h>

#include <algorithm>
#include <memory>

#include "linalg/solver_support.hpp"

namespace abut::linalg_detail {
namespace {

constexpr const char* kName = "CHOLMOD (supernodal Cholesky)";

const char* status_text(int status) {
  switch (status) {
    case CHOLMOD_NOT_INSTALLED:
      return "method not installed";
    case CHOLMOD_OUT_OF_MEMORY:
      return "out of memory";
    case CHOLMOD_TOO_LARGE:
      return "integer overflow (problem too large)";
    case CHOLMOD_INVALID:
      return "invalid input";
    case CHOLMOD_GPU_PROBLEM:
      return "GPU failure";
    default:
      return "unknown error";
  }
}

// Owns the cholmod_common workspace; every CHOLMOD object below is allocated through it.
struct Common {
  cholmod_common c;
  Common() {
    cholmod_start(&c);
    // The factor's name promises supernodal: CHOLMOD_AUTO would switch to a simplicial
    // factorisation for very sparse factors (cholmod_core.h, Common->supernodal).
    c.supernodal = CHOLMOD_SUPERNODAL;
    // No printing: every failure becomes an exception that says what happened.
    c.print = 0;
  }
  ~Common() { cholmod_finish(&c); }
  Common(const Common&) = delete;
  Common& operator=(const Common&) = delete;
};

struct FreeSparse {
  cholmod_common* c;
  void operator()(cholmod_sparse* p) const { cholmod_free_sparse(&p, c); }
};
struct FreeFactor {
  cholmod_common* c;
  void operator()(cholmod_factor* p) const { cholmod_free_factor(&p, c); }
};
struct FreeDense {
  cholmod_common* c;
  void operator()(cholmod_dense* p) const { cholmod_free_dense(&p, c); }
};

class CholmodSolver final : public LinearSolver {
 public:
  void factorize(const SparsePattern& a, std::span<const double> values) override {
    factored_ = false;
    if (!analysed_ || a != pattern_) analyse(a);
    check_values(pattern_, values, kName);
    auto* ax = static_cast<double*>(triangle_->x);
    for (std::size_t k = 0; k < triangle_source_.size(); ++k) ax[k] = values[triangle_source_[k]];

    // cholmod_factorize returns TRUE with Common->status = CHOLMOD_NOT_POSDEF when a pivot is zero
    // or negative; L->minor is then the column of L (in the permuted order P A P^T) where it
    // failed, and L->minor = n on success (cholmod_core.h, cholmod_factor).
    cholmod_factorize(triangle_.get(), factor_.get(), &common_.c);
    if (common_.c.status < CHOLMOD_OK) {
      throw std::runtime_error(fmt::format("{}: numeric factorisation failed: {} (status {})",
                                           kName, status_text(common_.c.status), common_.c.status));
    }
    if (common_.c.status == CHOLMOD_NOT_POSDEF || factor_->minor < factor_->n) {
      // Column k of L is equation Perm[k] of A (cholmod_factor: Perm is the ordering used).
      const auto* perm = static_cast<const int*>(factor_->Perm);
      const std::int64_t equation = perm[factor_->minor];
      throw SingularMatrixError(
          equation,
          fmt::format("{}: the matrix is not positive definite: zero or negative pivot at "
                      "equation {} (0-based; {} of {} columns factorised). A dof without "
                      "stiffness (missing support, rigid-body motion) or a negative stiffness.",
                      kName, equation, factor_->minor, factor_->n));
    }
    rcond_ = cholmod_rcond(factor_.get(), &common_.c);
    factored_ = true;
  }

  void solve(std::span<const double> rhs, std::span<double> x) override {
    if (!factored_) {
      throw std::logic_error(fmt::format("{}: solve() without a successful factorize()", kName));
    }
    check_solve(pattern_.n, rhs.size(), x.size(), kName);
    std::copy(rhs.begin(), rhs.end(), static_cast<double*>(rhs_->x));
    // cholmod_solve2 reuses the solution and workspace (solution_, y_, e_) from call to call
    // instead of allocating them each time (CHOLMOD User Guide, cholmod_solve2).
    cholmod_dense* solution = solution_.release();
    cholmod_dense* y = y_.release();
    cholmod_dense* e = e_.release();
    const int ok = cholmod_solve2(CHOLMOD_A, factor_.get(), rhs_.get(), nullptr, &solution, nullptr,
                                  &y, &e, &common_.c);
    solution_.reset(solution);
    y_.reset(y);
    e_.reset(e);
    if (!ok || common_.c.status < CHOLMOD_OK) {
      throw std::runtime_error(fmt::format("{}: solve failed: {} (status {})", kName,
                                           status_text(common_.c.status), common_.c.status));
    }
    const auto* s = static_cast<const double*>(solution_->x);
    std::copy(s, s + pattern_.n, x.begin());
  }

  const char* name() const override { return kName; }
  std::int64_t analysis_count() const override { return analyses_; }
  double reciprocal_condition() const override { return factored_ ? rcond_ : 0.0; }

 private:
  // The triangle CHOLMOD reads, and the fill-reducing ordering and symbolic factor of the pattern.
  void analyse(const SparsePattern& a) {
    analysed_ = false;
    check_pattern(a, kName);
    factor_.reset();
    triangle_.reset();
    const std::int32_t n = a.n;

    // CHOLMOD takes compressed sparse COLUMN matrices. Row r of our CSR, read as a column, is
    // column r of A^T = A (symmetric), so the entries with column <= row of the CSR form the
    // columns of the UPPER triangle: stype = 1, "use upper triangular part" (cholmod_core.h,
    // cholmod_sparse). The upper form is also the one "cholmod_analyze and cholmod_factorize
    // work fastest" with when a fill-reducing ordering is used (cholmod_core.h, prefer_upper).
    std::int64_t kept = 0;
    for (std::int32_t r = 0; r < n; ++r) {
      for (std::int64_t k = a.row_start[r]; k < a.row_start[r + 1]; ++k) kept += a.column[k] <= r;
    }
    triangle_.reset(cholmod_allocate_sparse(n, n, kept, /*sorted=*/1, /*packed=*/1, /*stype=*/1,
                                            CHOLMOD_REAL, &common_.c));
    if (!triangle_) fail("allocating the matrix");
    auto* cp = static_cast<int*>(triangle_->p);
    auto* ci = static_cast<int*>(triangle_->i);
    triangle_source_.clear();
    triangle_source_.reserve(kept);
    cp[0] = 0;
    for (std::int32_t r = 0; r < n; ++r) {
      for (std::int64_t k = a.row_start[r]; k < a.row_start[r + 1] && a.column[k] <= r; ++k) {
        ci[triangle_source_.size()] = a.column[k];
        triangle_source_.push_back(k);
      }
      cp[r + 1] = static_cast<int>(triangle_source_.size());
    }

    factor_.reset(cholmod_analyze(triangle_.get(), &common_.c));
    if (!factor_ || common_.c.status < CHOLMOD_OK) fail("symbolic analysis");
    rhs_.reset(cholmod_allocate_dense(n, 1, n, CHOLMOD_REAL, &common_.c));
    if (!rhs_) fail("allocating the right-hand side");
    solution_.reset();
    y_.reset();
    e_.reset();
    pattern_ = a;
    analysed_ = true;
    ++analyses_;
  }

  [[noreturn]] void fail(const char* what) const {
    throw std::runtime_error(fmt::format("{}: {} failed: {} (status {})", kName, what,
                                         status_text(common_.c.status), common_.c.status));
  }

  // Declared first: destroyed last, after every object allocated through it.
  Common common_;
  std::unique_ptr<cholmod_sparse, FreeSparse> triangle_{nullptr, FreeSparse{&common_.c}};
  std::unique_ptr<cholmod_factor, FreeFactor> factor_{nullptr, FreeFactor{&common_.c}};
  std::unique_ptr<cholmod_dense, FreeDense> rhs_{nullptr, FreeDense{&common_.c}};
  std::unique_ptr<cholmod_dense, FreeDense> solution_{nullptr, FreeDense{&common_.c}};
  std::unique_ptr<cholmod_dense, FreeDense> y_{nullptr, FreeDense{&common_.c}};
  std::unique_ptr<cholmod_dense, FreeDense> e_{nullptr, FreeDense{&common_.c}};
  SparsePattern pattern_;                      // the analysed pattern
  std::vector<std::int64_t> triangle_source_;  // CSR index of each entry of triangle_
  bool analysed_ = false;
  bool factored_ = false;
  double rcond_ = 0.0;
  std::int64_t analyses_ = 0;
};

}  // namespace

std::unique_ptr<LinearSolver> make_cholmod_solver() { return std::make_unique<CholmodSolver>(); }

}  // namespace abut::linalg_detail
