#include "abut/contact/broad_phase.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include "abut/core/parallel.hpp"

namespace abut {

void BucketGrid::build(std::span<const Box> boxes) {
  boxes_.assign(boxes.begin(), boxes.end());
  cell_start_.clear();
  cell_boxes_.clear();
  dims_ = {0, 0, 0};
  if (boxes_.empty()) return;

  Box all = boxes_[0];
  std::array<double, 3> mean_extent{0.0, 0.0, 0.0};
  for (const Box& b : boxes_)
    for (int k = 0; k < 3; ++k) {
      all.lo[k] = std::min(all.lo[k], b.lo[k]);
      all.hi[k] = std::max(all.hi[k], b.hi[k]);
      mean_extent[k] += b.hi[k] - b.lo[k];
    }
  origin_ = all.lo;

  // Cells about the size of a box along each axis; coarser if that would give more than ~2
  // cells per box. An axis along which the boxes are flat takes the largest mean extent.
  const double largest =
      std::max({all.hi[0] - all.lo[0], all.hi[1] - all.lo[1], all.hi[2] - all.lo[2]});
  const double widest = std::max({mean_extent[0], mean_extent[1], mean_extent[2]}) /
                        static_cast<double>(boxes_.size());
  for (int k = 0; k < 3; ++k) {
    const double mean = mean_extent[k] / static_cast<double>(boxes_.size());
    cell_size_[k] = mean > 1e-6 * widest ? mean : widest;
    if (!(cell_size_[k] > 0.0)) cell_size_[k] = largest > 0.0 ? largest : 1.0;
  }
  const auto max_cells = static_cast<double>(2 * boxes_.size() + 64);
  for (;;) {
    double cells = 1.0;
    for (int k = 0; k < 3; ++k) {
      dims_[k] = static_cast<std::int64_t>(
                     std::min(std::floor((all.hi[k] - all.lo[k]) / cell_size_[k]), 1e15)) +
                 1;
      cells *= static_cast<double>(dims_[k]);
    }
    if (cells <= max_cells) break;
    for (double& size : cell_size_) size *= 1.5;
  }

  auto range = [&](const Box& b, int k, std::int64_t& first, std::int64_t& last) {
    first = index_along(b.lo[k], k);
    last = index_along(b.hi[k], k);
  };
  const auto n_cells = static_cast<std::size_t>(dims_[0] * dims_[1] * dims_[2]);
  cell_start_.assign(n_cells + 1, 0);
  // Two passes (count, fill) in box order: a counting sort, linear in the number of boxes.
  for (int pass = 0; pass < 2; ++pass) {
    if (pass == 1) {
      for (std::size_t c = 0; c < n_cells; ++c) cell_start_[c + 1] += cell_start_[c];
      cell_boxes_.resize(cell_start_[n_cells]);
    }
    std::vector<std::size_t> fill;
    if (pass == 1) fill.assign(cell_start_.begin(), cell_start_.end() - 1);
    for (std::size_t i = 0; i < boxes_.size(); ++i) {
      std::int64_t r[3][2];
      for (int k = 0; k < 3; ++k) range(boxes_[i], k, r[k][0], r[k][1]);
      for (std::int64_t cz = r[2][0]; cz <= r[2][1]; ++cz)
        for (std::int64_t cy = r[1][0]; cy <= r[1][1]; ++cy)
          for (std::int64_t cx = r[0][0]; cx <= r[0][1]; ++cx) {
            const auto c = static_cast<std::size_t>((cz * dims_[1] + cy) * dims_[0] + cx);
            if (pass == 0)
              ++cell_start_[c + 1];
            else
              cell_boxes_[fill[c]++] = static_cast<std::int32_t>(i);
          }
    }
  }
}

std::int64_t BucketGrid::index_along(double coordinate, int k) const {
  const double s = std::floor((coordinate - origin_[k]) / cell_size_[k]);
  if (!(s > 0.0)) return 0;  // below the grid, or NaN
  return s >= static_cast<double>(dims_[k]) ? dims_[k] - 1 : static_cast<std::int64_t>(s);
}

bool BucketGrid::cell_of(double x, double y, double z, std::size_t& cell) const {
  const double p[3] = {x, y, z};
  std::int64_t idx[3];
  for (int k = 0; k < 3; ++k) {
    const double s = std::floor((p[k] - origin_[k]) / cell_size_[k]);
    // Outside the grid (or NaN): no box can contain the point.
    if (!(s >= 0.0) || s >= static_cast<double>(dims_[k])) return false;
    idx[k] = static_cast<std::int64_t>(s);
  }
  cell = static_cast<std::size_t>((idx[2] * dims_[1] + idx[1]) * dims_[0] + idx[0]);
  return true;
}

namespace {

// Fills the rows of `out` for n queries in two passes, each query writing only its own row:
// `visit(p, emit)` calls emit(b) for every box b of query p, in the same order both times;
// pass 1 counts, a prefix sum makes the offsets, pass 2 stores, and `finish(first, last)` may
// reorder the stored row.
template <class Visit, class Finish>
void fill_rows(std::size_t n, CandidateList& out, const Visit& visit, const Finish& finish) {
  out.offsets.assign(n + 1, 0);
  for (int pass = 0; pass < 2; ++pass) {
    if (pass == 1) {
      for (std::size_t p = 0; p < n; ++p) out.offsets[p + 1] += out.offsets[p];
      out.facets.resize(out.offsets[n]);
    }
#pragma omp parallel for schedule(static) if (n >= static_cast <std::size_t>(kParallelMinimum))
    for (std::size_t p = 0; p < n; ++p) {
      if (pass == 0) {
        std::size_t count = 0;
        visit(p, [&count](std::int32_t) { ++count; });
        out.offsets[p + 1] = count;
      } else {
        const std::size_t first = out.offsets[p];
        std::size_t at = first;
        visit(p, [&](std::int32_t b) { out.facets[at++] = b; });
        finish(first, at);
      }
    }
  }
}

}  // namespace

void BucketGrid::query(std::span<const double> x, std::span<const double> y,
                       std::span<const double> z, CandidateList& out,
                       const std::function<bool(std::size_t, std::int32_t)>& keep) const {
  if (boxes_.empty()) {
    out.offsets.assign(x.size() + 1, 0);
    out.facets.clear();
    return;
  }
  fill_rows(
      x.size(), out,
      [&](std::size_t p, const auto& emit) {
        std::size_t cell = 0;
        if (!cell_of(x[p], y[p], z[p], cell)) return;
        for (std::size_t k = cell_start_[cell]; k < cell_start_[cell + 1]; ++k) {
          const std::int32_t b = cell_boxes_[k];
          if (boxes_[b].contains(x[p], y[p], z[p]) && (!keep || keep(p, b))) emit(b);
        }
      },
      [](std::size_t, std::size_t) {});  // a cell's boxes are in facet order already
}

void BucketGrid::query(std::span<const Box> regions, CandidateList& out,
                       const std::function<bool(std::size_t, std::int32_t)>& keep) const {
  if (boxes_.empty()) {
    out.offsets.assign(regions.size() + 1, 0);
    out.facets.clear();
    return;
  }
  // As the point query. A pair is taken in one cell only, the first the two boxes share along
  // each axis; the rows are then sorted into facet order.
  fill_rows(
      regions.size(), out,
      [&](std::size_t p, const auto& emit) {
        const Box& region = regions[p];
        bool outside = false;
        std::int64_t r[3][2];
        for (int k = 0; k < 3; ++k) {
          // Beyond the grid (or NaN): no box overlaps it.
          outside = outside || !(region.hi[k] >= origin_[k]) ||
                    !((region.lo[k] - origin_[k]) / cell_size_[k] < static_cast<double>(dims_[k]));
          r[k][0] = index_along(region.lo[k], k);
          r[k][1] = index_along(region.hi[k], k);
        }
        if (outside) return;
        for (std::int64_t cz = r[2][0]; cz <= r[2][1]; ++cz)
          for (std::int64_t cy = r[1][0]; cy <= r[1][1]; ++cy)
            for (std::int64_t cx = r[0][0]; cx <= r[0][1]; ++cx) {
              const std::int64_t here[3] = {cx, cy, cz};
              const auto c = static_cast<std::size_t>((cz * dims_[1] + cy) * dims_[0] + cx);
              for (std::size_t k = cell_start_[c]; k < cell_start_[c + 1]; ++k) {
                const std::int32_t b = cell_boxes_[k];
                const Box& box = boxes_[b];
                if (!box.overlaps(region)) continue;
                bool first_shared = true;
                for (int a = 0; a < 3; ++a)
                  first_shared =
                      first_shared && index_along(std::max(box.lo[a], region.lo[a]), a) == here[a];
                if (first_shared && (!keep || keep(p, b))) emit(b);
              }
            }
      },
      [&out](std::size_t first, std::size_t last) {
        std::sort(out.facets.begin() + static_cast<std::ptrdiff_t>(first),
                  out.facets.begin() + static_cast<std::ptrdiff_t>(last));
      });
}

}  // namespace abut
