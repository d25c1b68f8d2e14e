// OUT/slurm/submission.json: what a study on Slurm submitted — its rows, and per submission the
// job id, the rows it ran and those it found complete — so that --collect and a resubmission
// need nothing but the folder.
#pragma once

#include <ctime>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hpcontact/io/study_reader.hpp"

namespace hpcontact::driver {

/// The record's path inside OUT.
inline const char* const kSubmissionRecord = "slurm/submission.json";

/// The study's rows as the record keeps them, and back.
nlohmann::json study_to_json(const io::StudySpec& study);
io::StudySpec study_from_json(const nlohmann::json& j);

/// OUT/slurm/submission.json, or null if there is none. IoError if it is not a record we wrote:
/// not JSON, or a key the collection reads missing or of another type, a row number beyond the
/// study's rows or a job id that is not digits (named by its key path).
nlohmann::json read_record(const std::string& out);

/// The submissions of a record that reached the scheduler (a job id), oldest first.
std::vector<nlohmann::json> submitted(const nlohmann::json& record);

/// An array task: job `job_id`, task `index` (the row's index).
struct TaskRef {
  std::string job_id;
  int index = 0;
  std::time_t submitted = 0;  ///< when its submission was made (UTC, whole seconds); 0 if unknown
};

/// The last submitted task of row `row`, if any.
std::optional<TaskRef> latest_task(const nlohmann::json& record, int row);

/// Whether a submission found row `row` complete (a successful run of its input) and left it out.
bool listed_complete(const nlohmann::json& record, int row);

}  // namespace hpcontact::driver
