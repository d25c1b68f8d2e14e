// The map x(xi, eta, zeta) from the reference cube [-1, 1]^3 onto one hexahedron.
#pragma once

#include <array>
#include <string_view>
#include <vector>

#include <Eigen/Dense>

#include "hpcontact/geometry/blending_hex.hpp"

namespace hpcontact::mesh {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

/// Gmsh's HEX27 node order (MHexahedron27), the reference position of node n being
/// kHex27Nodes[n] in {-1, 0, 1}^3:
///   0..7    the vertices, in the order of basis/hex_modes.hpp (VTK = Gmsh);
///   8..19   the mid-edge nodes of Gmsh's edges V0V1, V0V3, V0V4, V1V2, V1V5, V2V3, V2V6, V3V7,
///           V4V5, V4V7, V5V6, V6V7 (not VTK's edge order);
///   20..25  the face centres of zeta = -1, eta = -1, xi = -1, xi = +1, eta = +1, zeta = +1;
///   26      the centre.
extern const int kHex27Nodes[27][3];

/// Which kind of map a HexMap is: Lagrange interpolation of nodes, or the blending (Gordon–Hall
/// transfinite) map of exact faces and edges (geometry/blending_hex.hpp).
enum class HexMapKind { trilinear, triquadratic, blending };

/// Geometry of one hexahedron: Lagrange interpolation of its nodes, trilinear (8 vertices) or
/// triquadratic (27 nodes in Gmsh's order, kHex27Nodes), or the blending map of its vertices
/// and the exact surfaces of its faces. A value type, one per element.
class HexMap {
 public:
  /// The trilinear map of the 8 vertices (order of basis/hex_modes.hpp).
  static HexMap trilinear(const std::array<Vec3, 8>& vertices);
  /// The triquadratic map of a HEX27's nodes in Gmsh's order (kHex27Nodes).
  static HexMap triquadratic(const std::array<Vec3, 27>& nodes);
  /// The blending map of an exact hexahedron (geometry::blending_hex builds and checks one).
  static HexMap blending(const geometry::BlendingHex& geometry);

  HexMapKind kind() const { return kind_; }
  /// Degree of x(xi) in each reference coordinate: 1 (trilinear) or 2 (triquadratic); for a
  /// blending map, which is not a polynomial, a quadrature policy: kBlendingQuadratureDegree.
  int polynomial_degree() const;
  /// The nodes, in the order they were given (a blending map's: its 8 vertices).
  const std::vector<Vec3>& nodes() const { return nodes_; }

  /// x(xi, eta, zeta); if J is given, J = [dx/dxi, dx/deta, dx/dzeta] (columns).
  Vec3 map(double xi, double eta, double zeta, Mat3* J = nullptr) const;

 private:
  HexMapKind kind_ = HexMapKind::trilinear;
  std::vector<Vec3> nodes_;
  std::vector<std::array<int, 3>> reference_;  ///< each node's reference position in {-1, 0, 1}^3
  geometry::BlendingHex blend_;                 ///< the geometry of a blending map
};

/// The degree a blending map counts as in quadrature rules (points p + 3 per direction for the
/// stiffness, hex_gauss_points): its rational geometry terms are smooth and resolved by three
/// extra points to well below the discretisation error for p = 1..8 (measured on the thick
/// sphere, tests/verification/test_hex_sphere.cpp: p + 3 and p + 6 points agree in the energy).
inline constexpr int kBlendingQuadratureDegree = 3;

/// Checks det J > 0 at an n × n × n Gauss grid and at the 8 corners (beyond round-off: 1e-12 of
/// the map's scale (|J|_F / √3)³); throws MeshError naming `context`, the element and the
/// reference point: an inverted hex (det J < 0 somewhere) or a degenerate one (a collapsed edge
/// or face, or a flat hex: det J = 0).
void check_hex_jacobian(const HexMap& map, std::string_view context, int element, int n_points);

}  // namespace hpcontact::mesh
