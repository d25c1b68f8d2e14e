// The renderings of progress events: the times they show, the lines and the JSON they write.
#include "hpcontact/driver/progress_display.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

using namespace hpcontact;
using namespace hpcontact::driver;

namespace {

LoadStepProgress step(int k, int n, double solve_seconds, bool part = false) {
  LoadStepProgress s;
  s.step = k;
  s.of = n;
  s.part = part;
  s.solve_seconds = solve_seconds;
  s.detail = "factor " + std::to_string(k);
  s.newton_iterations = 2;
  s.residual = 1e-9;
  return s;
}

/// A display on `out` whose clock reads `*now`.
ProgressDisplayOptions at(ProgressStyle style, const double* now, int width = 80) {
  ProgressDisplayOptions o;
  o.style = style;
  o.width = width;
  o.clock = [now] { return *now; };
  return o;
}

}  // namespace

TEST(ProgressDisplay, ClockTextIsMinutesAndSecondsOrHours) {
  EXPECT_EQ(clock_text(0), "0:00");
  EXPECT_EQ(clock_text(59.9), "0:59");
  EXPECT_EQ(clock_text(61), "1:01");
  EXPECT_EQ(clock_text(3725), "1:02:05");
  EXPECT_EQ(clock_text(-3), "0:00");
}

// remaining = elapsed / done × (n − done); a part of a cut step is not a step done.
TEST(ProgressDisplay, RemainingIsThePaceOfTheStepsDone) {
  EXPECT_DOUBLE_EQ(*remaining_of_solve(step(3, 5, 6.0)), 4.0);
  EXPECT_DOUBLE_EQ(*remaining_of_solve(step(3, 5, 6.0, true)), 9.0);
  EXPECT_DOUBLE_EQ(*remaining_of_solve(step(5, 5, 6.0)), 0.0);
  EXPECT_FALSE(remaining_of_solve(step(1, 5, 6.0, true)));  // nothing done yet
  EXPECT_FALSE(remaining_of_solve(step(3, 0, 6.0)));        // n not known (arc-length)
  EXPECT_FALSE(remaining_of_solve(step(6, 5, 6.0)));        // beyond the plan (the secant's paths)
}

TEST(ProgressDisplay, PipedLinesSayKOfNAndTheElapsedTime) {
  std::ostringstream out;
  double now = 75;
  ProgressDisplay display(out, at(ProgressStyle::lines, &now));
  display(ProgressEvent("  iteration 1: |R| 1", IterationProgress{1, 1.0, 2.0, 3, 0.5}));
  display(ProgressEvent("load step 2: factor 2", step(2, 4, 10.0)));
  display(ProgressEvent("load step 3 (a part of it, cut): factor 3", step(3, 4, 16.0, true)));
  display(ProgressEvent("wrote summary.json", FileWrittenProgress{"summary.json"}));
  display(ProgressEvent("a note"));
  EXPECT_EQ(out.str(),
            "  load step 2 of 4: factor 2 \u00b7 elapsed 1:15 \u00b7 remaining ~0:10\n"
            "  load step 3 of 4 (a part of it, cut): factor 3 \u00b7 elapsed 1:15 \u00b7 remaining ~0:16\n"
            "  wrote summary.json\n"
            "  a note\n");
}

TEST(ProgressDisplay, VerbosePrintsTheIterations) {
  std::ostringstream out;
  double now = 0;
  auto o = at(ProgressStyle::lines, &now);
  o.verbose = true;
  ProgressDisplay display(out, o);
  display(ProgressEvent("  iteration 1: |R| 1", IterationProgress{1, 1.0, 2.0, 3, 0.5}));
  EXPECT_EQ(out.str(), "    iteration 1: |R| 1\n");
}

TEST(ProgressDisplay, AdaptiveLinesSayTheStepOfAtMostN) {
  std::ostringstream out;
  double now = 42;
  ProgressDisplay display(out, at(ProgressStyle::lines, &now));
  display(ProgressEvent("load step 1: factor 1", step(1, 2, 1.0)));
  display(ProgressEvent("hp step 2: estimated error 0.01",
                        AdaptStepProgress{"hp", 2, 8, 300, 0.01, 1e-3, "estimated error 0.01"}));
  // an adaptive run's remaining time is not the solve's: it is not said in its lines
  EXPECT_EQ(out.str(), "  load step 1 of 2: factor 1 \u00b7 elapsed 0:42 \u00b7 remaining ~0:01\n"
                       "  hp step 2 of at most 8: estimated error 0.01 \u00b7 elapsed 0:42\n");
}

