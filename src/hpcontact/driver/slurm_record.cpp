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
  HPC_REQUIRE(record.is_object() && record.contains("study") && record.contains("submissions"),
              IoError, path, ": not a submission record of hpcontact study --executor slurm; "
              "the file was edited: remove the folder's slurm/ and submit again");
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
