// Contact pairs from the problem description: edge sets, chained contact points, obstacles.
#include "hpcontact/model/contact_pairs.hpp"

#include <algorithm>

#include "hpcontact/core/error.hpp"
#include "hpcontact/model/axis.hpp"

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

/// An axisymmetric body's contact edges off its axis: an edge along r = 0 is a line of the solid,
/// not a surface (its circle has radius 0), and contact there has no area to carry a pressure.
void require_off_axis(const Body& body, const std::vector<int>& edges, const std::string& key) {
  if (!body.axisymmetric()) return;
  for (int e : edges) {
    const auto& edge = body.mesh.edge(e);
    HPC_REQUIRE(!edge_on_axis(body.mesh, e), InputError, key, ": edge ", body.mesh.node_id(edge.v0),
                "-", body.mesh.node_id(edge.v1), " of body '", body.name, "' lies on the axis r = 0 "
                "of the axisymmetric body: there the solid has no surface (a circle of radius 0), "
                "so contact has no area to act on; leave the axis' edges out of the contact's edge "
                "sets (the axis is held by u_r = 0)");
  }
}

/// The contact points of `edges` in the order of the boundary path(s) they form: edges sorted
/// into chains through shared nodes, the points of each edge running along its chain (zone ends
/// are found between neighbouring points, so the list must follow the boundary whatever the
/// order the edge sets list the edges in). `edges` is reordered the same way, and each point's
/// ContactPoint::edge indexes it.
std::vector<contact::ContactPoint> chained_contact_points(const Body& body, std::vector<int>& edges,
                                                          int quadrature,
                                                          std::vector<contact::ChainEdge>* chain_out = nullptr) {
  const auto chain = contact::chain_edges(body.mesh, edges);
  if (chain_out) *chain_out = chain;
  edges.clear();
  std::vector<contact::ContactPoint> points;
  for (const auto& ce : chain) {
    auto pts = contact::contact_points(body.mesh, body.dofs, body.maps, {ce.edge}, quadrature,
                                       body.out_of_plane());
    for (auto& cp : pts) cp.edge = static_cast<int>(edges.size());
    // Local edge parameters run with the element's edge; put them along the chain.
    if (ce.against) std::reverse(pts.begin(), pts.end());
    points.insert(points.end(), pts.begin(), pts.end());
    edges.push_back(ce.edge);
  }
  return points;
}

/// Two exactly enforced pairs of one body against parallel planes on a shared edge: where both
/// are active their constraints repeat one another (one of them is what the other says, or
/// contradicts it), and the multiplier system is singular.
void refuse_repeated_planes(const ProblemSpec& spec, const std::vector<ContactPair>& pairs) {
  for (size_t i = 0; i < pairs.size(); ++i)
    for (size_t j = i + 1; j < pairs.size(); ++j) {
      const ContactPair& a = pairs[i];
      const ContactPair& b = pairs[j];
      if (a.body != b.body || !a.constraints || !b.constraints) continue;
      const auto& oa = spec.contact[i].obstacle;
      const auto& ob = spec.contact[j].obstacle;
      if (oa.kind != ObstacleKind::plane || ob.kind != ObstacleKind::plane) continue;
      const Vec2 na = Vec2(oa.normal[0], oa.normal[1]).normalized();
      const Vec2 nb = Vec2(ob.normal[0], ob.normal[1]).normalized();
      if (std::abs(na.dot(nb)) < 1 - 1e-12) continue;
      for (int e : a.edges)
        HPC_REQUIRE(std::find(b.edges.begin(), b.edges.end(), e) == b.edges.end(), InputError,
                    spec.contact[j].where.str(), ".edges: shares contact edges with contact[", i,
                    "] (both of body '", spec.contact[j].body, "', enforced exactly, against "
                    "parallel planes): where both touch, their constraints repeat or contradict one "
                    "another; give the two planes separate edge sets, or one plane");
    }
}

/// A body's contact edges as a boundary at the undeformed state.
std::shared_ptr<contact::DeformableBoundary> undeformed_boundary(const Body& body, const std::vector<int>& edges) {
  auto boundary = std::make_shared<contact::DeformableBoundary>(body.mesh, body.dofs, body.maps, edges);
  boundary->set_displacement(Eigen::VectorXd::Zero(body.dofs.n_dofs()));
  return boundary;
}

/// A body's contact edges, undeformed, as a surface (contact::surface_of).
contact::SurfaceFramePtr undeformed_surface(const Body& body, const std::vector<int>& edges,
                                            const Vec2& origin) {
  return contact::surface_of(undeformed_boundary(body, edges), origin);
}

/// The common tangent of the linear theory, the line through reference_point along tangent:
/// where two surfaces touch over a zone small against their radii.
contact::SurfaceFramePtr common_tangent(const ContactPair& pair) {
  return contact::line_frame(pair.reference_point, pair.tangent);
}

