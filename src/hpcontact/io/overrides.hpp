// Command-line overrides ("--set key.path=value") applied to a problem file's YAML tree.
#pragma once

#include <yaml-cpp/yaml.h>

#include <cstddef>
#include <string>

#include "hpcontact/io/yaml_source.hpp"

namespace hpcontact::io {

/// Applies one override "key.path=value" to `root`, before validation. The path is dotted map
/// keys with [i] list indices ("bodies[0].material.E"); the value is parsed as YAML ("1e5",
/// "[6, 4]", "{E: 1, nu: 0.3}"). Missing map keys are created, at the last level and above
/// (so `solver.linear=ldlt` works in a file without a solver section); list elements are
/// never created. The changed path is recorded in `source` so messages say "(from --set)".
/// The value is bounded as a problem file is (yaml_limits.hpp), before its tree is built: at
/// most kMaxYamlBytes, and at most kMaxYamlValues less the values of the rest of the tree
/// (`tree_values`, count_yaml_values(root), less those of the node the value replaces).
/// Throws CommandLineError naming the file and the override if it is malformed, too large, its
/// value is not YAML, or its path runs through a scalar or a list index that does not exist.
void apply_override(YAML::Node& root, const std::string& override_text, YamlSource& source,
                    std::size_t tree_values);

}  // namespace hpcontact::io
