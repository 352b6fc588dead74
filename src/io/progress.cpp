#include "abut/io/progress.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <stdexcept>

namespace abut {
namespace {

constexpr double kRedrawInterval = 0.1;  // seconds between redraws of the terminal bar
constexpr int kBarWidth = 30;
// Slack so that t = 0.4 t_end counts as 40 % although the division may round just below 0.4.
constexpr double kRoundingSlack = 1e-9;

std::string clock_text(double seconds) {
  const auto s = static_cast<long long>(std::llround(std::max(seconds, 0.0)));
  return fmt::format("{}:{:02}:{:02}", s / 3600, s / 60 % 60, s % 60);
}

}  // namespace

ProgressReporter::ProgressReporter(double start_time, double end_time, std::ostream& out,
                                   bool interactive, WallClock clock)
    : start_time_(start_time),
      end_time_(end_time),
      out_(out),
      interactive_(interactive),
      clock_(std::move(clock)),
      wall_start_(clock_()) {
  if (!(end_time > start_time)) {
    throw std::invalid_argument(
        fmt::format("progress: end time {} must be after start time {}", end_time, start_time));
  }
}

ProgressReporter ProgressReporter::to_stderr(double start_time, double end_time) {
  return ProgressReporter(start_time, end_time, std::cerr, isatty(STDERR_FILENO) == 1);
}

double ProgressReporter::steady_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double ProgressReporter::fraction(double time) const {
  return std::clamp((time - start_time_) / (end_time_ - start_time_) + kRoundingSlack, 0.0, 1.0);
}

std::string ProgressReporter::status(double time, std::int64_t cycle, bool final) const {
  const double f = fraction(time);
  const double elapsed = clock_() - wall_start_;
  std::string line =
      fmt::format("{:4}%  t={:.2e}  cycle {}", static_cast<int>(f * 100.0), time, cycle);
  if (final) {
    line += "  wall " + clock_text(elapsed);
  } else if (f > kRoundingSlack) {
    line += "  ETA " + clock_text(elapsed * (1.0 - f) / f);  // remaining at the mean rate so far
  } else {
    line += "  ETA -:--:--";
  }
  return line;
}

void ProgressReporter::draw_bar(double time, std::int64_t cycle, bool final) {
  const int filled = static_cast<int>(fraction(time) * kBarWidth);
  std::string line = "\r[" + std::string(static_cast<std::size_t>(filled), '#') +
                     std::string(static_cast<std::size_t>(kBarWidth - filled), '.') + "]" +
                     status(time, cycle, final);
  const std::size_t width = line.size();
  if (width < last_width_) line.append(last_width_ - width, ' ');  // erase a longer old line
  last_width_ = width;
  out_ << line << std::flush;
}

void ProgressReporter::update(double time, std::int64_t cycle) {
  if (interactive_) {
    const double now = clock_();
    if (drawn_ && now - last_draw_ < kRedrawInterval) return;
    drawn_ = true;
    last_draw_ = now;
    draw_bar(time, cycle, false);
    return;
  }
  // Plain lines at 10 %, 20 %, ..., 90 %; the final line comes from finish().
  const int tenth = static_cast<int>(fraction(time) * 10.0);
  if (tenth <= last_tenth_ || tenth >= 10) return;
  last_tenth_ = tenth;
  out_ << status(time, cycle, false) << '\n' << std::flush;
}

void ProgressReporter::finish(double time, std::int64_t cycle) {
  if (interactive_) {
    // The bar's last redraw is the final line: a separate one would repeat its numbers.
    draw_bar(time, cycle, true);
    out_ << '\n' << std::flush;
    return;
  }
  out_ << status(time, cycle, true) << '\n' << std::flush;
}

}  // namespace abut
