// The hpcontact command line: parse -> read problem -> run (discretise, solve, post, write).
#include <CLI/CLI.hpp>

#include <sys/ioctl.h>
#include <sys/prctl.h>
#include <unistd.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif

#include <algorithm>
#include <atomic>
#include <charconv>
#include <chrono>
#include <csignal>
#include <cstring>
#include <ctime>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <iostream>
#include <new>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>
#include <omp.h>

#include "hpcontact/core/error.hpp"
#include "hpcontact/core/stop.hpp"
#include "hpcontact/driver/contact_compare.hpp"
#include "hpcontact/driver/progress_display.hpp"
#include "hpcontact/driver/run.hpp"
#include "hpcontact/driver/slurm_study.hpp"
#include "hpcontact/driver/study.hpp"
#include "hpcontact/io/input_schema.hpp"
#include "hpcontact/io/problem_reader.hpp"
#include "hpcontact/io/study_reader.hpp"
#include "hpcontact/model/contact_carrier.hpp"
#include "hpcontact/model/contact_solve.hpp"
#include "hpcontact/model/discretization.hpp"
#include "hpcontact/model/rigid_motion.hpp"
#include "hpcontact/model/solid_model.hpp"

using namespace hpcontact;

namespace {

/// Text for the terminal: control characters (an escape sequence in a case name or a value) as
/// \xNN and the Unicode controls of writing direction (U+202E turns the rest of a line around)
/// as \uNNNN, so that nothing the input holds can drive the terminal or disguise a line. With
/// `lines` (a message of several lines) newlines and tabs stay; without (a name, a path, a line
/// of progress) they are escaped too, so that a value cannot begin a line of its own.
std::string printable(std::string_view text, bool lines = false) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto u = static_cast<unsigned char>(text[i]);
    char code[9];
    if ((u < 0x20 && !(lines && (u == '\n' || u == '\t'))) || u == 0x7f) {
      std::snprintf(code, sizeof code, "\\x%02x", u);
      out += code;
      continue;
    }
    // U+061C, U+200E-F, U+202A-E, U+2066-9 in UTF-8
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
    unsigned point = 0;
    if (u == 0xd8 && i + 1 < text.size() && byte(i + 1) == 0x9c) point = 0x061c;
    if (u == 0xe2 && i + 2 < text.size() && (byte(i + 1) == 0x80 || byte(i + 1) == 0x81)) {
      const unsigned p = 0x2000 + ((byte(i + 1) & 0x3f) << 6) + (byte(i + 2) & 0x3f);
      if (p == 0x200e || p == 0x200f || (p >= 0x202a && p <= 0x202e) || (p >= 0x2066 && p <= 0x2069))
        point = p;
    }
    if (point) {
      std::snprintf(code, sizeof code, "\\u%04x", point);
      out += code;
      i += point == 0x061c ? 1 : 2;
      continue;
    }
    out += text[i];
  }
  return out;
}

/// A message for the terminal: printable() keeping its lines.
std::string printable_lines(std::string_view text) { return printable(text, true); }

/// A check of a count option: a whole number from `low` to `high`; `meaning` says what the
/// numbers mean, in the message of a value outside ("must be ... (got -1)").
CLI::Validator count_between(long low, long high, const std::string& meaning) {
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        long value = 0;
        const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (ec == std::errc() && end == text.data() + text.size() && value >= low && value <= high)
          return "";
        return "must be " + meaning + " (got '" + printable(text) + "')";
      },
      "INT");
}

/// The output folder: --out, else results/<file name without extension>.
std::string output_folder(const std::string& out_dir, const std::string& file) {
  return out_dir.empty() ? "results/" + std::filesystem::path(file).stem().string() : out_dir;
}

/// Exit codes: 0 success, 1 the problem could not be solved (bad input, mesh, numerics, I/O),
/// 2 the command line itself is wrong.
constexpr int kFailed = 1;

/// When the first stop signal came (CLOCK_MONOTONIC, ns).
std::atomic<long long> first_stop_ns{0};
static_assert(std::atomic<long long>::is_always_lock_free, "stop_on_signal must be async-signal-safe");

