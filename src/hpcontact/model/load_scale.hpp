// Whether a force target fits the bodies it acts on in double precision.
#pragma once

#include "hpcontact/model/discretization.hpp"
#include "hpcontact/model/problem_spec.hpp"

namespace hpcontact::model {

/// The smallest and largest displacement, relative to a body's size, that a force may cause and
/// still be solved for: below, the displacement is lost against the coordinates where contact
/// measures its gaps (double precision resolves 1e-16 of them); above, no elastic solution
/// means anything (strains of a million).
constexpr double kSmallestRelativeDisplacement = 1e-13;
constexpr double kLargestRelativeDisplacement = 1e6;

/// InputError naming solver.target_resultant and the body's material when the target force F of
/// the first contact pair moves its body (the softer one of a two-body pair) by u ≈ F / (E t)
/// (plane sections of thickness t; F / (E L) for an axisymmetric body, F its total and L its
/// size) outside [kSmallest, kLargest] × L: units of E and of the force that disagree (an E
/// of 1e100 made force control fail as "constraints that repeat one another", 1e-100 as "does
/// not reach the obstacle", a target of 1e100 ran for minutes). Nothing without a target.
void require_force_scale(const ProblemSpec& spec, const Discretization& d, int body, int other);

}  // namespace hpcontact::model
