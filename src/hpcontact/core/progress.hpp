// What a long computation reports while it runs: one event per load step, Newton iteration,
// adaptive step, file written or message, each with its text line and its figures, for the
// caller's progress callback to show (a terminal bar, plain lines, JSON lines).
#pragma once

#include <functional>
#include <limits>
#include <string>
#include <variant>

namespace hpcontact {

/// A converged load step (or arc-length step) of one solve.
struct LoadStepProgress {
  int step = 0;  ///< the input's numbering: a cut step keeps its number, stages continue it
  /// The input's load steps of this solve's path (all stages'); 0 if not known beforehand (the
  /// arc-length method). Force control by the secant adds paths: `step` may then exceed it.
  int of = 0;
  bool part = false;       ///< a part of a cut step (the step itself is not yet done)
  bool arc_length = false;  ///< an arc-length step (of the loads, after the displacements')
  std::string detail;      ///< "factor 0.6, 4 Newton iterations, |R| 1e+03 -> 1e-09"
  int newton_iterations = 0;
  double residual = 0;     ///< |R| at the end of the step
  double solve_seconds = 0;  ///< since this solve's path set out
};

/// A Newton iteration (of a load step).
struct IterationProgress {
  int iteration = 0;
  double residual = 0, correction = 0;  ///< |R| and |dx|
  int points_in_contact = -1;           ///< -1: no contact pairs
  double seconds = 0;                   ///< since the load step's Newton solve began
  /// The fraction of the Newton correction taken (< 1: shortened by the line search or to what
  /// the system admits).
  double step = 1;
  /// Multiplier rows (exact contact: active/inactive, open/stick/slip) whose state changed at
  /// the last tangent formed, from the tangent before; −1: no exact pair.
  int states_changed = -1;
};

/// A step of an adaptive loop (hp step, rp iteration), when its figures are known.
struct AdaptStepProgress {
  std::string method;  ///< "hp" or "rp"
  int step = 0;        ///< from 0 (the input's mesh)
  int max_steps = 0;   ///< the last step the loop may take (adapt.steps, adapt.max_iterations)
  long dofs = 0;       ///< free dofs of the step's solve
  /// hp: the estimated error held to the tolerance (contact traction, relative L2); rp: the
  /// nodes' distance to the zone ends over the body size. NaN when not measured.
  double estimate = std::numeric_limits<double>::quiet_NaN();
  double tolerance = 0;  ///< 0: none (a fixed number of steps)
  std::string detail;    ///< the rest of its line: "estimated error 0.02 (pressure, ...)"
};

/// A file written into the output folder (or its last-good/).
struct FileWrittenProgress {
  std::string path;  ///< as the line names it: relative to the output folder
};

/// One event of progress: its text line (what a plain log prints), and its figures.
struct ProgressEvent {
  using Data = std::variant<std::monostate, LoadStepProgress, IterationProgress, AdaptStepProgress,
                            FileWrittenProgress>;
  std::string text;
  Data data;  ///< monostate: a message (a decision, a cut, a note)

  /// A message.
  ProgressEvent(std::string line) : text(std::move(line)) {}  // NOLINT: implicit, as a line
  ProgressEvent(std::string line, Data figures) : text(std::move(line)), data(std::move(figures)) {}

  template <class T>
  const T* as() const { return std::get_if<T>(&data); }
};

/// The caller's progress callback; may be empty.
using ProgressFn = std::function<void(const ProgressEvent&)>;

}  // namespace hpcontact
