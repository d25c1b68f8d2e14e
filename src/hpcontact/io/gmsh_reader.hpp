// Reading a Gmsh MSH 4.1 ASCII file: of a 2D mesh its nodes, quadrilaterals, line elements and
// their physical groups; of a 3D mesh its nodes, hexahedra and boundary quadrilaterals.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace hpcontact::io {

/// A physical group of the file: its dimension, tag and name (the tag in decimal when the file
/// gives it no name in $PhysicalNames).
struct GmshPhysicalGroup {
  int dim = 0;
  int tag = 0;
  std::string name;
};

/// A quadrilateral: gmsh type 3 (4 nodes), 16 (8 nodes) or 10 (9 nodes).
struct GmshQuad {
  int tag = 0;
  int type = 3;
  std::array<int, 4> corners{};  ///< node tags in the file's order
  /// Second order: midside[k] is the node tag on the edge corners[k] -> corners[(k + 1) % 4];
  /// 0 for a first-order quad. The 9-node quad's centre node is not kept.
  std::array<int, 4> midside{};
  std::vector<std::string> groups;  ///< names of the 2D physical groups of its entity
  int entity = 0;                   ///< tag of its 2D entity (surface)
  int line = 0;                     ///< 1-based line in the file
};

/// A line element: gmsh type 1 (2 nodes) or 8 (3 nodes).
struct GmshLine {
  int tag = 0;
  std::array<int, 2> ends{};        ///< node tags
  int midside = 0;                  ///< node tag of the middle node; 0 for a 2-node line
  std::vector<std::string> groups;  ///< names of the 1D physical groups of its entity
  int line = 0;
};

/// A 2D element that is not a first- or second-order quadrilateral (a triangle, a cubic quad).
struct GmshOtherFace {
  int tag = 0;
  int type = 0;
  std::vector<std::string> groups;
  int entity = 0;
  std::vector<int> nodes;  ///< node tags in the file's order; kept by parse_gmsh_volume() only
  int line = 0;
};

/// A hexahedron: gmsh type 5 (8 nodes), 12 (27 nodes) or 17 (20 nodes).
struct GmshHex {
  int tag = 0;
  int type = 5;
  /// Node tags in Gmsh's order (mesh::kHex27Nodes): the 8 vertices (in the order of
  /// basis/hex_modes.hpp), then for types 12 and 17 the 12 mid-edge nodes, then for type 12 the
  /// 6 face centres and the centre.
  std::vector<int> nodes;
  std::vector<std::string> groups;  ///< names of the 3D physical groups of its entity
  int line = 0;
};

/// A 3D element that is not a hexahedron of order 1 or 2: a tetrahedron, prism or pyramid of
/// any order, a hexahedron of order 3 or more.
struct GmshOtherVolume {
  int tag = 0;
  int type = 0;
  std::vector<int> nodes;  ///< node tags in the file's order (vertices first, as Gmsh writes them)
  std::vector<std::string> groups;
  int line = 0;
};

/// The parts of a .msh file hpcontact uses. Elements keep the file's order; points, volumes and
/// unknown sections ($PartitionedEntities, $NodeData, ...) are skipped.
struct GmshMesh {
  std::string file;                            ///< the label messages name
  std::map<int, std::array<double, 2>> nodes;  ///< node tag -> (x, y)
  std::vector<GmshQuad> quads;
  std::vector<GmshLine> lines;
  std::vector<GmshOtherFace> other_faces;
  std::vector<GmshPhysicalGroup> groups;  ///< every physical group of $PhysicalNames and $Entities
};

/// The parts of a .msh file a 3D body is made of. Elements keep the file's order; points, lines
/// and unknown sections are skipped.
struct GmshVolumeMesh {
  std::string file;                            ///< the label messages name
  std::map<int, std::array<double, 3>> nodes;  ///< node tag -> (x, y, z)
  std::vector<GmshHex> hexes;
  std::vector<GmshOtherVolume> other_volumes;
  std::vector<GmshQuad> quads;  ///< the 2D quadrilaterals (boundary faces, with their groups)
  std::vector<GmshOtherFace> other_faces;
  std::vector<GmshPhysicalGroup> groups;  ///< every physical group of $PhysicalNames and $Entities
};

/// "triangle (gmsh type 2)", "element type 99" for an unknown type.
std::string gmsh_type_name(int type);

/// Parses the text of a .msh file (MSH 4.1, ASCII). `file_label` names the file in messages.
/// Checks: version and ASCII, section ends, counts, positive tags that fit an int, unique node
/// and element tags, every node of a kept element defined, z = 0 (to 1e-9 of the coordinates'
/// magnitude), the node count of every known element type, at most kMaxMeshNodes nodes and
/// kMaxMeshElements elements (checked at their headers). Throws InputError, one line:
/// "<file>:<line>: <what was expected> (got '<text>')".
GmshMesh parse_gmsh(std::string_view text, const std::string& file_label);

/// Parses the text of a .msh file of a 3D mesh, with the checks of parse_gmsh() but z = 0, and
/// that no hexahedron has a vertex twice. A file of hexahedra read by parse_gmsh() is refused at
/// its first node off z = 0; one without volume elements read by this function is read
/// (import_gmsh_hex_body() refuses it).
GmshVolumeMesh parse_gmsh_volume(std::string_view text, const std::string& file_label);

/// Largest .msh file read (bytes): its text is held while it is read, and kMaxMeshNodes nodes
/// with 17 digits take some 60 MB.
constexpr std::size_t kMaxMeshFileBytes = std::size_t{128} << 20;
/// Most nodes and elements (of every type, as the $Nodes and $Elements headers count them) of a
/// .msh file read, refused at their header: a body's mesh becomes part of the problem's YAML tree
/// (yaml_limits.hpp, some 4 values per node and 6 per element, at most kMaxYamlValues), so a
/// larger mesh could not be used, and its reading alone would take some 200 bytes per element.
constexpr std::uint64_t kMaxMeshNodes = 800'000;
constexpr std::uint64_t kMaxMeshElements = 200'000;

/// Reads and parses the .msh file at `path` (the label in messages is `path` as given). Throws
/// IoError if it cannot be read, is not a regular file or is larger than kMaxMeshFileBytes,
/// InputError as parse_gmsh().
GmshMesh read_gmsh(const std::string& path);
/// Reads and parses the .msh file of a 3D mesh at `path`, with the errors of read_gmsh().
GmshVolumeMesh read_gmsh_volume(const std::string& path);

}  // namespace hpcontact::io
