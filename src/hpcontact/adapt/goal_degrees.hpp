// Goal-oriented degrees for hp to a tolerance: the rising degree (min_degree at Γ*, one more per
// layer) corrected, element by element, where the error estimate's indicators of the contact
// traction's error show an element's degree too low or too high for its share.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "hpcontact/adapt/solved.hpp"
#include "hpcontact/model/problem_spec.hpp"

namespace hpcontact::adapt {

/// Per body, per element user id: how many degrees an element departs from the rising rule,
/// learnt step by step. An element keeps its id from one step's mesh to the next unless it is
/// split (the elements at Γ*), so a correction follows the element through the later steps.
class DegreeCorrections {
public:
  /// Indicator per dof of one degree more above `raise` times the mean: one degree more.
  static constexpr double raise = 3;
  /// Below `lower` times the mean: one degree less.
  static constexpr double lower = 0.1;

  /// After a step: `coarse` its solve, `enriched` the estimate's solve one degree higher on the
  /// same mesh. Each element's goal-oriented indicator η_K (traction_error_indicators) is divided
  /// by the dofs one more degree costs it, 2 p_K + 3 (per component, tensor space), so that
  /// degrees are bought where they buy most accuracy; the elements far above and far below the
  /// mean are corrected. Returns how many were raised and how many lowered; why the indicators
  /// had no goal-oriented weights, if they had none, in `weights_left_out`.
  std::pair<int, int> learn(const Solved& coarse, const Solved& enriched,
                            const model::ProgressFn& progress = {},
                            std::string* weights_left_out = nullptr);

  /// The corrections added to the degrees of `spec` (elements with an entry in element_degrees),
  /// each kept within [min_degree, model::kMaxDegree].
  void apply(model::ProblemSpec& spec, int min_degree) const;

private:
  std::vector<std::map<int, int>> offsets_;  ///< [body][element id]
};

}  // namespace hpcontact::adapt
