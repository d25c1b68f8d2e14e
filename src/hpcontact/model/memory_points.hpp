// Memory points of frictional contact: where an earlier load step's stick zone ended inside the
// region that has stuck ever since, so that the last state's tangential traction has a kink there.
#pragma once

#include <vector>

#include "hpcontact/geometry/vec2.hpp"
#include "hpcontact/model/contact_solve.hpp"

namespace hpcontact::model {

/// The memory points of pair k, undeformed, on the pair's body (`own`) and on the other one.
struct MemoryPoints {
  std::vector<Vec2> own, other;
};

/// The stick–slip points of the load steps before the last (NonlinearSolution::
/// stick_slip_history) at which every later step, the last included, sticks: a point stuck
/// since keeps the tangential traction it carried then, whose slope changes at the end of the
/// stick zone it stuck in (Mindlin and Deresiewicz: unloaded after a shear, a contact sticks
/// inside the new reverse-slip annulus, and the traction keeps the loading's kink at the
/// loading's stick zone end). A point is left out when a later step slipped at it (the slip
/// rewrote its traction), and counted once: none within 1e-3 of the zone's extent of another or
/// of one of the last step's stick–slip points. Empty but for exact Coulomb pairs.
MemoryPoints memory_points(const NonlinearSolution& sol, size_t k);

}  // namespace hpcontact::model
