// Why a contact solve fails, said for the user (see contact_solve_failure.hpp).
#include "hpcontact/model/contact_solve_failure.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "hpcontact/model/contact_results.hpp"
#include "hpcontact/model/contact_system.hpp"
#include "hpcontact/model/rigid_motion.hpp"

namespace hpcontact::model {

std::string newton_failure_reason(const solve::SolveReport& report, const Discretization& d,
                                  const std::vector<ContactPair>& pairs,
                                  const ContactSystem& system) {
  std::string why = report.message;
  if (report.status == solve::SolveStatus::not_finite && !system.failure().empty())
    why += " (" + system.failure() + ")";
  if (report.status == solve::SolveStatus::singular) {
    std::vector<char> frictional(d.bodies.size(), 0);
    for (const auto& pair : pairs)
      if (pair.friction.active() || (pair.constraints && pair.constraints->has_friction()))
        for (int b : {pair.body, pair.other})
          if (b >= 0) frictional[b] = 1;
    const std::string where = explain_singular(d, report.singular_row, frictional);
    if (!where.empty()) why += " (" + where + ")";
  }
  return why;
}

bool same_residuals(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.empty() || a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (!(std::abs(a[i] - b[i]) <= 1e-12 * std::max(std::abs(a[i]), std::abs(b[i])))) return false;
  return true;
}

bool still_converging(const std::vector<double>& r) {
  if (r.size() < 4) return false;
  const auto last_half = r.begin() + static_cast<std::ptrdiff_t>(r.size() / 2);
  const double largest = *std::max_element(last_half, r.end());
  const double smallest = *std::min_element(last_half, r.end());
  return r.back() == smallest && r.back() <= 0.1 * largest;
}

std::string failed_step_message(const StepFailure& f) {
  std::ostringstream os;
  os << "load step " << f.step << " (" << f.factors << ") failed after " << f.cuts
     << " cuts: " << f.reason;
  if (f.repeated)
    os << "; halving the step repeated the same residuals: what does not converge does not "
          "change with the load step — bodies overlapping in the input (an interference, "
          "which no load scales: contact[].interference: ramp relieves it step by step) or "
          "a state the step starts from; more cuts cannot help";
  if (f.slow) {
    os << "; Newton was still converging when its iterations ran out (solver.max_iterations = "
       << f.max_iterations << "; over the last half of them the residual fell tenfold or more and was still falling): "
          "raise solver.max_iterations";
    if (f.cuts > 0)
      os << " (the last of " << f.cuts << " halvings was converging too: too few iterations, "
                                          "rather than a load beyond what the pairs can carry, "
                                          "is the likely cause)";
  } else if (f.at_capacity)
    os << "; the load cannot be carried beyond the last converged step (" << f.last_converged
       << "): a step from it of 1/" << (1LL << f.cuts) << " of a load step (solver.max_cuts = "
       << f.max_cuts << " halvings) does not converge" << f.capacity_used;
  os << "; residual history:";
  for (double r : f.residuals) os << ' ' << r;
  return os.str();
}

std::string no_force_to_scale(const SolverSpec& ss, const Discretization& d,
                              const ContactPair& pair, const Eigen::VectorXd& u,
                              const Eigen::VectorXd* multipliers, double factor, const Vec2& R) {
  const auto& tr = *ss.target_resultant;
  const char* axis = tr.component == 0 ? "x" : "y";
  std::ostringstream os;
  os << ss.where.str() << ".target_resultant: the prescribed displacements (factor " << factor
     << ") give the contact resultant (" << R.x() << ", " << R.y() << "), no force in " << axis
     << " to scale to the target " << tr.value << ": ";
  const ContactResult c = evaluate_contact(d, pair, u, multipliers);
  double closest = std::numeric_limits<double>::infinity();
  for (const auto& st : c.states) closest = std::min(closest, st.gap);
  if (d.prescribed.cwiseAbs().maxCoeff() == 0)
    os << "no displacement is prescribed, and force control scales only prescribed "
          "displacements (give the push as ux or uy)";
  else if (std::abs(R(1 - tr.component)) > 0)
    os << "the force is in " << (tr.component == 0 ? "y" : "x")
       << "; is target_resultant.component right?";
  else if (closest > 0)
    os << "the body does not reach the obstacle (its closest contact point stays " << closest
       << " away): give a larger push, or check the obstacle's position and normal and the push's "
          "sign";
  else
    os << "points touch the obstacle but press on nothing (is the push's sign right?)";
  return os.str();
}

}  // namespace hpcontact::model
