#include "abut/io/interrupt.hpp"

#include <csignal>

namespace abut::interrupt {
namespace {

volatile std::sig_atomic_t g_signal = 0;

// Async-signal-safe: records the signal and restores the default action, so that a second
// SIGINT or SIGTERM kills the program at once.
extern "C" void on_signal(int signal) {
  g_signal = signal;
  struct sigaction fallback {};
  fallback.sa_handler = SIG_DFL;
  sigemptyset(&fallback.sa_mask);
  sigaction(SIGINT, &fallback, nullptr);
  sigaction(SIGTERM, &fallback, nullptr);
}

}  // namespace

void install() {
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;  // file writes in progress complete rather than fail with EINTR
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

int received() { return g_signal; }

}  // namespace abut::interrupt
