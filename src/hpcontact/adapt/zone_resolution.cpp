// Zone resolution: corner refinement towards the vertex nearest to each zone end the mesh
// cannot serve, until a node lies near every end.
#include "hpcontact/adapt/zone_resolution.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <sstream>

#include "hpcontact/adapt/geometric_refinement.hpp"

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
      spec = refine_towards_node(spec, end.body, v.node_id, factor);
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