/// A stop signal within this of the first is the same request delivered twice, not a second
/// one: `timeout` signals the run and then its whole process group, and Ctrl-C reaches a study's
/// runs from the terminal and again from the study, which passes it on.
constexpr long long kRepeatNs = 1'000'000'000;

/// `run` under SIGTERM, SIGINT or SIGHUP (a scheduler's time limit, Ctrl-C): the solve is asked
/// to stop (core/stop.hpp) instead of the process being killed, so that the run ends as a failed
/// run that keeps what had converged in last-good/; the process then ends by the same signal. A
/// second signal more than kRepeatNs after the first kills at once.
extern "C" void stop_on_signal(int signal) {
  timespec now{};
  clock_gettime(CLOCK_MONOTONIC, &now);  // async-signal-safe, as request_stop and raise
  const long long t = now.tv_sec * 1'000'000'000LL + now.tv_nsec;
  if (!stop_requested()) {
    first_stop_ns.store(t);
    request_stop(signal);
    return;
  }
  if (t - first_stop_ns.load() < kRepeatNs) return;
  std::signal(signal, SIG_DFL);
  std::raise(signal);  // delivered as the handler returns (the signal is blocked until then)
}

void stop_runs_on_signals() {
  for (const int signal : {SIGTERM, SIGINT, SIGHUP}) std::signal(signal, stop_on_signal);
}

/// `run --parent-pid PID`, as a study starts its runs: the run stops as on SIGTERM when its
/// parent ends, also when the parent is killed outright (SIGKILL passes nothing on). The kernel
/// sends SIGTERM at the parent's death (PR_SET_PDEATHSIG, set once the handlers are in place);
/// a parent that died before that (the run is then another process's child) is the same stop.
void stop_with_parent(pid_t parent) {
  if (parent <= 0) return;
  ::prctl(PR_SET_PDEATHSIG, SIGTERM);
  if (::getppid() != parent) std::raise(SIGTERM);
}

