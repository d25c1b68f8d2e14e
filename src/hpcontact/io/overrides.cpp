// Parsing of "key.path=value" overrides and their application to a YAML tree.
#include "hpcontact/io/overrides.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <optional>
#include <vector>

#include "hpcontact/core/error.hpp"
#include "hpcontact/io/yaml_limits.hpp"

namespace hpcontact::io {

namespace {

/// One step of an override path: a map key, or a list index when `key` is empty.
struct PathStep {
  std::string key;
  std::size_t index = 0;
  bool is_index() const { return key.empty(); }
};

bool is_key_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
}

/// "a.b[0].c" -> a, b, [0], c; nothing if malformed.
std::optional<std::vector<PathStep>> parse_path(const std::string& path) {
  std::vector<PathStep> steps;
  std::size_t i = 0;
  while (true) {
    const std::size_t start = i;
    while (i < path.size() && is_key_char(path[i])) ++i;
    if (i == start) return std::nullopt;
    steps.push_back({path.substr(start, i - start)});
    while (i < path.size() && path[i] == '[') {
      const std::size_t close = path.find(']', i);
      if (close == std::string::npos || close == i + 1) return std::nullopt;
      std::size_t index = 0;
      const auto [end, ec] = std::from_chars(path.data() + i + 1, path.data() + close, index);
      if (ec != std::errc() || end != path.data() + close) return std::nullopt;
      steps.push_back({"", index});
      i = close + 1;
    }
    if (i == path.size()) return steps;
    if (path[i] != '.') return std::nullopt;
    ++i;
  }
}

/// The value of `key` in a map, without inserting it when absent (const access).
YAML::Node find_key(const YAML::Node& map, const std::string& key) {
  const YAML::Node value = map[key];
  return value ? value : YAML::Node(YAML::NodeType::Undefined);
}

/// The node at `steps` below `root`, or nothing if a step does not exist (const access: nothing
/// is inserted).
std::optional<YAML::Node> node_at(const YAML::Node& root, const std::vector<PathStep>& steps) {
  YAML::Node current = root;
  for (const PathStep& step : steps) {
    const YAML::Node& view = current;
    YAML::Node next;
    if (step.is_index()) {
      if (!view.IsSequence() || step.index >= view.size()) return std::nullopt;
      next.reset(view[step.index]);
    } else {
      if (!view.IsMap()) return std::nullopt;
      next.reset(find_key(view, step.key));
      if (!next) return std::nullopt;
    }
    current.reset(next);
  }
  return current;
}

}  // namespace

void apply_override(YAML::Node& root, const std::string& override_text, YamlSource& source,
                    std::size_t tree_values) {
  try {
    require_utf8(override_text, source.file() + ": --set", "override");
  } catch (const InputError& e) {
    throw CommandLineError(e.what());
  }
  const std::string label = source.file() + ": --set " + override_text + ": ";
  const std::size_t equals = override_text.find('=');
  if (equals == std::string::npos)
    throw CommandLineError(label + "must be key.path=value, e.g. discretization.degree=8");
  const std::string path_text = override_text.substr(0, equals);
  const std::optional<std::vector<PathStep>> steps = parse_path(path_text);
  if (!steps)
    throw CommandLineError(label + "malformed key path '" + path_text +
                     "' (expected keys joined by '.' with [i] list indices, e.g. "
                     "bodies[0].material.E)");
  // Bounded as a problem file is, before yaml-cpp builds the value's tree: its bytes, and its
  // values to what the tree leaves without the node it replaces. The label shows the start of
  // the value only, since it may be megabytes long.
  const std::string_view value_text = std::string_view(override_text).substr(equals + 1);
  const std::string bound_label = source.file() + ": --set " + path_text + "=" +
                                  one_line(value_text, 20) + ": ";
  if (const auto too_large = exceeded_yaml_bytes(value_text.size(), "--set value"))
    throw CommandLineError(bound_label + *too_large);
  const std::optional<YAML::Node> replaced = node_at(root, *steps);
  const std::size_t rest = tree_values - (replaced ? count_yaml_values(*replaced) : 0);
  YAML::Node value;
  try {
    if (const auto bound = exceeded_yaml_bound(value_text, "--set value",
                                               kMaxYamlValues - std::min(rest, kMaxYamlValues)))
      throw CommandLineError(bound_label + "at line " + std::to_string(bound->mark.line + 1) +
                             ", column " + std::to_string(bound->mark.column + 1) + ": " +
                             bound->what);
    value = YAML::Load(std::string(value_text));
  } catch (const YAML::ParserException& e) {
    throw CommandLineError(label + "value is not valid YAML: " + one_line(e.msg, 200));
  }

  YAML::Node current = root;  // reset() below re-points `current`; assignment would overwrite
  std::string path;
  for (std::size_t s = 0; s < steps->size(); ++s) {
    const PathStep& step = (*steps)[s];
    const bool last = s + 1 == steps->size();
    if (step.is_index()) {
      if (!current.IsSequence())
        throw CommandLineError(label + path + " is not a list (got " + shown_value(current) + ")");
      if (step.index >= current.size())
        throw CommandLineError(label + join_index(path, step.index) + ": no such list element (" + path +
                         " has " + std::to_string(current.size()) + ")");
      path = join_index(path, step.index);
      if (last) {
        current[step.index] = value;
        source.mark_override(path);
        return;
      }
      YAML::Node next = current[step.index];
      current.reset(next);
    } else {
      if (!current.IsMap())
        throw CommandLineError(label + (path.empty() ? "the file" : path) + " is not a map (got " +
                         shown_value(current) + ")");
      path = join_key(path, step.key);
      if (last) {
        current[step.key] = value;
        source.mark_override(path);
        return;
      }
      YAML::Node next = find_key(current, step.key);
      if (!next) {
        current[step.key] = YAML::Node(YAML::NodeType::Map);
        source.mark_override(path);
        next.reset(find_key(current, step.key));
      }
      current.reset(next);
    }
  }
}

}  // namespace hpcontact::io
