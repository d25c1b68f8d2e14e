// A chain of segments and fillet arcs through points: its faults, its pieces, its closest point.
#include "hpcontact/geometry/profile.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "hpcontact/core/error.hpp"

namespace hpcontact::geometry {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

Vec2 left(const Vec2& e) { return Vec2(-e.y(), e.x()); }
double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

std::string point_name(int i) { return "points[" + std::to_string(i) + "]"; }

std::string number(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

/// The straight chain of a spec: segment k from points[k] to points[(k + 1) % n]; at every
/// point its turn θ (signed, > 0 to the left; 0 at an open profile's ends) and the fillet's
/// tangent length r tan(|θ|/2) (0 where sharp).
struct Chain {
  int n_points = 0, n_segments = 0;
  double size = 0;  ///< the points' largest distance from the first
  std::vector<Vec2> direction;
  std::vector<double> length;
  std::vector<double> turn, radius, tangent_length;
  /// The index in `fillets` of point i's corner, −1 for an open profile's ends.
  int corner(int i) const {
    if (closed) return i;
    return i >= 1 && i <= n_points - 2 ? i - 1 : -1;
  }
  bool closed = false;
};

int n_corners(const ProfileSpec& spec) {
  const int n = static_cast<int>(spec.points.size());
  return spec.closed ? n : std::max(n - 2, 0);
}

/// The segments' directions and lengths (the points must not repeat).
Chain straight_chain(const ProfileSpec& spec) {
  Chain c;
  c.closed = spec.closed;
  c.n_points = static_cast<int>(spec.points.size());
  c.n_segments = spec.closed ? c.n_points : c.n_points - 1;
  for (const Vec2& p : spec.points) c.size = std::max(c.size, (p - spec.points.front()).norm());
  for (int k = 0; k < c.n_segments; ++k) {
    const Vec2 d = spec.points[(k + 1) % c.n_points] - spec.points[k];
    c.length.push_back(d.norm());
    c.direction.push_back(d / d.norm());
  }
  return c;
}

/// The turns and fillet tangent lengths at the points of a chain.
void add_corners(const ProfileSpec& spec, Chain& c) {
  c.turn.assign(c.n_points, 0.0);
  c.radius.assign(c.n_points, 0.0);
  c.tangent_length.assign(c.n_points, 0.0);
  for (int i = 0; i < c.n_points; ++i) {
    const int j = c.corner(i);
    if (j < 0) continue;
    const Vec2& before = c.direction[(i + c.n_segments - 1) % c.n_segments];
    const Vec2& after = c.direction[i % c.n_segments];
    c.turn[i] = std::atan2(cross(before, after), before.dot(after));
    if (!spec.fillets.empty()) c.radius[i] = spec.fillets[j];
    // t = r tan(|θ|/2): the arc of radius r touching both segments meets each at t from the corner.
    c.tangent_length[i] = c.radius[i] * std::tan(std::abs(c.turn[i]) / 2);
  }
}

/// A straight part of the chain for the crossing test: from a along the unit d for `length`
/// (infinite for an open profile's continuations), at `position` along the chain.
struct Part {
  Vec2 a, d;
  double length;
  int position;  ///< −1: the continuation before points[0]; k: segment k; n_segments: after
  int point;     ///< the point it is named by
  std::string name;
};

/// Whether two parts meet (cross, touch or overlap) within tolerance tol.
bool meet(const Part& p, const Part& q, double tol) {
  const double det = cross(p.d, q.d);
  const Vec2 ab = q.a - p.a;
  if (std::abs(det) > 1e-12) {
    const double s = cross(ab, q.d) / det, t = cross(ab, p.d) / det;
    return s >= -tol && s <= p.length + tol && t >= -tol && t <= q.length + tol;
  }
  if (std::abs(cross(ab, p.d)) > tol) return false;  // parallel, on different lines
  // On one line: do their intervals along p.d overlap?
  const double s0 = ab.dot(p.d), s1 = s0 + q.length * q.d.dot(p.d);
  return std::max(s0, s1) >= -tol && std::min(s0, s1) <= p.length + tol;
}

std::optional<ProfileFault> crossing(const ProfileSpec& spec, const Chain& c) {
  std::vector<Part> parts;
  const int n = c.n_points, m = c.n_segments;
  if (!c.closed)
    parts.push_back({spec.points[0], -c.direction[0], kInfinity, -1, 0,
                     "the continuation before " + point_name(0)});
  for (int k = 0; k < m; ++k)
    parts.push_back({spec.points[k], c.direction[k], c.length[k], k, k,
                     "the segment " + point_name(k) + "–" + point_name((k + 1) % n)});
  if (!c.closed)
    parts.push_back({spec.points[n - 1], c.direction[m - 1], kInfinity, m, n - 1,
                     "the continuation after " + point_name(n - 1)});
  const double tol = 1e-12 * c.size;
  for (size_t i = 0; i < parts.size(); ++i)
    for (size_t j = i + 1; j < parts.size(); ++j) {
      const Part &p = parts[i], &q = parts[j];
      const int apart = q.position - p.position;
      if (apart == 1 || (c.closed && apart == m - 1)) continue;  // neighbours share a point
      if (meet(p, q, tol))
        return ProfileFault{"points", q.point,
                            "the chain crosses itself: " + q.name + " meets " + p.name +
                                " (a profile's chain must not cross or touch itself)"};
    }
  return std::nullopt;
}

/// Fillets that do not fit on a segment: the tangent lengths at its two ends exceed its length.
std::optional<ProfileFault> fillet_misfit(const ProfileSpec& spec, const Chain& c) {
  for (int k = 0; k < c.n_segments; ++k) {
    const int a = k, b = (k + 1) % c.n_points;
    const double taken = c.tangent_length[a] + c.tangent_length[b];
    if (taken <= c.length[k] * (1 + 1e-9)) continue;
    const int at = c.tangent_length[b] > 0 ? b : a;
    const int other = at == b ? a : b;
    std::string cause = "the fillet of radius " + number(c.radius[at]) + " at " + point_name(at) +
                        " needs " + number(c.tangent_length[at]) + " of the segment " +
                        point_name(a) + "–" + point_name(b) + " (length " + number(c.length[k]) + ")";
    if (c.tangent_length[other] > 0)
      cause += ", of which the fillet at " + point_name(other) + " takes " +
               number(c.tangent_length[other]);
    cause += ": a fillet's arc must fit between its corner's neighbours (r tan(θ/2) from the "
             "corner, θ its turn)";
    return ProfileFault{"fillet", c.corner(at), cause};
  }
  return std::nullopt;
}

}  // namespace

std::optional<ProfileFault> profile_fault(const ProfileSpec& spec) {
  const int n = static_cast<int>(spec.points.size());
  const int least = spec.closed ? 3 : 2;
  if (n < least)
    return ProfileFault{"points", -1,
                        std::string(spec.closed ? "a closed" : "an open") + " profile needs at least " +
                            std::to_string(least) + " points (got " + std::to_string(n) + ")"};
  double size = 0;
  for (const Vec2& p : spec.points) size = std::max(size, (p - spec.points.front()).norm());
  for (int k = 0; k < (spec.closed ? n : n - 1); ++k) {
    const int next = (k + 1) % n;
    if ((spec.points[next] - spec.points[k]).norm() > 1e-12 * size) continue;
    if (next == 0)
      return ProfileFault{"points", n - 1,
                          "repeats " + point_name(0) + ": a closed profile joins its last point to "
                          "its first itself (leave the repeat out)"};
    return ProfileFault{"points", next, "repeats the point before it, " + point_name(k)};
  }
  const int corners = n_corners(spec);
  if (!spec.fillets.empty() && static_cast<int>(spec.fillets.size()) != corners)
    return ProfileFault{"fillet", -1,
                        "has " + std::to_string(spec.fillets.size()) + " radii for the " +
                            std::to_string(corners) + " corners of the profile (" +
                            (spec.closed ? "every point of a closed profile" : "its interior points") +
                            "): give one radius for all or one per corner"};
  for (int j = 0; j < static_cast<int>(spec.fillets.size()); ++j)
    if (!(spec.fillets[j] >= 0))
      return ProfileFault{"fillet", j, "must be >= 0 (got " + number(spec.fillets[j]) + ")"};
  Chain c = straight_chain(spec);
  for (int i = 0; i < n; ++i) {
    if (c.corner(i) < 0) continue;
    const Vec2& before = c.direction[(i + c.n_segments - 1) % c.n_segments];
    const Vec2& after = c.direction[i % c.n_segments];
    if (before.dot(after) < 0 && std::abs(cross(before, after)) <= 1e-12)
      return ProfileFault{"points", i,
                          "the chain turns back on itself at " + point_name(i) +
                              " (the segments before and after it overlap)"};
  }
  if (auto fault = crossing(spec, c)) return fault;
  add_corners(spec, c);
  return fillet_misfit(spec, c);
}

Profile::Profile(ProfileSpec spec) : spec_(std::move(spec)) {
  if (const auto fault = profile_fault(spec_)) {
    const std::string key = fault->index >= 0 ? fault->key + "[" + std::to_string(fault->index) + "]"
                                              : fault->key;
    HPC_REQUIRE(false, InputError, "profile ", key, ": ", fault->cause);
  }
  Chain c = straight_chain(spec_);
  add_corners(spec_, c);
  const int n = c.n_points, m = c.n_segments;
  for (int k = 0; k < m; ++k) {
    const int a = k, b = (k + 1) % n;
    const bool first = !c.closed && k == 0, last = !c.closed && k == m - 1;
    Piece s;
    s.direction = c.direction[k];
    s.start = spec_.points[a] + c.tangent_length[a] * s.direction;
    s.end = spec_.points[b] - c.tangent_length[b] * s.direction;
    s.length = std::max(0.0, (s.end - s.start).dot(s.direction));
    s.open_before = first;
    s.open_after = last;
    // A segment the fillets at both its ends take whole is left out (its arcs meet); an open
    // profile's end segments stay, for their continuations.
    if (first || last || s.length > 1e-12 * c.length[k]) pieces_.push_back(s);
    if (c.tangent_length[b] > 0 && (c.closed || b < n - 1)) {
      const Vec2& after = c.direction[b % m];
      Piece arc;
      arc.arc = true;
      arc.start = spec_.points[b] - c.tangent_length[b] * s.direction;
      arc.end = spec_.points[b] + c.tangent_length[b] * after;
      arc.radius = c.radius[b];
      arc.turn = c.turn[b];
      // The centre lies on the side the chain turns to, r from the tangent point.
      arc.centre = arc.start + (arc.turn > 0 ? 1.0 : -1.0) * arc.radius * left(s.direction);
      pieces_.push_back(arc);
    }
  }
  // The unit normals at the pieces' ends, summed where two pieces meet.
  auto normal_at = [](const Piece& p, bool at_end) -> Vec2 {
    if (!p.arc) return left(p.direction);
    const Vec2 radial = ((at_end ? p.end : p.start) - p.centre) / p.radius;
    return p.turn > 0 ? Vec2(-radial) : radial;  // the body on the centre's side of a left turn
  };
  const int count = static_cast<int>(pieces_.size());
  for (int j = 0; j < count; ++j) {
    if (!c.closed && j == count - 1) break;
    Piece &p = pieces_[j], &q = pieces_[(j + 1) % count];
    const Vec2 a = normal_at(p, true), b = normal_at(q, false);
    p.end_normals = q.start_normals = a + b;
    p.sharp_end = q.sharp_start = std::abs(cross(a, b)) > 1e-12 || a.dot(b) < 0;
  }
  starts_.assign(1, 0.0);
  for (const Piece& p : pieces_)
    starts_.push_back(starts_.back() + (p.arc ? p.radius * std::abs(p.turn) : p.length));
}

double Profile::arc_length(const Foot& foot) const {
  const Piece& p = pieces_[foot.piece];
  if (!p.arc) return starts_[foot.piece] + (foot.point - p.start).dot(p.direction);
  const Vec2 a0 = p.start - p.centre, v = foot.point - p.centre;
  return starts_[foot.piece] + p.radius * std::abs(std::atan2(cross(a0, v), a0.dot(v)));
}

Profile::Foot Profile::closest(const Vec2& x) const {
  Foot best;
  double best_distance = kInfinity;
  for (int j = 0; j < static_cast<int>(pieces_.size()); ++j) {
    const Piece& p = pieces_[j];
    Foot f;
    f.piece = j;
    if (!p.arc) {
      const double t = (x - p.start).dot(p.direction);
      if (t < 0 && !p.open_before) {
        f.point = p.start;
        f.end = p.sharp_start ? 0 : -1;
      } else if (t > p.length && !p.open_after) {
        f.point = p.end;
        f.end = p.sharp_end ? 1 : -1;
      } else {
        f.point = p.start + t * p.direction;
      }
    } else {
      // Inside the arc's angle (|turn| < π) the foot is the radial projection; else an end.
      const Vec2 v = x - p.centre, a0 = p.start - p.centre;
      const double angle = std::atan2(cross(a0, v), a0.dot(v));
      const bool inside = p.turn > 0 ? angle >= 0 && angle <= p.turn : angle <= 0 && angle >= p.turn;
      if (inside && v.norm() > 0) {
        f.point = p.centre + p.radius * v / v.norm();
      } else {
        const bool at_start = (x - p.start).squaredNorm() <= (x - p.end).squaredNorm();
        f.point = at_start ? p.start : p.end;
        f.end = at_start ? (p.sharp_start ? 0 : -1) : (p.sharp_end ? 1 : -1);
      }
    }
    const double d = (x - f.point).norm();
    if (d < best_distance) {
      best_distance = d;
      best = f;
    }
  }
  return best;
}

}  // namespace hpcontact::geometry
