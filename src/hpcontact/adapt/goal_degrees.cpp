// Goal-oriented degree corrections: the indicators of a step, per dof, against their mean.
#include "hpcontact/adapt/goal_degrees.hpp"

#include <algorithm>

#include "hpcontact/adapt/error_estimate.hpp"

namespace hpcontact::adapt {

std::pair<int, int> DegreeCorrections::learn(const Solved& coarse, const Solved& enriched,
                                             const model::ProgressFn& progress,
                                             std::string* weights_left_out) {
  auto score = traction_error_indicators(coarse, enriched, progress, weights_left_out);
  double total = 0;
  int n = 0;
  for (size_t b = 0; b < score.size(); ++b)
    for (size_t q = 0; q < score[b].size(); ++q) {
      score[b][q] /= 2 * coarse.discretization.bodies[b].dofs.element(static_cast<int>(q)).max_degree() + 3;
      total += score[b][q];
      ++n;
    }
  if (n == 0 || !(total > 0)) return {0, 0};
  const double mean = total / n;
  if (offsets_.size() < score.size()) offsets_.resize(score.size());
  int raised = 0, lowered = 0;
  for (size_t b = 0; b < score.size(); ++b) {
    const auto& mesh = coarse.discretization.bodies[b].mesh;
    for (size_t q = 0; q < score[b].size(); ++q) {
      const int id = mesh.quad_id(static_cast<int>(q));
      if (score[b][q] > raise * mean) {
        ++offsets_[b][id];
        ++raised;
      } else if (score[b][q] < lower * mean) {
        --offsets_[b][id];
        ++lowered;
      }
    }
  }
  return {raised, lowered};
}

void DegreeCorrections::apply(model::ProblemSpec& spec, int min_degree) const {
  for (size_t b = 0; b < offsets_.size() && b < spec.bodies.size(); ++b)
    for (auto& [id, p] : spec.bodies[b].element_degrees)
      if (const auto it = offsets_[b].find(id); it != offsets_[b].end())
        for (int& d : p) d = std::clamp(d + it->second, min_degree, model::kMaxDegree);
}

}  // namespace hpcontact::adapt
