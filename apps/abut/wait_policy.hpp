#pragma once
// OpenMP threads that wait at a barrier spin by default (libgomp: 300000 spins before they
// sleep). On a loaded machine a spinning thread takes the core from the thread it waits for: two
// threads took 266 s on the seed deck where one took 36 s, and 6.3 s with passive waiting. So
// abut waits passively unless the user chose otherwise (OMP_WAIT_POLICY or GOMP_SPINCOUNT set).
// libgomp reads its environment when it is loaded, before main: setting the variable in main
// would be too late, so the program sets it and executes itself again (same pid, same arguments).

namespace abut_cli {

// Call first in main. Returns only if the policy is the user's, or set, or cannot be set.
void ensure_passive_wait_policy(char** argv);

}  // namespace abut_cli
