#include "memory_budget.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace abut::deck {
namespace {

// Peak resident bytes of `abut run` per element and per node, rounded up from measurements
// (elastic hexes, one contact, VTU output): a 130 600-hex sphere on a box peaked at 188 MB, a
// 200 000-hex box at 245 MB. Element state (stress, hourglass, forces, reference gradients),
// mesh, contact faces and output buffers.
constexpr double kBytesPerElement = 1000.0;
constexpr double kBytesPerNode = 500.0;

std::string gigabytes(double bytes) {
  std::ostringstream s;
  s.precision(3);
  s << bytes / 1e9 << " GB";
  return s.str();
}

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

std::optional<double> machine_memory() {
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  double kilobytes = 0.0;
  std::string unit;
  while (meminfo >> key >> kilobytes >> unit) {
    if (key == "MemAvailable:") return kilobytes * 1024.0;
  }
  const long pages = sysconf(_SC_AVPHYS_PAGES);
  const long page_size = sysconf(_SC_PAGE_SIZE);
  if (pages > 0 && page_size > 0) return static_cast<double>(pages) * static_cast<double>(page_size);
  return std::nullopt;
}

// ABUT_MEMORY_MB, when it is a positive number of megabytes (2^20 bytes); empty otherwise.
std::optional<double> memory_cap() {
  const char* text = std::getenv("ABUT_MEMORY_MB");
  if (text == nullptr) return std::nullopt;
  char* end = nullptr;
  const double mb = std::strtod(text, &end);
  if (end == text || *end != '\0' || !(mb > 0.0) || !std::isfinite(mb)) return std::nullopt;
  return mb * 1024.0 * 1024.0;
}

}  // namespace

std::optional<double> available_memory() {
  const std::optional<double> machine = machine_memory();
  const std::optional<double> cap = memory_cap();
  if (machine && cap) return std::min(*machine, *cap);
  return cap ? cap : machine;
}

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
