// The contact pressure of a run against Hertz, Shtayerman and a reference curve (CASES.md §1).
#pragma once

#include <string>

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

#include "hpcontact/model/contact_solve.hpp"

namespace hpcontact::driver {

/// The error measures of the pair's pressure from the stresses (the seed's plotted pressure)
/// over [0, 1.5 b] against Hertz (b_Hertz), Shtayerman (b_Shtayerman) and, if given, the
/// reference curve (b_Hertz); keys as in RESULTS.md plus the half widths. If csv_path is not
/// empty, writes the curves on 1001 points of [0, 1.5 b_Hertz] and on the ends of the contact
/// zone `zone_ends` (coordinates along the obstacle) there (x, pressure_from_stress,
/// pressure_penalty, hertz, shtayerman), so that a curve read back as a reference keeps its kink.
nlohmann::json compare_pressure(const model::ProblemSpec& spec, const model::PressureCompareSpec& cmp,
                                const model::Discretization& d, const model::ContactPair& pair,
                                const Eigen::VectorXd& u, const std::vector<double>& zone_ends,
                                const std::string& csv_path);

}  // namespace hpcontact::driver
