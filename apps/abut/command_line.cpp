#include "command_line.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string_view>

namespace abut_cli {

std::string command_error(int argc, char** argv) {
  constexpr std::string_view commands =
      "use run, check or info on a deck, or plot on an output directory";
  if (argc < 2) return fmt::format("a command is required; {} (abut --help)", commands);
  const std::string_view command = argv[1];
  if (command.starts_with('-') || command == "run" || command == "check" || command == "info" ||
      command == "plot")
    return {};
  return fmt::format("unknown command '{}'; {}", command, commands);
}

std::string deck_error(const std::string& deck) {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::file_status status = fs::status(deck, error);
  if (!fs::exists(status)) return fmt::format("deck '{}' not found", deck);
  if (fs::is_directory(status)) return fmt::format("'{}' is a directory, not a deck", deck);
  errno = 0;
  const std::ifstream in(deck);
  if (!in) {
    const int reason = errno;
    return fmt::format("cannot read the deck '{}'{}", deck,
                       reason != 0 ? std::string(": ") + std::strerror(reason) : std::string());
  }
  return {};
}

std::string parse_threads(const std::string& text, int& threads) {
  int value = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || ptr != end || value < 1 || value > kMaxThreads)
    return fmt::format("--threads must be a whole number between 1 and {}, not '{}'", kMaxThreads,
                       text);
  threads = value;
  return {};
}

std::string parse_interval(const std::string& text, double& interval) {
  double value = 0.0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || ptr != end || !std::isfinite(value) || !(value > 0.0))
    return fmt::format("--restart-interval must be a positive model time, not '{}'",
                       text.substr(0, 80));
  interval = value;
  return {};
}

}  // namespace abut_cli
