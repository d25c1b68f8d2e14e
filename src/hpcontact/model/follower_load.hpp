// Follower pressures of finite-strain bodies (bodies[].loads[] with follower: true): the loaded
// edges in chain order, the pressure along them, and the part of them that is wetted when the
// pressure penetrates up to a contact zone (penetration: {contact, from}).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include "hpcontact/fem/follower_pressure.hpp"

namespace hpcontact::model {

struct Discretization;

/// One loaded edge of a follower load: the element side it is, and where the load's own pieces
/// break (its interval's ends, a shape's joint), as local edge parameters from −1 to 1.
struct FollowerEdge {
  int q = -1, le = -1;  ///< element and local edge
  int mesh_edge = -1;
  bool against = false;  ///< the local parameter runs against the chain's direction
  std::vector<double> breaks;
};

/// A follower pressure that acts only on the part of its edges that is not in contact: from the
/// chosen end of the chain of its edges up to the first point in contact of pair `pair`.
struct Penetration {
  int pair = -1;
  bool from_end = false;  ///< from the chain's end (else from its start)
};

/// A follower pressure on one body: its edges in the chain's order (chain_edges), the pressure
/// p(X) at an undeformed point (shape and scale applied: the load at a unit load factor).
struct FollowerLoad {
  int body = -1;
  std::string where;  ///< the load's key path, "file: bodies[0].loads[1]"
  std::vector<FollowerEdge> edges;
  fem::PressureFn pressure;
  std::optional<Penetration> penetration;
  /// On a body of the linear theory: the pressure on the undeformed boundary (a dead load, kept
  /// here only because penetration moves where it acts).
  bool dead = false;
};

/// The part of a follower load's chain that is loaded, as chain positions s in [0, n_edges]
/// (edge k covers [k, k + 1] in the chain's direction).
struct WetRange {
  double from = 0, to = 0;
  /// No point of the pair is in contact on the loaded edges: the pressure reaches the far end
  /// (the seal leaks). Always false without penetration.
  bool leaks = false;
};

/// Where a contact pair's point or multiplier node lies on a body, and its contact pressure
/// (exact: the multiplier of an active node, per undeformed length; penalty: the point's
/// pressure; 0 where it is not in contact).
struct ContactMark {
  int body = -1;
  int mesh_edge = -1;
  double t = 0;  ///< local parameter on that edge
  Vec2 X = Vec2::Zero();  ///< undeformed position
  double pressure = 0;
};

/// The whole chain of L, or with penetration the part from its pressurised end up to the first
/// of `marks` (those of L's pair on L's body) that seals: whose contact pressure exceeds the
/// load's pressure there (times loads_factor), as pressure penetration is judged in engineering
/// codes — the fluid enters a contact that presses less than it; all of it (leaks) if none does.
WetRange wetted_range(const FollowerLoad& L, const std::vector<ContactMark>& marks, double loads_factor);

/// Adds `factor` times the force of L at the state u (all dofs) over the range into f (all
/// dofs), and `factor` times its derivative ∂f/∂u into t (all dofs) if t is not null.
void add_follower_force(const Discretization& d, const FollowerLoad& L, const Eigen::VectorXd& u,
                        const WetRange& range, double factor, Eigen::VectorXd& f,
                        std::vector<Eigen::Triplet<double>>* t);

/// Where the range stops being loaded at the sealed side, as the undeformed point of the chain
/// and the undeformed length of the wetted part.
struct WetExtent {
  Vec2 stop = Vec2::Zero();
  double length = 0;
};
WetExtent wetted_extent(const Discretization& d, const FollowerLoad& L, const WetRange& range);

}  // namespace hpcontact::model
