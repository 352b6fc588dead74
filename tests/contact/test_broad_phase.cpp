#include "abut/contact/broad_phase.hpp"

#include <gtest/gtest.h>

#include <random>

namespace abut {
namespace {

// The bucket grid must return exactly the boxes that contain each point: compare with the
// all-pairs search on a random cloud of boxes of mixed sizes.
TEST(BucketGrid, FindsExactlyTheBruteForceCandidates) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> pos(-5.0, 5.0), size(0.01, 1.5);
  std::vector<Box> boxes(800);
  for (Box& b : boxes)
    for (int k = 0; k < 3; ++k) {
      b.lo[k] = pos(rng) * (k == 2 ? 0.1 : 1.0);
      b.hi[k] = b.lo[k] + size(rng) * (k == 2 ? 0.1 : 1.0);
    }
  std::vector<double> x(3000), y(3000), z(3000);
  std::uniform_real_distribution<double> wide(-6.0, 7.0);
  for (std::size_t p = 0; p < x.size(); ++p) {
    x[p] = wide(rng);
    y[p] = wide(rng);
    z[p] = wide(rng) * 0.1;
  }
  // Some points exactly on box faces.
  x[0] = boxes[3].lo[0], y[0] = boxes[3].lo[1], z[0] = boxes[3].hi[2];
  BucketGrid grid;
  grid.build(boxes);
  CandidateList found;
  grid.query(x, y, z, found);
  ASSERT_EQ(found.point_count(), x.size());
  std::size_t total = 0;
  for (std::size_t p = 0; p < x.size(); ++p) {
    std::vector<std::int32_t> expected;
    for (std::size_t b = 0; b < boxes.size(); ++b)
      if (boxes[b].contains(x[p], y[p], z[p])) expected.push_back(static_cast<std::int32_t>(b));
    const std::vector<std::int32_t> got(found.facets.begin() + static_cast<std::ptrdiff_t>(found.offsets[p]),
                                        found.facets.begin() + static_cast<std::ptrdiff_t>(found.offsets[p + 1]));
    EXPECT_EQ(got, expected) << "point " << p;
    total += expected.size();
  }
  EXPECT_GT(total, 300u);  // the cloud is dense enough to test something
  EXPECT_LE(grid.cell_count(), 2 * boxes.size() + 64);
}

// Regions (an S2S point's cell): exactly the boxes that overlap each, in facet order, each
// once, though a pair shares several grid cells.
TEST(BucketGrid, RegionsFindExactlyTheBruteForceOverlaps) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> pos(-5.0, 5.0), size(0.01, 1.5);
  auto random_boxes = [&](std::size_t n, double scale) {
    std::vector<Box> boxes(n);
    for (Box& b : boxes)
      for (int k = 0; k < 3; ++k) {
        b.lo[k] = pos(rng);
        b.hi[k] = b.lo[k] + scale * size(rng);
      }
    return boxes;
  };
  const std::vector<Box> boxes = random_boxes(600, 1.0);
  std::vector<Box> regions = random_boxes(1500, 0.7);
  regions[0] = boxes[5];                        // the same box
  regions[1].lo = regions[1].hi = boxes[9].hi;  // a point on a corner
  regions[2].lo = {-100, -100, -100};           // reaching past the grid
  regions[2].hi = {-99, -99, -99};              // and wholly outside it
  BucketGrid grid;
  grid.build(boxes);
  CandidateList found;
  grid.query(regions, found);
  ASSERT_EQ(found.point_count(), regions.size());
  std::size_t total = 0;
  for (std::size_t p = 0; p < regions.size(); ++p) {
    std::vector<std::int32_t> expected;
    for (std::size_t b = 0; b < boxes.size(); ++b)
      if (boxes[b].overlaps(regions[p])) expected.push_back(static_cast<std::int32_t>(b));
    const std::vector<std::int32_t> got(
        found.facets.begin() + static_cast<std::ptrdiff_t>(found.offsets[p]),
        found.facets.begin() + static_cast<std::ptrdiff_t>(found.offsets[p + 1]));
    EXPECT_EQ(got, expected) << "region " << p;
    total += expected.size();
  }
  EXPECT_GT(total, 1000u);
}

// Issue 28: the long sides of a slab are strips lying side by side (n boxes 1 long and 1/n
// wide). The grid's cells follow the boxes' extent along each axis, so a point near a strip
// visits O(1) boxes, not O(n): each grid cell holds a handful of boxes.
TEST(BucketGrid, SideBySideStripsKeepTheCellsSmall) {
  for (const std::size_t n : {1000u, 8000u}) {
    std::vector<Box> strips(n);
    const double width = 1.0 / static_cast<double>(n);
    for (std::size_t i = 0; i < n; ++i)
      strips[i] = Box{{-0.25, width * static_cast<double>(i), 0.0},
                      {0.25, width * static_cast<double>(i + 1), 1.0}};
    BucketGrid grid;
    grid.build(strips);
    EXPECT_GE(grid.cell_count(), n / 4) << n;  // cells along the strips' narrow axis
    // Every point in the middle of a strip lies in that strip only.
    std::vector<double> x(n, 0.0), y(n), z(n, 0.5);
    for (std::size_t i = 0; i < n; ++i) y[i] = width * (static_cast<double>(i) + 0.5);
    CandidateList found;
    grid.query(x, y, z, found);
    EXPECT_EQ(found.facets.size(), n);
  }
}

TEST(BucketGrid, EmptyAndDegenerateInputs) {
  BucketGrid grid;
  grid.build({});
  CandidateList found;
  const double x[1] = {0.0};
  grid.query(x, x, x, found);
  EXPECT_EQ(found.offsets, (std::vector<std::size_t>{0, 0}));
  const Box point_box{{1, 1, 1}, {1, 1, 1}};  // zero-size box
  grid.build({&point_box, 1});
  const double one[1] = {1.0};
  grid.query(one, one, one, found);
  EXPECT_EQ(found.facets, (std::vector<std::int32_t>{0}));
}

}  // namespace
}  // namespace abut
