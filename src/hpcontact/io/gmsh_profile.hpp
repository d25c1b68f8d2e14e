// A rigid obstacle's boundary from a Gmsh file: the line elements of a 1D physical group
// chained end to end into the points of a `profile` or `curve` obstacle.
#pragma once

#include <yaml-cpp/yaml.h>

#include <array>
#include <string>
#include <vector>

#include "hpcontact/io/gmsh_reader.hpp"
#include "hpcontact/io/yaml_source.hpp"

namespace hpcontact::io {

/// The points of a chain of line elements.
struct GmshPath {
  std::vector<std::array<double, 2>> points;
  bool closed = false;   ///< the chain returns to its start (the first point is not repeated)
  int lines = 0;         ///< line elements chained
  int straight_on = 0;   ///< points left out where the chain goes straight on
};

/// The line elements of the 1D physical group `group` chained into one path: its vertices (and
/// the midside nodes of second-order lines) in order, walking in the direction of the group's
/// first line in the file (the opposite one with `reverse`), a point where the path goes straight
/// on (turning by less than 1e-9 rad) left out, so that a straight Gmsh line of many elements is
/// one segment. Throws GmshOptionError (key "curve") for a group that does not exist or has no
/// lines, a node where three or more of its lines meet, or lines in more than one piece.
GmshPath gmsh_path(const GmshMesh& mesh, const std::string& group, bool reverse);

/// Replaces the `gmsh` section of every contact[].obstacle of a problem file's tree (after --set
/// overrides, before the schema check) by the `points` it stands for, and `closed: true` for a
/// closed chain; the .msh file is found relative to the folder of source.file(). Returns one line
/// per obstacle so made, for the header of the effective input. Throws InputError naming the key:
/// gmsh with a type other than profile or curve, with points, with `closed` that contradicts the
/// chain, a closed chain for a curve; the .msh file's errors as read_gmsh().
std::vector<std::string> expand_gmsh_obstacles(YAML::Node& root, YamlSource& source);

}  // namespace hpcontact::io
