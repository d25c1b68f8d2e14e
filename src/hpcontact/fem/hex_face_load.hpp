// Consistent nodal forces of a pressure or a traction on one face of a hexahedron.
#pragma once

#include <array>

#include <Eigen/Dense>

#include "hpcontact/basis/hex_modes.hpp"
#include "hpcontact/mesh/hex_map.hpp"

namespace hpcontact::fem {

/// Reference point (xi, eta, zeta) of local face lf (0..5) at its local coordinates (s, t)
/// (basis/hex_modes.hpp: the normal coordinate at -1 for even lf, +1 for odd).
mesh::Vec3 hex_face_reference_point(int lf, double s, double t);

/// n dA / (ds dt) at (s, t) of local face lf: the cross product of the map's tangents along s and
/// t, turned outward (s × t is outward on F1, F2, F5, inward on F0, F3, F4); its length is the
/// area element.
mesh::Vec3 hex_face_area_normal(const mesh::HexMap& map, int lf, double s, double t);

/// Gauss points per direction on local face lf: the larger face degree plus the map's degree
/// (mesh::HexMap::polynomial_degree) plus 1. For a polynomial map of degree q the integrand
/// N (x_s × x_t) is a polynomial of degree at most p + 2q − 1 per direction, which p + q + 1
/// points integrate exactly; for a blending map (q = kBlendingQuadratureDegree) it is smooth and
/// resolved to 1e-10 and better (tests/unit/fem/test_hex_face_load.cpp).
int hex_face_gauss_points(const basis::HierarchicHex& element, const mesh::HexMap& map, int lf);

/// f_e = −∫ N p n dA over local face lf: the load of a pressure p (force per area, positive in
/// compression, so it pushes against the outward normal n, as in analytic/lame_sphere.hpp), with an
/// n_points × n_points Gauss rule on the face (hex_face_gauss_points). Component-blocked like every
/// hexahedron vector (fem/hex_elasticity.hpp): 3 n_modes entries, x block, y block, z block; the
/// entries of modes that vanish on the face are zero.
Eigen::VectorXd hex_face_pressure_load(const basis::HierarchicHex& element,
                                       const mesh::HexMap& map, int lf, double pressure,
                                       int n_points);

/// f_e = ∫ N t dA over local face lf for a constant traction vector t (force per area), with
/// the same rule and layout as hex_face_pressure_load.
Eigen::VectorXd hex_face_traction_load(const basis::HierarchicHex& element,
                                       const mesh::HexMap& map, int lf,
                                       const mesh::Vec3& traction, int n_points);

}  // namespace hpcontact::fem
