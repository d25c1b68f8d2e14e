// Source references, value rendering and scalar conversions for problem-file YAML nodes.
#include "hpcontact/io/yaml_source.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "hpcontact/core/error.hpp"

namespace hpcontact::io {

namespace {

/// `path` is `prefix` or lies below it ("a.b" and "a.b[0].c" lie below "a.b"; "a.bc" does not).
bool lies_below(const std::string& path, const std::string& prefix) {
  if (!path.starts_with(prefix)) return false;
  return path.size() == prefix.size() || path[prefix.size()] == '.' || path[prefix.size()] == '[';
}

bool any_lies_below(const std::string& path, const std::vector<std::string>& prefixes) {
  for (const std::string& p : prefixes)
    if (lies_below(path, p)) return true;
  return false;
}

/// Scalar text without a leading '+', which std::from_chars does not accept.
std::string_view number_text(const YAML::Node& node) {
  std::string_view s = node.Scalar();
  if (s.size() > 1 && s.front() == '+') s.remove_prefix(1);
  return s;
}

}  // namespace

model::SourceRef YamlSource::where(const YAML::Node& node, const std::string& path) const {
  model::SourceRef ref;
  ref.file = file_;
  ref.key = path;
  if (any_lies_below(path, override_paths_)) {
    ref.origin = "from --set";
  } else if (any_lies_below(path, default_paths_)) {
    ref.origin = "default";
  } else if (const auto it = std::find_if(
                 generated_paths_.begin(), generated_paths_.end(),
                 [&](const auto& generated) { return lies_below(path, generated.first); });
             it != generated_paths_.end()) {
    ref.origin = it->second;
  } else if (node.IsDefined() && !node.Mark().is_null()) {
    ref.line = node.Mark().line + 1;
    ref.column = node.Mark().column + 1;
  }
  return ref;
}

void YamlSource::fail(const YAML::Node& node, const std::string& path,
                      const std::string& what) const {
  const model::SourceRef ref = where(node, path);
  if (any_lies_below(path, override_paths_)) throw CommandLineError(ref.str() + ": " + what);
  throw InputError(ref.str() + ": " + what);
}

YAML::Node load_yaml_map(const std::string& text, const std::string& file_label,
                         const std::string& what, const std::string& expected) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    throw InputError(file_label + ":" + std::to_string(e.mark.line + 1) + ":" +
                     std::to_string(e.mark.column + 1) +
                     ": YAML syntax error: " + one_line(e.msg, 200));
  }
  if (!root.IsDefined() || root.IsNull()) throw InputError(file_label + ": empty " + what);
  if (!root.IsMap())
    throw InputError(file_label + ": must be " + expected + " (got " + quoted_value(root) + ")");
  return root;
}

std::string join_key(const std::string& parent, const std::string& key) {
  return parent.empty() ? key : parent + "." + key;
}

std::string join_index(const std::string& parent, std::size_t index) {
  return parent + "[" + std::to_string(index) + "]";
}

std::string one_line(std::string_view text, std::size_t max_length) {
  std::string out;
  for (char c : text) {
    if (out.size() >= max_length) return out + "...";
    if (c == '\n')
      out += "\\n";
    else if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
      out += '?';
    else
      out += c;
  }
  return out;
}

std::string shown_value(const YAML::Node& node) {
  if (!node.IsDefined() || node.IsNull()) return "nothing";
  if (node.IsScalar()) return one_line(node.Scalar());
  YAML::Emitter out;
  out << YAML::Flow << node;
  return one_line(out.c_str());
}

std::string quoted_value(const YAML::Node& node) {
  if (node.IsDefined() && node.IsScalar())
    return std::string("'").append(one_line(node.Scalar())).append("'");
  return shown_value(node);
}

std::optional<double> to_number(const YAML::Node& node) {
  if (!node.IsDefined() || !node.IsScalar()) return std::nullopt;
  const std::string_view s = number_text(node);
  double value = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (ec != std::errc() || end != s.data() + s.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

std::optional<int> to_integer(const YAML::Node& node) {
  if (!node.IsDefined() || !node.IsScalar()) return std::nullopt;
  const std::string_view s = number_text(node);
  int value = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
  return value;
}

std::optional<bool> to_boolean(const YAML::Node& node) {
  if (!node.IsDefined() || !node.IsScalar()) return std::nullopt;
  bool value = false;
  if (!YAML::convert<bool>::decode(node, value)) return std::nullopt;
  return value;
}

}  // namespace hpcontact::io
