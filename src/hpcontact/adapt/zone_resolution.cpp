// Zone resolution: corner refinement towards the vertex nearest to each zone end the mesh
// cannot serve, until a node lies near every end.
#include "hpcontact/adapt/zone_resolution.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <sstream>

#include "hpcontact/adapt/geometric_refinement.hpp"
#include "hpcontact/contact/penalty.hpp"
#include "hpcontact/core/error.hpp"

namespace hpcontact::adapt {

namespace {

/// The vertex of body `body`'s contact edges (of every pair it is in) nearest to X, and the
/// length of the contact edge from it towards X (its chord).
struct NearVertex {
  int node_id = -1;
  Vec2 X = Vec2::Zero();
  double edge_length = 0;
};

NearVertex nearest_vertex(const Solved& s, int body, const Vec2& X) {
  const mesh::Mesh& m = s.discretization.bodies[body].mesh;
  NearVertex best;
  double best_distance = std::numeric_limits<double>::infinity();
  for (const auto& pair : s.solution.pairs) {
    if (pair.body != body && pair.other != body) continue;
    for (int e : pair.body == body ? pair.edges : pair.other_edges) {
      const auto& edge = m.edge(e);
      for (const auto& [v, w] : {std::pair(edge.v0, edge.v1), std::pair(edge.v1, edge.v0)}) {
        const Vec2 a = m.node(v), b = m.node(w);
        const double dist = (a - X).norm();
        // the edge from v that points towards X (X projects inside it)
        const double along = (X - a).dot(b - a) / (b - a).squaredNorm();
        if (along < 0 || along > 1) continue;
        if (dist < best_distance) {
          best_distance = dist;
          best = {m.node_id(v), a, (b - a).norm()};
        }
      }
    }
  }
  return best;
}

/// Whether every point of `track`'s body between the parameters a and b of the track is in
/// contact (in a pair on that body), and some point is: one closed zone between them.
bool closed_between(const Solved& s, const BoundaryTrack& track, double a, double b) {
  if (a > b) std::swap(a, b);
  int inside = 0;
  for (size_t k = 0; k < s.solution.contact.size(); ++k) {
    const auto& c = s.solution.contact[k];
    const auto& pair = s.solution.pairs[k];
    const bool own = pair.body == track.body();
    if (!own && pair.other != track.body()) continue;
    const auto& states = own ? c.states : c.other_states;
    const auto& X = own ? c.X : c.other_X;
    for (size_t i = 0; i < states.size() && i < X.size(); ++i) {
      const double t = track.parameter(X[i]);
      if (t <= a || t >= b || (track.point(t) - X[i]).norm() > 1e-6 * (1 + X[i].norm())) continue;
      if (contact::contact_state(states[i]) == contact::ContactState::open) return false;
      ++inside;
    }
  }
  return inside > 0;
}

/// Whether the contact zone end `end` has no node of its own because the node nearest to it
/// serves the zone's other end on its far side (a zone inside the two elements at one node of a
/// coarse mesh, e.g. where a roller touches a block in the input): moved onto one end, the node
/// would leave the other in an element as large as the input's, and the point the bodies touch
/// at without a node. Only for the two ends of one closed zone around the node's middle (the
/// nearer end at least half as far as the other: a zone grown around the node); a node near
/// one end of its zone, or between ends around an opening (a coarse solve's island), serves the
/// nearer, and hp follows the other if the estimated error is there.
bool node_between_ends(const Solved& s, const std::vector<NodeForEnd>& nodes, const ZoneEnd& end) {
  for (const NodeForEnd& n : nodes) {
    if (n.end.body != end.body || n.end.kind != ZoneEnd::Kind::contact) continue;
    if (n.end.X == end.X) return false;  // served
  }
  for (const NodeForEnd& n : nodes) {
    if (n.end.body != end.body || n.end.kind != ZoneEnd::Kind::contact) continue;
    const double here = n.track.parameter(end.X) - n.track.node();
    const double there = n.track.parameter(n.end.X) - n.track.node();
    const bool middle =
        std::min(std::abs(here), std::abs(there)) >= 0.5 * std::max(std::abs(here), std::abs(there));
    if (here * there < 0 && middle && n.track.reaches(n.track.parameter(end.X)) &&
        closed_between(s, n.track, n.track.parameter(end.X), n.track.parameter(n.end.X)))
      return true;
  }
  return false;
}

}  // namespace

bool node_near_enough(const NodeForEnd& n) {
  const double move = std::abs(n.track.parameter(n.end.X) - n.track.node());
  const double room = std::min(n.track.node() - n.track.lower(), n.track.upper() - n.track.node());
  return move <= 0.5 * room;
}

Resolution resolve_zones(const SolvedPtr& s0, int max_rounds, bool stick_slip,
                         const model::ProgressFn& progress) {
  Resolution r;
  r.solved = s0;
  for (int round = 1; round <= max_rounds; ++round) {
    const SolvedPtr s = r.solved;
    const std::vector<ZoneEnd> ends = zone_ends_of(*s, stick_slip);
    if (ends.empty()) break;  // no zone end (e.g. in contact to the boundary's ends): none to resolve
    // The ends to refine towards: those whose node is too far, and the stick–slip points no node
    // serves (the edge they lie in has no movable vertex, e.g. between two corners of the body).
    std::vector<ZoneEnd> unserved;
    const auto nodes = nearest_movable_nodes(*s, ends);
    for (const auto& n : nodes)
      if (!node_near_enough(n)) unserved.push_back(n.end);
    for (const ZoneEnd& end : ends)
      if (end.kind == ZoneEnd::Kind::contact && node_between_ends(*s, nodes, end))
        unserved.push_back(end);
    for (const ZoneEnd& end : ends) {
      if (end.kind != ZoneEnd::Kind::stick_slip) continue;
      const bool served = std::any_of(nodes.begin(), nodes.end(), [&](const NodeForEnd& n) {
        return n.end.body == end.body && n.end.kind == end.kind && n.end.X == end.X;
      });
      if (!served) unserved.push_back(end);
    }
    model::ProblemSpec spec = s->spec;
    const size_t before = r.towards.size();
    std::set<std::pair<int, int>> refined;  // (body, node): once per round
    for (const ZoneEnd& end : unserved) {
      const NearVertex v = nearest_vertex(*s, end.body, end.X);
      if (v.node_id < 0) continue;
      const double d = (v.X - end.X).norm();
      // A point on a vertex that cannot move (a corner of the body) is as resolved as it can be.
      if (d <= 1e-3 * v.edge_length) continue;
      if (!refined.insert({end.body, v.node_id}).second) continue;
      const double factor = std::clamp(d / v.edge_length, 0.15, 0.5);
      try {
        spec = refine_towards_node(spec, end.body, v.node_id, factor);
      } catch (const AdaptError& e) {
        std::ostringstream os;
        os.precision(6);
        os << "no mesh refined towards the boundary point (" << v.X.x() << ", " << v.X.y()
           << ") for the zone end (" << end.X.x() << ", " << end.X.y() << ") can be built ("
           << without_file_name(e.what(), spec.file) << "); left to the later steps' refinement around the zone end";
        r.left_out.push_back(os.str());
        if (progress) progress("hp: " + os.str());
        continue;
      }
      r.towards.push_back(v.X);
    }
    if (r.towards.size() == before) break;
    if (progress) {
      std::ostringstream os;
      os << "hp: a contact zone is narrow against its elements; refined towards "
         << r.towards.size() - before << " boundary node(s) (round " << round << ")";
      progress(os.str());
    }
    r.solved = solve(spec, progress, s.get());
    r.rounds = round;
  }
  return r;
}

}  // namespace hpcontact::adapt
