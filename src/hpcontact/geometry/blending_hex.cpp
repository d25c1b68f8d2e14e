// The 3D blending map as a Boolean sum of face, edge and vertex interpolants, with its Jacobian.
#include "hpcontact/geometry/blending_hex.hpp"

#include <algorithm>

#include "hpcontact/core/error.hpp"

namespace hpcontact::geometry {

namespace {

// The cube's numbering (basis/hex_modes.hpp; geometry does not depend on basis, so it is
// repeated here and checked against basis by tests/unit/mesh/test_hex_blending.cpp).
constexpr int kVertex[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                               {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
constexpr int kEdgeVertices[12][2] = {{0, 1}, {1, 2}, {3, 2}, {0, 3}, {4, 5}, {5, 6},
                                      {7, 6}, {4, 7}, {0, 4}, {1, 5}, {3, 7}, {2, 6}};
constexpr int kEdgeAxis[12] = {0, 1, 0, 1, 0, 1, 0, 1, 2, 2, 2, 2};
constexpr int kFaceVertices[6][4] = {{0, 3, 7, 4}, {1, 2, 6, 5}, {0, 1, 5, 4},
                                     {3, 2, 6, 7}, {0, 1, 2, 3}, {4, 5, 6, 7}};
constexpr int kFaceAxes[6][2] = {{1, 2}, {1, 2}, {0, 2}, {0, 2}, {0, 1}, {0, 1}};
constexpr int kFaceNormalAxis[6] = {0, 0, 1, 1, 2, 2};

/// The linear function of t that is 1 at side c (−1 or +1) and 0 at the other, and its slope.
double linear(int c, double t) { return 0.5 * (1 + c * t); }
double slope(int c) { return 0.5 * c; }

int edge_between(int a, int b) {
  for (int e = 0; e < 12; ++e)
    if ((kEdgeVertices[e][0] == a && kEdgeVertices[e][1] == b) ||
        (kEdgeVertices[e][0] == b && kEdgeVertices[e][1] == a))
      return e;
  return -1;
}

/// The edges of face f: bottom (t = −1, along s), right (s = +1, along t), top (t = +1, along
/// s), left (s = −1, along t); every one runs along its axis's positive direction.
struct FaceEdges {
  int bottom, right, top, left;
};

FaceEdges face_edges(int f) {
  const int* v = kFaceVertices[f];
  return {edge_between(v[0], v[1]), edge_between(v[1], v[2]), edge_between(v[3], v[2]),
          edge_between(v[0], v[3])};
}

/// E_e(t) and dE/dt: the chord, or the curve of the edge's surface between its ends.
Vec3 edge_point(const BlendingHex& h, int e, double t, Vec3* dE) {
  const Vec3& A = h.vertices[kEdgeVertices[e][0]];
  const Vec3& B = h.vertices[kEdgeVertices[e][1]];
  if (h.edges[e]) return h.edges[e]->edge(A, B, t, dE);
  if (dE) *dE = 0.5 * (B - A);
  return 0.5 * (1 - t) * A + 0.5 * (1 + t) * B;
}

/// F_f(s, t) and its partial derivatives: the surface's image of the 2D blending of the edges.
Vec3 face_point(const BlendingHex& h, int f, double s, double t, Vec3* dF_ds, Vec3* dF_dt) {
  const FaceEdges k = face_edges(f);
  const int* v = kFaceVertices[f];
  const std::array<Vec3, 4> X{h.vertices[v[0]], h.vertices[v[1]], h.vertices[v[2]],
                              h.vertices[v[3]]};
  Vec3 db, dr, dt_, dl;
  const Vec3 b = edge_point(h, k.bottom, s, &db), r = edge_point(h, k.right, t, &dr),
             top = edge_point(h, k.top, s, &dt_), l = edge_point(h, k.left, t, &dl);
  // T = (1−t)/2 b(s) + (1+t)/2 top(s) + (1−s)/2 l(t) + (1+s)/2 r(t) − bilinear (eq. 2.76).
  const double ls0 = linear(-1, s), ls1 = linear(1, s), lt0 = linear(-1, t), lt1 = linear(1, t);
  Vec3 T = lt0 * b + lt1 * top + ls0 * l + ls1 * r -
           (ls0 * lt0 * X[0] + ls1 * lt0 * X[1] + ls1 * lt1 * X[2] + ls0 * lt1 * X[3]);
  Vec3 T_s = lt0 * db + lt1 * dt_ - 0.5 * l + 0.5 * r -
             0.5 * (-lt0 * X[0] + lt0 * X[1] + lt1 * X[2] - lt1 * X[3]);
  Vec3 T_t = -0.5 * b + 0.5 * top + ls0 * dl + ls1 * dr -
             0.5 * (-ls0 * X[0] - ls1 * X[1] + ls1 * X[2] + ls0 * X[3]);
  if (!h.faces[f]) {
    *dF_ds = T_s;
    *dF_dt = T_t;
    return T;
  }
  Mat3 dP;
  const Vec3 x = h.faces[f]->onto(T, &dP);
  *dF_ds = dP * T_s;
  *dF_dt = dP * T_t;
  return x;
}

}  // namespace

Vec3 BlendingHex::map(double xi, double eta, double zeta, Mat3* J) const {
  const double r[3] = {xi, eta, zeta};
  Vec3 x = Vec3::Zero();
  Mat3 G = Mat3::Zero();  // the Jacobian's columns, accumulated term by term

  // + Σ_f L(ξ_n) F_f(ξ_s, ξ_t)
  for (int f = 0; f < 6; ++f) {
    const int n = kFaceNormalAxis[f], a = kFaceAxes[f][0], b = kFaceAxes[f][1];
    const int side = f % 2 ? 1 : -1;
    Vec3 F_s, F_t;
    const Vec3 F = face_point(*this, f, r[a], r[b], &F_s, &F_t);
    const double w = linear(side, r[n]);
    x += w * F;
    G.col(n) += slope(side) * F;
    G.col(a) += w * F_s;
    G.col(b) += w * F_t;
  }
  // − Σ_e L(ξ_b) L(ξ_c) E_e(ξ_a), b and c the edge's fixed axes at the sides of its first vertex
  for (int e = 0; e < 12; ++e) {
    const int a = kEdgeAxis[e], b = (a + 1) % 3, c = (a + 2) % 3;
    const int* V = kVertex[kEdgeVertices[e][0]];
    Vec3 E_t;
    const Vec3 E = edge_point(*this, e, r[a], &E_t);
    const double wb = linear(V[b], r[b]), wc = linear(V[c], r[c]);
    x -= wb * wc * E;
    G.col(a) -= wb * wc * E_t;
    G.col(b) -= slope(V[b]) * wc * E;
    G.col(c) -= wb * slope(V[c]) * E;
  }
  // + Σ_v L L L X_v
  for (int v = 0; v < 8; ++v) {
    const int* V = kVertex[v];
    const double w0 = linear(V[0], xi), w1 = linear(V[1], eta), w2 = linear(V[2], zeta);
    x += w0 * w1 * w2 * vertices[v];
    G.col(0) += slope(V[0]) * w1 * w2 * vertices[v];
    G.col(1) += w0 * slope(V[1]) * w2 * vertices[v];
    G.col(2) += w0 * w1 * slope(V[2]) * vertices[v];
  }
  if (J) *J = G;
  return x;
}

BlendingHex blending_hex(const std::array<Vec3, 8>& vertices,
                         const std::array<SurfacePtr, 6>& faces, const char* context) {
  BlendingHex h;
  h.vertices = vertices;
  h.faces = faces;
  double size = 0;
  for (const Vec3& X : vertices) size = std::max(size, (X - vertices[0]).norm());
  const double tol = 1e-10 * size;

  for (int f = 0; f < 6; ++f) {
    if (!faces[f]) continue;
    for (int k = 0; k < 4; ++k) {
      const Vec3& X = vertices[kFaceVertices[f][k]];
      HPC_REQUIRE((faces[f]->onto(X) - X).norm() <= tol, InputError, context, ": vertex V",
                  kFaceVertices[f][k], " is not on ", faces[f]->describe(), ", the surface of face F",
                  f, " (off by ", (faces[f]->onto(X) - X).norm(), ")");
    }
  }
  // Each edge on the curved surface of its faces; both faces must agree on it.
  for (int f = 0; f < 6; ++f) {
    if (!faces[f] || faces[f]->flat()) continue;
    const FaceEdges k = face_edges(f);
    for (int e : {k.bottom, k.right, k.top, k.left}) {
      HPC_REQUIRE(!h.edges[e] || h.edges[e] == faces[f], InputError, context, ": edge E", e,
                  " lies on two curved surfaces, ", h.edges[e]->describe(), " and ",
                  faces[f]->describe(), ": neither surface's curve follows their intersection");
      h.edges[e] = faces[f];
    }
  }
  for (int f = 0; f < 6; ++f) {
    if (!faces[f]) continue;
    const FaceEdges k = face_edges(f);
    for (int e : {k.bottom, k.right, k.top, k.left})
      for (double t : {-1.0, -0.5, 0.0, 0.5, 1.0}) {
        const Vec3 E = edge_point(h, e, t, nullptr);
        const double off = (faces[f]->onto(E) - E).norm();
        HPC_REQUIRE(off <= tol, InputError, context, ": edge E", e, " leaves ",
                    faces[f]->describe(), ", the surface of face F", f, ", by ", off, " at t = ", t,
                    " (its image under ", h.edges[e] ? h.edges[e]->describe() : "no surface",
                    " is not on it)");
      }
  }
  return h;
}

}  // namespace hpcontact::geometry
