// A plain run asked to stop while in a solve with no Newton iteration left to end at (here a
// linear one): it ends as stopped and writes nothing, as its scheduler reports it cancelled.
#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
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
}  // namespace

TEST(RunStop, ALinearRunAskedToStopWritesNoResults) {
  const auto spec = io::read_problem(kExample, {"discretization.degree=3"});
  const fs::path stopped = fresh_folder("stopped"), finished = fresh_folder("finished");

  driver::RunOptions options;
  options.out_dir = finished.string();
  driver::run_problem(spec, options);  // the same run without a stop request: its results
  EXPECT_TRUE(fs::exists(finished / "summary.json"));

  options.out_dir = stopped.string();
  request_stop(SIGTERM);
  try {
    driver::run_problem(spec, options);
    ADD_FAILURE() << "a run asked to stop ended as a success";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("stopped by SIGTERM before the results were written"),
              std::string::npos)
        << e.what();
  }
  clear_stop();
  EXPECT_FALSE(fs::exists(stopped / "summary.json"));
  fs::remove_all(stopped);
  fs::remove_all(finished);
}