/// The body's undeformed point nearest the rigid circle (outside it): the nearest of its contact
/// points and edge ends, then the foot of the centre on its contact edges where that is nearer
/// (inside an edge). Where the surfaces first touch: the common tangent of the linear theory is
/// the circle's tangent there (a block under a roller; a half model or an axisymmetric body
/// touching on its mirror line or axis, where the contact edges end).
Vec2 nearest_to_circle(const Body& body, const ContactPair& pair, const std::vector<contact::ChainEdge>& chain,
                       const Vec2& centre) {
  std::vector<Vec2> candidates;
  for (const auto& cp : pair.points) candidates.push_back(cp.X);
  for (const auto& ce : chain) {
    candidates.push_back(body.mesh.node(ce.start));
    candidates.push_back(body.mesh.node(ce.end));
  }
  Vec2 nearest = candidates.front();
  for (const auto& X : candidates)
    if ((X - centre).norm() < (nearest - centre).norm()) nearest = X;
  if (contact::BoundaryPoint foot; undeformed_boundary(body, pair.edges)->project(centre, foot) &&
                                   (foot.x - centre).norm() < (nearest - centre).norm())
    nearest = foot.x;
  return nearest;
}

/// The frame against a rigid circle: the circle where the body's contact edges are an arc
/// conforming with it (a pin in a rigid hole), angles from the middle of its contact edges;
/// otherwise the circle's tangent at the foot of the body's point nearest it (outside the
/// circle: nearest_to_circle) or of the middle of its contact edges (inside).
contact::SurfaceFramePtr circle_frame(const Body& body, const ContactPair& pair,
                                      const std::vector<contact::ChainEdge>& chain, const Vec2& centre,
                                      double radius, bool inside) {
  const Vec2 middle = pair.points[pair.points.size() / 2].X;
  const auto own = undeformed_surface(body, pair.edges, middle)->circle();
  if (own && contact::conforming(*own, {centre, radius}))
    return contact::arc_frame(centre, radius, middle, inside);
  const Vec2 towards = inside ? middle : nearest_to_circle(body, pair, chain, centre);
  const Vec2 radial = (towards - centre).normalized();
  const Vec2 foot = centre + radius * radial, n = inside ? Vec2(-radial) : radial;
  Vec2 t(n.y(), -n.x());
  if (t.x() < -1e-12 || (std::abs(t.x()) <= 1e-12 && t.y() < 0)) t = -t;
  return contact::line_frame(foot, t, n);
}

/// The frame against another body: its undeformed contact boundary where that is a line, or
/// an arc conforming with the pair's own (a pin in a hole); otherwise the common tangent.
contact::SurfaceFramePtr body_frame(const Body& body, const Body& other, const ContactPair& pair) {
  const auto partner = undeformed_surface(other, pair.other_edges, pair.reference_point);
  if (partner->straight()) return partner;
  const auto own = undeformed_surface(body, pair.edges, pair.reference_point)->circle();
  if (const auto theirs = partner->circle(); theirs && own && contact::conforming(*own, *theirs))
    return partner;
  return common_tangent(pair);
}

}  // namespace

