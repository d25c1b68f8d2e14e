// The one declaration of every problem-file key (type, default, unit, meaning) that validation and
// docs share.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hpcontact::io {

/// What the value of a key must be.
enum class ValueType {
  section,         ///< a map of the keys declared under "<path>."
  section_list,    ///< a list of maps, each with the keys declared under "<path>[]."
  string,          ///< any scalar, kept as text
  number,          ///< a finite real number
  integer,         ///< a whole number
  boolean,         ///< true or false
  choice,          ///< one of KeySpec::choices
  point,           ///< [x, y], two numbers
  node_pair,       ///< [a, b], two node ids
  degree,          ///< p or [p_xi, p_eta], integers; bounds apply to each
  point3,          ///< [x, y, z], three numbers
  degree3,         ///< p or [p_xi, p_eta, p_zeta], integers; bounds apply to each
  count3,          ///< n or [n_x, n_y, n_z], integers; bounds apply to each
  scalar_text,     ///< a number or an expression, kept verbatim as text
  string_list,     ///< a list of scalars
  point_list,      ///< a list of [x, y]
  numbers,         ///< a number or a list of numbers; bounds apply to each
  integer_list,    ///< a list of whole numbers
  node_table,      ///< a map node id -> [x, y]
  element_table,   ///< a map element id -> [n1, n2, n3, n4]
  degree_table,    ///< a map element id -> degree
  edge_set_table,  ///< a map set name -> list of [a, b] node pairs
};

/// A bound on a number (or on each component of a degree).
struct Bound {
  double value = 0;
  bool inclusive = true;  ///< true: the value itself is allowed (>=, <=); false: strict (>, <)
};

constexpr Bound greater_than(double v) { return {v, false}; }
constexpr Bound at_least(double v) { return {v, true}; }
constexpr Bound less_than(double v) { return {v, false}; }
constexpr Bound at_most(double v) { return {v, true}; }

/// The declaration of one key.
struct KeySpec {
  std::string_view path;  ///< dotted pattern; "[]" stands for any list index: "bodies[].material.E"
  ValueType type = ValueType::string;
  bool required = false;
  std::string_view default_yaml;  ///< YAML text filled in when the key is absent; empty: no default
  std::string_view unit;          ///< physical unit; empty for dimensionless or non-numeric keys
  std::string_view doc;           ///< one-line meaning, including rules that involve other keys
  std::vector<std::string_view> choices;  ///< allowed values of a ValueType::choice
  std::optional<Bound> lower, upper;      ///< number, integer, degree, degree_table
  /// Why the upper bound (what a larger value would cost): said when it is exceeded, and in the
  /// docs.
  std::string_view upper_why;
  int min_items = 0;                      ///< least number of entries of a list or table
};

/// The keys of one kind of problem file, parents before their children, in the order of the
/// docs.
using Schema = std::vector<KeySpec>;

/// Every key of a (2D) problem file.
const Schema& input_schema();

/// The declaration whose pattern is `pattern` ("bodies[].material.E") in `schema`, or nullptr.
const KeySpec* find_key_spec(std::string_view pattern, const Schema& schema = input_schema());

/// The keys directly below a section or section-list pattern ("" for the top level,
/// "bodies[]" for a body, "bodies[].material"), in declaration order.
std::vector<const KeySpec*> child_key_specs(std::string_view parent_pattern,
                                            const Schema& schema = input_schema());

/// The type of a key as the docs and error messages say it: "number > 0", "one of: p, h".
std::string describe_type(const KeySpec& key);

/// The schema rendered as Markdown: one table per section with key, type, default, unit and
/// meaning. docs/input.md and `hpcontact --help-input` print this.
std::string input_schema_markdown();

/// One schema's tables (its top level, then each section depth first) in that Markdown form.
std::string schema_tables_markdown(const Schema& schema);

}  // namespace hpcontact::io
