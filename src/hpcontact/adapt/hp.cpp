// The hp loop: solve -> Γ* -> centre node at Γ* -> k geometric layers with rising degree -> solve.
#include "hpcontact/adapt/hp.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <set>
#include <sstream>

#include "hpcontact/adapt/boundary_track.hpp"
#include "hpcontact/adapt/facing_degrees.hpp"
#include "hpcontact/adapt/geometric_refinement.hpp"
#include "hpcontact/adapt/zone_resolution.hpp"
#include "hpcontact/core/error.hpp"

namespace hpcontact::adapt {

namespace {

struct Centre {
  int body = 0, node = 0;
  Vec2 at = Vec2::Zero();  ///< where the node is put on the input mesh
  ZoneEnd::Kind kind = ZoneEnd::Kind::contact;  ///< what it follows
  bool fixed = false;  ///< a node of the input mesh at a singular point: it stays where it is
};

/// Centres at the singular points among `ends`: the mesh node there (it stays: a corner, the
/// end of an edge set), or for the foot of the other body's corner the nearest movable node
/// (moved onto it, as onto Γ*); none on a node that is a centre already.
void add_singular_centres(const Solved& s, const std::vector<ZoneEnd>& ends, std::vector<Centre>& centres) {
  for (const ZoneEnd& e : ends) {
    if (e.kind != ZoneEnd::Kind::singular) continue;
    const auto& mesh = s.discretization.bodies[e.body].mesh;
    Centre c{e.body, -1, e.X, ZoneEnd::Kind::singular};
    for (int v = 0; v < mesh.n_nodes(); ++v)
      if ((mesh.node(v) - e.X).norm() <= 1e-9 * mesh.size()) {
        c.node = mesh.node_id(v);
        c.fixed = true;
      }
    if (c.node < 0) {
      ZoneEnd as_end = e;
      as_end.kind = ZoneEnd::Kind::contact;
      try {
        const auto nodes = nearest_movable_nodes(s, {as_end});
        if (nodes.empty()) continue;
        c.node = nodes[0].track.node_id();
      } catch (const AdaptError&) {
        continue;  // no node can move there: the point is left to the other body's grading
      }
    }
    const bool taken = std::any_of(centres.begin(), centres.end(), [&](const Centre& o) {
      return o.body == c.body && o.node == c.node;
    });
    if (!taken) centres.push_back(c);
  }
}

/// A step's mesh, and what of it could not be built: a centre that cannot move onto its point
/// (stays where it is, refined around as it is) or whose next layer would make an invalid
/// element (keeps the layers it has) — one rule for every centre, so that no such failure of the
/// refinement ends the loop; what was left out is said (`left_out`, one entry per centre).
struct StepMesh {
  model::ProblemSpec spec;
  std::vector<std::string> left_out;
  std::vector<bool> complete;  ///< per centre: moved and refined `steps` times
};

std::string point_text(const Vec2& X) {
  std::ostringstream os;
  os.precision(6);
  os << "(" << X.x() << ", " << X.y() << ")";
  return os.str();
}

/// The node of `s`'s body `body` within `within` of X that cannot move (an end of an edge set, a
/// corner, a node on a mirror), or -1.
int fixed_node_at(const Solved& s, int body, const Vec2& X, double within) {
  const auto& mesh = s.discretization.bodies[body].mesh;
  for (int v = 0; v < mesh.n_nodes(); ++v) {
    if ((mesh.node(v) - X).norm() > within) continue;
    try {
      (void)BoundaryTrack(s.spec, body, mesh.node_id(v));
    } catch (const AdaptError&) {
      return mesh.node_id(v);
    }
  }
  return -1;
}

/// The centre for the point `n.end`: its nearest movable node, or — where the point lies on a
/// node that cannot move (a stick–slip point at the mirror; within 1e-3 of the movable node's
/// track) — that node, refined around where it is; none twice on one node.
void add_centre(const Solved& s, const NodeForEnd& n, std::vector<Centre>& centres) {
  Centre c{n.track.body(), n.track.node_id(), n.end.X, n.end.kind};
  const double track = (n.track.point(n.track.upper()) - n.track.point(n.track.lower())).norm();
  if (!n.track.reaches(n.end.X))
    if (const int fixed = fixed_node_at(s, c.body, n.end.X, 1e-3 * track); fixed >= 0) {
      c.node = fixed;
      c.fixed = true;
    }
  const bool taken = std::any_of(centres.begin(), centres.end(), [&](const Centre& o) {
    return o.body == c.body && o.node == c.node;
  });
  if (!c.fixed || !taken) centres.push_back(c);
}

/// The input mesh with the centres moved to their points and refined `steps` times around them,
/// degrees set by layer (and corrected, with goal-oriented degrees), equal on facing contact
/// edges of two bodies.
StepMesh build_mesh(const model::ProblemSpec& input, const std::vector<Centre>& centres, int steps,
                    const HpOptions& options, const DegreeCorrections& corrections) {
  StepMesh out{input, {}, std::vector<bool>(centres.size(), true)};
  model::ProblemSpec& spec = out.spec;
  std::vector<bool> refining(centres.size(), true);
  for (size_t i = 0; i < centres.size(); ++i) {
    const Centre& c = centres[i];
    if (c.fixed) continue;
    try {
      const BoundaryTrack track(spec, c.body, c.node);
      spec = with_node_moved(spec, track, track.parameter(c.at));
    } catch (const Error& e) {
      out.complete[i] = false;
      out.left_out.push_back("the node nearest to " + point_text(c.at) +
                             " cannot move onto it (" + without_file_name(e.what(), input.file) +
                             "): refined around where it is");
    }
  }
  for (int k = 0; k < steps; ++k)
    for (size_t i = 0; i < centres.size(); ++i) {
      if (!refining[i]) continue;
      try {
        spec = refine_towards_node(spec, centres[i].body, centres[i].node, options.factor);
      } catch (const Error& e) {
        refining[i] = false;
        out.complete[i] = false;
        out.left_out.push_back("the mesh around " + point_text(centres[i].at) + " cannot be refined " +
                               "more than " + std::to_string(k) + " times (" + without_file_name(e.what(), input.file) +
                               ")");
      }
    }
  if (options.degree != model::HpDegree::constant) {
    for (size_t b = 0; b < spec.bodies.size(); ++b) {
      std::vector<int> nodes;
      for (const Centre& c : centres)
        if (c.body == static_cast<int>(b)) nodes.push_back(c.node);
      if (nodes.empty()) continue;
      // One more per layer of the refinement; the input's elements beyond them (a mesh with
      // many rings of elements around Γ*) all get the degree of the outermost layer.
      for (const auto& [id, layer] : element_layers(spec.bodies[b], nodes)) {
        const int p = options.min_degree + std::clamp(layer, 0, steps + 1);
        spec.bodies[b].element_degrees[id] = {p, p};
      }
    }
  }
  if (options.degree == model::HpDegree::goal) corrections.apply(spec, options.min_degree);
  if (options.degree != model::HpDegree::constant) match_facing_degrees(spec);
  return out;
}

/// A mesh refined `step` times that cannot be built (its elements at Γ* have become too small
/// for the geometry's round-off): an AdaptError that says so, not the input's key it names.
[[noreturn]] void throw_refinement_failed(int step, const HpOptions& options, const Error& e) {
  std::ostringstream os;
  os.precision(3);
  os << "hp step " << step << ": the mesh refined " << step << " times around Γ* (its smallest "
     << "elements " << std::pow(options.factor, step) << " of the first ones) cannot be built: "
     << e.what() << "; fewer adapt.steps (or a larger adapt.factor) stay within what the "
        "geometry resolves";
  throw AdaptError(os.str());
}

/// Why a loop with a tolerance ended without reaching it, with the estimate it reached.
std::string limit_message(const HpOutcome& out, const HpOptions& options, const std::string& why) {
  std::ostringstream os;
  os.precision(3);
  os << "hp: the tolerance " << options.tolerance << " was not reached: " << why
     << "; the smallest estimated error, " << out.estimate.traction() << " (contact "
     << (out.estimate.traction() == out.estimate.pressure ? "pressure" : "shear")
     << ", relative L2), is that of the result kept";
  return os.str();
}

/// A contact edge holding at least this share of the estimated error of the pressure is where the
/// next centre goes, when a zone end on it has none.
constexpr double kErrorPeakShare = 0.5;

/// Whether centre c's node can move onto X in `base` (X between its two boundary neighbours):
/// a centre follows the nearest point of its kind only there — a point that is gone (a
/// stick–slip point at the mirror in one step, not in the next) would otherwise hand the centre
/// a point beyond its reach, e.g. another centre's.
bool can_follow(const model::ProblemSpec& base, const Centre& c, const Vec2& X) {
  try {
    return BoundaryTrack(base, c.body, c.node).reaches(X);
  } catch (const AdaptError&) {
    return false;
  }
}

/// With a tolerance: when one contact edge holds most of the estimated error of the pressure and
/// a zone end of the enriched solve lies within its length of the error's peak there with no
/// centre following it (two ends nearest to one node of a coarse input mesh: the node serves
/// one), a centre for it: the nearest vertex of the mesh the steps are built from (`base`'s)
/// that is no centre yet and can move onto it, followed from then on as the others. Whether one
/// was added.
bool add_unfollowed_zone_end(const Solved& base, const Solved& coarse, const Solved& enriched,
                             const std::vector<ZoneEnd>& ends, std::vector<Centre>& centres) {
  const auto peak = pressure_error_peak(coarse, enriched);
  if (!peak || peak->share < kErrorPeakShare) return false;
  const ZoneEnd* end = nearest_end(ends, peak->body, ZoneEnd::Kind::contact, peak->X);
  if (!end || (end->X - peak->X).norm() > peak->edge_length) return false;
  for (const Centre& c : centres)  // followed already: a centre at it, or ending the edge
    if (c.body == peak->body &&
        ((c.at - end->X).norm() <= 0.1 * peak->edge_length ||
         (c.at - peak->edge_ends[0]).norm() <= 1e-9 * (1 + peak->edge_length) ||
         (c.at - peak->edge_ends[1]).norm() <= 1e-9 * (1 + peak->edge_length)))
      return false;
  const auto& mesh = base.discretization.bodies[peak->body].mesh;
  std::vector<std::pair<double, int>> candidates;
  for (const auto& pair : base.solution.pairs) {
    if (pair.body != peak->body && pair.other != peak->body) continue;
    for (int e : pair.body == peak->body ? pair.edges : pair.other_edges)
      for (int v : {mesh.edge(e).v0, mesh.edge(e).v1})
        candidates.push_back({(mesh.node(v) - end->X).norm(), mesh.node_id(v)});
  }
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  for (const auto& [distance, id] : candidates) {
    const bool taken = std::any_of(centres.begin(), centres.end(), [&](const Centre& c) {
      return c.body == peak->body && c.node == id;
    });
    if (taken) continue;
    try {
      if (!BoundaryTrack(base.spec, peak->body, id).reaches(end->X)) continue;
    } catch (const AdaptError&) {
      continue;  // an end of an edge set, a corner: it cannot move
    }
    centres.push_back({peak->body, id, end->X, ZoneEnd::Kind::contact});
    return true;
  }
  return false;
}

/// A stick–slip or memory point counts as followed when a centre on its body lies within this
/// share of the contact zone's extent.
constexpr double kFollowedWithin = 0.02;

/// The extent of the contact zones on `body`: the largest distance between two of its zone ends.
double zone_extent(const std::vector<ZoneEnd>& ends, int body) {
  double extent = 0;
  for (const ZoneEnd& a : ends)
    for (const ZoneEnd& b : ends)
      if (a.body == body && b.body == body && a.kind == ZoneEnd::Kind::contact &&
          b.kind == ZoneEnd::Kind::contact)
        extent = std::max(extent, (a.X - b.X).norm());
  return extent;
}

/// A node of `base` for the point X of body `body`: the boundary vertex nearest to X whose
/// track (its two boundary edges) holds X is refined towards, with the factor that puts the new
/// node on its edge at X (clamped to [0.1, 0.5]); the new node's id, or -1 if no vertex holds X.
int node_made_at(model::ProblemSpec& base, int body, const Vec2& X) {
  const auto& nodes = base.bodies[body].node_ids;
  int best = -1;
  double best_distance = 0, factor = 0;
  for (int id : nodes) {
    try {
      const BoundaryTrack track(base, body, id);
      if (!track.reaches(X)) continue;
      const double d = (node_position(base.bodies[body], id) - X).norm();
      if (best >= 0 && d >= best_distance) continue;
      const double t = track.parameter(X);
      const double edge = t > track.node() ? track.upper() - track.node() : track.node() - track.lower();
      best = id;
      best_distance = d;
      factor = std::clamp(std::abs(t - track.node()) / edge, 0.1, 0.5);
    } catch (const AdaptError&) {
      continue;  // not on the boundary, or a corner
    }
  }
  if (best < 0) return -1;
  const std::set<int> before(nodes.begin(), nodes.end());
  base = refine_towards_node(base, body, best, factor);
  int made = -1;
  double made_distance = 0;
  for (int id : base.bodies[body].node_ids) {
    if (before.count(id)) continue;
    const double d = (node_position(base.bodies[body], id) - X).norm();
    if (made < 0 || d < made_distance) {
      made = id;
      made_distance = d;
    }
  }
  return made;
}

/// With a shear above the tolerance: each stick–slip and memory point of `points` (the enriched
/// solve's) that no centre follows gets one, on a node made for it in `base` — a later load
/// step's stick zone keeps the traction of an earlier one up to its end, a kink the estimate
/// finds but no zone end of the last state marks. A point whose refinement or centre would not
/// give a mesh `builds` accepts is left. The points now followed.
std::vector<Vec2> follow_new_points(model::ProblemSpec& base, std::vector<Centre>& centres,
                                    const std::vector<ZoneEnd>& points,
                                    const std::function<bool(const model::ProblemSpec&,
                                                             const std::vector<Centre>&)>& builds) {
  std::vector<Vec2> followed;
  for (const ZoneEnd& p : points) {
    if (p.kind != ZoneEnd::Kind::stick_slip) continue;
    const double within = kFollowedWithin * zone_extent(points, p.body);
    const bool has_centre = std::any_of(centres.begin(), centres.end(), [&](const Centre& c) {
      return c.body == p.body && (c.at - p.X).norm() <= within;
    });
    if (has_centre) continue;
    model::ProblemSpec refined = base;
    int node = -1;
    try {
      node = node_made_at(refined, p.body, p.X);
    } catch (const Error&) {
      continue;  // the refinement cannot be built there
    }
    if (node < 0) continue;
    std::vector<Centre> more = centres;
    more.push_back({p.body, node, p.X, ZoneEnd::Kind::stick_slip});
    if (!builds(refined, more)) continue;
    base = std::move(refined);
    centres = std::move(more);
    followed.push_back(p.X);
  }
  return followed;
}

/// What the steps after the first follow on a solve: its zone ends (not those at singular
/// points) and, with stick_slip, its stick–slip points and memory points.
std::vector<ZoneEnd> followed_points(const Solved& s, const HpOptions& options) {
  auto ends = without_ends_at_singular_points(zone_ends_of(s, options.stick_slip), singular_ends_of(s));
  if (options.stick_slip)
    for (const ZoneEnd& m : memory_points_of(s)) ends.push_back(m);
  return ends;
}

}  // namespace

HpOptions hp_options(const model::AdaptSpec& adapt) {
  HpOptions o;
  o.factor = adapt.factor;
  o.steps = adapt.steps;
  o.degree = adapt.degree;
  o.min_degree = adapt.min_degree;
  o.tolerance = adapt.method == model::AdaptMethod::hp && adapt.tolerance_given ? adapt.tolerance : 0;
  o.max_dofs = adapt.max_dofs;
  o.stick_slip = adapt.stick_slip;
  return o;
}

HpOutcome refine_towards_zone_ends(const model::ProblemSpec& spec, const HpOptions& options,
                                   const model::ProgressFn& progress, const HpObserver& observe) {
  using Clock = std::chrono::steady_clock;
  auto say = [&](const ProgressEvent& e) {
    if (progress) progress(e);
  };
  // A step's line with its figures (once they are known: after the estimate, with a tolerance).
  auto say_step = [&](int step, long dofs, double estimate, const std::string& detail) {
    AdaptStepProgress p{"hp", step, options.steps, dofs, estimate, options.tolerance, detail};
    say({"hp step " + std::to_string(step) + ": " + detail, p});
  };
  HpOutcome out;
  // The solve `s` of the history's last entry becomes the result.
  auto keep = [&](const SolvedPtr& s, const ErrorEstimate& estimate) {
    out.last = s;
    out.estimate = estimate;
    out.last_step = static_cast<int>(out.history.size()) - 1;
  };
  std::vector<Centre> centres;
  model::ProblemSpec base = spec;  // the input, refined where a zone is narrow (step 0)
  SolvedPtr base_solved;           // its solve
  DegreeCorrections corrections;
  std::string where;  // the solve under way, for a failure's message
  try {
    for (int step = 0; step <= options.steps; ++step) {
      const std::string step_name = "hp step " + std::to_string(step);
      where = step_name + ": ";
      const auto t0 = Clock::now();
      HpIteration rec;
      rec.step = step;
      SolvedPtr s;
      std::vector<ZoneEnd> ends;
      for (;; ++rec.recentred) {
        try {
          model::ProblemSpec mesh = spec;
          if (step > 0) {
            StepMesh built = build_mesh(base, centres, step, options, corrections);
            for (const std::string& note : built.left_out) say(step_name + ": " + note);
            rec.left_out = std::move(built.left_out);
            mesh = std::move(built.spec);
          }
          s = solve(mesh, progress, s ? s.get() : out.last.get());
        } catch (const InputError& e) {
          // The input was good at step 0: what the refined mesh refuses is the refinement's.
          if (step == 0) throw;
          throw_refinement_failed(step, options, e);
        } catch (const MeshError& e) {
          if (step == 0) throw;
          throw_refinement_failed(step, options, e);
        }
        try {
          if (step == 0 && options.resolve_rounds > 0) {
            const Resolution r =
                resolve_zones(s, options.resolve_rounds, options.stick_slip, progress);
            rec.resolve_rounds = r.rounds;
            rec.resolved_towards = r.towards;
            rec.left_out = r.left_out;
            s = r.solved;
            base = s->spec;
          }
          // A later step may find fewer ends (a stick–slip point gone on the coarse elements
          // next to it): the centres stay where they are.
          ends = step == 0 ? adapt_targets(*s, options.stick_slip, true) : followed_points(*s, options);
          if (step == 0) {
            base_solved = s;
            for (const auto& n : nearest_movable_nodes(*s, ends)) add_centre(*s, n, centres);
            add_singular_centres(*s, ends, centres);
          }
        } catch (const AdaptError& e) {
          // The solve itself succeeded: it is the last good result, recorded without centres.
          HpOutcome stopped = stopped_after_solve(
              std::move(out), rec, s, ends, std::chrono::duration<double>(Clock::now() - t0).count(),
              observe, e.what());
          stopped.last_step = static_cast<int>(stopped.history.size()) - 1;
          stopped.stopped = "error";
          return stopped;
        }
        if (step == 0) break;
        // Is each Γ* still within the two smallest elements at its centre? (Each centre follows
        // the zone end nearest to it; ends a coarse early step adds elsewhere are left alone.)
        rec.inside = true;
        std::vector<Centre> recentred = centres;
        for (Centre& c : recentred) {
          if (c.kind == ZoneEnd::Kind::singular || c.fixed) continue;  // an end or corner stays
          const BoundaryTrack track(s->spec, c.body, c.node);
          const ZoneEnd* nearest = nearest_end(ends, c.body, c.kind, c.at);
          if (!nearest) continue;  // a stick–slip point gone: the centre stays
          const double t = track.parameter(nearest->X);
          // (outside, and beyond the node's reach: the mesh cannot follow it, no new solve)
          if ((t <= track.lower() || t >= track.upper()) && can_follow(base, c, nearest->X)) {
            rec.inside = false;
            c.at = nearest->X;
          }
        }
        // With a tolerance the step's estimate measures what a Γ* outside the smallest elements
        // costs, and the next step is centred on the better solve's zone ends: no solve again.
        if (rec.inside || rec.recentred >= options.max_recentre || options.tolerance > 0) break;
        centres = std::move(recentred);
        say("hp step " + std::to_string(step) + ": Γ* left the smallest elements; refining again "
            "around it");
      }
      rec.solve = figures_of(*s, ends, std::chrono::duration<double>(Clock::now() - t0).count());
      if (step > 0)
        for (const Centre& c : centres) rec.centres.push_back(c.at);
      {
        std::ostringstream os;
        os.precision(10);
        os << rec.solve.elements << " elements, " << rec.solve.dofs << " dofs, U = "
           << rec.solve.strain_energy << ", Γ* at";
        for (const auto& g : rec.solve.gamma_star) os << " (" << g.x() << ", " << g.y() << ")";
        if (options.tolerance > 0)
          say("hp step " + std::to_string(step) + ": " + os.str());
        else
          say_step(step, rec.solve.dofs, ErrorEstimate::none, os.str());
      }
      if (options.tolerance <= 0) {
        out.history.push_back(rec);
        keep(s, {});
        if (observe) observe(rec, *s);
        continue;
      }
      if (options.max_dofs > 0 && rec.solve.dofs > options.max_dofs && out.last) {
        out.stopped = "dof limit";
        out.message = limit_message(out, options, "step " + std::to_string(step) + " has " +
                                                      std::to_string(rec.solve.dofs) +
                                                      " free dofs, more than adapt.max_dofs");
        return out;
      }
      SolvedPtr enriched;
      where = step_name + ", its estimate (one degree more): ";
      rec.estimate = estimate_by_enrichment(*s, progress, &enriched);
      {
        std::ostringstream os;
        os.precision(3);
        os << "estimated error " << rec.estimate.pressure << " (pressure, relative L2), ";
        if (!std::isnan(rec.estimate.shear)) os << rec.estimate.shear << " (shear), ";
        os << rec.estimate.energy << " (energy)";
        say_step(step, rec.solve.dofs, rec.estimate.traction(), os.str());
      }
      // Goal-oriented degrees learn from the steps on the refined meshes (the input mesh's
      // degrees are not the rule's).
      if (options.degree == model::HpDegree::goal && step > 0 &&
          !(rec.estimate.traction() <= options.tolerance)) {
        const auto [raised, lowered] = corrections.learn(*s, *enriched, progress, &rec.weights_left_out);
        rec.degrees_learnt = true;
        rec.degrees_raised = raised;
        rec.degrees_lowered = lowered;
      }
      out.history.push_back(rec);
      // The best estimated step so far (an estimate that is not a number is never the best; one
      // below the tolerance is, every earlier one having been above it).
      const bool better = std::isfinite(rec.estimate.traction()) &&
                          !(rec.estimate.traction() >= out.estimate.traction());
      if (!out.last || better) keep(s, rec.estimate);
      if (observe) observe(rec, *s);
      if (rec.estimate.traction() <= options.tolerance) {
        out.converged = true;
        out.stopped = "tolerance reached";
        return out;
      }
      // The next mesh is centred on the zone ends of the better solve.
      const auto ends_plus = followed_points(*enriched, options);
      if (base_solved && add_unfollowed_zone_end(*base_solved, *s, *enriched, ends_plus, centres)) {
        std::ostringstream os;
        os.precision(6);
        os << "hp step " << step << ": the estimated error concentrates at the zone end (" << centres.back().at.x()
           << ", " << centres.back().at.y() << "), which no refinement follows: refining towards it too";
        say(os.str());
      }
      for (Centre& c : centres)
        if (const ZoneEnd* nearest = nearest_end(ends_plus, c.body, c.kind, c.at);
            nearest && !c.fixed && can_follow(base, c, nearest->X))
          c.at = nearest->X;
      if (rec.estimate.shear > options.tolerance) {
        auto builds = [&](const model::ProblemSpec& b, const std::vector<Centre>& c) {
          try {
            return static_cast<bool>(build_mesh(b, c, step + 1, options, corrections).complete.back());
          } catch (const Error&) {
            return false;
          }
        };
        for (const Vec2& X : follow_new_points(base, centres, ends_plus, builds)) {
          std::ostringstream os;
          os.precision(6);
          os << "hp step " << step << ": the shear's estimate is above the tolerance and no refinement "
                "follows the stick-slip point (" << X.x() << ", " << X.y() << "): refining towards it too";
          say(os.str());
        }
      }
    }
    if (options.tolerance > 0) {
      out.stopped = "step limit";
      out.message = limit_message(out, options, std::to_string(options.steps) +
                                                    " steps taken (adapt.steps)");
      return out;
    }
    out.converged = true;
    out.stopped = "steps done";
  } catch (const Error& e) {
    // after the problem file's name, which the solver's message starts with
    const std::string file = spec.file + ": ", what = e.what();
    out.message = what.rfind(file, 0) == 0 ? file + where + what.substr(file.size()) : where + what;
    out.stopped = "error";
  }
  return out;
}

}  // namespace hpcontact::adapt
