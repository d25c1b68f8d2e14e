// A structured mesh of a box [x0, x1] × [y0, y1] × [z0, z1] in trilinear hexahedra.
#pragma once

#include <array>
#include <vector>

#include "hpcontact/mesh/hex_mesh.hpp"

namespace hpcontact::mesh {

/// The box lower <= x <= upper cut into n[0] × n[1] × n[2] equal trilinear hexahedra, each with
/// its local axes (xi, eta, zeta) along (x, y, z). Node (i, j, k) at
/// lerp(lower, upper, (i/n[0], j/n[1], k/n[2])) has index i + (n[0] + 1)(j + (n[1] + 1) k), element
/// (i, j, k) index i + n[0](j + n[1] k). Face sets, in element order: "x0" and "x1" (local faces
/// F0 and F1 on x = lower.x and x = upper.x), "y0", "y1" (F2, F3), "z0", "z1" (F4, F5); the
/// boundary nodes lie on their planes exactly (lerp gives the ends).
/// Throws InputError unless lower < upper in every coordinate and every n[d] >= 1.
HexMesh hex_box_mesh(const Vec3& lower, const Vec3& upper, std::array<int, 3> n);

/// The box planes[0].front() <= x <= planes[0].back() (and so for y, z) cut at the planes
/// x = planes[0][i], y = planes[1][j], z = planes[2][k] into (planes[d].size() − 1) elements along
/// each axis d, of any lengths (e.g. graded towards a clamped end); numbering and face sets as
/// above, with n[d] = planes[d].size() − 1 and node (i, j, k) at (planes[0][i], planes[1][j],
/// planes[2][k]).
/// Throws InputError unless each planes[d] has two or more entries, strictly increasing.
HexMesh hex_box_mesh(const std::array<std::vector<double>, 3>& planes);

}  // namespace hpcontact::mesh
