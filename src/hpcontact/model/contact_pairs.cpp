// Contact pairs from the problem description: edge sets, chained contact points, obstacles.
#include "hpcontact/model/contact_pairs.hpp"

#include <algorithm>
#include <map>

#include "hpcontact/core/error.hpp"

namespace hpcontact::model {

const Body& body_named(const Discretization& d, const std::string& name, const SourceRef& where,
                       int* index) {
  for (size_t b = 0; b < d.bodies.size(); ++b)
    if (d.bodies[b].name == name) {
      *index = static_cast<int>(b);
      return d.bodies[b];
    }
  throw InputError(where.str() + ".body: no body named '" + name + "'");
}

namespace {

/// The mesh edges of a body's edge sets, in order; InputError naming `key` for an unknown set.
std::vector<int> edges_named(const Body& body, const std::vector<std::string>& names,
                             const std::string& key) {
  std::vector<int> edges;
  for (const auto& name : names) {
    auto it = body.edge_sets.find(name);
    HPC_REQUIRE(it != body.edge_sets.end(), InputError, key, ": no edge set '", name, "' in body '",
                body.name, "'");
    edges.insert(edges.end(), it->second.begin(), it->second.end());
  }
  return edges;
}

/// The contact points of `edges` in the order of the boundary path(s) they form: edges sorted
/// into chains through shared nodes, the points of each edge running along its chain (zone ends
/// are found between neighbouring points, so the list must follow the boundary whatever the
/// order the edge sets list the edges in). `edges` is reordered the same way.
std::vector<contact::ContactPoint> chained_contact_points(const Body& body, std::vector<int>& edges,
                                                          int quadrature) {
  const auto& m = body.mesh;
  std::map<int, std::vector<int>> at_node;  // node -> positions in `edges`
  for (size_t k = 0; k < edges.size(); ++k)
    for (int v : {m.edge(edges[k]).v0, m.edge(edges[k]).v1}) at_node[v].push_back(static_cast<int>(k));
  std::vector<bool> used(edges.size(), false);
  std::vector<int> ordered;
  std::vector<bool> reversed;  // the edge's own direction v0 -> v1 runs against the chain
  auto walk = [&](int k, int from) {
    while (k >= 0 && !used[k]) {
      used[k] = true;
      const auto& e = m.edge(edges[k]);
      ordered.push_back(edges[k]);
      reversed.push_back(e.v0 != from);
      const int to = e.v0 == from ? e.v1 : e.v0;
      int next = -1;
      for (int j : at_node[to])
        if (!used[j]) next = j;
      k = next;
      from = to;
    }
  };
  // Chains start at a node with one edge; what is left are closed loops.
  for (const auto& [v, ks] : at_node)
    if (ks.size() == 1 && !used[ks[0]]) walk(ks[0], v);
  for (size_t k = 0; k < edges.size(); ++k)
    if (!used[k]) walk(static_cast<int>(k), m.edge(edges[k]).v0);
  edges = ordered;
  std::vector<contact::ContactPoint> points;
  for (size_t k = 0; k < edges.size(); ++k) {
    auto pts = contact::contact_points(m, body.dofs, body.maps, {edges[k]}, quadrature, body.thickness);
    // Local edge parameters run with the element's edge; put them along the chain.
    const auto& e = m.edge(edges[k]);
    const int q = e.quads[0], le = e.local_edge[0];
    const int local_start = m.quad(q)[mesh::kEdgeVertices[le][0]];
    const int chain_start = reversed[k] ? e.v1 : e.v0;
    if (local_start != chain_start) std::reverse(pts.begin(), pts.end());
    points.insert(points.end(), pts.begin(), pts.end());
  }
  return points;
}

}  // namespace

std::vector<ContactPair> make_contact_pairs(const ProblemSpec& spec, const Discretization& d) {
  std::vector<ContactPair> pairs;
  for (const auto& cs : spec.contact) {
    ContactPair pair;
    const Body& body = body_named(d, cs.body, cs.where, &pair.body);
    pair.edges = edges_named(body, cs.edge_sets, cs.where.str() + ".edges");
    HPC_REQUIRE(cs.penalty > 0, InputError, cs.where.str(), ".penalty: must be > 0 (got ",
                cs.penalty, ")");
    pair.penalty = cs.penalty;
    if (cs.friction.law != "none") {
      const std::string key = cs.friction.where.str();
      HPC_REQUIRE(cs.friction.law == "stick" || cs.friction.law == "coulomb", InputError, key,
                  ".law: unknown friction law '", cs.friction.law, "' (expected none, stick or coulomb)");
      HPC_REQUIRE(cs.friction.mu >= 0, InputError, key, ".mu: the friction coefficient must be >= 0 (got ",
                  cs.friction.mu, ")");
      HPC_REQUIRE(cs.friction.penalty > 0, InputError, key,
                  ".penalty: the tangential penalty must be > 0 (got ", cs.friction.penalty, ")");
      pair.friction.kind = cs.friction.law == "stick" ? contact::FrictionLaw::Kind::stick
                                                      : contact::FrictionLaw::Kind::coulomb;
      pair.friction.mu = cs.friction.mu;
      pair.friction.eps_t = cs.friction.penalty;
    }
    const auto& o = cs.obstacle;
    if (o.kind == ObstacleKind::plane) {
      const Vec2 p(o.point[0], o.point[1]), nrm(o.normal[0], o.normal[1]);
      HPC_REQUIRE(nrm.norm() > 0, InputError, cs.where.str(), ".obstacle.normal: must not be zero");
      pair.obstacle = std::make_shared<contact::RigidPlane>(p, nrm);
      pair.reference_point = p;
      pair.tangent = Vec2(nrm.y(), -nrm.x()).normalized();
    } else if (o.kind == ObstacleKind::curve) {
      std::vector<Vec2> points;
      for (const auto& p : o.points) points.emplace_back(p[0], p[1]);
      auto curve = std::make_shared<contact::RigidCurve>(points);
      // Positions along it (half width, pressure curves) are measured from `point` along its
      // chord (along its first tangent if it closes on itself).
      const Vec2 chord = points.back() - points.front();
      pair.reference_point = Vec2(o.point[0], o.point[1]);
      pair.tangent = chord.norm() > 1e-9 * curve->spline().end() ? Vec2(chord.normalized())
                                                                  : Vec2(curve->spline().derivative(0).normalized());
      pair.obstacle = curve;
    } else if (o.kind == ObstacleKind::circle) {
      pair.obstacle = std::make_shared<contact::RigidCircle>(Vec2(o.center[0], o.center[1]),
                                                             o.radius, o.inside);
      pair.reference_point = Vec2(o.center[0], o.center[1]);
    } else {
      const Body& other = body_named(d, o.body, cs.where, &pair.other);
      HPC_REQUIRE(pair.other != pair.body, InputError, cs.where.str(),
                  ".obstacle.body: must be another body than the contact's own");
      const auto other_edges = edges_named(other, o.edge_sets, cs.where.str() + ".obstacle.edges");
      pair.boundary = std::make_shared<contact::DeformableBoundary>(body.mesh, body.dofs, body.maps,
                                                                    pair.edges);
      pair.other_boundary = std::make_shared<contact::DeformableBoundary>(
          other.mesh, other.dofs, other.maps, other_edges);
      pair.obstacle = pair.other_boundary;
      pair.other_edges = other_edges;
      pair.other_points = chained_contact_points(other, pair.other_edges, cs.quadrature);
    }
    pair.points = chained_contact_points(body, pair.edges, cs.quadrature);
    // An obstacle the body starts deep inside (more than 1 % of its size) is a wrong normal or
    // position, not a contact problem: say so before solving.
    if (pair.other < 0) {
      const double size = body.mesh.size();
      const contact::ContactPoint* deepest = nullptr;
      double g_min = 0;
      for (const auto& cp : pair.points)
        if (const double g = pair.obstacle->gap(cp.X, nullptr, nullptr); g < g_min) {
          g_min = g;
          deepest = &cp;
        }
      HPC_REQUIRE(g_min >= -0.01 * size, InputError, cs.where.str(), ".obstacle: the undeformed body ",
                  "lies ", -g_min, " inside ", pair.obstacle->describe(), " at (", deepest->X.x(),
                  ", ", deepest->X.y(), "), more than 1 % of its size (", size,
                  "): is the obstacle's position or normal (pointing towards the body) wrong?");
    }
    if (pair.other < 0 && (o.displacement[0] != 0 || o.displacement[1] != 0)) {
      pair.moving = std::make_shared<contact::DisplacedObstacle>(
          pair.obstacle, Vec2(o.displacement[0], o.displacement[1]));
      pair.moving->set_load_factor(0);
      pair.obstacle = pair.moving;
    }
    if (pair.friction.active()) {
      pair.memory = std::make_shared<ContactPair::FrictionMemory>();
      pair.memory->points.resize(pair.points.size());
      pair.memory->other_points.resize(pair.other_points.size());
    }
    pairs.push_back(std::move(pair));
  }
  return pairs;
}

}  // namespace hpcontact::model
