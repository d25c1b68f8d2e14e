// Carrying a solution from one discretisation of a problem to another (the next mesh of an
// adaptive loop), as the start of the next solve.
#pragma once

#include "hpcontact/model/contact_solve.hpp"
#include "hpcontact/model/discretization.hpp"

namespace hpcontact::adapt {

/// The start of a solve on `to` from the solution `from` on `from_d`: the same dofs and
/// multipliers when the discretisations number them alike (an rp relocation moves a node, nothing
/// else); the same field and each exact pair's multiplier polynomial at the new nodes when `to`
/// has the same meshes with element spaces containing `from_d`'s (the error estimate's solve one
/// degree higher: an exact start); otherwise (an hp step) the old displacement at every vertex of
/// the new meshes (the vertex modes; edge and internal modes zero) and each exact pair's pressure
/// at its new nodes, interpolated along the old nodes. The load factor in all cases.
model::StartState carry_over(const model::Discretization& from_d,
                             const model::NonlinearSolution& from, const model::Discretization& to,
                             const std::vector<model::ContactPair>& to_pairs);

}  // namespace hpcontact::adapt
