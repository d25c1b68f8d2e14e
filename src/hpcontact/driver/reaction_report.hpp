// The reactions of a run as summary.json, path.csv and warnings report them.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hpcontact/model/problem_spec.hpp"
#include "hpcontact/model/reactions.hpp"

namespace hpcontact::driver {

/// The largest relative imbalance of a body's forces (model::BodyBalance::relative) a converged
/// run may leave without a warning: far above the solver's residual tolerance (solver.tolerance,
/// 1e-10 by default) and its quadrature's round-off, far below an error an engineer would see.
constexpr double kEquilibriumLimit = 1e-6;

/// summary.json's `reactions`: the supports (each constraint entry of each body, with the edge
/// sets, nodes and components it names), the pairs, each body's balance, and the rules used.
nlohmann::json reactions_json(const model::ProblemSpec& spec, const model::Reactions& r);

/// The warning when a body's forces do not balance to kEquilibriumLimit, else none.
std::optional<std::string> equilibrium_warning(const model::ProblemSpec& spec, const model::Reactions& r);

/// path.csv's columns of the reactions: per support reaction_<body>_<entry>_x, _y and _moment
/// (empty for an axisymmetric body), then equilibrium_residual.
std::string reaction_header(const model::ProblemSpec& spec, const model::Reactions& r);
/// The row of those columns at a step (each value after a comma).
std::string reaction_row(const model::Reactions& r);

}  // namespace hpcontact::driver
