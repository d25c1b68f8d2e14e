// The rp loop: solve -> Γ* -> move nodes (secant-accelerated) -> solve, until they coincide.
#include "hpcontact/adapt/rp.hpp"

#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>

#include "hpcontact/adapt/boundary_track.hpp"
#include "hpcontact/core/error.hpp"

namespace hpcontact::adapt {

RpOptions rp_options(const model::AdaptSpec& adapt) {
  RpOptions o;
  o.tolerance = adapt.tolerance;
  o.max_iterations = adapt.max_iterations;
  o.secant = adapt.secant;
  o.stick_slip = adapt.stick_slip;
  return o;
}

namespace {

/// The zone end (stick–slip point) of `kind` nearest to the node at X among those its track
/// reaches (strictly between its boundary neighbours), or none. The nearest of the body's may
/// lie beyond them — the other end of the zone when the node's own stick–slip point has
/// vanished — and the node cannot go there.
const ZoneEnd* reachable_end(const std::vector<ZoneEnd>& ends, const BoundaryTrack& track,
                             ZoneEnd::Kind kind, const Vec2& X) {
  const ZoneEnd* nearest = nullptr;
  for (const auto& e : ends) {
    if (e.body != track.body() || e.kind != kind || !track.reaches(e.X)) continue;
    if (!nearest || (e.X - X).norm() < (nearest->X - X).norm()) nearest = &e;
  }
  return nearest;
}

}  // namespace

RpOutcome relocate_nodes(const model::ProblemSpec& spec, const RpOptions& options,
                         const model::ProgressFn& progress, const IterationObserver& observe) {
  using Clock = std::chrono::steady_clock;
  auto say = [&](const ProgressEvent& e) {
    if (progress) progress(e);
  };
  RpOutcome out;
  model::ProblemSpec current = spec;
  struct Moved {
    int body, id;
    ZoneEnd::Kind kind;
  };
  std::vector<Moved> moved;  // per zone end (stick–slip point), fixed after the first solve
  try {
    for (int it = 0;; ++it) {
      const auto t0 = Clock::now();
      SolvedPtr s = solve(current, progress, out.last.get());
      RpIteration rec;
      rec.iteration = it;
      std::vector<ZoneEnd> ends;
      try {
        ends = adapt_targets(*s, options.stick_slip);
        if (moved.empty())
          for (const auto& n : nearest_movable_nodes(*s, ends, /*must_reach=*/true))
            moved.push_back({n.track.body(), n.track.node_id(), n.end.kind});
      } catch (const AdaptError& e) {
        // The solve itself succeeded: it is the last good result, recorded without nodes.
        return stopped_after_solve(std::move(out), rec, s, ends,
                                   std::chrono::duration<double>(Clock::now() - t0).count(),
                                   observe, e.what());
      }
      rec.solve = figures_of(*s, ends, std::chrono::duration<double>(Clock::now() - t0).count());
      for (const auto& c : s->solution.contact) rec.zone_ends_found += static_cast<int>(c.gamma_star.size());
      // Each node follows the zone end (stick–slip point) of its body nearest to it (ends a
      // coarse solve adds elsewhere, e.g. an opening at a symmetry line, are left alone); a
      // node whose stick–slip point is gone stays where it is.
      std::vector<Vec2> target;
      for (const auto& [body, id, kind] : moved) {
        const Vec2 X = node_position(current.bodies[body], id);
        const ZoneEnd* nearest = reachable_end(ends, BoundaryTrack(current, body, id), kind, X);
        const Vec2 to = nearest ? nearest->X : X;
        target.push_back(to);
        const double size = s->discretization.bodies[body].mesh.size();
        rec.distance = std::max(rec.distance, (to - X).norm() / size);
        rec.nodes.push_back({body, id, X, to, kind, nearest != nullptr});
      }
      {
        std::ostringstream os;
        os.precision(10);
        for (const auto& n : rec.nodes) {
          os << " node " << n.node_id << " at (" << n.position.x() << ", " << n.position.y()
             << "), " << kind_name(n.kind);
          if (n.has_target)
            os << " at (" << n.gamma_star.x() << ", " << n.gamma_star.y() << ");";
          else
            os << " none in reach, stays;";
        }
        os.precision(3);
        os << " distance " << rec.distance << " of the body size";
        const std::string detail = os.str().substr(os.str().empty() || os.str()[0] != ' ' ? 0 : 1);
        AdaptStepProgress p{"rp", it, options.max_iterations, rec.solve.dofs, rec.distance,
                            options.tolerance, detail};
        say({"rp iteration " + std::to_string(it) + ": " + detail, p});
      }
      out.history.push_back(rec);
      out.last = s;
      if (observe) observe(rec, *s);
      if (rec.distance <= options.tolerance) {
        out.converged = true;
        return out;
      }
      if (it >= options.max_iterations) {
        std::ostringstream os;
        os << spec.file << ": rp: the nodes did not reach the zone ends in "
           << options.max_iterations << " relocations (distance " << rec.distance
           << " of the body size, tolerance " << options.tolerance
           << "); raise adapt.max_iterations or adapt.tolerance";
        out.message = os.str();
        return out;
      }
      // Move each node: secant step on r(s) = Γ*(s) − s along its track, or onto Γ*.
      model::ProblemSpec next = current;
      for (size_t k = 0; k < moved.size(); ++k) {
        const BoundaryTrack track(next, moved[k].body, moved[k].id);
        const double phi = track.node(), psi = track.parameter(target[k]);
        // a neighbour moved before it may now lie between the node and its target (a stick–slip
        // point inside the zone, its node beyond the zone end's): it stays this time
        if (!track.reaches(psi)) continue;
        double s_new = psi;
        if (options.secant && out.history.size() >= 2) {
          const auto& prev = out.history[out.history.size() - 2].nodes[k];
          const double phi0 = track.parameter(prev.position), psi0 = track.parameter(prev.gamma_star);
          const double r = psi - phi, r0 = psi0 - phi0;
          if (std::abs(r - r0) > 1e-3 * std::abs(r) && std::abs(phi - phi0) > 0) {
            const double secant = phi - r * (phi - phi0) / (r - r0);
            const double span = track.upper() - track.lower();
            if (secant > track.lower() + 0.01 * span && secant < track.upper() - 0.01 * span)
              s_new = secant;
          }
        }
        next = with_node_moved(next, track, s_new);
      }
      current = std::move(next);
    }
  } catch (const Error& e) {
    out.message = e.what();
  }
  return out;
}

}  // namespace hpcontact::adapt
