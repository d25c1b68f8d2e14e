// How `hpcontact run` shows its progress events (core/progress.hpp): one line redrawn on a
// terminal, plain lines when piped, JSON lines with --log-json.
#pragma once

#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "hpcontact/core/progress.hpp"

namespace hpcontact::driver {

enum class ProgressStyle {
  terminal,  ///< a status line redrawn with \r (a bar for the current solve's load steps), the
             ///< messages that matter printed above it
  lines,     ///< a plain line per load step, adaptive step, file written and message
  json       ///< a JSON object per line per event (docs/output.md has the schema)
};

struct ProgressDisplayOptions {
  ProgressStyle style = ProgressStyle::lines;
  bool verbose = false;  ///< the Newton iterations too (JSON lines always have them)
  int width = 80;        ///< the terminal's columns (the status line is cut to fit)
  /// What a text goes through before it reaches the output (the command line's escaping of
  /// control characters); the identity if empty.
  std::function<std::string(std::string_view)> printable;
  /// Seconds since the run began; a steady clock from the display's construction if empty.
  std::function<double()> clock;
};

/// An adaptive run as the input sets it up, for the status line before its first step ends.
struct AdaptivePlan {
  std::string method;  ///< "hp" or "rp"
  int max_steps = 0;
  double tolerance = 0;  ///< 0: none
};

/// "0:42", "12:03", "1:02:03": a duration in seconds, rounded down to whole seconds.
std::string clock_text(double seconds);

/// The time the rest of a solve's load steps should take at the pace of those done: the solve's
/// elapsed time over the steps done (a cut step's part counts as not done) times the steps left;
/// none when no step is done or the number of steps is not known (arc-length, the secant's paths
/// beyond the planned ones).
std::optional<double> remaining_of_solve(const LoadStepProgress& step);

class ProgressDisplay {
 public:
  ProgressDisplay(std::ostream& out, ProgressDisplayOptions options,
                  std::optional<AdaptivePlan> plan = std::nullopt);
  ~ProgressDisplay() { finish(); }
  ProgressDisplay(const ProgressDisplay&) = delete;
  ProgressDisplay& operator=(const ProgressDisplay&) = delete;

  /// The adaptive loop the run will take (the status line names its step from the start).
  void set_plan(const AdaptivePlan& plan) { plan_ = plan; }
  /// A progress event of the run (RunOptions::progress).
  void operator()(const ProgressEvent& event);
  /// A line of the command's own (its heading, its result): above the status line on a
  /// terminal, ignored with JSON.
  void line(const std::string& text);
  /// With JSON: an event of the command's own ({"kind", "time_s", ...fields}); ignored otherwise.
  void json_event(const std::string& kind, nlohmann::json fields = nlohmann::json::object());
  /// Runs `write` (a warning to stderr) with the status line cleared, then redraws it.
  void aside(const std::function<void()>& write);
  /// Clears the status line (the terminal's cursor at the start of an empty line); the display
  /// may be used again after.
  void finish();

  double elapsed() const { return options_.clock(); }

 private:
  void show_line(const std::string& text);
  void on_load_step(const ProgressEvent& event, const LoadStepProgress& step);
  void on_adapt_step(const ProgressEvent& event, const AdaptStepProgress& step);
  std::string status() const;
  void redraw(bool force);
  std::string clean(std::string_view text) const;

  std::ostream& out_;
  ProgressDisplayOptions options_;
  std::optional<AdaptivePlan> plan_;
  std::optional<AdaptStepProgress> adapt_;  ///< the last adaptive step done
  std::optional<LoadStepProgress> load_;    ///< the current solve's last load step
  bool drawn_ = false;                      ///< a status line is on the terminal
  double last_draw_ = -1;
};

}  // namespace hpcontact::driver
