// Points where a contact pair's exact pressure is unbounded: the zone still closed where a body's
// contact boundary ends or turns at a corner (a flat punch's edge, a hub's end on its shaft). The
// pressure there is no converged value; what converges is the singularity's strength, fitted
// from the pressures around the point.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "hpcontact/model/contact_pairs.hpp"

namespace hpcontact::model {

struct ContactResult;

/// A corner of a contact boundary: a vertex where two contact edges meet at an angle of more
/// than this (degrees) — a polygon's kinks of a few degrees are not corners.
constexpr double kCornerAngleDegrees = 10;

/// pressure_max leaves out the pressures within this share of the zone's extent (on the side of
/// the zone) from a singular point, and within the elements touching it.
constexpr double kPressureMaxDistance = 0.01;

/// A fitted singularity p ≈ K d^(−λ) (d the distance from the point along the pair's surface):
/// log p = log K − λ log d + c d in least squares over the pressures in contact between `from`
/// and `to` (the elements touching the point left out: their pressure is the polynomial's attempt
/// at the peak; `to` a quarter of the zone's extent from the point). And the square-root
/// singularity's strength K½ = lim p d^(1/2) (a rigid flat punch's corner, frictionless): the same
/// fit with λ = 1/2 and c₁ d + c₂ d², which a pressure of another exponent fits worse (its rms).
struct SingularityFit {
  double exponent = 0;  ///< λ
  double strength = 0;  ///< K, in units of pressure · length^λ
  double square_root_strength = 0;  ///< K½, pressure · length^(1/2)
  double from = 0, to = 0;  ///< the distances fitted over
  int points = 0;           ///< how many pressures
  double rms = 0;           ///< the root mean square of the fit's residual in log p
  double square_root_rms = 0;  ///< the same of the square-root fit
};

/// A point where the pair's contact zone is closed up to an end or a corner of a contact
/// boundary and its pressure rises towards it.
struct SingularPoint {
  Vec2 X;         ///< undeformed position (on the body's boundary, or the other body's corner)
  Vec2 x;         ///< the same point deformed
  /// Its position along the pair's surface (the other body's corner: that of the undeformed
  /// point of this body it touches deformed).
  double s = 0;
  /// The undeformed point of the pair's body at s: X for the body's own end or corner, the foot
  /// of the other body's corner (where it touches this body deformed).
  Vec2 foot;
  bool on_other = false;  ///< X is the other body's end or corner
  /// Which boundary ends or turns there, in words: "the end of the contact edges of body
  /// 'block' (node 12)", "a corner of body 'hub' (node 40)".
  std::string where;
  /// The pressure of the point nearest to it: not a converged value.
  double peak = 0;
  /// The pressures within this distance (the elements touching the point) are left out of the
  /// fit and of pressure_max.
  double excluded = 0;
  /// pressure_max is the largest pressure farther than this from the point: beyond `excluded`
  /// and beyond kPressureMaxDistance of the zone's extent from it (so that it converges as the
  /// mesh is refined towards the point).
  double pressure_max_beyond = 0;
  std::optional<SingularityFit> fit;  ///< none when too few pressures lie beyond the excluded
};

/// The singular points of a pair's solved state: each end and corner of either body's contact
/// edges where the zone is closed (the body's point nearest it in contact) and the pressure rises
/// towards it — by the fit (λ > 0.05), or, with too few pressures to fit, the peak above 1.5
/// times the zone's mean. An end on a mirror or the axis (its displacement along the surface
/// held at zero, the other component free) is no end: the zone continues in the mirror image.
/// `u` the state's dofs (the other body's corners are found on this body deformed).
std::vector<SingularPoint> singular_points(const Discretization& d, const ContactPair& pair,
                                           const Eigen::VectorXd& u, const ContactResult& result);

/// The largest pressure of the result farther from each singular point than its
/// `pressure_max_beyond`.
double pressure_max_away(const ContactResult& result, const std::vector<SingularPoint>& points);

}  // namespace hpcontact::model
