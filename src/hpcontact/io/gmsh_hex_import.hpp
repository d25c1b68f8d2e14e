// A 3D body meshed with hexahedra made from a parsed Gmsh file: the hexahedra of chosen physical
// volumes, their geometric maps, and face sets from the physical surfaces on the body's boundary.
#pragma once

#include <string>
#include <vector>

#include "hpcontact/io/gmsh_reader.hpp"
#include "hpcontact/mesh/hex_mesh.hpp"

namespace hpcontact::io {

/// How to make a 3D body of a GmshVolumeMesh.
struct HexImportOptions {
  /// The 3D physical groups whose elements make the body; empty: every volume element of the
  /// file.
  std::vector<std::string> volumes;
};

/// Makes the body of the chosen volumes' hexahedra:
///   nodes     the hexahedra's vertices, numbered from 0 in increasing Gmsh node tag;
///   topology  the hexahedra in the file's order (element h of the body is the h-th chosen one);
///   maps      trilinear (8-node hexahedra), triquadratic (27-node, and 20-node ones completed
///             to 27 nodes by their serendipity map), each checked by mesh::check_hex_jacobian;
///   face_sets one per 2D physical group with a quadrilateral on the body's boundary: its
///             quadrilaterals that are faces of the body (those of other volumes' elements left
///             out), in the file's order; groups without such a face make no set;
///   context   the file's label.
/// Throws InputError naming the file and line of the element at fault, for: volume elements
/// other than hexahedra of order 1 or 2 among the chosen ones (with their counts by type); no
/// hexahedra; a 2D entity none of whose elements is a face of a volume element (a 2D body in a
/// file of volumes); a quadrilateral of a physical surface that is a face of no volume element,
/// or an interior face of the body. GmshOptionError (gmsh_import.hpp) for a volume name the
/// file does not define (key "volumes[i]"). MeshError for an inverted or degenerate hexahedron
/// (naming the file and line as "<file>:<line>: element <gmsh tag>", and the reference point),
/// and, naming the file and the body's element indices, for what mesh::HexTopology refuses (two
/// elements with the same nodes, a face of three elements, a twisted face).
mesh::HexMesh import_gmsh_hex_body(const GmshVolumeMesh& mesh,
                                   const HexImportOptions& options = {});

}  // namespace hpcontact::io
