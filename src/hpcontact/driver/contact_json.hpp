// summary.json's figures of the contact pairs of a solved state: resultants and normal force in
// the pair's own frame, the zone, Γ*, singular points, friction, and the pressure comparisons.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

#include "hpcontact/driver/contact_compare.hpp"
#include "hpcontact/model/contact_results.hpp"
#include "hpcontact/model/discretization.hpp"

namespace hpcontact::driver {

/// A solved state before post-processing: the discretisation, the dofs and the contact state.
struct SolvedState {
  const model::Discretization* d = nullptr;
  Eigen::VectorXd u;
  std::vector<model::ContactResult> contact;
  std::vector<model::ContactPair> pairs;
  std::vector<Eigen::VectorXd> multipliers;  ///< per pair (empty for penalty pairs)
  const Eigen::VectorXd* multipliers_of(size_t k) const {
    return k < multipliers.size() && multipliers[k].size() ? &multipliers[k] : nullptr;
  }
};

/// The pressure comparisons of a problem's pairs, set up before the first solve (the closed
/// forms' inputs and the reference files, every precondition checked): per pair, or nullopt.
using Comparisons = std::vector<std::optional<PressureComparison>>;

/// Points as [[x, y], ...].
nlohmann::json points_json(const std::vector<Vec2>& points);

/// Pair k's comparison, or null.
const PressureComparison* comparison_of(const Comparisons& c, size_t k);

/// The contact figures of pair k of a state for summary.json; with a comparison also the
/// pressure errors, and the pressure curve into csv_path if not empty.
nlohmann::json contact_json(const SolvedState& st, size_t k, const PressureComparison* comparison,
                            const std::string& csv_path);

/// Every pair's figures (summary.json "contact_pairs").
nlohmann::json contact_pairs_json(const SolvedState& st, const Comparisons& comparisons);

}  // namespace hpcontact::driver
