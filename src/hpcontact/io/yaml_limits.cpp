// The values of a YAML text counted from yaml-cpp's parser events, which build nothing: the
// tree yaml-cpp would build takes some 500 bytes per value, up to 500 per byte of text (a flow
// map "{a, a, ...}" has two values per two bytes), and an alias repeats a whole subtree for a few
// bytes, so the bytes of a text do not bound its tree.
#include "hpcontact/io/yaml_limits.hpp"

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/parser.h>

#include <istream>
#include <limits>
#include <streambuf>
#include <utility>
#include <vector>

#include "hpcontact/io/text_file.hpp"

namespace hpcontact::io {

namespace {

/// A read-only stream buffer over text that stays alive while it is read (no copy).
class ViewBuffer : public std::streambuf {
 public:
  explicit ViewBuffer(std::string_view text) {
    char* begin = const_cast<char*>(text.data());  // only read: the get area is never written
    setg(begin, begin, begin + text.size());
  }
};

/// Finds the first outermost flow collection ([...] or {...}) of a YAML text with more than `most`
/// tokens: its scalars, aliases, collections, commas and colons. yaml-cpp's scanner holds every
/// token of such a collection (some 140 bytes each) before its parser reports any of it, when the
/// collection stands where a key could ("- [...]", or at the start of a line), so the event count
/// comes too late for it. A reading of the text's lexical structure: comments, quoted and block
/// scalars are skipped; plain scalars of block context end at ": ", " #" or the line's end. Each
/// entry of a collection has at most twice as many tokens as values, so a collection it refuses
/// has more than (most - 1) / 2 values.
class FlowScanner {
 public:
  FlowScanner(std::string_view text, std::size_t most) : text_(text), most_(most) {}

  /// The mark of the collection's opening bracket, or nothing.
  std::optional<YAML::Mark> run() {
    bool node_start = true;  // block context: a node may begin here
    while (i_ < text_.size()) {
      const char c = text_[i_];
      if (c == '\n') {
        newline();
        node_start = true;
      } else if (c == ' ' || c == '\t' || c == '\r') {
        ++i_;
      } else if (c == '#' && after_space()) {
        skip_line();
      } else if (!node_start) {
        // Inside a plain scalar or after a node: only ": " starts a value.
        node_start = c == ':' && space_follows(i_ + 1);
        ++i_;
      } else if (c == '[' || c == '{') {
        const YAML::Mark start = mark();
        if (!flow_collection()) return start;
        node_start = false;
      } else if (c == '"' || c == '\'') {
        skip_quoted();
        node_start = false;
      } else if (c == '|' || c == '>') {
        skip_block_scalar();
      } else if ((c == '-' || c == '?' || c == ':') && space_follows(i_ + 1)) {
        ++i_;  // an indicator: a node may follow
      } else if (c == '&' || c == '!') {
        skip_word();  // an anchor or tag: its node follows
      } else {
        node_start = false;  // a plain scalar (or an alias)
        ++i_;
      }
    }
    return std::nullopt;
  }

