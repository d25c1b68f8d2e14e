// Which body of a two-body pair carries the multipliers (contact[].carrier: auto): a rule
// symmetric in the two bodies, so that the answer does not depend on the order the input names
// them in.
#pragma once

#include <string>

#include "hpcontact/model/discretization.hpp"
#include "hpcontact/model/problem_spec.hpp"

namespace hpcontact::model {

/// The problem with each pair of `carrier: auto` carried by the body chosen_carrier() names:
/// body and obstacle (with their edge sets) swapped where the obstacle's body is chosen,
/// normal_direction turned with them (it is the force on the pair's body), and the choice and
/// its reason in ContactPairSpec::carrier_choice; the pair then says `as-written`, so that a
/// discretisation built from the result (an adaptive step's) does not choose again. `d` is the
/// input's discretisation. A problem without such a pair is returned as it is.
ProblemSpec with_chosen_carriers(const ProblemSpec& spec, const Discretization& d);
/// The same on the input's own discretisation, made only if a pair asks for a choice.
ProblemSpec with_chosen_carriers(const ProblemSpec& spec);

/// The carrier of one two-body pair: whether the obstacle's body should carry instead of the
/// pair's body, and why (a sentence naming the chosen body). By the first of these that tells
/// the two apart:
///  1. the body whose contact boundary lies within the other's: the larger share of its
///     undeformed contact length faces the other's boundary (has a foot on it), by more than
///     1e-3 — its multipliers end where the other surface does, so the zone can end at its own
///     last node instead of inside an element (a shaft in a shorter hub: the hub);
///  2. the finer contact mesh: more multiplier nodes per unit length over the part facing the
///     other, by more than 1 % (the mortar method's choice: the finer trace carries);
///  3. the softer body: the smaller plane modulus E' at the first contact edge, by more than 1e-9;
///  4. the body named first under `bodies`.
struct CarrierChoice {
  bool swap = false;
  std::string reason;
};
CarrierChoice chosen_carrier(const ContactPairSpec& pair, const Discretization& d);

}  // namespace hpcontact::model
