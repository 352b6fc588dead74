#include "abut/linalg/sparse_matrix.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "abut/core/parallel.hpp"

namespace abut {
namespace {

// Row loops do a few dozen to a few hundred additions per row: worth a thread team from a few
// hundred rows on (the same ratio as the element loops, kParallelMinimum / 8). Dynamic schedule:
// row lengths vary (contact rows, boundary rows), and a row's result does not depend on which
// thread computes it.
constexpr std::int64_t kParallelRows = kParallelMinimum / 8;

void check_elements(std::int32_t n, std::span<const std::int64_t> element_start,
                    std::span<const std::int32_t> element_dofs) {
  if (n < 0) throw std::invalid_argument(fmt::format("SparseAssembly: negative size n = {}", n));
  if (element_start.empty() || element_start.front() != 0 ||
      element_start.back() != static_cast<std::int64_t>(element_dofs.size())) {
    throw std::invalid_argument(
        "SparseAssembly: element_start must have one offset per element plus one, start at 0 and "
        "end at the number of element dofs");
  }
  for (std::size_t e = 0; e + 1 < element_start.size(); ++e) {
    if (element_start[e + 1] < element_start[e]) {
      throw std::invalid_argument(
          fmt::format("SparseAssembly: element_start decreases at element {}", e));
    }
  }
  for (std::size_t k = 0; k < element_dofs.size(); ++k) {
    if (element_dofs[k] >= n) {
      throw std::invalid_argument(
          fmt::format("SparseAssembly: element dof {} (entry {}) is out of range for n = {}",
                      element_dofs[k], k, n));
    }
  }
}

}  // namespace

SparseAssembly::SparseAssembly(std::int32_t n, std::span<const std::int64_t> element_start,
                               std::span<const std::int32_t> element_dofs) {
  check_elements(n, element_start, element_dofs);
  const auto elements = static_cast<std::int64_t>(element_start.size()) - 1;
  const auto dofs_of = [&](std::int64_t e) {
    return element_dofs.subspan(element_start[e], element_start[e + 1] - element_start[e]);
  };

  // Values of element e start after the m^2 values of every earlier element.
  value_start_.assign(elements + 1, 0);
  std::vector<std::int64_t> kept(elements, 0);  // dofs of e that are not skipped
  for (std::int64_t e = 0; e < elements; ++e) {
    const auto m = static_cast<std::int64_t>(dofs_of(e).size());
    value_start_[e + 1] = value_start_[e] + m * m;
    kept[e] = std::count_if(dofs_of(e).begin(), dofs_of(e).end(), [](auto d) { return d >= 0; });
  }

  // Sources of each row, filled serially in element order then local row order: this loop fixes
  // the summation order of assemble().
  row_source_start_.assign(static_cast<std::size_t>(n) + 1, 0);
  for (const std::int32_t d : element_dofs) {
    if (d >= 0) ++row_source_start_[d + 1];
  }
  for (std::int32_t r = 0; r < n; ++r) row_source_start_[r + 1] += row_source_start_[r];
  const std::int64_t sources = row_source_start_[n];
  source_value_start_.resize(sources);
  source_width_.resize(sources);
  std::vector<std::int64_t> source_element(sources);
  {
    std::vector<std::int64_t> next(row_source_start_.begin(), row_source_start_.end() - 1);
    for (std::int64_t e = 0; e < elements; ++e) {
      const auto dofs = dofs_of(e);
      const auto m = static_cast<std::int64_t>(dofs.size());
      for (std::int64_t a = 0; a < m; ++a) {
        if (dofs[a] < 0) continue;
        const std::int64_t s = next[dofs[a]]++;
        source_value_start_[s] = value_start_[e] + a * m;
        source_width_[s] = static_cast<std::int32_t>(m);
        source_element[s] = e;
      }
    }
  }

  // Columns of each row: gather the kept dofs of its elements, sort, drop duplicates.
  std::vector<std::int64_t> gathered_start(static_cast<std::size_t>(n) + 1, 0);
  for (std::int32_t r = 0; r < n; ++r) {
    std::int64_t count = 0;
    for (std::int64_t s = row_source_start_[r]; s < row_source_start_[r + 1]; ++s) {
      count += kept[source_element[s]];
    }
    gathered_start[r + 1] = gathered_start[r] + count;
  }
  std::vector<std::int32_t> gathered(gathered_start[n]);
  std::vector<std::int64_t> row_length(n, 0);
#pragma omp parallel for schedule(dynamic, 64) if (n >= kParallelRows)
  for (std::int32_t r = 0; r < n; ++r) {
    auto out = gathered.begin() + gathered_start[r];
    const auto first = out;
    for (std::int64_t s = row_source_start_[r]; s < row_source_start_[r + 1]; ++s) {
      out = std::copy_if(dofs_of(source_element[s]).begin(), dofs_of(source_element[s]).end(), out,
                         [](auto d) { return d >= 0; });
    }
    std::sort(first, out);
    row_length[r] = std::unique(first, out) - first;
  }
  pattern_.n = n;
  pattern_.row_start.assign(static_cast<std::size_t>(n) + 1, 0);
  for (std::int32_t r = 0; r < n; ++r) {
    pattern_.row_start[r + 1] = pattern_.row_start[r] + row_length[r];
  }
  pattern_.column.resize(pattern_.row_start[n]);
#pragma omp parallel for schedule(static) if (n >= kParallelRows)
  for (std::int32_t r = 0; r < n; ++r) {
    std::copy_n(gathered.begin() + gathered_start[r], row_length[r],
                pattern_.column.begin() + pattern_.row_start[r]);
  }

  // Position of every element value in its CSR row. Each element row belongs to exactly one CSR
  // row, so the threads write disjoint entries.
  entry_position_.assign(value_start_.back(), -1);
#pragma omp parallel for schedule(dynamic, 64) if (n >= kParallelRows)
  for (std::int32_t r = 0; r < n; ++r) {
    const auto begin = pattern_.column.begin() + pattern_.row_start[r];
    const auto end = pattern_.column.begin() + pattern_.row_start[r + 1];
    for (std::int64_t s = row_source_start_[r]; s < row_source_start_[r + 1]; ++s) {
      const auto dofs = dofs_of(source_element[s]);
      for (std::size_t b = 0; b < dofs.size(); ++b) {
        if (dofs[b] < 0) continue;
        entry_position_[source_value_start_[s] + static_cast<std::int64_t>(b)] =
            static_cast<std::int32_t>(std::lower_bound(begin, end, dofs[b]) - begin);
      }
    }
  }
}

void SparseAssembly::assemble(std::span<const double> element_values,
                              std::vector<double>& csr_values) const {
  if (static_cast<std::int64_t>(element_values.size()) != element_value_count()) {
    throw std::invalid_argument(
        fmt::format("SparseAssembly::assemble: {} element values given, {} expected",
                    element_values.size(), element_value_count()));
  }
  csr_values.assign(pattern_.nonzeros(), 0.0);
  const std::int32_t n = pattern_.n;
  // One thread per row, and within the row the sources in their fixed order: the sum of each slot
  // is formed in the same order whatever the thread count.
#pragma omp parallel for schedule(dynamic, 64) if (n >= kParallelRows)
  for (std::int32_t r = 0; r < n; ++r) {
    double* row = csr_values.data() + pattern_.row_start[r];
    for (std::int64_t s = row_source_start_[r]; s < row_source_start_[r + 1]; ++s) {
      const std::int64_t first = source_value_start_[s];
      for (std::int64_t k = first; k < first + source_width_[s]; ++k) {
        const std::int32_t position = entry_position_[k];
        if (position >= 0) row[position] += element_values[k];
      }
    }
  }
}

void multiply(const SparsePattern& pattern, std::span<const double> values,
              std::span<const double> x, std::span<double> y) {
  const std::int32_t n = pattern.n;
  if (static_cast<std::int64_t>(pattern.row_start.size()) != std::int64_t{n} + 1 ||
      static_cast<std::int64_t>(values.size()) != pattern.nonzeros() ||
      static_cast<std::int64_t>(x.size()) != n || static_cast<std::int64_t>(y.size()) != n) {
    throw std::invalid_argument(fmt::format(
        "multiply: sizes do not match the {} x {} pattern with {} nonzeros (values {}, x {}, y {})",
        n, n, pattern.nonzeros(), values.size(), x.size(), y.size()));
  }
#pragma omp parallel for schedule(static) if (n >= kParallelMinimum)
  for (std::int32_t r = 0; r < n; ++r) {
    double sum = 0.0;
    for (std::int64_t k = pattern.row_start[r]; k < pattern.row_start[r + 1]; ++k) {
      sum += values[k] * x[pattern.column[k]];
    }
    y[r] = sum;
  }
}

}  // namespace abut
