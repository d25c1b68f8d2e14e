// The rp-version (seed §4.8, Fig. 4.14): solve, locate Γ*, move the nearest boundary node onto
// it along the exact boundary, solve again, until node and Γ* coincide.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "hpcontact/adapt/solved.hpp"
#include "hpcontact/geometry/vec2.hpp"
#include "hpcontact/model/contact_solve.hpp"
#include "hpcontact/model/discretization.hpp"
#include "hpcontact/model/problem_spec.hpp"

namespace hpcontact::adapt {

/// A node relocated onto a zone end.
struct RelocatedNode {
  int body = 0;
  int node_id = 0;
  Vec2 position = Vec2::Zero();    ///< where the node was in this iteration's solve
  Vec2 gamma_star = Vec2::Zero();  ///< the zone end (or stick–slip point) that solve found
  ZoneEnd::Kind kind = ZoneEnd::Kind::contact;
  /// false: no zone end of its kind lay within its reach (between its boundary neighbours) in
  /// this solve — its stick–slip point vanished or moved past a neighbour — and it stays;
  /// gamma_star is then its own position
  bool has_target = true;
};

struct RpIteration {
  int iteration = 0;  ///< 0: the starting mesh
  SolveFigures solve;
  std::vector<RelocatedNode> nodes;
  int zone_ends_found = 0;  ///< all sign changes of the gap, islands of opening included
  double distance = 0;      ///< max |Γ* − node| / body size
};

struct RpOptions {
  double tolerance = 1e-10;  ///< stop when distance <= tolerance
  int max_iterations = 20;   ///< relocations after the first solve
  bool secant = true;        ///< secant steps on Γ*(node) − node; false: move onto the last Γ*
  /// Nodes onto the stick–slip points of exact Coulomb pairs too (adapt_targets()).
  bool stick_slip = true;
};

/// The options an input's `adapt` section asks for.
RpOptions rp_options(const model::AdaptSpec& adapt);

/// Called after every solve with its record and result (for post-processing per iteration).
using IterationObserver = std::function<void(const RpIteration&, const Solved&)>;

struct RpOutcome {
  SolvedPtr last;  ///< the last successful solve (null if even the first failed)
  std::vector<RpIteration> history;
  bool converged = false;
  std::string message;  ///< why the loop stopped, when not converged
};

/// Runs the rp loop on a contact problem. Several zone ends are served at once, each by its own
/// node (nearest movable boundary node of the contact edges at the start, kept thereafter).
/// A failure (no Γ*, a node that cannot move, a solve that fails) ends the loop with the last
/// good solve kept and the reason in `message`; nothing throws but programming errors.
RpOutcome relocate_nodes(const model::ProblemSpec& spec, const RpOptions& options,
                         const model::ProgressFn& progress = {},
                         const IterationObserver& observe = {});

}  // namespace hpcontact::adapt