/// After a run that failed because it was asked to stop (its error said what last-good/ holds):
/// says so and ends by the signal.
void end_by_stop_signal() {
  const int signal = stop_signal();
  std::cerr << "hpcontact: " << stop_reason() << " before the run finished\n";
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

/// The adaptive loop of a problem, for the progress's status line; none without one.
std::optional<driver::AdaptivePlan> adaptive_plan(const model::ProblemSpec& spec) {
  const auto& a = spec.adapt;
  if (a.method == model::AdaptMethod::hp)
    return driver::AdaptivePlan{"hp", a.steps, a.tolerance_given ? a.tolerance : 0};
  if (a.method == model::AdaptMethod::rp) return driver::AdaptivePlan{"rp", a.max_iterations, a.tolerance};
  return std::nullopt;
}

/// `run`'s progress on stdout: JSON lines (--log-json), else a status line on a terminal or
/// plain lines; none with -q.
std::optional<driver::ProgressDisplayOptions> display_options(bool quiet, bool verbose, bool log_json) {
  if (quiet && !log_json) return std::nullopt;
  driver::ProgressDisplayOptions o;
  o.style = log_json                   ? driver::ProgressStyle::json
            : isatty(STDOUT_FILENO) != 0 ? driver::ProgressStyle::terminal
                                         : driver::ProgressStyle::lines;
  o.verbose = verbose;
  winsize size{};
  if (::ioctl(STDOUT_FILENO, TIOCGWINSZ, &size) == 0 && size.ws_col > 0) o.width = size.ws_col;
  o.printable = [](std::string_view text) { return printable(text); };
  return o;
}

int run_command(const std::string& file, std::string out_dir, const std::vector<std::string>& sets,
                driver::ProgressDisplay* display, bool log_json) {
  out_dir = output_folder(out_dir, file);
  // Opened (locked, checked) before the problem is read: a folder that holds the problem file
  // is refused before anything else. The earlier results stay until this run succeeds.
  driver::OutputFolder folder(out_dir, driver::run_layout(), {{file, "the problem file"}});
  const auto read = io::read_problem_full(file, sets);
  driver::RunOptions options;
  options.folder = &folder;
  options.effective_input = read.effective_yaml;
  // Warnings reach stderr whatever -q says: they are about the user's input or result.
  options.warning = [display](const std::string& warning) {
    auto write = [&] { std::cerr << "hpcontact: warning: " << printable(warning) << std::endl; };
    if (!display) return write();
    display->json_event("warning", {{"message", warning}});
    display->aside(write);
  };
  if (display) {
    options.progress = [display](const ProgressEvent& e) { (*display)(e); };
    if (const auto plan = adaptive_plan(read.spec)) display->set_plan(*plan);
    display->json_event("start", {{"case", read.spec.case_name}, {"file", file}, {"out", out_dir}});
    display->line("hpcontact: " + printable(file) + " (" + printable(read.spec.case_name) + ")");
  }
  const auto result = driver::run_problem(read.spec, options);
  const auto& s = result.summary;
  if (display) display->finish();
  if (log_json) {
    display->json_event("done", {{"converged", true}, {"dofs", s.dofs}, {"strain_energy", s.strain_energy},
                                 {"wall_time_s", s.wall_time_s},
                                 {"summary", (std::filesystem::path(out_dir) / "summary.json").string()}});
  } else if (display) {
    std::cout << "  dofs " << s.dofs << ", strain energy " << s.strain_energy;
    if (s.error) {
      std::cout << ", energy error " << s.error->energy_rel_percent << " %";
      if (s.error->energy_norm_rel_percent)
        std::cout << " (error norm " << *s.error->energy_norm_rel_percent << " %)";
    }
    std::cout << "\n  results in " << printable(out_dir) << "/ (summary.json";
    if (!read.spec.contact.empty()) std::cout << ", contact.csv";
    if (read.spec.output.vtu) std::cout << ", solution.vtu";
    std::cout << ", input.yaml), " << s.wall_time_s << " s\n";
  }
  return 0;
}

/// `check` of a 3D problem: the body's mesh, face sets and modes.
int check_solid(const std::string& file, const model::ProblemSpec& spec) {
  const model::SolidSpec& solid = *spec.solid;
  const model::SolidDiscretization d = model::discretize_solid(solid, spec.file);
  std::cout << printable(file) << ": case '" << printable(spec.case_name)
            << "', 3D, p-version (hexahedra, " << (solid.tensor_space ? "tensor" : "trunk")
            << " space)\n";
  std::cout << "  body '" << printable(solid.body.name) << "': " << d.mesh.topology.n_nodes()
            << " nodes, " << d.mesh.topology.n_hexes() << " hexahedra, degree " << solid.degree[0]
            << "," << solid.degree[1] << "," << solid.degree[2] << "\n  face sets:";
  for (const auto& [name, faces] : d.mesh.face_sets)
    std::cout << ' ' << printable(name) << " (" << faces.size() << ")";
  std::cout << "\n  " << solid.body.constraints.size() << " constraint(s), "
            << solid.body.loads.size() << " load(s)\n  free dofs " << d.n_free() << " ("
            << d.n_free_external()
            << " after condensing internal modes)\n";
  return 0;
}

int check_command(const std::string& file, const std::vector<std::string>& sets) {
  const auto spec = model::with_chosen_carriers(io::read_problem(file, sets));
  if (spec.solid) return check_solid(file, spec);
  const auto d = model::discretize(spec);
  model::require_held(spec, d);
  std::cout << printable(file) << ": case '" << printable(spec.case_name) << "', " << d.method
            << "-version\n";
  for (const auto& warning : d.warnings) std::cout << "  warning: " << printable(warning) << '\n';
  for (const auto& b : d.bodies) {
    std::cout << "  body '" << printable(b.name) << "': " << b.mesh.n_nodes() << " nodes, " << b.mesh.n_quads()
              << " elements, " << b.mesh.n_edges() << " edges, degrees";
    for (int q = 0; q < b.mesh.n_quads(); ++q) {
      const auto& es = b.dofs.element(q);
      if (es.is_lagrange)
        std::cout << ' ' << b.mesh.quad_id(q) << ":Q" << (es.n_modes());
      else
        std::cout << ' ' << b.mesh.quad_id(q) << ":(" << es.hierarchic.p_xi << ","
                  << es.hierarchic.p_eta << ")";
    }
    std::cout << '\n';
  }
  std::cout << "  free dofs " << d.n_free << " (" << d.n_free_external
            << " after condensing internal modes)\n";
  // Contact pairs are built as a run builds them (obstacle seen by the edges, penalty, friction).
  const auto pairs = model::make_contact_pairs(spec, d);
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const auto& pair = pairs[k];
    std::cout << "  contact[" << k << "]: body '" << printable(d.bodies[pair.body].name) << "', "
              << pair.edges.size() << " edges, " << pair.points.size() << " Gauss points, against ";
    if (pair.other >= 0)
      std::cout << "body '" << printable(d.bodies[pair.other].name) << "' (" << pair.other_points.size()
                << " Gauss points)";
    else
      std::cout << printable(pair.obstacle->describe());
    if (pair.constraints)
      std::cout << ", exact: " << pair.constraints->size() << " multiplier nodes, "
                << (pair.constraints->rule == model::ConstraintRule::mortar ? "mortar" : "collocation");
    else
      std::cout << ", penalty " << pair.penalty;
    std::cout << (spec.contact[k].friction.law == "none" ? "" : ", friction " + spec.contact[k].friction.law)
              << '\n';
    if (!pair.carrier_choice.empty()) std::cout << "    carrier " << printable(pair.carrier_choice) << '\n';
  }
  driver::require_references(spec);
  // The compare sections' preconditions, as a run checks them before solving.
  const auto comparisons = driver::make_comparisons(spec, d, pairs);
  for (std::size_t k = 0; k < comparisons.size(); ++k)
    if (comparisons[k]) {
      const auto& in = comparisons[k]->inputs();
      std::cout << "  contact[" << k << "].compare: E* " << in.effective_modulus << ", R* "
                << in.effective_radius << " (R1 " << in.radius << ", R2 " << in.other_radius
                << "), F ";
      if (in.force) std::cout << *in.force;
      else std::cout << "from the resultant";
      std::cout
                << (in.models_of_whole == 2 ? " (a symmetric half carries F/2)" : "") << '\n';
    }
  return 0;
}

