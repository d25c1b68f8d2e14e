// The contact pairs of a problem: each body's contact points, its obstacle (rigid or another
// body), the penalty and the friction law, built once from the problem description.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "hpcontact/contact/deformable_boundary.hpp"
#include "hpcontact/contact/obstacle.hpp"
#include "hpcontact/contact/penalty.hpp"
#include "hpcontact/contact/surface_frame.hpp"
#include "hpcontact/model/contact_multipliers.hpp"
#include "hpcontact/model/discretization.hpp"

namespace hpcontact::model {

/// A resolved contact pair: the body, its contact points, the obstacle and the penalty. Against
/// another deformable body (`other` >= 0) the obstacle is that body's deformed boundary, and
/// the other body's points are evaluated against this body's boundary too (seed §3.6).
struct ContactPair {
  int body = -1;
  /// How `body` came to carry the multipliers of a two-body pair: empty as the input wrote it,
  /// else "auto: " and the rule (ContactPairSpec::carrier_choice).
  std::string carrier_choice;
  std::vector<contact::ContactPoint> points;
  std::vector<int> edges;  ///< mesh edges of the contact boundary, in order
  contact::ObstaclePtr obstacle;
  /// The same obstacle when it moves (a rigid obstacle with a displacement), else null.
  std::shared_ptr<contact::DisplacedObstacle> moving;
  int other = -1;  ///< the other body of a bilateral pair, -1 against a rigid obstacle
  std::vector<contact::ContactPoint> other_points;
  std::vector<int> other_edges;  ///< the other body's contact edges (mesh edges)
  std::shared_ptr<const contact::DeformableBoundary> boundary, other_boundary;
  double penalty = 0;
  /// Exact enforcement (augmented Lagrangian): the multiplier constraints; null for the penalty.
  std::shared_ptr<const PairConstraints> constraints;
  contact::FrictionLaw friction;
  /// The friction histories of the pair's points (and of the other body's points), carried from
  /// load step to load step; shared by copies of the pair.
  struct FrictionMemory {
    std::vector<contact::FrictionHistory> points, other_points;
    /// The histories the last committed step started from (what its Newton iterations saw),
    /// for its tangent (contact_tangent): evaluated with the committed slips, slipping points
    /// lie on the cone, where a difference quotient straddles stick and slip.
    std::vector<contact::FrictionHistory> points_before, other_points_before;
  };
  std::shared_ptr<FrictionMemory> memory;
  /// The surface the pair's results are reported along (contact.csv's s and pressure, the
  /// zone's ends and extent): a plane, the circle, the other body's undeformed contact boundary
  /// (a line or a circle where its edges lie on one); a curve obstacle's common tangent.
  contact::SurfaceFramePtr frame;
  /// The direction the normal force is measured along (the input's normal_direction, a plane's
  /// normal, a curve's at `reference_point`); none: the resultant's own.
  std::optional<Vec2> force_direction;
  /// The normal force's direction for a resultant R on the body: force_direction, else R's.
  Vec2 force_normal(const Vec2& resultant) const {
    if (force_direction) return *force_direction;
    return resultant.norm() > 0 ? Vec2(resultant.normalized()) : Vec2(0, 1);
  }

  /// The linear theory's common tangent, what closed forms (compare) measure positions along:
  /// a line through reference_point along `tangent` (a plane's; a curve's tangent at the foot
  /// of reference_point; for another body its tangent at the foot of reference_point; x for a
  /// circle).
  Vec2 reference_point = Vec2::Zero();
  Vec2 tangent = Vec2(1, 0);
  /// Coordinate of a point along the common tangent: (X − reference point)·tangent.
  double coordinate(const Vec2& X) const { return (X - reference_point).dot(tangent); }
  /// d coordinate / dh of the point X + h dX at h = 0 (dX a direction, e.g. dX/dt of a boundary).
  double coordinate_rate(const Vec2& /*X*/, const Vec2& dX) const { return tangent.dot(dX); }
  /// The common tangent turned left (a plane's normal; y for a circle and another body).
  Vec2 normal() const { return Vec2(-tangent.y(), tangent.x()); }
};

/// Contact pairs of a problem; InputError naming the key when a pair is wrong.
std::vector<ContactPair> make_contact_pairs(const ProblemSpec& spec, const Discretization& d);

/// The body called `name` and its index; InputError naming `where`.body if there is none.
const Body& body_named(const Discretization& d, const std::string& name, const SourceRef& where,
                       int* index);

}  // namespace hpcontact::model
