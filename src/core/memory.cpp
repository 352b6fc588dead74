#include "abut/core/memory.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

namespace abut {
namespace {

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
  if (pages > 0 && page_size > 0)
    return static_cast<double>(pages) * static_cast<double>(page_size);
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

std::string gigabytes(double bytes) {
  std::ostringstream s;
  s.precision(3);
  s << bytes / 1e9 << " GB";
  return s.str();
}

}  // namespace abut