/// The executable itself, for the study's runs.
std::string this_program(const char* argv0) {
  std::error_code ec;
  const auto self = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::filesystem::absolute(argv0).string() : self.string();
}

/// Prints a line per finished row, with a progress bar on a terminal ("ok"/"FAILED", the
/// row's time, a failed row's message), and counts the failed rows.
class StudyProgress {
 public:
  explicit StudyProgress(bool quiet) : quiet_(quiet), bar_(!quiet && isatty(STDOUT_FILENO)) {}
  void operator()(const driver::StudyRowResult& row, int done, int total) {
    failed_ += !row.converged();
    if (quiet_) return;
    const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
    std::ostringstream line;
    line << (row.converged() ? "ok     " : "FAILED ") << printable(row.run.label) << " ("
         << std::setprecision(3) << row.seconds << " s)";
    if (!row.converged()) line << ": " << printable(row.message);
    if (bar_) {
      const int width = 30, filled = width * done / total;
      std::cout << "\r\033[K" << line.str() << "\n[" << std::string(filled, '#')
                << std::string(width - filled, '.') << "] " << done << "/" << total << ", "
                << failed_ << " failed, " << std::setprecision(3) << t << " s" << std::flush;
      if (done == total) std::cout << '\n';
    } else {
      std::cout << "  [" << done << "/" << total << "] " << line.str() << '\n';
    }
  }

 private:
  bool quiet_, bar_;
  int failed_ = 0;
  std::chrono::steady_clock::time_point t0_ = std::chrono::steady_clock::now();
};

/// The closing line of a study: how many rows converged and where the tables are; the exit code.
int study_result(const std::vector<driver::StudyRowResult>& rows, const std::string& out_dir,
                 bool quiet) {
  const auto converged = std::count_if(rows.begin(), rows.end(),
                                       [](const driver::StudyRowResult& r) { return r.converged(); });
  if (!quiet)
    std::cout << "  " << converged << " of " << rows.size() << " runs converged; table in "
              << printable(out_dir) << "/study.csv, summaries in " << printable(out_dir)
              << "/study.json, the page to read in " << printable(out_dir) << "/report.html, runs in "
              << printable(out_dir) << "/runs/\n";
  return converged == static_cast<long>(rows.size()) ? 0 : kFailed;
}