 private:
  static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }
  static bool is_flow_indicator(char c) {
    return c == ',' || c == '[' || c == ']' || c == '{' || c == '}';
  }
  bool space_follows(std::size_t k) const { return k >= text_.size() || is_space(text_[k]); }
  bool after_space() const { return i_ == line_start_ || is_space(text_[i_ - 1]); }
  YAML::Mark mark() const {
    YAML::Mark m;
    m.pos = static_cast<int>(i_);
    m.line = line_;
    m.column = static_cast<int>(i_ - line_start_);
    return m;
  }
  void newline() {
    ++i_;
    ++line_;
    line_start_ = i_;
  }
  /// Moves to the next character, across a line's end.
  void advance() {
    if (text_[i_] == '\n')
      newline();
    else
      ++i_;
  }
  void skip_line() {
    while (i_ < text_.size() && text_[i_] != '\n') ++i_;
  }
  void skip_word() {
    while (i_ < text_.size() && !is_space(text_[i_]) && !is_flow_indicator(text_[i_])) ++i_;
  }
  /// 'text' ('' inside is a quote) or "text" (\ escapes the next character).
  void skip_quoted() {
    const char quote = text_[i_];
    ++i_;
    while (i_ < text_.size()) {
      const char c = text_[i_];
      if (quote == '"' && c == '\\' && i_ + 1 < text_.size()) {
        ++i_;
        advance();
      } else if (c == quote) {
        ++i_;
        if (quote == '"' || i_ >= text_.size() || text_[i_] != '\'') return;
        ++i_;
      } else {
        advance();
      }
    }
  }
  /// A block scalar's header line, then every line that is blank or indented deeper than the
  /// line the header stands on.
  void skip_block_scalar() {
    std::size_t indent = 0;
    while (line_start_ + indent < text_.size() && text_[line_start_ + indent] == ' ') ++indent;
    skip_line();
    while (i_ < text_.size()) {
      std::size_t k = i_ + 1, depth = 0;  // the next line
      while (k < text_.size() && text_[k] == ' ') ++k, ++depth;
      if (k < text_.size() && text_[k] != '\n' && text_[k] != '\r' && depth <= indent) return;
      newline();
      skip_line();
    }
  }
  /// A plain scalar of flow context: it ends at a flow indicator, at ": " (or ':' before one) and
  /// at " #"; it may go on over lines.
  void skip_flow_plain() {
    while (i_ < text_.size()) {
      const char c = text_[i_];
      if (is_flow_indicator(c)) return;
      if (c == ':' && (space_follows(i_ + 1) || is_flow_indicator(text_[i_ + 1]))) return;
      if (c == '#' && after_space()) return;
      advance();
    }
  }
  /// Reads a collection from its opening bracket to the matching closing one; false as soon as
  /// it has more than `most_` tokens.
  bool flow_collection() {
    std::size_t depth = 0, tokens = 0;
    while (i_ < text_.size()) {
      const char c = text_[i_];
      if (c == '#' && after_space()) {
        skip_line();
        continue;
      }
      if (is_space(c)) {
        advance();
        continue;
      }
      if (c == ']' || c == '}') {
        ++i_;
        if (--depth == 0) return true;
        continue;
      }
      if (c == '&' || c == '!') {
        skip_word();
        continue;
      }
      if (c == '?' && space_follows(i_ + 1)) {
        ++i_;
        continue;
      }
      if (++tokens > most_) return false;
      if (c == '[' || c == '{') {
        ++depth;
        ++i_;
      } else if (c == ',' || c == ':') {
        ++i_;
      } else if (c == '"' || c == '\'') {
        skip_quoted();
      } else if (c == '*') {
        skip_word();
      } else {
        skip_flow_plain();
      }
    }
    return true;  // unclosed: yaml-cpp reports the syntax error
  }

  std::string_view text_;
  std::size_t most_;
  std::size_t i_ = 0, line_start_ = 0;
  int line_ = 0;
};

/// Counts the values of one document as its events arrive; throws Stop at the first value
/// beyond `most` or at an alias of a list or map that is still open.
class ValueCounter : public YAML::EventHandler {
 public:
  explicit ValueCounter(std::size_t most) : most_(most) {}

  struct Stop {
    YAML::Mark mark;
    bool cycle = false;
  };

