#pragma once
// Broad phase: which facets may touch which contact points.
//
// Facet bounding boxes (inflated by the caller: detection depth + search margin) are bucket-
// sorted into a uniform grid whose cell size along each axis follows the mean box extent along
// it, so that a box covers O(1) cells and the cell count stays proportional to the number of
// boxes, also for long thin facets lying side by side (a slab's sides): building and querying
// cost O(facets + points). A point's candidates are the boxes that contain it; a region's (an
// S2S point's cell) the boxes that overlap it; in increasing facet order (deterministic,
// independent of the thread count).
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "abut/core/state_archive.hpp"

namespace abut {

struct Box {
  std::array<double, 3> lo{}, hi{};
  bool contains(double x, double y, double z) const {
    return x >= lo[0] && x <= hi[0] && y >= lo[1] && y <= hi[1] && z >= lo[2] && z <= hi[2];
  }
  bool overlaps(const Box& o) const {
    return lo[0] <= o.hi[0] && o.lo[0] <= hi[0] && lo[1] <= o.hi[1] && o.lo[1] <= hi[1] &&
           lo[2] <= o.hi[2] && o.lo[2] <= hi[2];
  }
};

// Candidate facets of each point, compressed rows: facets[offsets[p] .. offsets[p+1]).
struct CandidateList {
  std::vector<std::size_t> offsets;
  std::vector<std::int32_t> facets;
  std::size_t point_count() const { return offsets.empty() ? 0 : offsets.size() - 1; }
  void archive(StateArchive& a) { a.values(offsets, facets); }
};

class BucketGrid {
 public:
  void build(std::span<const Box> boxes);
  // Fills `out` with the boxes containing each point (OpenMP over points); `keep(point, box)`,
  // if given, drops pairs that can never touch (called concurrently for different points).
  void query(std::span<const double> x, std::span<const double> y, std::span<const double> z,
             CandidateList& out,
             const std::function<bool(std::size_t, std::int32_t)>& keep = {}) const;
  // Fills `out` with the boxes overlapping each region (OpenMP over regions).
  void query(std::span<const Box> regions, CandidateList& out,
             const std::function<bool(std::size_t, std::int32_t)>& keep = {}) const;
  std::size_t cell_count() const { return cell_start_.empty() ? 0 : cell_start_.size() - 1; }
  // The grid as built, for a restart (state_archive.hpp).
  void archive(StateArchive& a) {
    a.values(boxes_, origin_, cell_size_, dims_, cell_start_, cell_boxes_);
  }

 private:
  bool cell_of(double x, double y, double z, std::size_t& cell) const;
  std::int64_t index_along(double coordinate, int k) const;  // clamped to the grid

  std::vector<Box> boxes_;
  std::array<double, 3> origin_{};
  std::array<double, 3> cell_size_{1.0, 1.0, 1.0};
  std::array<std::int64_t, 3> dims_{0, 0, 0};
  std::vector<std::size_t> cell_start_;  // CSR over cells
  std::vector<std::int32_t> cell_boxes_;
};

}  // namespace abut
