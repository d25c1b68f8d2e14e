// A 3D problem as plain data: one body meshed with hexahedra, what its problem file says.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "hpcontact/mesh/hex_mesh.hpp"
#include "hpcontact/model/problem_spec.hpp"

namespace hpcontact::model {

using Point3 = std::array<double, 3>;

enum class SolidMeshKind { box, shell_octant, gmsh };

/// Where a 3D body's mesh comes from: a generator and its parameters.
struct SolidMeshSpec {
  SolidMeshKind kind = SolidMeshKind::box;
  Point3 from{}, to{};                  ///< box: opposite corners
  std::array<int, 3> elements{1, 1, 1};  ///< box: elements along x, y, z
  double inner_radius = 0, outer_radius = 0;  ///< shell_octant
  int layers = 1;                             ///< shell_octant
  /// gmsh: the body as read from its file (io reads it with the problem file, as the 2D path
  /// expands a body's gmsh section into its nodes and elements).
  std::shared_ptr<const mesh::HexMesh> imported;
  SourceRef where;
};

/// Displacement components prescribed (constant) on face sets.
struct FaceConstraintSpec {
  std::vector<std::string> faces;
  std::array<std::optional<double>, 3> u;  ///< ux, uy, uz; absent: free
  SourceRef where;
};

/// A constant surface load on face sets: a traction vector or a pressure.
struct FaceLoadSpec {
  std::vector<std::string> faces;
  std::optional<Point3> traction;
  std::optional<double> pressure;  ///< positive pushing into the body
  std::optional<double> resultant;  ///< scale the load to this magnitude of its integral
  SourceRef where;
};

/// An exact surface that named face sets lie on.
struct SurfaceSpec {
  std::vector<std::string> faces;
  bool sphere = false;  ///< false: a cylinder
  Point3 point{}, axis{};  ///< cylinder: a point of its axis and its direction; sphere: centre
  double radius = 0;
  SourceRef where;
};

struct SolidBodySpec {
  std::string name;
  double youngs_modulus = 0, poisson_ratio = 0;
  SolidMeshSpec mesh;
  std::vector<SurfaceSpec> surfaces;
  std::vector<FaceConstraintSpec> constraints;
  std::vector<FaceLoadSpec> loads;
  Point3 body_force{};
  SourceRef where;
};

/// The 3D part of a problem (ProblemSpec::solid); case, file and output are ProblemSpec's.
struct SolidSpec {
  SolidBodySpec body;
  std::array<int, 3> degree{4, 4, 4};
  bool tensor_space = false;  ///< false: trunk
  std::optional<double> exact_strain_energy;
  SourceRef where;
};

}  // namespace hpcontact::model
