// The adaptive hp-version towards the end of the contact zone (seed §4.7, Fig. 4.12–4.13):
// geometric refinement around a node placed at Γ* (and at the singular points), the degree
// rising away from it.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "hpcontact/adapt/error_estimate.hpp"
#include "hpcontact/adapt/goal_degrees.hpp"
#include "hpcontact/adapt/solved.hpp"

namespace hpcontact::adapt {

struct HpOptions {
  double factor = 0.5;      ///< size of the corner square per step (seed: 0.5, option 0.17)
  int steps = 8;            ///< refinement steps
  /// rising: min_degree + layer; constant: the input's degrees; goal: rising, corrected after
  /// each step by the estimate's goal-oriented indicators (goal_degrees.hpp; with a tolerance).
  model::HpDegree degree = model::HpDegree::rising;
  int min_degree = 1;       ///< degree of the elements at Γ* (rising and goal)
  int max_recentre = 3;     ///< re-refinements of one step when Γ* leaves the smallest elements
  /// Rounds of zone resolution on the input mesh before the first move (resolve_zones).
  int resolve_rounds = 12;
  /// > 0: the requested accuracy. Each step's error is estimated (estimate_by_enrichment) and
  /// the loop stops at the first below it; `steps` is then the most it may take. 0: `steps`.
  double tolerance = 0;
  int max_dofs = 0;  ///< > 0 (with a tolerance): a mesh of more free dofs ends the loop
  /// Centres on the stick–slip points of exact Coulomb pairs too (adapt_targets()).
  bool stick_slip = true;
};

/// The options an input's `adapt` section asks for.
HpOptions hp_options(const model::AdaptSpec& adapt);

struct HpIteration {
  int step = 0;  ///< 0: the input mesh
  SolveFigures solve;
  std::vector<Vec2> centres;  ///< refinement centres of this mesh (nodes on the boundary)
  int recentred = 0;          ///< how often this step was re-refined around a moved centre
  bool inside = true;         ///< every Γ* within the smallest elements at its centre
  ErrorEstimate estimate;     ///< with a tolerance: the estimated error of this step's solve
  /// Step 0: rounds of zone resolution taken, and the boundary nodes refined towards.
  int resolve_rounds = 0;
  std::vector<Vec2> resolved_towards;
  /// Goal-oriented degrees: whether this step's indicators corrected the degrees of the later
  /// steps, and how many elements they gave one degree more and one less.
  bool degrees_learnt = false;
  int degrees_raised = 0, degrees_lowered = 0;
  /// Why this step's indicators had no goal-oriented weights (the energy surplus alone), if so.
  std::string weights_left_out;
  /// What of this step's refinement could not be built and was left out (a centre that cannot
  /// move onto its point, a layer that would make an invalid element), each with its cause.
  std::vector<std::string> left_out;
};

using HpObserver = std::function<void(const HpIteration&, const Solved&)>;

struct HpOutcome {
  SolvedPtr last;  ///< the result: the last step's solve, with a tolerance the best estimated one
  std::vector<HpIteration> history;
  bool converged = false;  ///< all steps done, or the tolerance reached
  std::string message;     ///< why it failed (converged false)
  std::string stopped;     ///< why the loop ended, in a few words (summary.json adapt.stopped)
  ErrorEstimate estimate;  ///< with a tolerance: the estimate of `last`
  int last_step = -1;      ///< the history entry of `last`
};

/// Solves, refines the input mesh where a zone end has no node near enough to move onto it
/// (resolve_zones: a zone narrow against its elements), places the nearest movable boundary
/// node of each zone end on it (one rp move) and refines geometrically around those nodes, one
/// more layer per step; and around each singular point (singular_ends_of: the node there, which
/// stays, or the node nearest the foot of the other body's corner, moved onto it), whose zone
/// ends within the elements touching it are dropped. When
/// a solve puts Γ* outside the two smallest elements at its centre, that centre is moved to the
/// new Γ* and the mesh of the step is built again from the input mesh (the seed re-refines
/// from the second-last mesh; rebuilding from the input gives the same mesh with the centre
/// moved, and never distorts small elements). Failures end the loop with the last good solve.
/// With a tolerance, every step's error is estimated from a solve one degree higher on its mesh;
/// the loop stops at the first step estimated below the tolerance, and the next step's centres
/// are the zone ends of that better solve. Not reaching it within `steps` (or `max_dofs`) is a
/// failure whose result is the step with the smallest estimate.
HpOutcome refine_towards_zone_ends(const model::ProblemSpec& spec, const HpOptions& options,
                                   const model::ProgressFn& progress = {},
                                   const HpObserver& observe = {});

}  // namespace hpcontact::adapt
