// Reading a 3D problem file (`dimension: 3`) into a ProblemSpec whose `solid` is set.
#pragma once

#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "hpcontact/io/yaml_source.hpp"
#include "hpcontact/model/solid_spec.hpp"

namespace hpcontact::io {

/// Whether a problem file's tree (overrides applied) is a 3D problem: it has `dimension` at the
/// top level (whatever its value: solid_problem() checks it, so that `dimension: 2` is refused
/// rather than read as a 2D file with an unknown key).
bool is_solid_problem(const YAML::Node& root);

/// Checks the tree against solid_schema() (filling in defaults) and the cross references the
/// schema cannot (one body, one mesh source, face set names of that mesh, a load's one kind, the
/// work the degrees and elements ask for), and builds the spec. Throws InputError naming the
/// file, line, key and cause.
model::ProblemSpec solid_problem(YAML::Node& root, YamlSource& source);

/// The face sets a generated mesh has, in the order the docs list them (none for gmsh: those are
/// the file's physical surfaces).
std::vector<std::string> solid_face_set_names(model::SolidMeshKind kind);

}  // namespace hpcontact::io
