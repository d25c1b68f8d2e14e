// The contact pressure of a run against Hertz, Shtayerman and a reference curve (docs/cases.md §1).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

#include "hpcontact/analytic/hertz.hpp"
#include "hpcontact/material/linear_elastic.hpp"
#include "hpcontact/model/contact_solve.hpp"

namespace hpcontact::driver {

/// A piecewise linear curve p(x) read from a CSV (columns x and pressure_from_stress, or
/// pressure); zero outside its range.
struct ReferenceCurve {
  std::vector<double> x, p;
  double operator()(double s) const;
};

/// The curves of pressure.csv: a pair's pressure and the closed forms along the obstacle.
struct PressureCurve {
  std::vector<double> x;            ///< coordinate along the obstacle, ascending
  std::vector<double> from_stress;  ///< -n·σ·n (0 where no contact edge reaches x)
  std::vector<double> penalty;      ///< the pressure the method carries: eps_N <-g_N>, or the multiplier
  std::vector<double> hertz, shtayerman;
  std::vector<double> reference;    ///< the reference curve; empty when the input names none
  /// Whether `penalty` holds the multiplier of exact enforcement (column pressure_multiplier)
  /// rather than the penalty traction (pressure_penalty).
  bool multiplier = false;
};

/// The curve as CSV text: x,pressure_from_stress,pressure_penalty (or pressure_multiplier),
/// hertz,shtayerman (the reference is not written: it is an input), 12 significant digits.
std::string pressure_csv(const PressureCurve& curve);

/// The file a compare section's `reference` names (relative to the problem file's folder).
/// Precondition: cmp.reference is not empty.
std::string reference_path(const model::ProblemSpec& spec, const model::PressureCompareSpec& cmp);

/// Reads every compare section's reference file; InputError naming the key and the file if one
/// cannot be read or is no reference curve. `check` and a run (before solving) call it.
void require_references(const model::ProblemSpec& spec);

/// The contact pressure of a pair against Hertz, Shtayerman (for the exact circle) and, if the
/// input names one, a reference curve (docs/cases.md §1). Built once per run: the closed forms and
/// the reference file are set up when constructed, each solve is then measured with measure().
class PressureComparison {
public:
  /// For the material of the body in contact; InputError (naming the key) when it is not plane
  /// strain or the reference file cannot be read.
  PressureComparison(const model::ProblemSpec& spec, const model::PressureCompareSpec& cmp,
                     const material::LinearElastic& material);

  /// The error measures of the pair's pressure from the stresses (the seed's plotted pressure)
  /// and, under "penalty_traction", of the penalty traction, over [0, 1.5 b] against Hertz
  /// (b_Hertz), Shtayerman (b_Shtayerman) and the reference (b_Hertz); keys as in summary.json
  /// plus the half widths. If csv_path is not empty, writes the curves on 1001 points of
  /// [0, 1.5 b_Hertz] and on the ends of the contact zone `zone_ends` (coordinates along the
  /// obstacle) there (pressure_csv(curve(...))), so that a curve read back as a reference
  /// keeps its kink.
  nlohmann::json measure(const model::Discretization& d, const model::ContactPair& pair,
                         const Eigen::VectorXd& u, const std::vector<double>& zone_ends,
                         const std::string& csv_path,
                         const Eigen::VectorXd* multipliers = nullptr) const;

  /// The pair's pressure on 1001 points of [0, 1.5 b_Hertz] and on the zone ends inside it,
  /// with Hertz, Shtayerman and the reference there.
  PressureCurve curve(const model::Discretization& d, const model::ContactPair& pair,
                      const Eigen::VectorXd& u, const std::vector<double>& zone_ends,
                      const Eigen::VectorXd* multipliers = nullptr) const;

private:
  analytic::Hertz hertz_;
  analytic::Shtayerman shtayerman_;
  std::optional<ReferenceCurve> reference_;
  std::string reference_name_;
};

}  // namespace hpcontact::driver