  void OnDocumentStart(const YAML::Mark&) override {}
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& mark, YAML::anchor_t anchor) override { leaf(mark, anchor); }
  void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                const std::string&) override {
    leaf(mark, anchor);
  }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t anchor) override {
    const std::size_t size = anchor < anchor_sizes_.size() ? anchor_sizes_[anchor] : 1;
    if (size == kOpen) throw Stop{mark, true};
    add(mark, size);
  }
  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                       YAML::EmitterStyle::value) override {
    open(mark, anchor);
  }
  void OnSequenceEnd() override { close(); }
  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                  YAML::EmitterStyle::value) override {
    open(mark, anchor);
  }
  void OnMapEnd() override { close(); }

 private:
  static constexpr std::size_t kOpen = std::numeric_limits<std::size_t>::max();

  void add(const YAML::Mark& mark, std::size_t n) {
    values_ += n;
    if (values_ > most_) throw Stop{mark};
  }
  void leaf(const YAML::Mark& mark, YAML::anchor_t anchor) {
    add(mark, 1);
    if (anchor != YAML::NullAnchor) name(anchor, 1);
  }
  void open(const YAML::Mark& mark, YAML::anchor_t anchor) {
    add(mark, 1);
    open_.emplace_back(anchor, values_ - 1);
    if (anchor != YAML::NullAnchor) name(anchor, kOpen);
  }
  void close() {
    const auto [anchor, start] = open_.back();
    open_.pop_back();
    if (anchor != YAML::NullAnchor) anchor_sizes_[anchor] = values_ - start;
  }
  /// yaml-cpp numbers anchors 1, 2, ... in the order they appear, so the table stays as short as
  /// the anchors are many.
  void name(YAML::anchor_t anchor, std::size_t size) {
    if (anchor_sizes_.size() <= anchor) anchor_sizes_.resize(anchor + 1, 1);
    anchor_sizes_[anchor] = size;
  }

  std::size_t most_;
  std::size_t values_ = 0;
  std::vector<std::pair<YAML::anchor_t, std::size_t>> open_;  // anchor, values before it
  std::vector<std::size_t> anchor_sizes_;                    // by anchor: values it repeats
};

}  // namespace

std::optional<YamlBound> exceeded_yaml_bound(std::string_view text, const std::string& what,
                                             std::size_t most) {
  const std::string limit =
      most == kMaxYamlValues
          ? "the " + std::to_string(most) + " YAML values an input may have"
          : "the " + std::to_string(most) + " YAML values the rest of the problem leaves it of the " +
                std::to_string(kMaxYamlValues) + " an input may have";
  const std::string why =
      ": yaml-cpp keeps some 500 bytes of memory for each (a scalar, list, map or empty value; "
      "an alias counts as what it repeats); a mesh takes about 4 per node and 6 per element, "
      "inline or from a Gmsh file: give fewer elements (a p-FEM mesh needs few: raise the degree)";
  if (const auto start = FlowScanner(text, 2 * most + 1).run())
    return YamlBound{*start, "the " + what + " has a flow list or map ([...] or {...}) starting "
                             "here with more than " + limit + why};
  ViewBuffer buffer(text);
  std::istream in(&buffer);
  YAML::Parser parser(in);
  ValueCounter counter(most);
  try {
    parser.HandleNextDocument(counter);
  } catch (const ValueCounter::Stop& stop) {
    if (stop.cycle)
      return YamlBound{stop.mark, "an alias inside the list or map its anchor names: a cycle, "
                                  "which repeats without end; a " + what + " is a tree"};
    return YamlBound{stop.mark, "the " + what + " has more than " + limit +
                                    " (the last counted is here)" + why};
  }
  return std::nullopt;
}

std::optional<std::string> exceeded_yaml_bytes(std::size_t bytes, const std::string& what) {
  if (bytes <= kMaxYamlBytes) return std::nullopt;
  return "the " + what + " is larger than the " + in_megabytes(kMaxYamlBytes) + " it may have (" +
         in_megabytes(bytes) + ")";
}

std::size_t count_yaml_values(const YAML::Node& node) {
  std::size_t n = 1;
  if (node.IsSequence())
    for (const YAML::Node& item : node) n += count_yaml_values(item);
  else if (node.IsMap())
    for (const auto& pair : node) n += count_yaml_values(pair.first) + count_yaml_values(pair.second);
  return n;
}

}  // namespace hpcontact::io
