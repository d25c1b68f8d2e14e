// Boundary tracks and node moves: the geometric half of rp relocation.
#include "hpcontact/adapt/boundary_track.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "hpcontact/core/error.hpp"
#include "hpcontact/model/discretization.hpp"

namespace hpcontact::adapt {

namespace {

using EdgeKey = std::pair<int, int>;
EdgeKey key(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

/// How many elements share each edge (user node ids); boundary edges have one.
std::map<EdgeKey, int> edge_counts(const model::BodySpec& b) {
  std::map<EdgeKey, int> count;
  for (const auto& e : b.elements)
    for (int k = 0; k < 4; ++k) ++count[key(e[k], e[(k + 1) % 4])];
  return count;
}

const model::CurveSpec* curve_of(const model::BodySpec& b, int u, int v) {
  for (const auto& c : b.curves)
    if (key(c.node_a, c.node_b) == key(u, v)) return &c;
  return nullptr;
}

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

}  // namespace

Vec2 node_position(const model::BodySpec& b, int id) {
  const auto it = std::find(b.node_ids.begin(), b.node_ids.end(), id);
  HPC_ASSERT(it != b.node_ids.end(), "node ", id);
  const auto& p = b.nodes[it - b.node_ids.begin()];
  return Vec2(p[0], p[1]);
}

BoundaryTrack::BoundaryTrack(const model::ProblemSpec& spec, int body, int node_id)
    : body_(body), node_id_(node_id) {
  const model::BodySpec& b = spec.bodies[body];
  const std::string who = "rp: node " + std::to_string(node_id) + " of body '" + b.name + "'";
  std::vector<int> neighbours;
  for (const auto& [edge, n] : edge_counts(b)) {
    if (n != 1) continue;
    if (edge.first == node_id) neighbours.push_back(edge.second);
    if (edge.second == node_id) neighbours.push_back(edge.first);
  }
  HPC_REQUIRE(neighbours.size() == 2, AdaptError, who, " is not a node of the boundary with two "
              "boundary edges (it has ", neighbours.size(), "); it cannot slide along the boundary");
  // An edge set that holds one of the node's boundary edges and not the other ends at the node
  // (the contact edges, a loaded or held part): moving the node would change what it covers.
  for (const auto& set : b.edge_sets) {
    auto holds = [&](int other) {
      return std::any_of(set.edges.begin(), set.edges.end(), [&](const auto& e) {
        return key(e[0], e[1]) == key(node_id, other);
      });
    };
    HPC_REQUIRE(holds(neighbours[0]) == holds(neighbours[1]), AdaptError, who, " ends edge set '",
                set.name, "' (between nodes ", neighbours[0], " and ", neighbours[1],
                "); moving it would change what the set covers");
  }
  const Vec2 X = node_position(b, node_id);
  const Vec2 A = node_position(b, neighbours[0]), B = node_position(b, neighbours[1]);
  const model::CurveSpec* ca = curve_of(b, node_id, neighbours[0]);
  const model::CurveSpec* cb = curve_of(b, node_id, neighbours[1]);
  for (const auto* c : {ca, cb})
    HPC_REQUIRE(!c || c->kind == model::CurveKind::arc, AdaptError, who,
                " lies on a parametric curve (", c->where.str(),
                "); rp moves nodes along circles and straight lines only");
  auto corner = [&](const std::string& why) {
    return detail::concat(who, " sits where the boundary changes from one curve to another (",
                          why, " between nodes ", neighbours[0], ", ", node_id, " and ",
                          neighbours[1], "); moving it would change the geometry");
  };
  if (ca && cb) {
    const Vec2 c0(ca->center[0], ca->center[1]), c1(cb->center[0], cb->center[1]);
    const double r = ca->radius;
    HPC_REQUIRE((c0 - c1).norm() <= 1e-9 * r && std::abs(ca->radius - cb->radius) <= 1e-9 * r,
                AdaptError, corner("two different circles"));
    circle_ = true;
    center_ = c0;
    radius_ = r;
    axis_ = (X - c0).normalized();
  } else {
    HPC_REQUIRE(!ca && !cb, AdaptError, corner("a circle and a straight edge"));
    const Vec2 da = X - A, db = B - X;
    HPC_REQUIRE(std::abs(cross(da, db)) <= 1e-9 * da.norm() * db.norm() && da.dot(db) > 0,
                AdaptError, corner("two straight edges at an angle"));
    center_ = X;
    axis_ = (B - A).normalized();
  }
  s_node_ = parameter(X);
  s_lower_ = parameter(A);
  s_upper_ = parameter(B);
  if (s_lower_ > s_upper_) std::swap(s_lower_, s_upper_);
}

double BoundaryTrack::parameter(const Vec2& X) const {
  if (!circle_) return (X - center_).dot(axis_);
  const Vec2 r = X - center_;
  return std::atan2(cross(axis_, r), axis_.dot(r));
}

Vec2 BoundaryTrack::point(double s) const {
  if (!circle_) return center_ + s * axis_;
  const Vec2 normal(-axis_.y(), axis_.x());
  return center_ + radius_ * (std::cos(s) * axis_ + std::sin(s) * normal);
}

std::string BoundaryTrack::describe() const {
  std::ostringstream os;
  if (circle_)
    os << "circle (centre (" << center_.x() << ", " << center_.y() << "), radius " << radius_ << ")";
  else
    os << "straight boundary";
  return os.str();
}

model::ProblemSpec with_node_moved(const model::ProblemSpec& spec, const BoundaryTrack& track,
                                   double s) {
  const model::BodySpec& b = spec.bodies[track.body()];
  const int id = track.node_id();
  const Vec2 target = track.point(s);
  HPC_REQUIRE(track.reaches(s), AdaptError, spec.file, ": rp: node ", id,
              " of body '", b.name, "' cannot move to (", target.x(), ", ", target.y(),
              "): that point is not between its two boundary neighbours on its ", track.describe());

  const auto counts = edge_counts(b);
  std::set<int> boundary;
  for (const auto& [edge, c] : counts)
    if (c == 1) boundary.insert({edge.first, edge.second});
  std::vector<int> interior;  // nodes joined to the moved one by an element edge, off the boundary
  for (const auto& [edge, c] : counts) {
    const int other = edge.first == id ? edge.second : edge.second == id ? edge.first : -1;
    if (other >= 0 && !boundary.count(other)) interior.push_back(other);
  }

  const Vec2 shift = target - node_position(b, id);
  std::string last_error;
  for (const double follow : {0.0, 0.5, 1.0}) {
    if (follow > 0 && interior.empty()) break;
    model::ProblemSpec moved = spec;
    model::BodySpec& mb = moved.bodies[track.body()];
    for (size_t i = 0; i < mb.node_ids.size(); ++i) {
      const int n = mb.node_ids[i];
      const double w = n == id ? 1.0
                       : std::count(interior.begin(), interior.end(), n) ? follow
                                                                          : 0.0;
      mb.nodes[i][0] += w * shift.x();
      mb.nodes[i][1] += w * shift.y();
      if (n == id) mb.nodes[i] = {target.x(), target.y()};  // exactly on the curve
    }
    try {
      (void)model::discretize(moved);  // checks det J of every element
      return moved;
    } catch (const MeshError& e) {
      last_error = e.what();
    }
  }
  throw AdaptError(detail::concat(spec.file, ": rp: moving node ", id, " of body '", b.name, "' to (",
                                  target.x(), ", ", target.y(), ") would invert an element",
                                  interior.empty() ? " (the node has no interior neighbours that "
                                                     "could follow: one element across the body)"
                                                   : " even with its interior neighbours following",
                                  ": ", last_error));
}

}  // namespace hpcontact::adapt
