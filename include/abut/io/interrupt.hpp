#pragma once
// Ctrl-C (SIGINT) and SIGTERM stop a run cleanly: the run finishes its current cycle (explicit)
// or increment (static), writes a final state and summary.json with status "interrupted", and
// the program exits with 128 + the signal number. A second signal kills the program at once,
// for a run that does not come to the end of its cycle or increment soon enough.

namespace abut::interrupt {

// Installs the handlers of SIGINT and SIGTERM. Call before a run, not before reading a deck:
// until then the default (killing the program at once) loses nothing.
void install();

// The signal received since install(), 0 if none. Safe to poll from the run's main thread.
int received();

}  // namespace abut::interrupt
