#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <bit>
#include <map>
#include <random>
#include <utility>
#include <vector>

#include "abut/linalg/sparse_matrix.hpp"

namespace abut {
namespace {

// Six dofs; dof 5 belongs to no element, -1 is a fixed dof, element 4 is empty and element 5 lists
// dof 1 twice.
const std::vector<std::int64_t> kStart = {0, 3, 6, 8, 10, 10, 12};
const std::vector<std::int32_t> kDofs = {0, 1, 2, /**/ 2, -1, 3, /**/ 3, 0, /**/ -1, 4, /**/ 1, 1};

// Element values numbered 1, 2, 3, ...: all distinct, so a misplaced value shows.
std::vector<double> numbered_values(const SparseAssembly& assembly) {
  std::vector<double> v(assembly.element_value_count());
  for (std::size_t k = 0; k < v.size(); ++k) v[k] = 1.0 + static_cast<double>(k) * 0.37;
  return v;
}

// The reference: each element value added to its (row, column) in element order, then local
// (row-major) order: the order the assembly promises, so the sums must match bit for bit.
std::map<std::pair<int, int>, double> reference_sum(std::span<const std::int64_t> start,
                                                    std::span<const std::int32_t> dofs,
                                                    std::span<const double> values) {
  std::map<std::pair<int, int>, double> sum;
  std::int64_t k = 0;
  for (std::size_t e = 0; e + 1 < start.size(); ++e) {
    const std::int64_t m = start[e + 1] - start[e];
    for (std::int64_t a = 0; a < m; ++a) {
      for (std::int64_t b = 0; b < m; ++b, ++k) {
        const int i = dofs[start[e] + a], j = dofs[start[e] + b];
        if (i >= 0 && j >= 0) sum[{i, j}] += values[k];
      }
    }
  }
  return sum;
}

std::map<std::pair<int, int>, double> as_map(const SparsePattern& p, std::span<const double> v) {
  std::map<std::pair<int, int>, double> m;
  for (int r = 0; r < p.n; ++r) {
    for (std::int64_t k = p.row_start[r]; k < p.row_start[r + 1]; ++k) m[{r, p.column[k]}] = v[k];
  }
  return m;
}

TEST(SparseAssembly, PatternOfOverlappingElementsEqualsHandBuiltPattern) {
  const SparseAssembly assembly(6, kStart, kDofs);
  SparsePattern expected;
  expected.n = 6;
  // Row 0: elements 0 {0,1,2} and 2 {3,0}; row 1: elements 0 and 5; row 2: elements 0 and 1
  // {2,3}; row 3: elements 1 and 2; row 4: element 3 {4}; row 5: no element.
  expected.row_start = {0, 4, 7, 11, 14, 15, 15};
  expected.column = {0, 1, 2, 3, /**/ 0, 1, 2, /**/ 0, 1, 2, 3, /**/ 0, 2, 3, /**/ 4};
  EXPECT_EQ(assembly.pattern(), expected);
  EXPECT_EQ(assembly.pattern().nonzeros(), 15);
  EXPECT_EQ(assembly.element_count(), 6);
  // Values of element e start after the m^2 of the earlier ones: 9, 9, 4, 4, 0, 4.
  EXPECT_EQ(assembly.value_start(1), 9);
  EXPECT_EQ(assembly.value_start(3), 22);
  EXPECT_EQ(assembly.value_start(5), 26);
  EXPECT_EQ(assembly.element_value_count(), 30);
}

TEST(SparseAssembly, AssemblyEqualsDenseReferenceSum) {
  const SparseAssembly assembly(6, kStart, kDofs);
  const std::vector<double> values = numbered_values(assembly);
  std::vector<double> csr = {42.0};  // stale content must be overwritten
  assembly.assemble(values, csr);
  ASSERT_EQ(static_cast<std::int64_t>(csr.size()), assembly.pattern().nonzeros());
  // Same keys (no entry lost, none invented) and bitwise the same sums.
  EXPECT_EQ(as_map(assembly.pattern(), csr), reference_sum(kStart, kDofs, values));
  // Spot checks by hand: (1, 1) gets element 0's local (1, 1) = value 4 and all four entries of
  // element 5 (values 26..29); (3, 0) gets element 2's local (0, 1) = value 19.
  const auto v = [&](int k) { return 1.0 + k * 0.37; };
  EXPECT_DOUBLE_EQ(csr[5], v(4) + v(26) + v(27) + v(28) + v(29));
  EXPECT_DOUBLE_EQ(csr[11], v(19));
}

TEST(SparseAssembly, RejectsInconsistentInput) {
  const std::vector<std::int32_t> out_of_range = {0, 6};
  const std::vector<std::int64_t> two = {0, 2};
  EXPECT_THROW(SparseAssembly(6, two, out_of_range), std::invalid_argument);
  const std::vector<std::int64_t> short_start = {0, 1};
  EXPECT_THROW(SparseAssembly(6, short_start, out_of_range), std::invalid_argument);
  const std::vector<std::int64_t> decreasing = {0, 2, 1, 2};
  EXPECT_THROW(SparseAssembly(6, decreasing, out_of_range), std::invalid_argument);
  const SparseAssembly assembly(6, kStart, kDofs);
  std::vector<double> csr;
  std::vector<double> too_few(assembly.element_value_count() - 1);
  EXPECT_THROW(assembly.assemble(too_few, csr), std::invalid_argument);
}

TEST(SparseAssembly, MultiplyEqualsDenseProduct) {
  const SparseAssembly assembly(6, kStart, kDofs);
  std::vector<double> csr;
  assembly.assemble(numbered_values(assembly), csr);
  const std::vector<double> x = {1.0, -2.0, 0.5, 3.0, -1.5, 7.0};
  std::vector<double> y(6, -99.0);
  multiply(assembly.pattern(), csr, x, y);
  std::vector<double> expected(6, 0.0);
  for (const auto& [ij, a] : as_map(assembly.pattern(), csr))
    expected[ij.first] += a * x[ij.second];
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(y[i], expected[i], 1e-12 * std::abs(expected[i])) << i;
  EXPECT_EQ(y[5], 0.0);  // empty row
  std::vector<double> short_y(5);
  EXPECT_THROW(multiply(assembly.pattern(), csr, x, short_y), std::invalid_argument);
}

// A random "mesh": elements of 2 to 12 dofs drawn near each other (as a mesh numbers them), some
// fixed (-1), some repeated; random values in [-1, 1].
struct RandomMesh {
  std::int32_t n = 6000;
  std::vector<std::int64_t> start = {0};
  std::vector<std::int32_t> dofs;
  explicit RandomMesh(int elements) {
    std::mt19937_64 random(20240611);
    std::uniform_int_distribution<int> size(2, 12), offset(-40, 40), centre(0, n - 1);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int e = 0; e < elements; ++e) {
      const int c = centre(random), m = size(random);
      for (int a = 0; a < m; ++a) {
        const int d = std::clamp(c + offset(random), 0, n - 1);
        dofs.push_back(unit(random) < 0.1 ? -1 : d);
      }
      start.push_back(static_cast<std::int64_t>(dofs.size()));
    }
  }
};

TEST(SparseAssembly, BitwiseIdenticalForOneAndTwoThreads) {
  const RandomMesh mesh(4000);
  const int threads_before = omp_get_max_threads();
  omp_set_num_threads(1);
  const SparseAssembly serial(mesh.n, mesh.start, mesh.dofs);
  std::vector<double> values(serial.element_value_count());
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (double& v : values) v = unit(random);
  std::vector<double> one;
  serial.assemble(values, one);

  omp_set_num_threads(2);
  const SparseAssembly parallel(mesh.n, mesh.start, mesh.dofs);
  std::vector<double> two;
  parallel.assemble(values, two);
  omp_set_num_threads(threads_before);

  ASSERT_EQ(serial.pattern(), parallel.pattern());
  ASSERT_EQ(one.size(), two.size());
  ASSERT_GT(one.size(), 50000u);  // large enough for both threads to get rows
  std::size_t differing = 0;
  for (std::size_t k = 0; k < one.size(); ++k) {
    differing += std::bit_cast<std::uint64_t>(one[k]) != std::bit_cast<std::uint64_t>(two[k]);
  }
  EXPECT_EQ(differing, 0u);
  // And both follow the documented order: element order, then local-entry order.
  EXPECT_EQ(as_map(serial.pattern(), one), reference_sum(mesh.start, mesh.dofs, values));
}

}  // namespace
}  // namespace abut
