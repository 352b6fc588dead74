#pragma once
// The memory a run may still count on, for refusing a model that would not fit before it is
// allocated (the deck's mesh generators, contact set-up) instead of swapping or bad_alloc.
#include <optional>
#include <string>

namespace abut {

// Bytes the machine can still give: MemAvailable of /proc/meminfo on Linux, else the free
// physical pages; at most ABUT_MEMORY_MB megabytes when that environment variable is a positive
// number (a batch slot, a shared machine, the fuzzer's memory limit); empty when unknown (then
// nothing is refused).
std::optional<double> available_memory();

// "1.23 GB": a byte count for messages.
std::string gigabytes(double bytes);

}  // namespace abut
