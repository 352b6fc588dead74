#pragma once
// Loops over fewer items than this run on one thread (OpenMP `if` clause): starting a thread
// team costs more than such a loop's work, and on a busy machine one descheduled thread stalls
// the whole team for a scheduler time slice at every barrier.
#include <cstdint>

namespace abut {

inline constexpr std::int64_t kParallelMinimum = 2048;

}  // namespace abut
