// study.csv and study.json from the rows of a study, and the helpers both executors share.
#include "hpcontact/driver/study_table.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <set>
#include <sstream>

#include "hpcontact/driver/study_report.hpp"
#include "hpcontact/post/output_file.hpp"

namespace hpcontact::driver {

namespace fs = std::filesystem;

namespace {

/// The value at a dotted path of a JSON object ("contact.half_width"; a list's entry by its
/// index: "contact_pairs.1.pressure_max"), or null.
const nlohmann::json* at_path(const nlohmann::json& j, const std::string& path) {
  const nlohmann::json* node = &j;
  std::size_t start = 0;
  while (start <= path.size()) {
    const std::size_t dot = path.find('.', start);
    const std::string key = path.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    if (node->is_array()) {
      const bool index = !key.empty() && key.size() < 10 &&
                         key.find_first_not_of("0123456789") == std::string::npos;
      if (!index || std::stoul(key) >= node->size()) return nullptr;
      node = &(*node)[std::stoul(key)];
    } else {
      if (!node->is_object() || !node->contains(key)) return nullptr;
      node = &(*node)[key];
    }
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  return node;
}

std::string csv_field(std::string s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c == '\n' ? ' ' : c);
  return q + "\"";
}

std::string json_cell(const nlohmann::json* v) {
  if (!v || v->is_null()) return "";
  if (v->is_number_float()) {
    std::ostringstream os;
    os << std::setprecision(12) << v->get<double>();
    return os.str();
  }
  if (v->is_string()) return v->get<std::string>();
  return v->dump();
}


// Summary keys shown when any row has them, in this order.
const char* const kMeasures[] = {
    "contact.resultant",           "contact.half_width",
    "contact.p_max",               "contact.max_penetration",
    "contact.e_seed_hertz_percent", "contact.e_seed_shtayerman_percent",
    "contact.e_L2_hertz_percent",  "contact.e_L2_shtayerman_percent",
    "contact.e_L2_reference_percent", "error.energy_rel_percent",
    "error.energy_norm_rel_percent"};

}  // namespace

std::string row_folder_name(int index, const std::string& label) {
  std::ostringstream os;
  os << std::setw(2) << std::setfill('0') << index + 1 << '-';
  for (char c : label) os << (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '.' || c == '=' ? c : '_');
  return os.str();
}

std::string log_error_line(const std::string& log_file, const std::string& skip_prefix) {
  const std::string prefix = "hpcontact: error: ";
  std::ifstream in(log_file);
  std::string line, last, error;
  while (std::getline(in, line)) {
    if (!skip_prefix.empty() && line.rfind(skip_prefix, 0) == 0) continue;
    if (!line.empty()) last = line;
    if (line.rfind(prefix, 0) == 0) error = line.substr(prefix.size());
  }
  return error.empty() ? last : error;
}

nlohmann::json read_summary(const std::string& run_dir) {
  std::ifstream in(fs::path(run_dir) / "summary.json");
  if (!in) return nullptr;
  auto summary = nlohmann::json::parse(in, nullptr, false);
  return summary.is_discarded() ? nlohmann::json() : summary;
}

namespace {
/// A column the study fills from the run itself (its label, case, outcome, folder, seeds), not
/// from its summary.json.
bool is_run_column(const std::string& c) {
  return c == "label" || c == "case" || c == "converged" || c == "message" || c == "run_dir" ||
         c.rfind("seed_", 0) == 0;
}
}  // namespace

std::string study_cell(const StudyRowResult& row, const std::string& column) {
  if (!is_run_column(column)) return row.summary.is_object() ? json_cell(at_path(row.summary, column)) : "";
  if (column == "label") return row.run.label;
  if (column == "case") return row.run.case_file;
  if (column == "converged") return row.converged() ? "true" : "false";
  if (column == "message") return row.converged() ? "" : row.message;
  if (column == "run_dir") return row.run_dir;
  for (const auto& [k, v] : row.run.seed)  // a seed_ column
    if ("seed_" + k == column) {
      std::ostringstream os;
      os << std::setprecision(12) << v;
      return os.str();
    }
  return "";
}

std::vector<std::string> absent_columns(const io::StudySpec& study,
                                        const std::vector<StudyRowResult>& rows) {
  std::vector<std::string> absent;
  for (const auto& c : study.columns) {
    if (is_run_column(c)) continue;
    const bool somewhere = std::any_of(rows.begin(), rows.end(), [&](const StudyRowResult& r) {
      return r.summary.is_object() && at_path(r.summary, c) != nullptr;
    });
    if (!somewhere) absent.push_back(c);
  }
  return absent;
}

std::vector<std::string> study_columns(const io::StudySpec& study,
                                       const std::vector<StudyRowResult>& rows) {
  std::vector<std::string> cols = {"label", "case", "converged", "dofs", "wall_time_s",
                                   "strain_energy", "load_steps", "newton_iterations"};
  auto any_has = [&](const std::string& key) {
    return std::any_of(rows.begin(), rows.end(), [&](const StudyRowResult& r) {
      return r.summary.is_object() && at_path(r.summary, key) != nullptr;
    });
  };
  for (const char* m : kMeasures)
    if (any_has(m)) cols.push_back(m);
  for (const auto& c : study.columns)
    if (std::find(cols.begin(), cols.end(), c) == cols.end()) cols.push_back(c);
  std::set<std::string> seen;
  for (const auto& r : study.runs)
    for (const auto& [k, v] : r.seed)
      if (seen.insert(k).second) cols.push_back("seed_" + k);
  cols.push_back("message");
  cols.push_back("run_dir");
  return cols;
}


void write_study_tables(const io::StudySpec& study, const std::vector<StudyRowResult>& rows,
                        const std::string& out_dir) {
  const auto columns = study_columns(study, rows);
  std::ostringstream csv;
  for (std::size_t c = 0; c < columns.size(); ++c) csv << (c ? "," : "") << columns[c];
  csv << '\n';
  nlohmann::json all = nlohmann::json::array();
  for (const auto& row : rows) {
    nlohmann::json j = {{"label", row.run.label}, {"case", row.run.case_file},
                        {"set", row.run.sets}, {"run_dir", row.run_dir},
                        {"exit_code", row.exit_code}, {"converged", row.converged()},
                        {"seconds", row.seconds}};
    if (!row.converged()) j["message"] = row.message;
    if (row.summary.is_object()) j["summary"] = row.summary;
    for (const auto& [k, v] : row.run.seed) j["seed"][k] = v;
    all.push_back(j);
    for (std::size_t c = 0; c < columns.size(); ++c)
      csv << (c ? "," : "") << csv_field(study_cell(row, columns[c]));
    csv << '\n';
  }
  post::write_text_file((fs::path(out_dir) / "study.csv").string(), csv.str());
  write_study_report(out_dir, study, rows, columns);
  nlohmann::json doc = {{"study", study.name}, {"file", study.file}, {"runs", all}};
  if (!study.title.empty()) doc["title"] = study.title;
  // a path of bytes that are not UTF-8 (a file name) has them as U+FFFD: the file stays JSON
  post::write_text_file((fs::path(out_dir) / "study.json").string(),
                        doc.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
}

}  // namespace hpcontact::driver
