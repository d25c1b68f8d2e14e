// The submission record of a study on Slurm, as JSON.
#include "hpcontact/driver/slurm_record.hpp"

#include <filesystem>

#include "hpcontact/core/error.hpp"
#include "hpcontact/io/text_file.hpp"

namespace hpcontact::driver {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {
/// A record of thousands of rows is a few MB.
constexpr std::size_t kMaxRecordBytes = 64u << 20;

/// The checks of a record's shape: every key the collection reads, of the type it reads it as,
/// so that an edited or forged record is named by its key path instead of failing in the JSON
/// library, and a row or job id cannot lead outside the study (a row beyond it, a log's path).
class RecordShape {
public:
  explicit RecordShape(std::string path) : path_(std::move(path)) {}

  void check(const json& record) {
    require(record.is_object(), "", "an object {study, submissions, ...}", record);
    const json& study = member(record, "", "study");
    require(study.is_object(), "study", "an object {file, name, title, columns, runs}", study);
    for (const char* key : {"file", "name", "title"}) text(study, "study", key);
    texts(study, "study", "columns");
    const json& runs = member(study, "study", "runs");
    require(runs.is_array(), "study.runs", "a list of rows", runs);
    for (std::size_t i = 0; i < runs.size(); ++i) {
      const std::string at = "study.runs[" + std::to_string(i) + "]";
      require(runs[i].is_object(), at, "an object {label, case, set, seed}", runs[i]);
      text(runs[i], at, "label");
      text(runs[i], at, "case");
      texts(runs[i], at, "set");
      const json& seed = member(runs[i], at, "seed");
      require(seed.is_array(), at + ".seed", "a list of [name, number]", seed);
      for (const auto& s : seed)
        require(s.is_array() && s.size() == 2 && s[0].is_string() && s[1].is_number(),
                at + ".seed", "a list of [name, number]", s);
    }
    const json& submissions = member(record, "", "submissions");
    require(submissions.is_array(), "submissions", "a list of submissions", submissions);
    for (std::size_t i = 0; i < submissions.size(); ++i) {
      const std::string at = "submissions[" + std::to_string(i) + "]";
      const json& s = submissions[i];
      require(s.is_object(), at, "an object {job_id, rows, complete, ...}", s);
      const json& id = member(s, at, "job_id");
      require(id.is_string() && id.get<std::string>().find_first_not_of("0123456789") ==
                                    std::string::npos,
              at + ".job_id", "Slurm's job id, digits (or \"\" if never submitted)", id);
      rows(s, at, "rows", runs.size(), true);
      rows(s, at, "complete", runs.size(), false);
      if (s.contains("submitted")) text(s, at, "submitted");
    }
  }

private:
  [[noreturn]] void fail(const std::string& key, const std::string& what, const json& got) const {
    std::string shown = got.dump(-1, ' ', false, json::error_handler_t::replace);
    if (shown.size() > 60) shown = shown.substr(0, 57) + "...";
    throw IoError(path_ + ": not a submission record of hpcontact study --executor slurm: " +
                  (key.empty() ? "the file" : key) + " must be " + what + " (got " + shown +
                  "); the file was edited: restore it, or move it away and submit the study "
                  "again (the rows with a successful run are not run again)");
  }
  void require(bool ok, const std::string& key, const std::string& what, const json& got) const {
    if (!ok) fail(key, what, got);
  }
  const json& member(const json& object, const std::string& at, const std::string& key) const {
    const std::string where = at.empty() ? key : at + "." + key;
    if (!object.contains(key)) fail(where, "there", nullptr);
    return object.at(key);
  }
  void text(const json& object, const std::string& at, const std::string& key) const {
    const json& v = member(object, at, key);
    require(v.is_string(), at + "." + key, "a string", v);
  }
  void texts(const json& object, const std::string& at, const std::string& key) const {
    const json& v = member(object, at, key);
    require(v.is_array(), at + "." + key, "a list of strings", v);
    for (const auto& e : v) require(e.is_string(), at + "." + key, "a list of strings", e);
  }
  /// A list of row numbers of a study of n rows (optional unless `required`).
  void rows(const json& object, const std::string& at, const std::string& key, std::size_t n,
            bool required) const {
    if (!required && !object.contains(key)) return;
    const json& v = member(object, at, key);
    const std::string what = n == 0 ? std::string("empty (the study has no rows)")
                                    : "a list of row numbers from 0 to " + std::to_string(n - 1);
    require(v.is_array(), at + "." + key, what, v);
    for (const auto& r : v)
      require(r.is_number_integer() && r.get<long long>() >= 0 &&
                  r.get<long long>() < static_cast<long long>(n),
              at + "." + key, what, r);
  }

