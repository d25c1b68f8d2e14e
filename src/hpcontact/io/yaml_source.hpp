// Where the nodes of a problem file's YAML tree came from, and the scalar conversions messages rely
// on.
#pragma once

#include <yaml-cpp/yaml.h>

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "hpcontact/model/problem_spec.hpp"

namespace hpcontact::io {

/// The file label of a YAML tree plus the key paths whose nodes are not from the file (a --set
/// override, a filled-in default or a mesh made from a gmsh file), whose YAML marks therefore
/// mean nothing.
class YamlSource {
 public:
  explicit YamlSource(std::string file) : file_(std::move(file)) {}

  const std::string& file() const { return file_; }

  /// The node at `path` and everything below it came from a --set override.
  void mark_override(const std::string& path) { override_paths_.push_back(path); }
  /// The node at `path` and everything below it is a filled-in default.
  void mark_default(const std::string& path) { default_paths_.push_back(path); }
  /// The node at `path` and everything below it was made by the reader; `origin` says from
  /// what ("from mesh.msh"), in messages as "(from mesh.msh)".
  void mark_generated(const std::string& path, const std::string& origin) {
    generated_paths_.emplace_back(path, origin);
  }

  /// File, 1-based line and column (from the node's mark, unless the node is not from the file)
  /// and the key path.
  model::SourceRef where(const YAML::Node& node, const std::string& path) const;

  /// Throws InputError "<where>: <what>".
  [[noreturn]] void fail(const YAML::Node& node, const std::string& path,
                         const std::string& what) const;

 private:
  std::string file_;
  std::vector<std::string> override_paths_;
  std::vector<std::string> default_paths_;
  std::vector<std::pair<std::string, std::string>> generated_paths_;  // path, origin
};

/// InputError "<file>:<line>:<col>: the <what> is not UTF-8 text (byte 0x..)" at the first byte
/// that is not UTF-8: YAML is Unicode, and names end up in JSON, which must be.
void require_utf8(std::string_view text, const std::string& file_label, const std::string& what);

/// The top-level map of an input file's text (UTF-8, one YAML document, nested a few levels,
/// within kMaxYamlBytes and kMaxYamlValues: both checked before the tree is built). InputError
/// naming `file_label`: "<file>: the <what> is larger than ...", "<file>:<line>:<col>: the <what>
/// has more than the 1000000 YAML values ...", "<file>:<line>:<col>: YAML syntax error: ...",
/// "<file>: empty <what>", or "<file>: must be <expected> (got ...)" when the text is not a map.
YAML::Node load_yaml_map(const std::string& text, const std::string& file_label,
                         const std::string& what, const std::string& expected);

/// "a.b" from "a" and "b"; "b" when the parent path is empty (the top level).
std::string join_key(const std::string& parent, const std::string& key);
/// "a[3]".
std::string join_index(const std::string& parent, std::size_t index);

/// Text fit for a one-line message: newlines as "\n", other control characters as '?',
/// shortened to `max_length` characters (plus "...").
std::string one_line(std::string_view text, std::size_t max_length = 60);

/// A value as a message shows it after "got": scalar text as written, a list or map in flow
/// style (shortened if long), "nothing" for an empty value.
std::string shown_value(const YAML::Node& node);
/// As shown_value, but scalar text in single quotes: for "must be a number (got 'abc')".
std::string quoted_value(const YAML::Node& node);

/// The node's scalar as a finite number, or nothing if it is not one.
std::optional<double> to_number(const YAML::Node& node);
/// The node's scalar as a whole number that fits an int, or nothing if it is not one.
std::optional<int> to_integer(const YAML::Node& node);
/// The node's scalar as a YAML boolean (true/false, yes/no, on/off), or nothing if it is not one.
std::optional<bool> to_boolean(const YAML::Node& node);

}  // namespace hpcontact::io
