// The deformed contact boundary of a body as the other body of a pair sees it: closest-point
// projection onto the high-order curve, and the gap with the boundary's outward normal.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Dense>

#include "hpcontact/contact/obstacle.hpp"
#include "hpcontact/fem/dof_map.hpp"
#include "hpcontact/mesh/element_map.hpp"
#include "hpcontact/mesh/mesh.hpp"

namespace hpcontact::contact {

/// A point of the deformed boundary x(t) = X(t) + Σ N_k(t) u_k on one edge, with what the
/// two-body contact terms need: dx/dt, the outward normal, the modes living on the edge and N_k,
/// dN_k/dt (n·d²x/dt² on demand: DeformableBoundary::curvature).
struct BoundaryPoint {
  int edge = -1;      ///< index into the boundary's edges
  double t = 0;       ///< local edge parameter in [-1, 1]
  Vec2 x, dx_dt;      ///< deformed position and (unnormalised) tangent
  Vec2 normal;        ///< deformed outward unit normal
  std::vector<int> modes;
  Eigen::VectorXd N, dN;
};

/// The contact edges of a deformable body, as an obstacle for the other body's points. The
/// displacement is a state: set_displacement() before gap() or project().
class DeformableBoundary final : public Obstacle {
public:
  DeformableBoundary(const mesh::Mesh& mesh, const fem::DofMap& dofs,
                     const std::vector<mesh::ElementMap>& maps, const std::vector<int>& edges);

  /// The body's dofs (dof = 2·mode + component); kept by copy. The deformed boundary is then
  /// sampled once, at the first projection or segmentation (the points they bracket between),
  /// not at every one.
  void set_displacement(const Eigen::VectorXd& u) const {
    u_ = u;
    sampled_ = false;
  }

  /// The closest point of the deformed boundary to x (a local minimum of the distance with its
  /// foot inside an edge, or on a node shared by two edges); false if there is none.
  bool project(const Vec2& x, BoundaryPoint& foot) const;

  /// The free end of the boundary (an edge end no other edge shares) nearest to x, as a foot:
  /// edge, t = ±1, the deformed point, tangent and normal there; false if the boundary has none.
  /// What a point beyond the boundary (project() false) is measured against.
  bool free_end(const Vec2& x, BoundaryPoint& end) const;

  /// Signed gap (x − x_m)·n_m, n_m the boundary's outward normal at the closest point x_m;
  /// +∞ when x has no foot on the boundary. dnormal_dx is not provided (set to zero): the
  /// two-body terms use their own linearisation (two_body_contact).
  double gap(const Vec2& x, Vec2* normal, Mat2* dnormal_dx) const override;
  std::string describe() const override;

  /// The point of edge k at parameter t, deformed by the current displacement.
  void evaluate(int k, double t, BoundaryPoint& bp) const;
  /// The same point undeformed.
  Vec2 undeformed(int k, double t) const;
  /// ds/dS there: the deformed boundary's length per unit of its undeformed length (1 undeformed).
  /// Where two boundaries touch, a length dS_a of one lies on dS_b = dS_a · stretch_a / stretch_b
  /// of the other: what refers a traction per unit length of one to the other's.
  double stretch(int k, double t) const;
  int n_edges() const { return static_cast<int>(edges_.size()); }

  /// A vertex of the deformed boundary: its position and the mean unit tangent of the edges
  /// that meet there (one edge at an end of the boundary).
  struct Vertex {
    Vec2 x, tangent;
  };
  /// The vertices of the boundary's edges, each once.
  std::vector<Vertex> vertices() const;

  /// The parameters of edge k between which the closest point of `master` to the points of the
  /// edge lies on one edge of `master`: where the projection crosses a vertex of master, the
  /// ends of the mortar segments, ascending, −1 and 1 included. Both boundaries' displacements
  /// must be set.
  std::vector<double> segments(int k, const DeformableBoundary& master) const;

  /// n · d²x/dt² at a foot (the curvature term of the consistent tangent), by central
  /// differences of the exact tangent; only active points of a tangent evaluation need it.
  double curvature(const BoundaryPoint& foot) const;

private:
  struct Edge {
    int element, local_edge;
    std::vector<int> local;  ///< element-local modes non-zero on the edge
    std::array<bool, 2> shared_end{false, false};  ///< t = −1, +1 on a vertex of another edge
    /// For a shared end: the other edge there and which of its ends (0: t = −1, 1: t = +1).
    std::array<std::pair<int, int>, 2> neighbour{std::pair{-1, 0}, std::pair{-1, 0}};
  };
  const mesh::Mesh& mesh_;
  const fem::DofMap& dofs_;
  const std::vector<mesh::ElementMap>& maps_;
  std::vector<Edge> edges_;
  mutable Eigen::VectorXd u_;
  /// Per edge, the deformed position and tangent at its bracketing samples, for the current
  /// displacement once sampled_.
  struct Sample {
    Vec2 x, dx_dt;
  };
  mutable std::vector<Sample> samples_;
  mutable bool sampled_ = false;
  /// The samples of edge k (sampling the boundary first if the displacement changed).
  const Sample* samples_of(int k) const;
  mutable Eigen::VectorXd N_, dxi_, deta_;  ///< scratch of evaluate()
  Vec2 tangent_at(int k, double t) const;
};

}  // namespace hpcontact::contact
