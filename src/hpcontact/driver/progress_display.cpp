// The three renderings of a run's progress: terminal status line, plain lines, JSON lines.
#include "hpcontact/driver/progress_display.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace hpcontact::driver {

namespace {

constexpr const char* kSeparator = " \u00b7 ";  // " · "
constexpr int kBarWidth = 10;
/// The status line is redrawn at most this often for events that change only its times.
constexpr double kRedrawSeconds = 0.1;

/// The first `columns` characters (code points) of a UTF-8 line.
std::string cut_to(const std::string& text, int columns) {
  int seen = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if ((static_cast<unsigned char>(text[i]) & 0xc0) == 0x80) continue;  // a continuation byte
    if (seen++ == columns) return text.substr(0, i);
  }
  return text;
}

std::string number_text(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2g", value);
  return buffer;
}

/// "load step 3 of 5", "load step 3 of 5 (a part of it, cut)", "arc-length step 3".
std::string step_title(const LoadStepProgress& step) {
  std::string title = (step.arc_length ? "arc-length step " : "load step ") + std::to_string(step.step);
  if (step.of > 0) title += " of " + std::to_string(step.of);
  if (step.part) title += " (a part of it, cut)";
  return title;
}

std::string adapt_title(const std::string& method, int step, int max_steps) {
  return method + (method == "rp" ? " iteration " : " step ") + std::to_string(step) +
         " of at most " + std::to_string(max_steps);
}

nlohmann::json number_or_null(double value) {
  return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json();
}

}  // namespace

std::string clock_text(double seconds) {
  const long total = seconds > 0 ? static_cast<long>(seconds) : 0;
  char buffer[32];
  if (total >= 3600)
    std::snprintf(buffer, sizeof buffer, "%ld:%02ld:%02ld", total / 3600, total / 60 % 60, total % 60);
  else
    std::snprintf(buffer, sizeof buffer, "%ld:%02ld", total / 60, total % 60);
  return buffer;
}

std::optional<double> remaining_of_solve(const LoadStepProgress& step) {
  const int done = step.step - (step.part ? 1 : 0);
  if (step.of <= 0 || step.step > step.of || done <= 0) return std::nullopt;
  return step.solve_seconds / done * (step.of - done);
}

ProgressDisplay::ProgressDisplay(std::ostream& out, ProgressDisplayOptions options,
                                 std::optional<AdaptivePlan> plan)
    : out_(out), options_(std::move(options)), plan_(std::move(plan)) {
  if (!options_.clock) {
    const auto t0 = std::chrono::steady_clock::now();
    options_.clock = [t0] {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    };
  }
}

std::string ProgressDisplay::clean(std::string_view text) const {
  return options_.printable ? options_.printable(text) : std::string(text);
}

void ProgressDisplay::json_event(const std::string& kind, nlohmann::json fields) {
  if (options_.style != ProgressStyle::json) return;
  fields["kind"] = kind;
  fields["time_s"] = elapsed();
  // A path or text that is not UTF-8 (a file name of bytes) has its bad bytes as U+FFFD: the
  // line stays JSON.
  out_ << fields.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << std::endl;
}

void ProgressDisplay::show_line(const std::string& text) {
  if (options_.style == ProgressStyle::terminal && drawn_) out_ << "\r\033[K";
  drawn_ = false;
  // each line flushed: a log followed while the run goes on (tail -f, a scheduler's file)
  out_ << text << std::endl;
  if (options_.style == ProgressStyle::terminal) redraw(true);
}

void ProgressDisplay::line(const std::string& text) {
  if (options_.style != ProgressStyle::json) show_line(text);
}

void ProgressDisplay::aside(const std::function<void()>& write) {
  const bool was_drawn = drawn_;
  if (drawn_) out_ << "\r\033[K" << std::flush;
  drawn_ = false;
  write();
  if (was_drawn) redraw(true);
}

void ProgressDisplay::finish() {
  if (drawn_) out_ << "\r\033[K" << std::flush;
  drawn_ = false;
}

void ProgressDisplay::operator()(const ProgressEvent& event) {
  const bool json = options_.style == ProgressStyle::json;
  if (const auto* it = event.as<IterationProgress>()) {
    if (json) {
      nlohmann::json j = {{"message", event.text.substr(event.text.find_first_not_of(' '))},
                          {"iteration", it->iteration}, {"residual", number_or_null(it->residual)},
                          {"correction", number_or_null(it->correction)}, {"seconds", it->seconds}};
      if (it->points_in_contact >= 0) j["points_in_contact"] = it->points_in_contact;
      j["step"] = it->step;
      if (it->states_changed >= 0) j["states_changed"] = it->states_changed;
      json_event("iteration", j);
    } else if (options_.verbose) {
      show_line("  " + clean(event.text));
    } else if (options_.style == ProgressStyle::terminal) {
      redraw(false);  // the times go on
    }
    return;
  }
  if (const auto* step = event.as<LoadStepProgress>()) return on_load_step(event, *step);
  if (const auto* step = event.as<AdaptStepProgress>()) return on_adapt_step(event, *step);
  if (const auto* file = event.as<FileWrittenProgress>()) {
    if (json) json_event("file_written", {{"message", event.text}, {"path", file->path}});
    else show_line("  " + clean(event.text));
    return;
  }
  if (json) json_event("message", {{"message", event.text}});
  else show_line("  " + clean(event.text));
}