  std::string path_;
};

/// "YYYY-MM-DDTHH:MM:SSZ" (the record's "submitted") as seconds since the epoch; 0 if unreadable.
std::time_t utc_seconds(const std::string& text) {
  std::tm t{};
  const char* end = strptime(text.c_str(), "%Y-%m-%dT%H:%M:%SZ", &t);
  return end && *end == '\0' ? timegm(&t) : 0;
}
}  // namespace

json study_to_json(const io::StudySpec& study) {
  json runs = json::array();
  for (const auto& r : study.runs) {
    json seed = json::array();
    for (const auto& [k, v] : r.seed) seed.push_back({k, v});
    runs.push_back({{"label", r.label}, {"case", r.case_file}, {"set", r.sets}, {"seed", seed}});
  }
  return {{"file", study.file}, {"name", study.name}, {"title", study.title},
          {"columns", study.columns}, {"runs", runs}};
}

io::StudySpec study_from_json(const json& j) {
  io::StudySpec study;
  study.file = j.at("file").get<std::string>();
  study.name = j.at("name").get<std::string>();
  study.title = j.at("title").get<std::string>();
  study.columns = j.at("columns").get<std::vector<std::string>>();
  for (const auto& r : j.at("runs")) {
    io::StudyRun run;
    run.label = r.at("label").get<std::string>();
    run.case_file = r.at("case").get<std::string>();
    run.sets = r.at("set").get<std::vector<std::string>>();
    for (const auto& s : r.at("seed")) run.seed.emplace_back(s.at(0).get<std::string>(), s.at(1).get<double>());
    study.runs.push_back(std::move(run));
  }
  return study;
}

json read_record(const std::string& out) {
  const std::string path = out + "/" + kSubmissionRecord;
  std::error_code ec;
  if (!fs::exists(path, ec)) return nullptr;
  json record = json::parse(io::read_bounded_file(path, "submission record", kMaxRecordBytes, false),
                            nullptr, false);
  HPC_REQUIRE(!record.is_discarded(), IoError, path, ": not a submission record of hpcontact "
              "study --executor slurm: not JSON; the file was edited: restore it, or move it "
              "away and submit the study again (the rows with a successful run are not run again)");
  RecordShape(path).check(record);
  return record;
}

std::vector<json> submitted(const json& record) {
  std::vector<json> out;
  for (const auto& s : record.at("submissions"))
    if (!s.value("job_id", std::string()).empty()) out.push_back(s);
  return out;
}

std::optional<TaskRef> latest_task(const json& record, int row) {
  std::optional<TaskRef> task;
  for (const auto& s : submitted(record))
    for (const auto& r : s.at("rows"))
      if (r.get<int>() == row)
        task = TaskRef{s.at("job_id").get<std::string>(), row, utc_seconds(s.value("submitted", ""))};
  return task;
}

bool listed_complete(const json& record, int row) {
  for (const auto& s : submitted(record))
    for (const auto& r : s.value("complete", json::array()))
      if (r.get<int>() == row) return true;
  return false;
}

}  // namespace hpcontact::driver
