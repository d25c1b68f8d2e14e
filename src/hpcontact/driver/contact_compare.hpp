// The contact pressure of a run against Hertz, Shtayerman and a reference curve (docs/cases.md §1).
#pragma once

#include <optional>
#include <unordered_map>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

#include "hpcontact/analytic/hertz.hpp"
#include "hpcontact/driver/hertz_inputs.hpp"
#include "hpcontact/material/linear_elastic.hpp"
#include "hpcontact/model/contact_solve.hpp"

namespace hpcontact::driver {

/// A pressure curve p(x) read from a CSV (columns x and, of an exact-contact pressure.csv,
/// pressure; else pressure_from_stress, or pressure), zero outside its range: between two samples p² is
/// interpolated linearly where both are ≥ 0 (the square-root end of a contact zone reproduced),
/// p itself elsewhere.
struct ReferenceCurve {
  std::vector<double> x, p;
  double operator()(double s) const;
};

/// The curves of pressure.csv: a pair's pressures and the closed forms along the obstacle.
struct PressureCurve {
  std::vector<double> x;  ///< coordinate along the obstacle from obstacle.point, ascending
  /// The contact pressure: normal force per unit length along the obstacle, of the method
  /// (0 where no contact edge reaches x), and the same from the stresses.
  std::vector<double> pressure, pressure_from_stress;
  /// The traction the method carries per unit undeformed boundary length: eps_N <-g_N>, or
  /// the multiplier (column pressure_penalty or pressure_multiplier).
  std::vector<double> traction;
  std::vector<double> minus_sigma_nn;  ///< −n·σ·n on the body's undeformed normal
  std::vector<double> hertz, shtayerman;
  std::vector<double> reference;    ///< the reference curve; empty when the input names none
  /// Whether `traction` holds the multiplier of exact enforcement (column pressure_multiplier)
  /// rather than the penalty traction (pressure_penalty).
  bool multiplier = false;
};

/// The curve as CSV text: x,pressure_from_stress,pressure_penalty (or pressure_multiplier),
/// hertz,shtayerman,pressure,minus_sigma_nn (the columns of earlier versions first; the
/// reference is not written: it is an input), 12 significant digits.
std::string pressure_csv(const PressureCurve& curve);

/// The file a compare section's `reference` names (relative to the problem file's folder).
/// Precondition: cmp.reference is not empty.
std::string reference_path(const model::ProblemSpec& spec, const model::PressureCompareSpec& cmp);

/// Reads every compare section's reference file; InputError naming the key and the file if one
/// cannot be read or is no reference curve. `check` and a run (before solving) call it.
void require_references(const model::ProblemSpec& spec);

/// The contact pressure of a pair against Hertz, Shtayerman (two circles of radii R_1, R_2,
/// the pair's E*) and, if the input names one, a reference curve (docs/cases.md §1), all on
/// force per unit length along the obstacle. Built once per run, before the solve (so that
/// what contradicts the input fails before it); each solve is then measured with measure().
class PressureComparison {
public:
  /// InputError (naming the key) when the reference file cannot be read, or its force
  /// differs from the known F/2 by more than 1 %.
  PressureComparison(const model::ProblemSpec& spec, const model::PressureCompareSpec& cmp,
                     HertzInputs inputs);

  /// The error measures of the pair's pressure from the stresses and, under "multiplier" or
  /// "penalty_traction", of the method's pressure, over [0, 1.5 b] against Hertz (b_Hertz),
  /// Shtayerman (b_Shtayerman) and the reference (b_Hertz); keys as in summary.json plus the
  /// half widths and what they are computed for (F, E*, R*). If csv_path is not empty, writes
  /// the curves (pressure_csv(curve(...))). InputError when a given force contradicts the
  /// load (comparison_force).
  nlohmann::json measure(const model::Discretization& d, const model::ContactPair& pair,
                         const model::ContactResult& result, const Eigen::VectorXd& u,
                         const std::string& csv_path,
                         const Eigen::VectorXd* multipliers = nullptr) const;

  /// The pair's pressures on 1001 points of [0, 1.5 b_Hertz] and on the ends of the contact
  /// zone inside it (so that a curve read back as a reference keeps its kink), with Hertz,
  /// Shtayerman and the reference there.
  PressureCurve curve(const model::Discretization& d, const model::ContactPair& pair,
                      const model::ContactResult& result, const Eigen::VectorXd& u,
                      const Eigen::VectorXd* multipliers = nullptr) const;

  const HertzInputs& inputs() const { return in_; }

private:
  struct ClosedForms {
    double force;
    analytic::Hertz hertz;
    /// Shtayerman's exact circle: plane models only (none for spheres).
    std::optional<analytic::Shtayerman> shtayerman;
  };
  /// The closed forms for the pair's force, built once per force (an adaptive loop under force
  /// control compares every step at the same F).
  const ClosedForms& closed_forms(const model::ContactPair& pair,
                                  const model::ContactResult& result) const;
  /// Shtayerman's pressure at x (a quadrature per point), kept for the force of closed_forms():
  /// the error integrals of the steps share most of their points (those of the pieces no
  /// contact edge's end splits).
  double shtayerman_pressure(double x) const;
  void check_reference_force(double force) const;

  HertzInputs in_;
  std::optional<ReferenceCurve> reference_;
  std::string reference_name_;
  // Caches of closed_forms() and shtayerman_pressure(): a comparison is used by one thread.
  mutable std::optional<ClosedForms> closed_forms_;
  mutable std::unordered_map<double, double> shtayerman_at_;
};

/// Per pair of the problem, its comparison (nullopt without a compare section), every
/// precondition checked (hertz_inputs, the reference files).
std::vector<std::optional<PressureComparison>> make_comparisons(
    const model::ProblemSpec& spec, const model::Discretization& d,
    const std::vector<model::ContactPair>& pairs);

}  // namespace hpcontact::driver
