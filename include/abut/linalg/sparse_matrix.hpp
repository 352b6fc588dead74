#pragma once
// Sparse matrices for the implicit solver: the compressed sparse row (CSR) pattern of an n x n
// matrix and its assembly from element matrices. Plain arrays only, so that the linear solvers
// (linear_solver.hpp) and any caller (elements, contact pairs, a test) share one format.
//
// Assembly is deterministic: every CSR value is the sum of its contributions in a fixed order,
// whatever the number of OpenMP threads, so a run is bitwise identical with 1 or N threads
// (docs/architecture.md).
#include <cstdint>
#include <span>
#include <vector>

namespace abut {

// n x n sparse matrix pattern in compressed sparse row form, full storage (both triangles even
// when the matrix is symmetric), columns sorted and unique within each row. The columns of row r
// are column[row_start[r]] .. column[row_start[r + 1] - 1].
struct SparsePattern {
  std::int32_t n = 0;
  std::vector<std::int64_t> row_start;  // n + 1 offsets into column; row_start[0] == 0
  std::vector<std::int32_t> column;     // nnz column indices
  std::int64_t nonzeros() const { return row_start.empty() ? 0 : row_start.back(); }
  friend bool operator==(const SparsePattern&, const SparsePattern&) = default;
};

// Assembly of "element" matrices. An element is anything with a dense square matrix over a list
// of global dofs: a finite element, a contact pair, a spring. The pattern is built once from the
// elements' dof lists; entries with dof < 0 (a fixed or eliminated dof) are skipped. A dof that no
// element touches gets an empty row (the matrix is then singular; the caller decides).
//
// assemble() adds every element's dense matrix into the CSR values in a FIXED order: for each CSR
// slot, its contributions in element order, then in local-entry order (row-major within the
// element matrix, so a dof listed twice in one element is summed too). Rows are assembled in
// parallel with OpenMP, each by one thread, so the result is bitwise identical for any number of
// threads.
class SparseAssembly {
 public:
  // element_dofs: the dof lists of all elements concatenated; element_start: offsets into it
  // (size elements + 1, element_start[0] == 0, non-decreasing, last == element_dofs.size()).
  // Every dof is < n. Throws std::invalid_argument otherwise.
  SparseAssembly(std::int32_t n, std::span<const std::int64_t> element_start,
                 std::span<const std::int32_t> element_dofs);

  const SparsePattern& pattern() const { return pattern_; }
  std::int64_t element_count() const { return static_cast<std::int64_t>(value_start_.size()) - 1; }

  // Element e's dense matrix is row-major, m_e x m_e with m_e its dof count (skipped dofs
  // included), stored in element_values from value_start(e) = sum over earlier elements of m^2.
  std::int64_t value_start(std::int64_t element) const { return value_start_.at(element); }
  std::int64_t element_value_count() const { return value_start_.back(); }

  // csr_values (resized to pattern().nonzeros()) = sum of the element matrices. element_values
  // must hold element_value_count() values (std::invalid_argument otherwise).
  void assemble(std::span<const double> element_values, std::vector<double>& csr_values) const;

 private:
  SparsePattern pattern_;
  std::vector<std::int64_t> value_start_;  // elements + 1
  // The element rows adding into each CSR row, in element order then local row order: source s of
  // row r (row_source_start_[r] <= s < row_source_start_[r + 1]) is the element row whose values
  // start at element_values[source_value_start_[s]] and has source_width_[s] entries.
  std::vector<std::int64_t> row_source_start_;  // n + 1
  std::vector<std::int64_t> source_value_start_;
  std::vector<std::int32_t> source_width_;
  // For each element value: its position within its CSR row (the slot is row_start[row] + it),
  // or -1 when its row or column dof is skipped.
  std::vector<std::int32_t> entry_position_;
};

// y = A x for the CSR matrix (pattern, values); parallel over rows, deterministic. For residual
// checks and tests. Throws std::invalid_argument when a size does not match the pattern.
void multiply(const SparsePattern& pattern, std::span<const double> values,
              std::span<const double> x, std::span<double> y);

}  // namespace abut