std::vector<ContactPair> make_contact_pairs(const ProblemSpec& spec, const Discretization& d) {
  std::vector<ContactPair> pairs;
  for (const auto& cs : spec.contact) {
    ContactPair pair;
    const Body& body = body_named(d, cs.body, cs.where, &pair.body);
    pair.carrier_choice = cs.carrier_choice;
    pair.edges = edges_named(body, cs.edge_sets, cs.where.str() + ".edges");
    require_off_axis(body, pair.edges, cs.where.str() + ".edges");
    std::vector<contact::ChainEdge> chain;
    pair.points = chained_contact_points(body, pair.edges, cs.quadrature, &chain);
    const bool exact = cs.enforcement == Enforcement::augmented_lagrangian;
    HPC_REQUIRE(cs.penalty > 0 || (exact && cs.penalty == 0), InputError, cs.where.str(),
                ".penalty: must be > 0 (got ", cs.penalty, ")");
    pair.penalty = cs.penalty;
    if (cs.friction.law != "none") {
      const std::string key = cs.friction.where.str();
      HPC_REQUIRE(cs.friction.law == "stick" || cs.friction.law == "coulomb", InputError, key,
                  ".law: unknown friction law '", cs.friction.law, "' (expected none, stick or coulomb)");
      HPC_REQUIRE(cs.friction.mu >= 0, InputError, key, ".mu: the friction coefficient must be >= 0 (got ",
                  cs.friction.mu, ")");
      HPC_REQUIRE(cs.friction.penalty > 0 || (exact && cs.friction.penalty == 0), InputError, key,
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
      pair.frame = contact::line_frame(p, pair.tangent, nrm.normalized());
      pair.force_direction = nrm.normalized();
    } else if (o.kind == ObstacleKind::curve) {
      std::vector<Vec2> points;
      for (const auto& p : o.points) points.emplace_back(p[0], p[1]);
      auto curve = std::make_shared<contact::RigidCurve>(points);
      // Positions along it (half width, pressure curves) are measured from `point` along its
      // tangent at the foot of `point`: the common tangent of the linear theory (the chord of
      // an asymmetric point list is not).
      pair.reference_point = Vec2(o.point[0], o.point[1]);
      const auto& spline = curve->spline();
      pair.tangent = spline.derivative(spline.closest_parameter(pair.reference_point)).normalized();
      pair.obstacle = curve;
      pair.frame = contact::line_frame(pair.reference_point, pair.tangent);
      pair.force_direction = pair.normal();
    } else if (o.kind == ObstacleKind::profile) {
      geometry::ProfileSpec outline;
      for (const auto& p : o.points) outline.points.emplace_back(p[0], p[1]);
      outline.fillets = o.fillets;
      outline.closed = o.closed;
      auto profile = std::make_shared<contact::RigidProfile>(std::move(outline));
      // The normal force along the profile's normal at the point nearest `point`, and positions
      // measured along the profile from there: a line's if it is one segment (a plane), the arc
      // length along the profile else (a groove's bottom and walls).
      pair.reference_point = Vec2(o.point[0], o.point[1]);
      Vec2 nrm;
      profile->gap(pair.reference_point, &nrm, nullptr);
      pair.tangent = Vec2(nrm.y(), -nrm.x());
      pair.obstacle = profile;
      pair.frame = profile->profile().pieces().size() == 1
                       ? contact::line_frame(pair.reference_point, pair.tangent, nrm)
                       : contact::profile_frame(profile, pair.reference_point);
      pair.force_direction = nrm;
    } else if (o.kind == ObstacleKind::circle) {
      pair.obstacle = std::make_shared<contact::RigidCircle>(Vec2(o.center[0], o.center[1]),
                                                             o.radius, o.inside);
      pair.reference_point = Vec2(o.center[0], o.center[1]);
      pair.frame = circle_frame(body, pair, chain, Vec2(o.center[0], o.center[1]), o.radius, o.inside);
      // The normal force along the frame's normal where it is a line (the circle's normal where
      // the surfaces first touch), as against a plane: not the resultant's direction, which an
      // axisymmetric body's meridian tractions tilt (their x-components do not cancel in the
      // section, only round the circle).
      if (pair.frame->straight()) pair.force_direction = pair.frame->normal(pair.reference_point);
    } else {
      const Body& other = body_named(d, o.body, cs.where, &pair.other);
      HPC_REQUIRE(pair.other != pair.body, InputError, cs.where.str(),
                  ".obstacle.body: must be another body than the contact's own");
      HPC_REQUIRE(other.axisymmetric() == body.axisymmetric(), InputError, cs.where.str(),
                  ".obstacle.body: body '", body.name, "' is ",
                  body.axisymmetric() ? "axisymmetric" : "a plane section", " and body '",
                  other.name, "' is ", other.axisymmetric() ? "axisymmetric" : "a plane section",
                  ": bodies in contact must be sections of one kind (material.plane: axisymmetric "
                  "for both, or plane strain / stress for both)");
      pair.other_edges = edges_named(other, o.edge_sets, cs.where.str() + ".obstacle.edges");
      require_off_axis(other, pair.other_edges, cs.where.str() + ".obstacle.edges");
      pair.other_points = chained_contact_points(other, pair.other_edges, cs.quadrature);
      // Both boundaries list their edges in chain order, as the points and multiplier nodes do.
      pair.boundary = std::make_shared<contact::DeformableBoundary>(body.mesh, body.dofs, body.maps,
                                                                    pair.edges);
      pair.other_boundary = std::make_shared<contact::DeformableBoundary>(
          other.mesh, other.dofs, other.maps, pair.other_edges);
      pair.obstacle = pair.other_boundary;
      // Positions along the other body are measured along its tangent at the point nearest
      // reference_point, undeformed (the common tangent of the linear theory: x for a block's
      // top or a cylinder's bottom, the axis direction for a bore), not along x whatever the
      // interface.
      pair.other_boundary->set_displacement(Eigen::VectorXd::Zero(other.dofs.n_dofs()));
      if (contact::BoundaryPoint foot; pair.other_boundary->project(pair.reference_point, foot)) {
        pair.tangent = Vec2(foot.normal.y(), -foot.normal.x());
        if (pair.tangent.x() < -1e-12 || (std::abs(pair.tangent.x()) <= 1e-12 && pair.tangent.y() < 0))
          pair.tangent = -pair.tangent;  // the sense of x (of y for a tangent along y)
      }
      pair.frame = body_frame(body, other, pair);
      if (pair.frame->straight()) pair.force_direction = pair.frame->normal(pair.reference_point);
    }
    if (exact) {
      pair.constraints = make_pair_constraints(cs, body, chain, pair.points, pair.other >= 0);
    }
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
    if (cs.normal_direction) pair.force_direction = Vec2((*cs.normal_direction)[0], (*cs.normal_direction)[1]);
    if (pair.friction.active() && !exact) {
      pair.memory = std::make_shared<ContactPair::FrictionMemory>();
      pair.memory->points.resize(pair.points.size());
      pair.memory->other_points.resize(pair.other_points.size());
    }
    pairs.push_back(std::move(pair));
  }
  refuse_repeated_planes(spec, pairs);
  return pairs;
}

}  // namespace hpcontact::model
