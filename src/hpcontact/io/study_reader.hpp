// Reading a study file: a list of runs of problem files (rows of a table, or a sweep over input
// values), validated like a problem file.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace hpcontact::io {

/// One run of a study: `hpcontact run CASE --set ...`.
struct StudyRun {
  std::string label;                                ///< unique in the study
  std::string case_file;                            ///< path, relative to the working folder
  std::vector<std::string> sets;                    ///< overrides, in order
  std::vector<std::pair<std::string, double>> seed;  ///< published values for the row (seed_*)
};

struct StudySpec {
  std::string file;   ///< the study file as given
  std::string name;   ///< `study`
  std::string title;  ///< `title`, may be empty
  std::vector<StudyRun> runs;
  std::vector<std::string> columns;  ///< extra summary.json keys (dotted) for the table
};

/// Reads a study file (docs/study.md). Keys (unknown ones are errors):
///   study: name (required); title: one line (optional);
///   case: the problem file of the sweep and of runs without their own (relative to the study
///         file's folder); set: overrides applied to every run, before a run's own;
///   sweep: {key.path: [values], ...} – every key an axis of the Cartesian product;
///   zip: {key.path: [values], ...} – keys that vary together (lists of one length): one more
///        axis, after the sweep's; one run per combination, in order (the last axis varies
///        fastest), labelled "degree=4, pressure=100, force=2000" (the last part of each key,
///        the whole key where two end alike);
///   runs: [{label, case, set, seed: {name: number}}] – explicit rows, after the sweep's;
///   columns: [summary keys] – e.g. contact.half_width, added to the table.
/// At least one run. Throws InputError "<file>:<line>:<col>: <key>: <what>", IoError if the
/// file cannot be read.
StudySpec read_study(const std::string& path);

/// read_study() on text; `file_label` names the file in messages and locates the cases.
StudySpec parse_study(const std::string& text, const std::string& file_label);

}  // namespace hpcontact::io
