// What the closed forms of a pair's compare section are computed for: the pair's contact
// modulus E* and radius R* (both bodies, both curvatures) and the force, given or derived from
// the load, each checked against the input before the solve.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "hpcontact/model/contact_solve.hpp"

namespace hpcontact::driver {

/// The inputs of Hertz and Shtayerman for one pair (docs/input.md, contact[].compare).
struct HertzInputs {
  double radius = 0;        ///< R_1, the body's surface at the contact
  double other_radius = 0;  ///< R_2, the obstacle's (∞ a plane, < 0 concave)
  double effective_radius = 0;   ///< R*: 1/R* = 1/R_1 + 1/R_2
  double modulus = 0;            ///< E'_1 of the body: E/(1 − ν²) plane strain, E plane stress
  double other_modulus = 0;      ///< E'_2 of the other body, ∞ for a rigid obstacle
  double effective_modulus = 0;  ///< E*: 1/E* = 1/E'_1 + 1/E'_2
  /// F on the whole cylinder when known before the solve: given (compare.force) or derived
  /// from solver.target_resultant; nullopt: derived from the pair's resultant after the solve.
  std::optional<double> force;
  bool force_given = false;  ///< compare.force was given (to be checked after the solve)
  /// F over the force the model carries: 2 for a symmetric half (the contact boundary on one
  /// side of obstacle.point), 1 for a whole model.
  double models_of_whole = 2;
  /// +1 when the contact boundary lies on the positive side of obstacle.point along the
  /// obstacle (or both), −1 when on the negative side: the comparison samples side · [0, 1.5 b].
  double side = 1;
  /// The body is axisymmetric: 3-D Hertz of spheres, F the total force (models_of_whole 1).
  bool axisymmetric = false;
  std::string where;  ///< the compare section's key path and place in the file
};

/// The inputs of pair k's compare section (spec.contact[k].compare must be set). InputError,
/// naming the key, the file place and the values, when a material is not linear elastic in
/// plane strain or stress, a radius cannot be derived or contradicts the mesh or obstacle,
/// 1/R_1 + 1/R_2 <= 0, or compare.force contradicts solver.target_resultant.
HertzInputs hertz_inputs(const model::ProblemSpec& spec, const model::Discretization& d,
                         const std::vector<model::ContactPair>& pairs, size_t k);

/// The force F of the whole cylinder the pair carries at a solved state: models_of_whole ×
/// |resultant · normal| of the pair.
double carried_force(const HertzInputs& in, const model::ContactPair& pair,
                     const model::ContactResult& result);

/// F for the closed forms at a solved state: the known force (given, or from the target), or
/// the carried one. A given force under displacement control is the user's nominal value: its
/// difference from the carried force is reported (summary.json compared_for), not refused.
double comparison_force(const HertzInputs& in, const model::ContactPair& pair,
                        const model::ContactResult& result);

}  // namespace hpcontact::driver
