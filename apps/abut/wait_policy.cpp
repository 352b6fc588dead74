#include "wait_policy.hpp"

#include <unistd.h>

#include <cstdlib>

namespace abut_cli {

void ensure_passive_wait_policy(char** argv) {
  if (std::getenv("OMP_WAIT_POLICY") != nullptr || std::getenv("GOMP_SPINCOUNT") != nullptr)
    return;  // the user's choice, or already set by the execution below
  if (setenv("OMP_WAIT_POLICY", "passive", 0) != 0) return;
  execv("/proc/self/exe", argv);
  // Only reached if the execution failed (no /proc): run on with the runtime's default policy.
}

}  // namespace abut_cli
