// The rows of a study (a run's outcome) and the tables made of them: study.csv and study.json,
// whichever executor ran the rows.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hpcontact/io/study_reader.hpp"

namespace hpcontact::driver {

struct StudyRowResult {
  io::StudyRun run;
  std::string run_dir;  ///< the run's output folder (summary.json, log.txt, ...)
  int exit_code = -1;   ///< of `hpcontact run`; < 0: killed by a signal (its number, negated)
  double seconds = 0;   ///< wall time of the process
  std::string message;  ///< a failed run: the last line it printed
  nlohmann::json summary;  ///< summary.json of a run that converged; null otherwise
  bool converged() const { return exit_code == 0 && summary.is_object(); }
};

/// The folder of row `index` (0-based) under OUT/runs/: "NN-label", the label's letters,
/// digits, '-', '.', '=' kept and every other character '_'.
std::string row_folder_name(int index, const std::string& label);

/// A run's error from its log: the last "hpcontact: error: ..." line (without that prefix),
/// else the last non-empty line not starting with `skip_prefix` (when given); "" if none.
std::string log_error_line(const std::string& log_file, const std::string& skip_prefix = "");

/// summary.json of a run folder, or null if it is missing or not JSON.
nlohmann::json read_summary(const std::string& run_dir);

/// The table's columns for these rows: label, case, converged, dofs, wall time, energy,
/// iterations, the contact and error measures any row has, the study's columns, seed_* values.
std::vector<std::string> study_columns(const io::StudySpec& study,
                                       const std::vector<StudyRowResult>& rows);

/// The text of a row's cell in a column of study.csv (numbers to 12 digits; "" where the row has
/// no value).
std::string study_cell(const StudyRowResult& row, const std::string& column);

/// Writes DIR/study.csv (a line per row, study_columns()) and DIR/study.json (every row with its
/// summary) and DIR/report.html (the table and a log-log plot of its error measures against DOF);
/// docs/study.md describes them. IoError if a file cannot be written.
/// The study's `columns` that no run's summary.json has (their study.csv column stays empty):
/// a key misspelt, or one the runs do not write.
std::vector<std::string> absent_columns(const io::StudySpec& study, const std::vector<StudyRowResult>& rows);

void write_study_tables(const io::StudySpec& study, const std::vector<StudyRowResult>& rows,
                        const std::string& dir);

}  // namespace hpcontact::driver
