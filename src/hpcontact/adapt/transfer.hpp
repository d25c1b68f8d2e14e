// Carrying a solution from one discretisation of a problem to another (the next mesh of an
// adaptive loop), as the start of the next solve.
#pragma once

#include "hpcontact/model/contact_solve.hpp"
#include "hpcontact/model/discretization.hpp"

namespace hpcontact::adapt {

/// The start of a solve on `to` from the solution `from` on `from_d`: the same dofs and
/// multipliers when the discretisations number them alike (an rp relocation moves a node, nothing
/// else); otherwise (an hp step) the old displacement at every vertex of the new meshes (the
/// vertex modes; edge and internal modes zero) and each exact pair's pressure at its new nodes,
/// interpolated along the old nodes. The load factor in both cases.
model::StartState carry_over(const model::Discretization& from_d,
                             const model::NonlinearSolution& from, const model::Discretization& to,
                             const std::vector<model::ContactPair>& to_pairs);

}  // namespace hpcontact::adapt
