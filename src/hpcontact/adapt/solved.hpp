// A solved discretisation and the ends of its contact zones: what the rp and hp loops adapt to.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "hpcontact/adapt/boundary_track.hpp"
#include "hpcontact/geometry/vec2.hpp"
#include "hpcontact/model/contact_solve.hpp"
#include "hpcontact/model/discretization.hpp"
#include "hpcontact/model/problem_spec.hpp"

namespace hpcontact::adapt {

/// One solved discretisation; heap-held because the contact pairs refer into its bodies.
struct Solved {
  model::ProblemSpec spec;
  model::Discretization discretization;
  model::NonlinearSolution solution;
};
using SolvedPtr = std::shared_ptr<const Solved>;

/// Discretises and solves a contact problem; NumericalError when the solver does not converge.
/// `previous` (if not null) is a solve of the same problem on another mesh: the solve starts from
/// its solution carried over (carry_over(): its load factor, displacements and pressures).
SolvedPtr solve(const model::ProblemSpec& spec, const model::ProgressFn& progress = {},
                const Solved* previous = nullptr);

/// A point of the undeformed boundary of a body that rp and hp adapt the mesh to: an end of a
/// contact zone (Γ*), a stick–slip point of a frictional zone, where the tangential traction
/// has the same square-root end the pressure has at Γ*, or (hp) a singular point, where the
/// pressure is unbounded (model::SingularPoint: a node of the mesh, or the foot of the other
/// body's corner).
struct ZoneEnd {
  enum class Kind { contact, stick_slip, singular };
  int body = 0;
  Vec2 X = Vec2::Zero();
  Kind kind = Kind::contact;
  /// A singular point: the extent of the elements touching it (model::SingularPoint::excluded),
  /// within which a zone end found is the discretisation's oscillation at the point.
  double radius = 0;
};

/// "zone end", "stick-slip point" (progress lines, summary.json).
const char* kind_name(ZoneEnd::Kind kind);

/// The outer ends of every pair's active region (ContactResult::outer_ends), pair by pair, on
/// both bodies, and with `stick_slip` every exact Coulomb pair's stick–slip points
/// (ContactResult::stick_slip) on both bodies; possibly none.
std::vector<ZoneEnd> zone_ends_of(const Solved& s, bool stick_slip);

/// The memory points of `s`'s pairs (ContactResult::memory_points: earlier steps' stick–slip
/// points where it has stuck since, the tangential traction kinked there) on both bodies, as
/// stick–slip points.
std::vector<ZoneEnd> memory_points_of(const Solved& s);

/// zone_ends_of(s, false); AdaptError when there is none.
std::vector<ZoneEnd> outer_zone_ends(const Solved& s);

/// Every pair's singular points (ContactResult::singular_points) on the bodies whose boundaries
/// they lie on: the end or corner on its body, and the other body's corner also at its foot on
/// the pair's body.
std::vector<ZoneEnd> singular_ends_of(const Solved& s);
/// `ends` without the zone ends (Γ*) that lie within the radius of a singular point of `singular`
/// on the same body: the zone is closed up to the point.
std::vector<ZoneEnd> without_ends_at_singular_points(std::vector<ZoneEnd> ends,
                                                     const std::vector<ZoneEnd>& singular);
/// What rp and hp adapt to: zone_ends_of(s, stick_slip), with `singular` also
/// singular_ends_of(s); AdaptError when there is none.
std::vector<ZoneEnd> adapt_targets(const Solved& s, bool stick_slip, bool singular = false);

/// The point of `body` and `kind` nearest to X, or null if that body has none.
const ZoneEnd* nearest_end(const std::vector<ZoneEnd>& ends, int body, ZoneEnd::Kind kind,
                           const Vec2& X);

/// A boundary node that can move onto a zone end, and that end.
struct NodeForEnd {
  BoundaryTrack track;
  ZoneEnd end;
};

/// For each zone end, the movable boundary node of its pair's contact edges nearest to it (one
/// per node: of two ends nearest to the same node, the nearer is served); AdaptError when an
/// end has no movable node. Stick–slip points choose after the zone ends, among the nodes no
/// zone end has taken; one with none left gets no node. With must_reach (rp, which moves the
/// node onto its end) only a node whose track reaches the end serves it, and an end no movable
/// node reaches gets none; without (hp and the zone resolution, which refine towards the
/// nearest node) the nearest serves.
std::vector<NodeForEnd> nearest_movable_nodes(const Solved& s, const std::vector<ZoneEnd>& ends,
                                              bool must_reach = false);

/// The figures of one solve of an adaptive loop, as its history records them.
struct SolveFigures {
  int dofs = 0, elements = 0;
  int min_degree = 0, max_degree = 0;  ///< over every element of every body
  double strain_energy = 0;
  int newton_iterations = 0;
  double seconds = 0;            ///< the solve(s) behind this record
  std::vector<Vec2> gamma_star;  ///< the outer zone ends found (undeformed)
};

SolveFigures figures_of(const Solved& s, const std::vector<ZoneEnd>& ends, double seconds);

/// Ends an adaptive loop (rp or hp) whose solve succeeded but whose next step cannot be taken
/// (no zone end, no node to move): the solve is recorded as the iteration `rec` and kept as the
/// last good result, and `why` becomes the outcome's message.
template <class Outcome, class Iteration, class Observer>
Outcome stopped_after_solve(Outcome out, Iteration rec, const SolvedPtr& s,
                            const std::vector<ZoneEnd>& ends, double seconds,
                            const Observer& observe, const std::string& why) {
  rec.solve = figures_of(*s, ends, seconds);
  out.history.push_back(rec);
  out.last = s;
  if (observe) observe(rec, *s);
  out.message = why;
  return out;
}

}  // namespace hpcontact::adapt