TEST(ProgressDisplay, JsonCarriesTheFigures) {
  std::ostringstream out;
  double now = 3;
  ProgressDisplay display(out, at(ProgressStyle::json, &now));
  display(ProgressEvent("load step 3: factor 3", step(3, 5, 6.0)));
  display(ProgressEvent("hp step 1: e", AdaptStepProgress{"hp", 1, 8, 120, NAN, 0, "e"}));
  display.line("not JSON: left out");
  std::istringstream lines(out.str());
  std::string first, second, third;
  std::getline(lines, first);
  std::getline(lines, second);
  EXPECT_FALSE(std::getline(lines, third));
  const auto a = nlohmann::json::parse(first), b = nlohmann::json::parse(second);
  EXPECT_EQ(a["kind"], "load_step");
  EXPECT_EQ(a["step"], 3);
  EXPECT_EQ(a["of"], 5);
  EXPECT_EQ(a["time_s"], 3.0);
  EXPECT_EQ(a["solve_remaining_s"], 4.0);
  EXPECT_EQ(a["message"], "load step 3: factor 3");
  EXPECT_EQ(b["kind"], "adapt_step");
  EXPECT_TRUE(b["estimate"].is_null() && b["tolerance"].is_null());
  EXPECT_EQ(b["max_steps"], 8);
}

// An iteration's JSON: the fraction of the correction taken always, the multiplier states
// changed only where there are multipliers (−1: none).
TEST(ProgressDisplay, JsonIterationCarriesTheStepAndTheStatesChanged) {
  std::ostringstream out;
  double now = 1;
  ProgressDisplay display(out, at(ProgressStyle::json, &now));
  display(ProgressEvent("  iteration 2: |R| 1", IterationProgress{2, 1.0, 2.0, 7, 0.5, 0.25, 3}));
  display(ProgressEvent("  iteration 1: |R| 1", IterationProgress{1, 1.0, 2.0, 3, 0.5}));
  std::istringstream lines(out.str());
  std::string first, second;
  std::getline(lines, first);
  std::getline(lines, second);
  const auto a = nlohmann::json::parse(first), b = nlohmann::json::parse(second);
  EXPECT_EQ(a["step"], 0.25);
  EXPECT_EQ(a["states_changed"], 3);
  EXPECT_EQ(b["step"], 1.0);
  EXPECT_FALSE(b.contains("states_changed"));
}

TEST(ProgressDisplay, TerminalRedrawsOneStatusLineCutToTheWidth) {
  std::ostringstream out;
  double now = 12;
  ProgressDisplay display(out, at(ProgressStyle::terminal, &now, 40));
  display(ProgressEvent("load step 2: factor 2", step(2, 4, 10.0)));
  EXPECT_EQ(out.str(), "\r\033[Kload step 2 of 4 [#####.....] \u00b7 elapsed");  // 39 columns
  out.str("");
  display(ProgressEvent("a note"));  // above the status, which is drawn again
  EXPECT_EQ(out.str(), "\r\033[K  a note\n\r\033[Kload step 2 of 4 [#####.....] \u00b7 elapsed");
  out.str("");
  display.finish();
  EXPECT_EQ(out.str(), "\r\033[K");
}

TEST(ProgressDisplay, TerminalStatusOfAnHpRunSaysNoMadeUpRemainingTime) {
  std::ostringstream out;
  double now = 70;
  ProgressDisplay display(out, at(ProgressStyle::terminal, &now, 200));
  display.set_plan({"hp", 8, 1e-3});
  display(ProgressEvent("hp step 1: e", AdaptStepProgress{"hp", 1, 8, 120, 0.021, 1e-3, "e"}));
  out.str("");
  display(ProgressEvent("load step 3: factor 3", step(3, 5, 6.0)));
  EXPECT_EQ(out.str(), "\r\033[Khp step 2 of at most 8 \u00b7 load step 3 of 5 [######....] \u00b7 "
                       "estimate 0.021 (tolerance 0.001) \u00b7 elapsed 1:10 \u00b7 remaining "
                       "unknown (this solve ~0:04)");
}