/// A warning per column of the study that no run's summary.json has (its study.csv column empty).
void warn_absent_columns(const std::string& file, const std::vector<std::string>& columns) {
  for (const std::string& column : columns)
    std::cerr << "hpcontact: warning: " << printable(file) << ": columns: '" << printable(column)
              << "' is in no run's summary.json, so its study.csv column is empty (a dotted key; a "
                 "list's entries by their index: contact_pairs.1.pressure_max)\n";
}

int study_command(const std::string& file, std::string out_dir, int jobs, bool quiet,
                  const char* argv0) {
  out_dir = output_folder(out_dir, file);
  driver::OutputFolder folder(out_dir, driver::study_layout(), {{file, "the study file"}});
  const auto study = io::read_study(file);
  driver::StudyOptions options;
  options.program = this_program(argv0);
  options.folder = &folder;
  options.jobs = jobs > 0 ? jobs : std::max(1u, std::thread::hardware_concurrency());
  if (!quiet)
    std::cout << "hpcontact: study " << printable(file) << " ('" << printable(study.name) << "'): " << study.runs.size()
              << " runs, " << options.jobs << " at a time, into " << printable(out_dir) << "/\n";
  StudyProgress progress(quiet);
  options.finished = std::ref(progress);
  const auto outcome = driver::run_study(study, options);
  if (outcome.signal) {
    // The runs were stopped and waited for; the study ends by the signal it was sent.
    std::cerr << "\nhpcontact: study stopped by " << strsignal(outcome.signal)
              << ": its running runs were stopped (each keeps what had converged in its "
                 "last-good/), no table written in " << printable(out_dir) << "/"
              << (outcome.logs.empty() ? "" : "; the runs' logs are in " + printable(outcome.logs) + "/")
              << "\n";
    std::signal(outcome.signal, SIG_DFL);
    std::raise(outcome.signal);
    return kFailed;
  }
  warn_absent_columns(file, outcome.absent_columns);
  return study_result(outcome.rows, out_dir, quiet);
}

/// `study --collect DIR [--wait]`, and the end of `study FILE --executor slurm --wait`: follows
/// the last submission if asked, then builds the tables from the runs as they are.
int collect_command(driver::SlurmStudyOptions& options, bool wait, bool quiet) {
  const std::string out_dir = options.folder->target();
  StudyProgress progress(quiet);
  options.finished = std::ref(progress);
  if (wait) {
    if (!quiet)
      std::cout << "  following the job (Ctrl-C stops following, not the job: hpcontact study "
                   "--collect " << printable(out_dir) << " collects later)\n";
    driver::follow_slurm_study(options);
  }
  const auto outcome = driver::collect_slurm_study(options);
  warn_absent_columns(out_dir, outcome.absent_columns);
  if (!wait && !quiet)  // followed rows were printed as they ended
    for (const auto& row : outcome.rows)
      if (!row.converged())
        std::cout << "  FAILED " << printable(row.run.label) << ": " << printable(row.message) << '\n';
  return study_result(outcome.rows, out_dir, quiet);
}

int slurm_study_command(const std::string& file, std::string out_dir,
                        const driver::SlurmOptions& slurm, bool wait, bool quiet, const char* argv0) {
  out_dir = output_folder(out_dir, file);
  driver::require_slurm_client(out_dir);  // before the output folder is made
  driver::OutputFolder folder(out_dir, driver::study_layout(), {{file, "the study file"}});
  const auto study = io::read_study(file);
  driver::SlurmStudyOptions options;
  options.program = this_program(argv0);
  options.folder = &folder;
  options.slurm = slurm;
  options.note = [quiet](const std::string& line) {
    if (!quiet || line.rfind("warning", 0) == 0) std::cout << "  " << printable(line) << '\n';
  };
  if (!quiet)
    std::cout << "hpcontact: study " << printable(file) << " ('" << printable(study.name) << "'): "
              << study.runs.size() << " runs on Slurm, into " << printable(out_dir) << "/\n";
  const auto submission = driver::submit_slurm_study(study, options);
  if (!wait) {
    if (!quiet && !submission.job_id.empty())
      std::cout << "  squeue -j " << submission.job_id << " shows it; when it has ended: hpcontact study --collect "
                << printable(out_dir) << '\n';
    if (submission.job_id.empty()) return collect_command(options, false, quiet);
    return 0;
  }
  return collect_command(options, !submission.job_id.empty(), quiet);
}

}  // namespace

