#pragma once
// Checks of the command line that CLI11 would answer with its own exit codes (105, 106, 109) or
// unclear messages ("A subcommand is required", a 309-digit range): each returns a plain message
// for "error: ..." and exit code 2, or an empty string when all is well.
#include <string>

namespace abut_cli {

// The largest --threads accepted; more is a typing error, not a machine.
constexpr int kMaxThreads = 1024;

// The command word: run, check, info or plot (options such as --help are left to CLI11).
std::string command_error(int argc, char** argv);

// The deck exists, is a file and can be read.
std::string deck_error(const std::string& deck);

// A whole number of threads from 1 to kMaxThreads, stored in `threads`.
std::string parse_threads(const std::string& text, int& threads);

// A positive, finite model time for --restart-interval, stored in `interval`.
std::string parse_interval(const std::string& text, double& interval);

}  // namespace abut_cli
