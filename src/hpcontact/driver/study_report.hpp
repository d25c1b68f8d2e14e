// report.html of a study: its table and the convergence of its error measures, one page.
#pragma once

#include <string>
#include <vector>

#include "hpcontact/driver/study_table.hpp"

namespace hpcontact::driver {

/// The page: the study's name and file, the table of study.csv (each cell's text that of
/// study.csv, in a <td> with data-row (0-based) and data-column attributes; a failed row's
/// message), and, where any row has an error measure (a column ending in _percent, or hp's
/// estimated error), a log–log plot of the measures against DOF, a series per column.
std::string study_report_html(const io::StudySpec& study, const std::vector<StudyRowResult>& rows,
                              const std::vector<std::string>& columns);

/// Writes dir/report.html (IoError on failure).
void write_study_report(const std::string& dir, const io::StudySpec& study,
                        const std::vector<StudyRowResult>& rows,
                        const std::vector<std::string>& columns);

}  // namespace hpcontact::driver
