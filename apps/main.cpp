// The hpcontact command line: parse -> read problem -> run (discretise, solve, post, write).
#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "hpcontact/core/error.hpp"
#include "hpcontact/driver/run.hpp"
#include "hpcontact/io/input_schema.hpp"
#include "hpcontact/io/problem_reader.hpp"
#include "hpcontact/model/discretization.hpp"
#include "hpcontact/model/rigid_motion.hpp"

using namespace hpcontact;

namespace {

/// Exit codes: 0 success, 1 the problem could not be solved (bad input, mesh, numerics, I/O),
/// 2 the command line itself is wrong.
constexpr int kFailed = 1;

int run_command(const std::string& file, std::string out_dir, const std::vector<std::string>& sets,
                bool quiet) {
  if (out_dir.empty()) out_dir = "results/" + std::filesystem::path(file).stem().string();
  driver::prepare_output_folder(out_dir);  // before reading: bad input must not leave an old summary
  const auto read = io::read_problem_full(file, sets);
  driver::RunOptions options;
  options.out_dir = out_dir;
  options.effective_input = read.effective_yaml;
  if (!quiet) options.progress = [](const std::string& line) { std::cout << "  " << line << '\n'; };
  if (!quiet) std::cout << "hpcontact: " << file << " (" << read.spec.case_name << ")\n";
  const auto result = driver::run_problem(read.spec, options);
  const auto& s = result.summary;
  if (!quiet) {
    std::cout << "  dofs " << s.dofs << ", strain energy " << s.strain_energy;
    if (s.error) {
      std::cout << ", energy error " << s.error->energy_rel_percent << " %";
      if (s.error->energy_norm_rel_percent)
        std::cout << " (error norm " << *s.error->energy_norm_rel_percent << " %)";
    }
    std::cout << "\n  results in " << out_dir << "/ (summary.json";
    if (!read.spec.contact.empty()) std::cout << ", contact.csv";
    if (read.spec.output.vtu) std::cout << ", solution.vtu";
    std::cout << ", input.yaml), " << s.wall_time_s << " s\n";
  }
  return 0;
}

int check_command(const std::string& file, const std::vector<std::string>& sets) {
  const auto spec = io::read_problem(file, sets);
  const auto d = model::discretize(spec);
  model::require_held(spec, d);
  std::cout << file << ": case '" << spec.case_name << "', " << d.method << "-version\n";
  for (const auto& b : d.bodies) {
    std::cout << "  body '" << b.name << "': " << b.mesh.n_nodes() << " nodes, " << b.mesh.n_quads()
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
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
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

  auto* check = app.add_subcommand("check", "validate a problem file and describe it, without solving");
  check->add_option("case", file, "problem file (YAML)")->required()->check(CLI::ExistingFile);
  check->add_option("--set", sets, "override an input value: dotted.key=value (repeatable)");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    std::cerr << "hpcontact: " << e.what() << "\n\n" << app.help();
    return 2;
  }
  if (help_input) {
    std::cout << io::input_schema_markdown();
    return 0;
  }
  try {
    if (*run) return run_command(file, out_dir, sets, quiet);
    if (*check) return check_command(file, sets);
    std::cerr << "hpcontact: no sub-command given\n\n" << app.help();
    return 2;
  } catch (const Error& e) {
    std::cerr << "hpcontact: error: " << e.what() << '\n';
    return kFailed;
  } catch (const std::exception& e) {
    std::cerr << "hpcontact: internal error: " << e.what() << '\n';
    return kFailed;
  }
}
