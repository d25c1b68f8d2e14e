// The study's page: study.csv as a table and its error measures against DOF.
#include "hpcontact/driver/study_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <numeric>
#include <sstream>

#include "hpcontact/post/html_text.hpp"
#include "hpcontact/post/output_file.hpp"
#include "hpcontact/post/svg_plot.hpp"

namespace hpcontact::driver {

namespace {

using post::escape_html;

bool ends_with(const std::string& s, const std::string& end) {
  return s.size() >= end.size() && s.compare(s.size() - end.size(), end.size(), end) == 0;
}

/// A column the plot shows: an error measure in percent, or hp's estimate (relative).
bool error_column(const std::string& column) {
  return ends_with(column, "_percent") || column.rfind("adapt.estimated_error.", 0) == 0;
}

/// A cell's text as a number, if all of it is one.
std::optional<double> number_of(const std::string& text) {
  if (text.empty()) return std::nullopt;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size()) return std::nullopt;
  return v;
}

std::string table(const std::vector<StudyRowResult>& rows, const std::vector<std::string>& columns) {
  std::ostringstream os;
  os << "<div class=\"wide\"><table data-table=\"study\"><tr><th>#</th>";
  for (const auto& c : columns) os << "<th>" << escape_html(c) << "</th>";
  os << "</tr>\n";
  for (size_t i = 0; i < rows.size(); ++i) {
    os << "<tr><td class=\"num\">" << i + 1 << "</td>";
    for (const auto& c : columns) {
      const std::string text = study_cell(rows[i], c);
      os << "<td" << (number_of(text) ? " class=\"num\"" : "") << " data-row=\"" << i
         << "\" data-column=\"" << escape_html(c) << "\">" << escape_html(text) << "</td>";
    }
    os << "</tr>\n";
  }
  os << "</table></div>\n";
  return os.str();
}

/// The error measures against DOF, the rows in order of DOF; "" without a measure.
std::string convergence_plot(const std::vector<StudyRowResult>& rows, const std::vector<std::string>& columns) {
  std::vector<size_t> order(rows.size());
  std::iota(order.begin(), order.end(), 0);
  auto dofs = [&](size_t i) { return number_of(study_cell(rows[i], "dofs")).value_or(NAN); };
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return dofs(a) < dofs(b); });
  post::LinePlot plot;
  plot.figure = "convergence";
  plot.title = "Error measures against DOF";
  plot.x_label = "DOF";
  plot.y_label = "error (% ; estimates relative)";
  plot.log_x = plot.log_y = true;
  for (const auto& c : columns) {
    if (!error_column(c)) continue;
    post::PlotSeries s{c, c, {}, {}, true, false, true};
    bool any = false;
    for (const size_t i : order) {
      const auto v = number_of(study_cell(rows[i], c));
      s.x.push_back(dofs(i));
      s.y.push_back(v.value_or(NAN));
      any = any || (v && *v > 0);
    }
    if (any) plot.series.push_back(s);
  }
  if (plot.series.empty()) return "<p>No error measures in the table: no convergence plot.</p>\n";
  return post::line_plot_svg(plot) +
         "<p class=\"note\">The rows in order of DOF; a row without a value leaves a gap.</p>\n";
}

}  // namespace

std::string study_report_html(const io::StudySpec& study, const std::vector<StudyRowResult>& rows,
                              const std::vector<std::string>& columns) {
  const int failed = static_cast<int>(std::count_if(rows.begin(), rows.end(),
                                                    [](const StudyRowResult& r) { return !r.converged(); }));
  std::ostringstream body;
  body << "<h1>hpcontact study: <span data-case>" << escape_html(study.name) << "</span></h1>\n";
  if (!study.title.empty()) body << "<p>" << escape_html(study.title) << "</p>\n";
  body << "<p>Study file <code data-file>" << escape_html(study.file) << "</code>; " << rows.size()
       << " run(s)";
  if (failed) body << ", <strong data-status=\"failed\">" << failed << " failed</strong> (their message in the table)";
  body << ". Each run's own report.html is in its folder (run_dir).</p>\n<h2>The table (study.csv)</h2>\n"
       << table(rows, columns) << "<h2>Convergence</h2>\n" << convergence_plot(rows, columns)
       << "<p class=\"note\">Written by hpcontact with study.csv; every cell is study.csv's.</p>\n";
  return post::html_document("hpcontact study: " + study.name, body.str());
}

void write_study_report(const std::string& dir, const io::StudySpec& study,
                        const std::vector<StudyRowResult>& rows,
                        const std::vector<std::string>& columns) {
  post::write_text_file((std::filesystem::path(dir) / "report.html").string(),
                        study_report_html(study, rows, columns));
}

}  // namespace hpcontact::driver
