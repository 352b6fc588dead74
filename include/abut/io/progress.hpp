#pragma once
// Progress of a run for the person waiting on it. On a terminal a bar redrawn in place (carriage
// return), at most about ten times a second; otherwise (a log file, CI) one plain line at every
// tenth of the run, e.g.
//     40%  t=4.00e-04  cycle 1234  ETA 0:00:03
// and a final line with the wall time (on a terminal: the bar's last redraw, not another line). The output stream and the wall clock are injected, so the
// reporter can be tested.
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <string>

namespace abut {

class ProgressReporter {
 public:
  using WallClock = std::function<double()>;  // wall seconds from any fixed origin

  // `interactive`: redraw one bar line instead of printing plain lines.
  ProgressReporter(double start_time, double end_time, std::ostream& out, bool interactive,
                   WallClock clock = steady_seconds);

  // Reports to std::cerr, interactively if stderr is a terminal.
  static ProgressReporter to_stderr(double start_time, double end_time);

  // Called once per cycle; prints only when a redraw or a new tenth is due.
  void update(double time, std::int64_t cycle);
  // The final line (also when the run stops before the end time).
  void finish(double time, std::int64_t cycle);

  static double steady_seconds();

 private:
  double fraction(double time) const;
  std::string status(double time, std::int64_t cycle, bool final) const;
  void draw_bar(double time, std::int64_t cycle, bool final);

  double start_time_, end_time_;
  std::ostream& out_;
  bool interactive_;
  WallClock clock_;
  double wall_start_;
  double last_draw_ = 0.0;
  bool drawn_ = false;
  int last_tenth_ = 0;
  std::size_t last_width_ = 0;
};

}  // namespace abut
