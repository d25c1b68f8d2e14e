// The error of a solve estimated from the solution itself: a second solve one degree higher on
// the same mesh, and the change of the contact pressure and the energy between the two.
#pragma once

#include <array>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "hpcontact/adapt/solved.hpp"
#include "hpcontact/model/problem_spec.hpp"

namespace hpcontact::adapt {

struct ErrorEstimate {
  static constexpr double none = std::numeric_limits<double>::quiet_NaN();
  /// ‖t − t⁺‖ / ‖t⁺‖ in L2 over the contact edges of every pair, t the traction the method
  /// carries (the multiplier, or the penalty traction) per unit undeformed length.
  double pressure = none;
  /// The same of the tangential traction λ_T over the pairs enforced exactly with friction; not a
  /// number without one.
  double shear = none;
  /// √(|U⁺ − U| / U⁺), U the strain energy: the relative energy-norm error the difference
  /// shows (U − U⁺ = ‖u⁺ − u‖²_E for a linear problem, Pythagoras).
  double energy = none;
  int dofs = 0;                ///< free dofs of the solve one degree higher
  int newton_iterations = 0;   ///< of that solve
  double seconds = 0;          ///< of that solve

  /// What a tolerance on the contact traction is held to: the larger of the pressure's and
  /// the shear's relative errors (the pressure's alone without friction); not a number if the
  /// pressure's is not.
  double traction() const { return shear > pressure ? shear : pressure; }  // NaN shear: pressure
};

/// The problem with the degree of every element of every body raised by one (p_xi and p_eta);
/// AdaptError if an element already has the largest degree the input allows (30).
model::ProblemSpec with_degrees_raised(const model::ProblemSpec& spec);

/// The estimate of `coarse` from `enriched`, a solve of the same mesh with higher degrees.
ErrorEstimate estimate_error(const Solved& coarse, const Solved& enriched);

/// Where the estimated error of the contact pressure concentrates: the contact edge holding the
/// largest share of ‖t − t⁺‖² (estimate_error's integral, away from singular points) and on it
/// the point where (t − t⁺)² is largest, undeformed.
struct ErrorPeak {
  int body = -1;
  Vec2 X = Vec2::Zero();
  double share = 0;        ///< the edge's share of the whole ‖t − t⁺‖²
  double edge_length = 0;  ///< the edge's undeformed length
  std::array<Vec2, 2> edge_ends;  ///< the edge's vertices, undeformed
};
std::optional<ErrorPeak> pressure_error_peak(const Solved& coarse, const Solved& enriched);

/// Per body, per element: the strain energy of the part of `field` (over `enriched`'s dofs) that
/// the modes `coarse`'s element lacks carry — on one mesh whose degrees `enriched` raised, what
/// the element's own degree leaves out (the hierarchic surplus), not what its neighbours do.
std::vector<std::vector<double>> surplus_energies(const model::Discretization& coarse,
                                                  const model::Discretization& enriched,
                                                  const Eigen::VectorXd& field);

/// ∂J/∂λ of the goal J(λ) = ∫ (t⁺ − t) λ ds / ‖t⁺‖² + ∫ (t_T⁺ − t_T) λ_T ds / ‖t_T⁺‖² for the
/// multipliers of `enriched`, per pair (empty for a penalty pair): W_j (t⁺ − t) / ‖t⁺‖² at each
/// multiplier node j (W_j its weight), and with friction W_j (t_T⁺ − t_T) / ‖t_T⁺‖² at each
/// tangential one; the norms Σ W_j t⁺_j² over every pair's nodes (a shear of zero: the
/// pressure's). J(λ⁺) − J(λ) is then the sum of the squared relative errors of the pressure and
/// the shear at the nodes: the two weigh alike.
std::vector<Eigen::VectorXd> traction_error_gradient(const Solved& coarse, const Solved& enriched);

/// Where `coarse`'s error in the contact traction comes from, element by element (goal-oriented,
/// dual-weighted): per body, per element K, η_K = √(S_K(u⁺) · E_K(z⁺)), with S_K(u⁺) the surplus
/// energy of the solve one degree higher (surplus_energies: what K's own degree leaves out) and
/// E_K(z⁺) the strain energy on K of its adjoint (model::multiplier_adjoint) for
/// J(λ) = ∫ (t⁺ − t) λ ds / ‖t⁺‖² + ∫ (t_T⁺ − t_T) λ_T ds / ‖t_T⁺‖² over the exactly enforced
/// pairs' contact edges (the second term with friction), the traction's error as the weight,
/// each part relative to its size (traction_error_gradient): by Cauchy–Schwarz, how much an
/// error of K's size moves J. Without exact pairs
/// (no multipliers), or when the adjoint cannot be solved (said through `progress`), S_K alone,
/// and why in `weights_left_out` (if not null; else it is left empty).
std::vector<std::vector<double>> traction_error_indicators(const Solved& coarse,
                                                           const Solved& enriched,
                                                           const model::ProgressFn& progress = {},
                                                           std::string* weights_left_out = nullptr);

/// Solves `coarse`'s problem one degree higher (starting from its solution) and estimates the
/// error of `coarse` from it; the solve is returned in `enriched` when not null.
ErrorEstimate estimate_by_enrichment(const Solved& coarse, const model::ProgressFn& progress,
                                     SolvedPtr* enriched = nullptr);

}  // namespace hpcontact::adapt
