// The map x(xi, eta, zeta) from the reference cube [-1, 1]^3 onto one hexahedron.
#pragma once

#include <array>
#include <string_view>
#include <vector>

#include <Eigen/Dense>

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

/// Which kind of map a HexMap is. A blending (Gordon–Hall transfinite) map from exact faces and
/// edges is meant to join as a third kind: it would carry its faces' geometry beside the nodes
/// and answer map() and polynomial_degree() (the latter a quadrature policy, as a blending map is
/// not a polynomial) through the same interface.
enum class HexMapKind { trilinear, triquadratic };

/// Geometry of one hexahedron: Lagrange interpolation of its nodes, trilinear (8 vertices) or
/// triquadratic (27 nodes in Gmsh's order, kHex27Nodes). A value type, one per element.
class HexMap {
 public:
  /// The trilinear map of the 8 vertices (order of basis/hex_modes.hpp).
  static HexMap trilinear(const std::array<Vec3, 8>& vertices);
  /// The triquadratic map of a HEX27's nodes in Gmsh's order (kHex27Nodes).
  static HexMap triquadratic(const std::array<Vec3, 27>& nodes);

  HexMapKind kind() const { return kind_; }
  /// Degree of x(xi) in each reference coordinate: 1 (trilinear) or 2 (triquadratic).
  int polynomial_degree() const { return kind_ == HexMapKind::trilinear ? 1 : 2; }
  /// The nodes, in the order they were given.
  const std::vector<Vec3>& nodes() const { return nodes_; }

  /// x(xi, eta, zeta); if J is given, J = [dx/dxi, dx/deta, dx/dzeta] (columns).
  Vec3 map(double xi, double eta, double zeta, Mat3* J = nullptr) const;

 private:
  HexMapKind kind_ = HexMapKind::trilinear;
  std::vector<Vec3> nodes_;
  std::vector<std::array<int, 3>> reference_;  ///< each node's reference position in {-1, 0, 1}^3
};

/// Checks det J > 0 at an n × n × n Gauss grid and at the 8 corners (beyond round-off: 1e-12 of
/// the map's scale (|J|_F / √3)³); throws MeshError naming `context`, the element and the
/// reference point: an inverted hex (det J < 0 somewhere) or a degenerate one (a collapsed edge
/// or face, or a flat hex: det J = 0).
void check_hex_jacobian(const HexMap& map, std::string_view context, int element, int n_points);

}  // namespace hpcontact::mesh
