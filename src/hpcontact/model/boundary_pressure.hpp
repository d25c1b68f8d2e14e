// The pressures at any point of a pair's contact boundary, located by its coordinate along the
// obstacle: the traction the method carries and what the stresses say there.
#pragma once

#include <array>
#include <optional>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "hpcontact/contact/surface_frame.hpp"
#include "hpcontact/model/contact_pairs.hpp"
#include "hpcontact/model/discretization.hpp"

namespace hpcontact::model {

/// Pressures at one point of a contact boundary.
struct BoundaryPressure {
  Vec2 X;  ///< undeformed position
  /// The contact pressure: normal force per unit length along the obstacle (traction · dS/ds).
  double pressure = 0;
  /// The same from the stresses: −n_o·(P N) dS/ds.
  double pressure_from_stress = 0;
  /// The traction the method carries per unit undeformed boundary length: eps_N <-g_N>
  /// (penalty), the multiplier λ_h (exact).
  double traction = 0;
  double minus_sigma_nn = 0;  ///< −n·σ·n, n the body's undeformed outward normal
};

/// Pressures along the contact boundary of a pair, located by the coordinate
/// s = (X - reference point)·tangent of the undeformed point X along the obstacle (the linear
/// theory's coordinate: Hertz and Shtayerman place the pressure on the undeformed surface). The boundary is sampled once when
/// constructed; each query then refines one bracket.
class BoundaryPressureProbe {
public:
  /// `multipliers`: the pair's multipliers when it is enforced exactly (kept by reference).
  BoundaryPressureProbe(const Discretization& d, const ContactPair& pair, const Eigen::VectorXd& u,
                        const Eigen::VectorXd* multipliers = nullptr);
  /// Pressures at the boundary point with coordinate s; nullopt if no contact edge reaches s.
  std::optional<BoundaryPressure> operator()(double s) const;
  /// The traction the method carries at parameter t of the pair's contact edge k (edges[k]):
  /// λ_h or eps_N <-g_N>, per unit undeformed length; x, X (may be null) the point deformed and
  /// undeformed.
  double traction(int k, double t, Vec2* x = nullptr, Vec2* X = nullptr) const;
  /// Whether the pair carries a tangential multiplier (exact enforcement with friction).
  bool has_tangential_traction() const;
  /// The tangential multiplier λ_T,h at parameter t of contact edge k, per unit undeformed
  /// length, signed along the pair's friction tangent; 0 without has_tangential_traction().
  double tangential_traction(int k, double t) const;
  /// The coordinates s of the contact edges' ends, where the pressures are not smooth.
  std::vector<double> edge_ends() const;

private:
  static constexpr int kSamples = 32;  ///< sub-intervals per edge
  const Discretization& d_;
  const ContactPair& pair_;
  const Eigen::VectorXd& u_;
  const Eigen::VectorXd* multipliers_;
  contact::SurfaceFramePtr common_tangent_;  ///< the line of the pair's common tangent
  std::vector<std::array<double, kSamples + 1>> coord_;  ///< per edge, at t = -1 + 2i/kSamples
  std::vector<std::pair<double, double>> range_;        ///< per edge, the least and largest of them
  double coordinate(int edge_index, double t) const;
};

}  // namespace hpcontact::model
