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
