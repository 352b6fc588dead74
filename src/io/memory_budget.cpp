#include "memory_budget.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace abut::deck {
namespace {

// Peak resident bytes of `abut run` per element and per node, rounded up from measurements
// (elastic hexes, one contact, VTU output): a 130 600-hex sphere on a box peaked at 188 MB, a
// 200 000-hex box at 245 MB. Element state (stress, hourglass, forces, reference gradients),
// mesh, contact faces and output buffers.
constexpr double kBytesPerElement = 1000.0;
constexpr double kBytesPerNode = 500.0;

std::string count(double n) {
  std::ostringstream s;
  if (n < 1e15) {
    s.precision(0);
    s << std::fixed << n;
  } else {
    s.precision(3);
    s << n;
  }
  return s.str();
}

}  // namespace

double run_memory(const MeshSize& size) {
  return kBytesPerElement * size.elements + kBytesPerNode * size.nodes;
}

void require_memory(const MeshSize& total, std::optional<double> available,
                    const SourceLocation& where) {
  if (!available) return;
  const double need = run_memory(total);
  if (need <= *available) return;
  throw InputError(where, "the mesh asked for so far has about " + count(total.elements) +
                              " elements and " + count(total.nodes) +
                              " nodes; a run of it needs about " + gigabytes(need) +
                              " of memory, but only " + gigabytes(*available) +
                              " are available: use fewer elements");
}

void require_readable(const std::string& file, double bytes, std::optional<double> available) {
  if (!available || 3.0 * bytes <= *available) return;
  throw InputError("deck file '" + file + "' has " + gigabytes(bytes) +
                   "; reading it needs about three times that, but only " + gigabytes(*available) +
                   " are available");
}

}  // namespace abut::deck
