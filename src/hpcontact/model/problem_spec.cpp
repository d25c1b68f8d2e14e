// Formatting of problem-file source references for messages.
#include "hpcontact/model/problem_spec.hpp"

namespace hpcontact::model {

std::string SourceRef::str() const {
  std::string s = file;
  if (line > 0) {
    s += ":" + std::to_string(line);
    if (column > 0) s += ":" + std::to_string(column);
  }
  if (!key.empty()) s += (s.empty() ? "" : ": ") + key;
  if (!origin.empty()) s += (s.empty() ? "(" : " (") + origin + ")";
  return s;
}

}  // namespace hpcontact::model