int main(int argc, char** argv) {
#ifdef __GLIBC__
  // Each Newton iteration builds and frees the same large buffers (triplets, the multiplier
  // system's dense blocks): keep freed memory for the next one instead of returning it to the
  // system and faulting it in again (examples/two-bars/coulomb.yaml, farm-bench A/B: system time
  // 0.19 s -> 0.04 s, wall 0.70 s -> 0.55 s). Blocks above 32 MiB still go back at once.
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
#endif
  // CHOLMOD asks for teams of 4 OpenMP threads in its supernodal factorisation whatever the
  // machine has: on 2 processors the threads spin against each other. With dynamic adjustment
  // a team is no larger than the processors free (processors less the load average):
  // examples/hertz/hp-tolerance.yaml, farm-bench A/B wall 0.90 (0.205 s -> 0.184 s).
  omp_set_dynamic(1);
  CLI::App app{"hpcontact: 2D contact problems with high-order finite elements"};
  app.set_version_flag("--version", std::string("hpcontact ") + HPC_VERSION);
  bool help_input = false;
  app.add_flag("--help-input", help_input, "print every key of the problem file (Markdown) and exit");
  app.require_subcommand(0, 1);

  std::string file, out_dir;
  std::vector<std::string> sets;
  bool quiet = false;
  auto* run = app.add_subcommand("run", "solve a problem file and write its results");
  run->add_option("case", file, "problem file (YAML)")->required()->check(CLI::ExistingFile);
  run->add_option("--out,-o", out_dir, "output folder (default results/<case file name>)");
  run->add_option("--set", sets, "override an input value: dotted.key=value (repeatable)");
  run->add_flag("--quiet,-q", quiet, "print nothing but errors");
  int parent_pid = 0;
  run->add_option("--parent-pid", parent_pid,
                  "(hpcontact study's runs) stop as on SIGTERM when process PID, the parent, ends")
      ->group("");  // not for users: hidden from --help
  bool log_json = false, verbose = false;
  run->add_flag("--log-json", log_json,
                "progress as JSON lines on stdout (kind: start, iteration, load_step, adapt_step, "
                "file_written, message, warning, done, error; docs/output.md)");
  run->add_flag("--verbose,-v", verbose, "a line per Newton iteration too");

  auto* check = app.add_subcommand("check", "validate a problem file and describe it, without solving");
  check->add_option("case", file, "problem file (YAML)")->required()->check(CLI::ExistingFile);
  check->add_option("--set", sets, "override an input value: dotted.key=value (repeatable)");

  std::string study_file;
  int jobs = 0;
  auto* study = app.add_subcommand(
      "study", "run every case of a study file (rows or a sweep), in parallel, into one table");
  study->add_option("study", study_file, "study file (YAML)")->check(CLI::ExistingFile);
  study->add_option("--out,-o", out_dir, "output folder (default results/<study file name>)");
  study->add_option("--jobs,-j", jobs, "runs at a time (default: the machine's cores)")
      ->check(count_between(0, 4096, "a number of runs at a time from 1 to 4096, or 0 for "
                                     "the machine's cores"));
  study->add_flag("--quiet,-q", quiet, "print nothing but errors");
  std::string executor = "local", collect_dir;
  driver::SlurmOptions slurm;
  bool wait = false;
  study->add_option("--executor", executor, "local (processes on this machine) or slurm (a job array)")
      ->check(CLI::IsMember({"local", "slurm"}));
  auto* partition = study->add_option("--partition", slurm.partition, "slurm: the partition (default: the cluster's)");
  auto* time_limit = study->add_option("--time", slurm.time, "slurm: time limit per task, as sbatch --time");
  auto* cpus = study->add_option("--cpus-per-task", slurm.cpus_per_task,
                                 "slurm: CPUs per task (and the run's threads; default 1)")
                   ->check(count_between(1, 4096, "a number of CPUs from 1 to 4096"));
  auto* sbatch_options = study->add_option("--sbatch-option", slurm.sbatch_options,
                                           "slurm: one more option for sbatch, as --sbatch-option=--mem=2G (repeatable)");
  auto* wait_flag = study->add_flag("--wait", wait, "slurm: follow the job until every task has ended, then collect");
  auto* collect = study->add_option("--collect", collect_dir,
                                    "build study.csv and study.json in DIR from its Slurm runs (after the job, or a part of it)");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    std::cerr << "hpcontact: " << printable_lines(e.what()) << "\n\n" << app.help();
    return 2;
  }
  if (help_input) {
    std::cout << io::input_schema_markdown();
    return 0;
  }
  // A closed stdout (`hpcontact run ... | head`) must not kill a solve half way: without
  // SIGPIPE the progress lines fail quietly, the run writes its results and says so on stderr.
  std::signal(SIGPIPE, SIG_IGN);
  try {
    if (*run) {
      std::optional<driver::ProgressDisplay> display;
      if (auto o = display_options(quiet, verbose, log_json)) display.emplace(std::cout, std::move(*o));
      stop_runs_on_signals();
      stop_with_parent(parent_pid);
      try {
        const int code = run_command(file, out_dir, sets, display ? &*display : nullptr, log_json);
        if (!std::cout)
          std::cerr << "hpcontact: the standard output was closed during the run; the run went "
                       "on, and its results are in "
                    << printable(output_folder(out_dir, file)) << "/\n";
        return code;
      } catch (const std::exception& e) {
        if (display) {
          display->finish();
          display->json_event("error", {{"message", e.what()}});
        }
        if (stop_signal() > 0) {
          std::cerr << "hpcontact: error: " << printable_lines(e.what()) << '\n';
          end_by_stop_signal();
        }
        throw;
      }
    }
    if (*check) return check_command(file, sets);
    if (*study) {
      const bool on_slurm = executor == "slurm";
      if (!collect->empty()) {
        if (!study_file.empty() || !out_dir.empty() || on_slurm || *partition || *time_limit || *cpus || *sbatch_options)
          throw CommandLineError("--collect DIR takes no study file, --out or submission options (only --wait, -q)");
        HPC_REQUIRE(std::filesystem::is_directory(collect_dir), IoError, collect_dir,
                    ": no such folder (--collect takes the --out folder of a study submitted with "
                    "--executor slurm)");
        driver::OutputFolder folder(collect_dir, driver::study_layout());
        driver::SlurmStudyOptions options;
        options.folder = &folder;
        return collect_command(options, wait, quiet);
      }
      if (study_file.empty()) throw CommandLineError("study: give a study file (or --collect DIR)");
      if (!on_slurm) {
        for (const auto* o : {partition, time_limit, cpus, sbatch_options, wait_flag})
          if (*o) throw CommandLineError(o->get_name() + ": only with --executor slurm");
        return study_command(study_file, out_dir, jobs, quiet, argv[0]);
      }
      if (jobs > 0) throw CommandLineError("--jobs: not with --executor slurm (the scheduler runs the tasks)");
      return slurm_study_command(study_file, out_dir, slurm, wait, quiet, argv[0]);
    }
    std::cerr << "hpcontact: no sub-command given\n\n" << app.help();
    return 2;
  } catch (const CommandLineError& e) {
    std::cerr << "hpcontact: error: " << printable_lines(e.what()) << "\n\n" << (*run ? run : *study ? study : check)->help();
    return 2;
  } catch (const Error& e) {
    std::cerr << "hpcontact: error: " << printable_lines(e.what()) << '\n';
    return kFailed;
  } catch (const std::bad_alloc&) {
    std::cerr << "hpcontact: error: out of memory: the problem needs more memory than this "
                 "process may use (fewer elements, a lower degree or fewer "
                 "output.vtu_subdivisions need less)\n";
    return kFailed;
  } catch (const std::exception& e) {
    std::cerr << "hpcontact: internal error: " << printable_lines(e.what()) << '\n';
    return kFailed;
  }
}
