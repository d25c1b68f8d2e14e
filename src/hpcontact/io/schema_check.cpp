// Schema-driven validation of a problem file's YAML tree, with defaults filled in.
#include "hpcontact/io/schema_check.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>

#include "hpcontact/io/input_schema.hpp"
#include "hpcontact/model/problem_spec.hpp"

namespace hpcontact::io {

namespace {

using T = ValueType;

class SchemaChecker {
 public:
  SchemaChecker(YamlSource& source, const Schema& schema) : source_(source), schema_(schema) {}

  /// Checks the keys of `map` (a YAML map) declared under `pattern`; `path` is its concrete path.
  void check_section(YAML::Node map, const std::string& pattern, const std::string& path) {
    const std::vector<const KeySpec*> children = child_key_specs(pattern, schema_);
    const auto name_of = [&](const KeySpec* child) {
      return std::string(child->path.substr(pattern.empty() ? 0 : pattern.size() + 1));
    };
    std::set<std::string> seen;
    for (auto it = map.begin(); it != map.end(); ++it) {
      const std::string name = key_name(it->first, path);
      const std::string key_path = join_key(path, name);
      if (!seen.insert(name).second) source_.fail(it->first, key_path, "duplicate key");
      const bool known = std::any_of(children.begin(), children.end(),
                                     [&](const KeySpec* child) { return name_of(child) == name; });
      if (!known) {
        std::string allowed;
        for (const KeySpec* child : children)
          allowed += (allowed.empty() ? "" : ", ") + name_of(child);
        source_.fail(it->first, key_path, "unknown key (allowed here: " + allowed + ")");
      }
    }
    const YAML::Node& lookup = map;  // const access does not insert missing keys
    for (const KeySpec* child : children) {
      const std::string name = name_of(child);
      const std::string key_path = join_key(path, name);
      if (!lookup[name]) {
        if (child->required) source_.fail(map, path, "missing required key '" + name + "'");
        if (child->default_yaml.empty()) continue;
        // A section starts as an empty block map; its own defaults are filled in below.
        map[name] = child->type == T::section ? YAML::Node(YAML::NodeType::Map)
                                              : YAML::Load(std::string(child->default_yaml));
        source_.mark_default(key_path);
      }
      check_value(lookup[name], *child, key_path);
    }
  }

  void check_value(const YAML::Node& node, const KeySpec& key, const std::string& path) {
    switch (key.type) {
      case T::section:
        require_map(node, path);
        check_section(node, std::string(key.path), path);
        return;
      case T::section_list: {
        require_list(node, key, path, "a list of sections");
        const std::string item_pattern = std::string(key.path) + "[]";
        for (std::size_t i = 0; i < node.size(); ++i) {
          const std::string item_path = join_index(path, i);
          require_map(node[i], item_path);
          check_section(node[i], item_pattern, item_path);
        }
        return;
      }
      case T::string:
        if (!node.IsScalar())
          source_.fail(node, path, "must be a string (got " + shown_value(node) + ")");
        return;
      case T::scalar_text:
        if (!node.IsScalar() || node.Scalar().empty())
          source_.fail(node, path, "must be a number or a formula (got " + shown_value(node) + ")");
        if (const auto value = to_number(node)) check_magnitude(node, *value, path);
        return;
      case T::number: check_number(node, key, path); return;
      case T::integer: check_integer(node, key, path); return;
      case T::boolean:
        if (!to_boolean(node))
          source_.fail(node, path, "must be true or false (got " + quoted_value(node) + ")");
        return;
      case T::choice: check_choice(node, key, path); return;
      case T::point: check_pair(node, path, false, "[x, y]"); return;
      case T::node_pair: check_pair(node, path, true, "[a, b] with two node ids"); return;
      case T::degree: check_integers(node, key, path, "[p_xi, p_eta]", 2); return;
      case T::point3: check_numbers(node, path, 3, "[x, y, z]"); return;
      case T::degree3: check_integers(node, key, path, "[p_xi, p_eta, p_zeta]", 3); return;
      case T::count3: check_integers(node, key, path, "[n_x, n_y, n_z]", 3); return;
      case T::string_list:
        require_list(node, key, path, "a list of names");
        for (std::size_t i = 0; i < node.size(); ++i)
          if (!node[i].IsScalar() || node[i].Scalar().empty())
            source_.fail(node[i], join_index(path, i),
                         "must be a name (got " + shown_value(node[i]) + ")");
        return;
      case T::point_list:
        require_list(node, key, path, "a list of [x, y] points");
        for (std::size_t i = 0; i < node.size(); ++i)
          check_pair(node[i], join_index(path, i), false, "[x, y]");
        return;
      case T::numbers:
        if (node.IsSequence())
          for (std::size_t i = 0; i < node.size(); ++i) check_number(node[i], key, join_index(path, i));
        else
          check_number(node, key, path);
        return;
      case T::integer_list:
        require_list(node, key, path, "a list of integers");
        for (std::size_t i = 0; i < node.size(); ++i)
          check_integer(node[i], KeySpec{}, join_index(path, i));
        return;
      case T::node_table:
        for_each_table_entry(node, key, path, true,
                             [&](const YAML::Node& value, const std::string& p) {
                               check_pair(value, p, false, "[x, y]");
                             });
        return;
      case T::element_table:
        for_each_table_entry(
            node, key, path, true,
            [&](const YAML::Node& value, const std::string& p) { check_element(value, p); });
        return;
      case T::degree_table:
        for_each_table_entry(
            node, key, path, true,
            [&](const YAML::Node& value, const std::string& p) {
              check_integers(value, key, p, "[p_xi, p_eta]", 2);
            });
        return;
      case T::edge_set_table:
        for_each_table_entry(
            node, key, path, false, [&](const YAML::Node& value, const std::string& p) {
              if (!value.IsSequence() || value.size() == 0)
                source_.fail(value, p,
                             "must be a non-empty list of [a, b] node pairs (got " +
                                 shown_value(value) + ")");
              for (std::size_t i = 0; i < value.size(); ++i)
                check_pair(value[i], join_index(p, i), true, "[a, b] with two node ids");
            });
        return;
    }
  }