void ProgressDisplay::on_load_step(const ProgressEvent& event, const LoadStepProgress& step) {
  // A new solve (the next mesh of an adaptive loop, its estimate) starts again at step 1.
  if (load_ && (step.step < load_->step || (step.step == load_->step && !load_->part))) load_.reset();
  load_ = step;
  const auto remaining = remaining_of_solve(step);
  const bool adaptive = plan_.has_value();
  switch (options_.style) {
    case ProgressStyle::json:
      json_event("load_step", {{"message", event.text},
                               {"step", step.step},
                               {"of", step.of > 0 ? nlohmann::json(step.of) : nlohmann::json()},
                               {"part", step.part},
                               {"arc_length", step.arc_length},
                               {"newton_iterations", step.newton_iterations},
                               {"residual", number_or_null(step.residual)},
                               {"solve_elapsed_s", step.solve_seconds},
                               {"solve_remaining_s", remaining ? nlohmann::json(*remaining) : nlohmann::json()}});
      return;
    case ProgressStyle::lines: {
      std::string text = "  " + step_title(step) + ": " + clean(step.detail) + kSeparator +
                         "elapsed " + clock_text(elapsed());
      if (!adaptive && remaining) text += std::string(kSeparator) + "remaining ~" + clock_text(*remaining);
      show_line(text);
      return;
    }
    case ProgressStyle::terminal:
      redraw(true);
      return;
  }
}

void ProgressDisplay::on_adapt_step(const ProgressEvent& event, const AdaptStepProgress& step) {
  adapt_ = step;
  load_.reset();
  if (!plan_) plan_ = AdaptivePlan{step.method, step.max_steps, step.tolerance};
  if (options_.style == ProgressStyle::json) {
    json_event("adapt_step", {{"message", event.text},
                              {"method", step.method},
                              {"step", step.step},
                              {"max_steps", step.max_steps},
                              {"dofs", step.dofs},
                              {"estimate", number_or_null(step.estimate)},
                              {"tolerance", step.tolerance > 0 ? nlohmann::json(step.tolerance)
                                                               : nlohmann::json()}});
    return;
  }
  show_line("  " + adapt_title(step.method, step.step, step.max_steps) + ": " + clean(step.detail) +
            kSeparator + "elapsed " + clock_text(elapsed()));
}

/// "hp step 2 of at most 8 · load step 3 of 5 [######....] · estimate 0.021 (tolerance 0.001)
/// · elapsed 0:42 · remaining unknown (this solve ~0:10)"
std::string ProgressDisplay::status() const {
  std::vector<std::string> parts;
  if (plan_) {
    const int step = adapt_ ? std::min(adapt_->step + 1, plan_->max_steps) : 0;
    parts.push_back(adapt_title(plan_->method, step, plan_->max_steps));
  }
  if (load_) {
    std::string part = step_title(*load_);
    if (load_->of > 0 && load_->step <= load_->of) {
      const int done = load_->step - (load_->part ? 1 : 0);
      const int filled = kBarWidth * done / load_->of;
      part += " [" + std::string(filled, '#') + std::string(kBarWidth - filled, '.') + "]";
    }
    parts.push_back(part);
  }
  if (adapt_ && std::isfinite(adapt_->estimate)) {
    std::string part = (adapt_->method == "rp" ? "distance " : "estimate ") + number_text(adapt_->estimate);
    if (adapt_->tolerance > 0) part += " (tolerance " + number_text(adapt_->tolerance) + ")";
    parts.push_back(part);
  }
  parts.push_back("elapsed " + clock_text(elapsed()));
  const auto solve_left = load_ ? remaining_of_solve(*load_) : std::nullopt;
  if (plan_)  // the steps to come are not known (a tolerance) and each costs more than the last
    parts.push_back("remaining unknown" +
                    (solve_left ? " (this solve ~" + clock_text(*solve_left) + ")" : std::string()));
  else
    parts.push_back(solve_left ? "remaining ~" + clock_text(*solve_left) : "remaining unknown");
  std::string line;
  for (const auto& p : parts) line += (line.empty() ? "" : kSeparator) + p;
  return line;
}

void ProgressDisplay::redraw(bool force) {
  if (options_.style != ProgressStyle::terminal) return;
  const double now = elapsed();
  if (!force && now - last_draw_ < kRedrawSeconds) return;
  last_draw_ = now;
  out_ << "\r\033[K" << cut_to(status(), std::max(10, options_.width - 1)) << std::flush;
  drawn_ = true;
}

}  // namespace hpcontact::driver
