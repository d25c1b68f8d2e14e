// Source references, value rendering and scalar conversions for problem-file YAML nodes.
#include "hpcontact/io/yaml_source.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

#include <yaml-cpp/depthguard.h>

#include "hpcontact/core/error.hpp"
#include "hpcontact/io/yaml_limits.hpp"

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

namespace {

/// The length of the UTF-8 sequence at text[i], or 0 if it is not a valid one (overlong forms,
/// surrogates and code points above U+10FFFF included).
std::size_t utf8_sequence(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char c = byte(i);
  if (c < 0x80) return 1;
  const std::size_t n = c >= 0xc2 && c <= 0xdf ? 2 : c >= 0xe0 && c <= 0xef ? 3
                        : c >= 0xf0 && c <= 0xf4                ? 4
                                                                : 0;
  if (n == 0 || i + n > text.size()) return 0;
  for (std::size_t k = 1; k < n; ++k)
    if ((byte(i + k) & 0xc0) != 0x80) return 0;
  const unsigned char c1 = byte(i + 1);
  if ((c == 0xe0 && c1 < 0xa0) || (c == 0xed && c1 > 0x9f) || (c == 0xf0 && c1 < 0x90) ||
      (c == 0xf4 && c1 > 0x8f))
    return 0;
  return n;
}

/// InputError if the text holds a second YAML document: content after a line '---' or '...' at
/// column 0 that follows the first document's content (a document marker wherever it stands:
/// YAML forbids them inside scalars; '---' before any content starts the one document, and
/// markers with nothing after them are harmless). Found by reading the lines: yaml-cpp's
/// LoadAll loops forever on some malformed input.
void require_one_document(std::string_view text, const std::string& file_label,
                          const std::string& what) {
  bool content = false;       // the first document has begun
  std::size_t boundary = 0;   // the line of a marker after it, 0 if none
  std::size_t number = 0;
  for (std::size_t start = 0; start <= text.size();) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    const std::string_view line = text.substr(start, end - start);
    start = end + 1;
    ++number;
    const auto rest_from = [&](std::size_t at) {
      const std::size_t k = line.find_first_not_of(" \t\r", at);
      return k == std::string_view::npos || line[k] == '#' ? std::string_view() : line.substr(k);
    };
    const bool marker = (line.rfind("---", 0) == 0 || line.rfind("...", 0) == 0) &&
                        (line.size() == 3 || line[3] == ' ' || line[3] == '\t' || line[3] == '\r');
    bool has_content;
    if (marker) {
      if (content && !boundary) boundary = number;
      has_content = !rest_from(3).empty();  // "--- {a: 1}": the document it starts
    } else {
      has_content = !rest_from(0).empty() && !(!content && line[0] == '%');  // not a directive
    }
    if (!has_content) continue;
    if (boundary)
      throw InputError(file_label + ":" + std::to_string(boundary) +
                       ": a second YAML document starts here; a " + what +
                       " is one document: remove the line '---' (or '...') or split the file");
    content = true;
  }
}

}  // namespace

void require_utf8(std::string_view text, const std::string& file_label, const std::string& what) {
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t n = utf8_sequence(text, i);
    if (n == 0) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "0x%02x", static_cast<unsigned char>(text[i]));
      throw InputError(file_label + ":" + std::to_string(line) + ":" + std::to_string(column) +
                       ": the " + what + " is not UTF-8 text (byte " + hex +
                       "): write it in UTF-8");
    }
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
    i += n;
  }
}

YAML::Node load_yaml_map(const std::string& text, const std::string& file_label,
                         const std::string& what, const std::string& expected) {
  if (const auto too_large = exceeded_yaml_bytes(text.size(), what))
    throw InputError(file_label + ": " + *too_large);
  require_utf8(text, file_label, what);
  require_one_document(text, file_label, what);
  YAML::Node root;
  try {
    if (const auto bound = exceeded_yaml_bound(text, what))
      throw InputError(file_label + ":" + std::to_string(bound->mark.line + 1) + ":" +
                       std::to_string(bound->mark.column + 1) + ": " + bound->what);
    root = YAML::Load(text);
  } catch (const YAML::DeepRecursion& e) {
    throw InputError(file_label + ":" + std::to_string(e.mark.line + 1) + ":" +
                     std::to_string(e.mark.column + 1) + ": lists and maps nested " +
                     std::to_string(e.depth()) + " deep (or more); a " + what +
                     " needs a few levels");
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
