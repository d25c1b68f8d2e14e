// Validation of a problem file's YAML tree against the schema, filling in defaults.
#pragma once

#include <yaml-cpp/yaml.h>

#include "hpcontact/io/input_schema.hpp"
#include "hpcontact/io/yaml_source.hpp"

namespace hpcontact::io {

/// Checks every key and value of the tree against `schema`: unknown or duplicate keys,
/// missing required keys, types, choices, bounds and list lengths. Absent keys with a default
/// are added to the tree (and recorded in `source` as defaults), so that afterwards every value
/// can be converted without further checks. Cross references (node ids, edge set names) are
/// not checked here. Throws InputError naming the file, line, column, key path and value.
/// Precondition: `root` is a map.
void check_and_fill_defaults(YAML::Node& root, YamlSource& source,
                             const Schema& schema = input_schema());

/// As check_and_fill_defaults() for one key and what lies below it: `node` is the value at the
/// concrete key path `path`, declared by the schema pattern `pattern` ("bodies[].gmsh").
/// Used to check a section that the reader consumes before the whole tree is checked.
/// Precondition: `pattern` is declared in input_schema().
void check_and_fill_defaults(YAML::Node node, const std::string& pattern,
                             const std::string& path, YamlSource& source);

}  // namespace hpcontact::io
