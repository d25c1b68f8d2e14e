// A run asked to stop while in a solve with no Newton iteration left to end at (a plain run's
// linear solve, an adaptive loop's last one): it ends as stopped, as its scheduler reports it
// cancelled — the plain run writing nothing (asked while it assembles, at once), the loop keeping
// its result as the last good one.
#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <unistd.h>

#include "hpcontact/core/error.hpp"
#include "hpcontact/core/stop.hpp"
#include "hpcontact/driver/run.hpp"
#include "hpcontact/io/problem_reader.hpp"

using namespace hpcontact;
namespace fs = std::filesystem;

namespace {
const std::string kExample = std::string(HPC_SOURCE_DIR) + "/examples/lame/thick-cylinder.yaml";

fs::path fresh_folder(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("hpc-run-stop-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  return dir;
}

/// run_problem ends with an error of type E that says `said`, not as a success; the stop request
/// is cleared afterwards.
template <class E>
void expect_stopped(const model::ProblemSpec& spec, const driver::RunOptions& options,
                    const std::string& said) {
  try {
    driver::run_problem(spec, options);
    ADD_FAILURE() << "a run asked to stop ended as a success";
  } catch (const E& e) {
    EXPECT_NE(std::string(e.what()).find(said), std::string::npos) << e.what();
  }
  clear_stop();
}
}  // namespace

TEST(RunStop, ALinearRunAskedToStopWritesNoResults) {
  const auto spec = io::read_problem(kExample, {"discretization.degree=3"});
  const fs::path stopped = fresh_folder("stopped"), finished = fresh_folder("finished");

  driver::RunOptions options;
  options.out_dir = finished.string();
  driver::run_problem(spec, options);  // the same run without a stop request: its results
  EXPECT_TRUE(fs::exists(finished / "summary.json"));

  // asked once the linear solve is done: no Newton iteration or stop point left to end at
  options.out_dir = stopped.string();
  options.progress = [](const ProgressEvent& e) {
    if (e.text.rfind("solved:", 0) == 0) request_stop(SIGTERM);
  };
  expect_stopped<NumericalError>(spec, options, "stopped by SIGTERM before the results were written");
  EXPECT_FALSE(fs::exists(stopped / "summary.json"));
  // asked before: the assembly is given up at its first stop point
  options.progress = {};
  request_stop(SIGTERM);
  expect_stopped<NumericalError>(spec, options, "the solver stopped: stopped by SIGTERM while "
                                                "assembling, before anything had converged");
  EXPECT_FALSE(fs::exists(stopped / "summary.json"));
  fs::remove_all(stopped);
  fs::remove_all(finished);
}

// A contact run asked to stop while it assembles its system, before any load step (a degree-30
// Hertz run spends seconds there): the assembly is given up, and the run ends as stopped with
// nothing to keep — no summary.json, no last-good/.
TEST(RunStop, AContactRunAskedToStopWhileItAssemblesEndsThere) {
  const auto spec = io::read_problem(std::string(HPC_SOURCE_DIR) + "/examples/hertz/p5.yaml",
                                     {"output.vtu=false"});
  const fs::path stopped = fresh_folder("assembling");
  driver::RunOptions options;
  options.out_dir = stopped.string();
  request_stop(SIGTERM);
  expect_stopped<NumericalError>(spec, options, "p5.yaml: the solver stopped: stopped by SIGTERM "
                                                "while assembling, before anything had converged");
  EXPECT_FALSE(fs::exists(stopped / "summary.json"));
  EXPECT_FALSE(fs::exists(stopped / "last-good"));
  fs::remove_all(stopped);
}

// An adaptive run asked to stop after its loop's last solve (here while it reports its last hp
// step: no Newton iteration is left to end at) ends as stopped as well: its result is kept
// apart in last-good/ with converged false, and the output folder has no summary.json.
TEST(RunStop, AnAdaptiveRunAskedToStopAfterItsLastSolveKeepsItAsLastGood) {
  const auto spec = io::read_problem(std::string(HPC_SOURCE_DIR) + "/examples/hertz/hp.yaml",
                                     {"adapt.steps=2", "output.vtu=false"});
  const fs::path stopped = fresh_folder("adaptive");
  driver::RunOptions options;
  options.out_dir = stopped.string();
  bool asked = false;
  options.progress = [&](const ProgressEvent& e) {
    const std::string& line = e.text;
    if (line.find("hp step 2:") != std::string::npos && line.find("dofs") != std::string::npos) {
      request_stop(SIGTERM);
      asked = true;
    }
  };
  expect_stopped<Error>(spec, options, "stopped by SIGTERM after the loop's last solve");
  EXPECT_TRUE(asked);
  EXPECT_FALSE(fs::exists(stopped / "summary.json"));
  ASSERT_TRUE(fs::exists(stopped / "last-good" / "summary.json"));
  std::ifstream in(stopped / "last-good" / "summary.json");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("\"converged\": false"), std::string::npos);
  fs::remove_all(stopped);
}