 private:
  std::string key_name(const YAML::Node& key, const std::string& parent_path) {
    if (!key.IsScalar() || key.Scalar().empty())
      source_.fail(key, parent_path, "keys must be names (got " + shown_value(key) + ")");
    return key.Scalar();
  }

  void require_map(const YAML::Node& node, const std::string& path) {
    if (!node.IsMap())
      source_.fail(node, path, "must be a map of keys (got " + shown_value(node) + ")");
  }

  void require_list(const YAML::Node& node, const KeySpec& key, const std::string& path,
                    const std::string& what) {
    if (!node.IsSequence())
      source_.fail(node, path, "must be " + what + " (got " + shown_value(node) + ")");
    if (node.size() < static_cast<std::size_t>(key.min_items))
      source_.fail(node, path,
                   "must have at least " + std::to_string(key.min_items) +
                       (key.min_items == 1 ? " entry" : " entries") + " (got " + shown_value(node) +
                       ")");
  }

  void check_bounds(const YAML::Node& node, double value, const KeySpec& key,
                    const std::string& path) {
    if (key.lower && (key.lower->inclusive ? value < key.lower->value : value <= key.lower->value))
      source_.fail(node, path,
                   std::string("must be ") + (key.lower->inclusive ? ">= " : "> ") +
                       shown_bound(key.lower->value) + " (got " + node.Scalar() + ")");
    if (key.upper && (key.upper->inclusive ? value > key.upper->value : value >= key.upper->value))
      source_.fail(node, path,
                   std::string("must be ") + (key.upper->inclusive ? "<= " : "< ") +
                       shown_bound(key.upper->value) + " (got " + node.Scalar() + ")" +
                       (key.upper_why.empty() ? "" : ": " + std::string(key.upper_why)));
  }

  /// The rule for every real number (model::kMaxMagnitude).
  void check_magnitude(const YAML::Node& node, double value, const std::string& path) {
    const double a = std::abs(value);
    if (a > model::kMaxMagnitude || (a > 0 && a < 1 / model::kMaxMagnitude))
      source_.fail(node, path,
                   "must be 0 or of magnitude between " + shown_bound(1 / model::kMaxMagnitude) + " and " +
                       shown_bound(model::kMaxMagnitude) + " (got " + node.Scalar() +
                       "): products of the input's values must stay within double precision "
                       "(1e-308 to 1e308)");
  }

  static std::string shown_bound(double v) {
    std::ostringstream os;
    os << v;
    return os.str();
  }

  void check_number(const YAML::Node& node, const KeySpec& key, const std::string& path) {
    const std::optional<double> value = to_number(node);
    if (!value) source_.fail(node, path, "must be a number (got " + quoted_value(node) + ")");
    check_magnitude(node, *value, path);
    check_bounds(node, *value, key, path);
  }

  void check_integer(const YAML::Node& node, const KeySpec& key, const std::string& path) {
    const std::optional<int> value = to_integer(node);
    if (!value) source_.fail(node, path, "must be an integer (got " + quoted_value(node) + ")");
    check_bounds(node, *value, key, path);
  }

