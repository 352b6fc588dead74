#pragma once
// The contact verification models are small: they run on one thread, as parallel regions
// would only add synchronisation (and, on a shared machine, waits for a descheduled thread).
// Restores the thread count on destruction.
#include <omp.h>

namespace abut::verification {

class OneThread {
 public:
  OneThread() : saved_(omp_get_max_threads()) { omp_set_num_threads(1); }
  ~OneThread() { omp_set_num_threads(saved_); }
  OneThread(const OneThread&) = delete;
  OneThread& operator=(const OneThread&) = delete;

 private:
  int saved_;
};

}  // namespace abut::verification
