// Turning a body's `gmsh` section into the nodes, elements, curves and edge sets it stands for.
#pragma once

#include <yaml-cpp/yaml.h>

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "hpcontact/core/error.hpp"
#include "hpcontact/io/gmsh_reader.hpp"
#include "hpcontact/io/yaml_source.hpp"

namespace hpcontact::io {

/// The plain mesh of one body made from a GmshMesh: what a problem file would give by hand.
struct ImportedMesh {
  /// The corner nodes of the quads: (gmsh tag, (x, y)), by tag; midside nodes are left out.
  std::vector<std::pair<int, std::array<double, 2>>> nodes;
  /// The quads in the file's order: (gmsh tag, corner tags counter-clockwise).
  std::vector<std::pair<int, std::array<int, 4>>> elements;
  struct Arc {
    std::array<int, 2> nodes{};  ///< the edge, oriented from nodes[0] to nodes[1]
    std::array<double, 2> center{};
    double radius = 0;
    int ccw = 0;  ///< +1 counter-clockwise, -1 clockwise from nodes[0]; 0: the shorter arc
  };
  std::vector<Arc> arcs;
  std::vector<std::pair<std::string, std::vector<std::array<int, 2>>>> edge_sets;
  int n_recovered_arcs = 0;  ///< arcs found from midside nodes
  double size = 0;           ///< bounding-box diagonal of the nodes
};

/// How to make a body of a GmshMesh; the keys of bodies[].gmsh.
struct ImportOptions {
  std::string surface;  ///< 2D physical group; empty: every quadrilateral
  struct NamedArc {
    std::string group;
    std::array<double, 2> center{};
    double radius = 0;
  };
  std::vector<NamedArc> arcs;
  double arc_tolerance = 1e-8;
  /// Edges that already carry a curve (given by hand): no arc is recovered for them.
  std::vector<std::array<int, 2>> edges_with_curves;
};

/// An ImportOptions value at fault. `key` is its path below bodies[].gmsh ("surface",
/// "arcs[1].edges"), `what` the message without it.
class GmshOptionError : public InputError {
 public:
  GmshOptionError(const std::string& option_key, const std::string& what)
      : InputError(option_key + ": " + what), key(option_key), what_text(what) {}
  std::string key;
  std::string what_text;
};

/// [x, y] as a YAML flow sequence of the shortest texts that read back as x and y.
YAML::Node point_node(const std::array<double, 2>& p);

/// The names of the file's physical groups of dimension `dim`, for "(defined: ...)"; "none".
std::string gmsh_group_list(const GmshMesh& mesh, int dim);

/// Makes the body's mesh: selects the quadrilaterals, orders their corners counter-clockwise,
/// makes the named arcs and recovers the arcs of curved second-order edges, and the edge set of
/// every 1D physical group. Throws InputError naming the .msh file and line, GmshOptionError
/// for an option that does not fit the mesh (the caller adds the problem file's key path).
ImportedMesh import_gmsh_body(const GmshMesh& mesh, const ImportOptions& options);

/// Reads the .msh file that a `gmsh` section at `path` names in its `file` key, relative to the
/// folder of source.file(); IoError naming the key if it cannot be read, InputError as read_gmsh().
GmshMesh read_gmsh_section(const YAML::Node& section, const std::string& path, YamlSource& source);

/// Refuses a second `gmsh` key in the map `parent` (only the first would be expanded, the other
/// silently dropped: the schema check that reports duplicate keys comes after the expansion),
/// naming it as `gmsh_path`.
void refuse_second_gmsh_key(const YAML::Node& parent, const std::string& gmsh_path, YamlSource& source);

/// Replaces the `gmsh` section of every body of a problem file's tree (after --set overrides,
/// before the schema check) by the nodes, elements, curves and edge_sets it stands for; the
/// .msh file is found relative to the folder of source.file(). Returns one line per body so made,
/// for the header of the effective input. Throws InputError (IoError if the file cannot be read)
/// naming the problem file's key and, for errors in the mesh, the .msh file and line; also, before
/// a mesh is written into the tree, if the tree would then hold more than kMaxYamlValues values.
std::vector<std::string> expand_gmsh_meshes(YAML::Node& root, YamlSource& source);

}  // namespace hpcontact::io