  void check_choice(const YAML::Node& node, const KeySpec& key, const std::string& path) {
    if (node.IsScalar())
      for (std::string_view choice : key.choices)
        if (node.Scalar() == choice) return;
    std::string allowed;
    for (std::string_view choice : key.choices)
      allowed += (allowed.empty() ? "" : ", ") + std::string(choice);
    source_.fail(node, path, "must be one of " + allowed + " (got " + quoted_value(node) + ")");
  }

  /// [x, y] numbers, or [a, b] integers when `integers`.
  void check_pair(const YAML::Node& node, const std::string& path, bool integers,
                  const std::string& what) {
    if (!node.IsSequence() || node.size() != 2)
      source_.fail(node, path, "must be " + what + " (got " + shown_value(node) + ")");
    for (std::size_t i = 0; i < 2; ++i) {
      if (integers)
        check_integer(node[i], KeySpec{}, join_index(path, i));
      else
        check_number(node[i], KeySpec{}, join_index(path, i));
    }
  }

  /// One integer for every direction, or one per direction (n of them, `what`: "[p_xi, p_eta]").
  void check_integers(const YAML::Node& node, const KeySpec& key, const std::string& path,
                      const std::string& what, int n) {
    if (node.IsScalar()) {
      check_integer(node, key, path);
      return;
    }
    if (!node.IsSequence() || node.size() != static_cast<std::size_t>(n))
      source_.fail(node, path,
                   "must be an integer or " + what + " (got " + shown_value(node) + ")");
    for (int i = 0; i < n; ++i) check_integer(node[i], key, join_index(path, i));
  }

  /// A list of exactly n numbers.
  void check_numbers(const YAML::Node& node, const std::string& path, int n,
                     const std::string& what) {
    if (!node.IsSequence() || node.size() != static_cast<std::size_t>(n))
      source_.fail(node, path, "must be " + what + " (got " + shown_value(node) + ")");
    for (int i = 0; i < n; ++i) check_number(node[i], KeySpec{}, join_index(path, i));
  }

  void check_element(const YAML::Node& node, const std::string& path) {
    if (!node.IsSequence() || node.size() != 4)
      source_.fail(node, path,
                   "must be [n1, n2, n3, n4] with four node ids (got " + shown_value(node) + ")");
    std::set<int> distinct;
    for (std::size_t i = 0; i < 4; ++i) {
      check_integer(node[i], KeySpec{}, join_index(path, i));
      distinct.insert(*to_integer(node[i]));
    }
    if (distinct.size() != 4)
      source_.fail(node, path, "must have four distinct node ids (got " + shown_value(node) + ")");
  }

  /// Checks a map from ids (integers if `integer_keys`) or names to values: non-empty if the key
  /// says so, no duplicate keys; calls check(value, entry path) for each entry.
  template <class Check>
  void for_each_table_entry(const YAML::Node& node, const KeySpec& key, const std::string& path,
                            bool integer_keys, Check check) {
    if (!node.IsMap())
      source_.fail(node, path,
                   std::string("must be a map ") + (integer_keys ? "id" : "name") +
                       " -> value (got " + shown_value(node) + ")");
    if (node.size() < static_cast<std::size_t>(key.min_items))
      source_.fail(node, path,
                   "must have at least " + std::to_string(key.min_items) +
                       (key.min_items == 1 ? " entry" : " entries") + " (got " + shown_value(node) +
                       ")");
    std::set<std::string> seen;
    for (auto it = node.begin(); it != node.end(); ++it) {
      const std::string name = key_name(it->first, path);
      const std::string entry_path = join_key(path, name);
      if (integer_keys && !to_integer(it->first))
        source_.fail(it->first, entry_path,
                     "must be an integer id (got " + quoted_value(it->first) + ")");
      const std::string canonical = integer_keys ? std::to_string(*to_integer(it->first)) : name;
      if (!seen.insert(canonical).second) source_.fail(it->first, entry_path, "duplicate id");
      check(it->second, entry_path);
    }
  }

  YamlSource& source_;
  const Schema& schema_;
};

}  // namespace

void check_and_fill_defaults(YAML::Node& root, YamlSource& source, const Schema& schema) {
  SchemaChecker(source, schema).check_section(root, "", "");
}

void check_and_fill_defaults(YAML::Node node, const std::string& pattern, const std::string& path,
                             YamlSource& source) {
  const KeySpec* key = find_key_spec(pattern);
  if (!key) throw std::logic_error("check_and_fill_defaults: no schema key " + pattern);
  SchemaChecker(source, input_schema()).check_value(node, *key, path);
}

}  // namespace hpcontact::io
