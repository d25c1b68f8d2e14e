// Gordon–Hall transfinite (blending) map of the reference cube onto a hexahedron with exact faces.
#pragma once

#include <array>

#include "hpcontact/geometry/surface.hpp"

namespace hpcontact::geometry {

/// Geometry of one hexahedron for the blending function method in 3D: the 3D extension of seed
/// eq. 2.74–2.76 (Gordon and Hall's trilinear Boolean sum). Vertex, edge and face numbering and
/// directions as in basis/hex_modes.hpp (vertices V0..V7 the images of the cube's corners, edge
/// e from kHexEdgeVertices[e][0] to [e][1] along the positive direction of its axis, face f
/// with local axes (s, t) = kHexFaceAxes[f]).
///
///   edge e:  E_e(t)    = edges[e]->edge(A, B, t) (surface.hpp: a sphere's great-circle arc and a
///                        cylinder's circle, generator or helix, each uniform in angle), or the
///                        chord (1 − t)/2 A + (1 + t)/2 B
///   face f:  F_f(s, t) = P_f(T_f(s, t)),                    P_f = faces[f]->onto, or the identity
/// with T_f the 2D blending map of its four edges (seed eq. 2.76),
///   T_f = (1−t)/2 E_b(s) + (1+t)/2 E_t(s) + (1−s)/2 E_l(t) + (1+s)/2 E_r(t) − bilinear(corners),
/// and the element
///   x(ξ) = Σ_faces L_f(ξ_n) F_f − Σ_edges L(ξ_b) L(ξ_c) E_e + Σ_vertices L L L X_v,
/// L(t) = (1 ∓ t)/2 the linear function that is 1 on the face, edge or vertex. x restricted to a
/// face is that face's F_f when every face's map restricted to each of its edges is that edge's
/// E_e (blending_hex() checks it), so two elements that share a face with the same surfaces and
/// vertices share its image, and a face on a surface lies on it exactly.
struct BlendingHex {
  std::array<Vec3, 8> vertices;
  /// The surface whose curve (Surface::edge) each edge follows, or null for a straight edge.
  std::array<SurfacePtr, 12> edges;
  /// The surface each face is mapped onto, or null: the face is then the transfinite
  /// interpolant of its edges (flat if they lie in one plane, a ruled-like patch otherwise).
  std::array<SurfacePtr, 6> faces;

  /// x(xi, eta, zeta) and, if J is not null, J = [dx/dxi, dx/deta, dx/dzeta] (columns), by the
  /// chain rule through the surfaces' derivatives (analytic).
  Vec3 map(double xi, double eta, double zeta, Mat3* J = nullptr) const;
};

/// The blending hexahedron of 8 vertices and the surfaces of its faces (null: none). Each edge
/// takes the curved (not flat()) surface of its two faces, and is straight when both are flat or
/// null. Throws InputError naming `context`: an edge between two different curved surfaces (the
/// edge's curve would be their intersection, which neither surface's curve gives); a vertex not on
/// the surface of one of its faces; an edge whose image leaves the surface of one of its faces
/// (e.g. a sphere's arc against a plane not through its centre), checked at 5 points of each
/// edge, to 1e-10 of the element's size.
BlendingHex blending_hex(const std::array<Vec3, 8>& vertices,
                         const std::array<SurfacePtr, 6>& faces, const char* context = "hexahedron");

}  // namespace hpcontact::geometry
