// Solving once and locating the zone ends a node can serve.
#include "hpcontact/adapt/solved.hpp"

#include <algorithm>

#include <limits>
#include <optional>
#include <set>
#include <string>

#include "hpcontact/adapt/transfer.hpp"
#include "hpcontact/core/error.hpp"
#include "hpcontact/model/rigid_motion.hpp"
#include "hpcontact/post/fields.hpp"

namespace hpcontact::adapt {

SolvedPtr solve(const model::ProblemSpec& spec, const model::ProgressFn& progress,
                const Solved* previous) {
  auto s = std::make_shared<Solved>();
  s->spec = spec;
  s->discretization = model::discretize(s->spec);
  model::require_held(s->spec, s->discretization);
  model::StartState start;
  if (previous)
    start = carry_over(previous->discretization, previous->solution, s->discretization,
                       model::make_contact_pairs(s->spec, s->discretization));
  s->solution = model::solve_contact(s->spec, s->discretization, progress, start);
  HPC_REQUIRE(s->solution.converged, NumericalError, spec.file, ": the solver stopped: ",
              s->solution.message);
  return s;
}

std::vector<ZoneEnd> zone_ends_of(const Solved& s, bool stick_slip) {
  std::vector<ZoneEnd> ends;
  for (size_t k = 0; k < s.solution.contact.size(); ++k) {
    const auto& c = s.solution.contact[k];
    const auto& pair = s.solution.pairs[k];
    for (int i : c.outer_ends) ends.push_back({pair.body, c.gamma_star[i]});
    // Against another body, the zone ends on its boundary too (seed §5.2.3: both bodies).
    for (int i : c.other_zone_ends.outer) ends.push_back({pair.other, c.other_zone_ends.X[i]});
    if (!stick_slip) continue;
    for (const Vec2& X : c.stick_slip.X) ends.push_back({pair.body, X, ZoneEnd::Kind::stick_slip});
    for (const Vec2& X : c.other_stick_slip.X)
      ends.push_back({pair.other, X, ZoneEnd::Kind::stick_slip});
  }
  return ends;
}

std::vector<ZoneEnd> memory_points_of(const Solved& s) {
  std::vector<ZoneEnd> points;
  for (size_t k = 0; k < s.solution.contact.size(); ++k) {
    const auto& pair = s.solution.pairs[k];
    for (const Vec2& X : s.solution.contact[k].memory_points)
      points.push_back({pair.body, X, ZoneEnd::Kind::stick_slip});
    for (const Vec2& X : s.solution.contact[k].other_memory_points)
      points.push_back({pair.other, X, ZoneEnd::Kind::stick_slip});
  }
  return points;
}

std::vector<ZoneEnd> singular_ends_of(const Solved& s) {
  std::vector<ZoneEnd> ends;
  for (size_t k = 0; k < s.solution.contact.size(); ++k) {
    const auto& pair = s.solution.pairs[k];
    for (const auto& p : s.solution.contact[k].singular_points) {
      ends.push_back({p.on_other ? pair.other : pair.body, p.X, ZoneEnd::Kind::singular, p.excluded});
      if (p.on_other) ends.push_back({pair.body, p.foot, ZoneEnd::Kind::singular, p.excluded});
    }
  }
  return ends;
}

std::vector<ZoneEnd> without_ends_at_singular_points(std::vector<ZoneEnd> ends,
                                                     const std::vector<ZoneEnd>& singular) {
  std::erase_if(ends, [&](const ZoneEnd& e) {
    return e.kind == ZoneEnd::Kind::contact &&
           std::any_of(singular.begin(), singular.end(), [&](const ZoneEnd& p) {
             return p.kind == ZoneEnd::Kind::singular && p.body == e.body && (p.X - e.X).norm() <= p.radius;
           });
  });
  return ends;
}

std::vector<ZoneEnd> adapt_targets(const Solved& s, bool stick_slip, bool singular) {
  std::vector<ZoneEnd> ends = zone_ends_of(s, stick_slip);
  if (singular) {
    const std::vector<ZoneEnd> points = singular_ends_of(s);
    ends = without_ends_at_singular_points(std::move(ends), points);
    ends.insert(ends.end(), points.begin(), points.end());
  }
  HPC_REQUIRE(!ends.empty(), AdaptError, s.spec.file, ": no end of a contact zone found (no "
              "contact, or every contact point is closed)",
              stick_slip ? " and no stick–slip point (no friction, or all points stick or all slip)" : "",
              singular ? " and no singular point (a zone closed up to an end or a corner of its contact edges)" : "",
              "; there is no Γ* to adapt the mesh to");
  return ends;
}

std::vector<ZoneEnd> outer_zone_ends(const Solved& s) { return adapt_targets(s, false); }

const char* kind_name(ZoneEnd::Kind kind) {
  switch (kind) {
    case ZoneEnd::Kind::contact: return "zone end";
    case ZoneEnd::Kind::stick_slip: return "stick-slip point";
    case ZoneEnd::Kind::singular: return "singular point";
  }
  return "zone end";
}

const ZoneEnd* nearest_end(const std::vector<ZoneEnd>& ends, int body, ZoneEnd::Kind kind,
                           const Vec2& X) {
  const ZoneEnd* nearest = nullptr;
  for (const auto& e : ends)
    if (e.body == body && e.kind == kind && (!nearest || (e.X - X).norm() < (nearest->X - X).norm()))
      nearest = &e;
  return nearest;
}

SolveFigures figures_of(const Solved& s, const std::vector<ZoneEnd>& ends, double seconds) {
  SolveFigures f;
  f.dofs = s.discretization.n_free;
  for (const auto& b : s.discretization.bodies) {
    f.elements += b.mesh.n_quads();
    for (int q = 0; q < b.mesh.n_quads(); ++q) {
      const int p = b.dofs.element(q).max_degree();
      f.min_degree = f.min_degree == 0 ? p : std::min(f.min_degree, p);
      f.max_degree = std::max(f.max_degree, p);
    }
  }
  f.strain_energy = post::strain_energy(s.discretization, s.solution.u);
  f.newton_iterations = s.solution.newton_iterations;
  f.seconds = seconds;
  for (const auto& e : ends) f.gamma_star.push_back(e.X);
  return f;
}

std::vector<NodeForEnd> nearest_movable_nodes(const Solved& s, const std::vector<ZoneEnd>& ends,
                                              bool must_reach) {
  struct Choice {
    NodeForEnd node;
    double distance;
  };
  std::vector<Choice> chosen;
  // Zone ends choose first; a stick–slip point takes the nearest node no zone end has (on a
  // coarse mesh both may be nearest to one node, and the pressure's end matters more), and one
  // without a free node is left alone. With must_reach a node serves an end only if its track
  // reaches it; an end that movable nodes exist for but none reaches (it lies within 1 % of a
  // node that cannot move, e.g. where the other body's corner stands on this one) is left
  // alone too.
  std::vector<const ZoneEnd*> order;
  for (const auto kind : {ZoneEnd::Kind::contact, ZoneEnd::Kind::stick_slip})
    for (const ZoneEnd& end : ends)
      if (end.kind == kind) order.push_back(&end);
  std::set<std::pair<int, int>> zone_end_nodes;  // (body, node id)
  for (const ZoneEnd* end_ptr : order) {
    const ZoneEnd& end = *end_ptr;
    const bool stick_slip = end.kind == ZoneEnd::Kind::stick_slip;
    const model::Body* body = &s.discretization.bodies[end.body];
    double best = std::numeric_limits<double>::infinity();
    std::optional<BoundaryTrack> choice;
    std::string reasons;
    std::set<int> refused;  // node ids already explained
    bool movable = false;   // some node could move, though none reaches the end
    for (size_t k = 0; k < s.solution.pairs.size(); ++k) {
      const auto& pair = s.solution.pairs[k];
      if (pair.body != end.body && pair.other != end.body) continue;
      for (int e : pair.body == end.body ? pair.edges : pair.other_edges)
        for (int v : {body->mesh.edge(e).v0, body->mesh.edge(e).v1}) {
          const double dist = (body->mesh.node(v) - end.X).norm();
          if (dist >= best) continue;
          if (stick_slip && zone_end_nodes.count({end.body, body->mesh.node_id(v)})) continue;
          try {
            // built first: a node that refuses must not empty the choice made so far
            BoundaryTrack track(s.spec, end.body, body->mesh.node_id(v));
            movable = true;
            if (must_reach && !track.reaches(end.X)) continue;
            choice.emplace(std::move(track));
            best = dist;
          } catch (const AdaptError& err) {
            if (refused.insert(v).second) reasons += std::string("\n  ") + err.what();
          }
        }
    }
    if (!choice && (stick_slip || movable)) continue;
    HPC_REQUIRE(choice, AdaptError, s.spec.file, ": no boundary node of body '", body->name,
                "' can move onto the zone end at (", end.X.x(), ", ", end.X.y(), "):", reasons);
    // Two ends nearest to one node (a coarse solve whose zone starts open at a symmetry line as
    // well as ending): the node serves the nearer one; the other is left alone.
    bool taken = false;
    for (auto& c : chosen)
      if (c.node.track.body() == choice->body() && c.node.track.node_id() == choice->node_id()) {
        taken = true;
        if (best < c.distance) c = {{*choice, end}, best};
      }
    if (!taken) chosen.push_back({{*choice, end}, best});
    if (!stick_slip) zone_end_nodes.insert({choice->body(), choice->node_id()});
  }
  std::vector<NodeForEnd> nodes;
  for (const auto& c : chosen) nodes.push_back(c.node);
  return nodes;
}

}  // namespace hpcontact::adapt
