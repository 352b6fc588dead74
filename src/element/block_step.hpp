#pragma once
// The serial pass that ends a block's step (SolidBlock, ShellBlock), after its elements were
// updated in parallel: in element order the first failed element decides the message, the step's
// works are summed and the least stable step is taken, so that the result does not depend on the
// number of threads. Then erosion, if the block has criteria.
#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>

#include "abut/core/error.hpp"
#include "abut/element/solid_block.hpp"

namespace abut {

// `block`: a block's Impl with per-element failure codes (0: none), internal_work,
// hourglass_work and stable, the cumulative internal_energy, hourglass_energy, eroded_energy and
// eroded_count, eroded (empty without erosion), erode(BlockStep&) and element_name(e).
// `why[code]`: what a failure code means, appended to the element's name.
template <class Block>
BlockStep end_block_step(Block& block, std::size_t count, const std::array<const char*, 3>& why) {
  BlockStep out;
  out.stable_step = std::numeric_limits<double>::infinity();
  double internal = 0.0, hourglass = 0.0;
  for (std::size_t e = 0; e < count; ++e) {
    if (block.failure[e] != 0)
      throw InstabilityError(block.element_name(e) + why[block.failure[e]]);
    internal += block.internal_work[e];
    hourglass += block.hourglass_work[e];
    out.stable_step = std::min(out.stable_step, block.stable[e]);
  }
  block.internal_energy += internal;
  block.hourglass_energy += hourglass;
  if (!block.eroded.empty()) block.erode(out);
  out.internal_energy = block.internal_energy;
  out.hourglass_energy = block.hourglass_energy;
  out.eroded_energy = block.eroded_energy;
  out.eroded = block.eroded_count;
  return out;
}

// Erosion, serial in element order: the energy each living element has taken so far, then the
// block's criteria (`fails(e)`). An eroded element's energy leaves the internal (and hourglass)
// energy for the eroded energy, so the energy balance still closes; its forces of this step are
// dropped (`stride` per element in `forces`) and `clear(e)` drops its stress. The stable step is
// that of the living elements. `block` also holds element_internal and element_hourglass, the
// energy each element has taken.
template <class Block, class Fails, class Clear>
void erode_elements(Block& block, std::size_t count, std::size_t stride, BlockStep& out,
                    const Fails& fails, const Clear& clear) {
  out.stable_step = std::numeric_limits<double>::infinity();
  for (std::size_t e = 0; e < count; ++e) {
    if (block.eroded[e]) continue;
    block.element_internal[e] += block.internal_work[e];
    block.element_hourglass[e] += block.hourglass_work[e];
    if (!fails(e)) {
      out.stable_step = std::min(out.stable_step, block.stable[e]);
      continue;
    }
    block.eroded[e] = 1;
    ++block.eroded_count;
    block.eroded_energy += block.element_internal[e] + block.element_hourglass[e];
    block.internal_energy -= block.element_internal[e];
    block.hourglass_energy -= block.element_hourglass[e];
    std::fill_n(&block.forces[stride * e], stride, 0.0);
    clear(e);
  }
}

}  // namespace abut
