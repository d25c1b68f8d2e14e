// summary.json's reactions, path.csv's reaction columns and the equilibrium warning.
#include "hpcontact/driver/reaction_report.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>

namespace hpcontact::driver {

namespace {

nlohmann::json vec_json(const Vec2& v) { return {v.x() + 0.0, v.y() + 0.0}; }

nlohmann::json moment_json(double m) { return std::isnan(m) ? nlohmann::json() : nlohmann::json(m); }

/// The components a constraint entry prescribes: ["ux"], ["uy"] or both.
nlohmann::json components_json(const model::ConstraintSpec& c) {
  nlohmann::json j = nlohmann::json::array();
  if (c.ux) j.push_back("ux");
  if (c.uy) j.push_back("uy");
  return j;
}

}  // namespace

nlohmann::json reactions_json(const model::ProblemSpec& spec, const model::Reactions& r) {
  nlohmann::json supports = nlohmann::json::array();
  for (const auto& s : r.supports) {
    const auto& c = spec.bodies[s.body].constraints[s.constraint];
    supports.push_back({{"body", spec.bodies[s.body].name},
                        {"constraint", s.constraint},
                        {"edges", c.edge_sets},
                        {"nodes", c.nodes},
                        {"components", components_json(c)},
                        {"force", vec_json(s.reaction.force)},
                        {"moment", moment_json(s.reaction.moment)}});
  }
  nlohmann::json pairs = nlohmann::json::array();
  for (size_t k = 0; k < r.pairs.size(); ++k)
    pairs.push_back({{"pair", k},
                     {"body", spec.contact[k].body},
                     {"force", vec_json(r.pairs[k].force)},
                     {"moment", moment_json(r.pairs[k].moment)}});
  nlohmann::json balance = nlohmann::json::array();
  for (size_t b = 0; b < r.balance.size(); ++b) {
    const auto& bb = r.balance[b];
    balance.push_back({{"body", spec.bodies[b].name},
                       {"reactions", vec_json(bb.reactions)},
                       {"loads", vec_json(bb.loads)},
                       {"contact", vec_json(bb.contact)},
                       {"imbalance", vec_json(bb.imbalance)},
                       {"relative", bb.relative}});
  }
  return {{"supports", supports},
          {"pairs", pairs},
          {"balance", balance},
          {"equilibrium_limit", kEquilibriumLimit},
          {"moment_about", {0.0, 0.0}},
          {"shared_dofs", "a dof that two constraint entries prescribe belongs to the first listed"}};
}

std::optional<std::string> equilibrium_warning(const model::ProblemSpec& spec, const model::Reactions& r) {
  if (!(r.equilibrium_residual > kEquilibriumLimit)) return std::nullopt;
  size_t worst = 0;
  for (size_t b = 0; b < r.balance.size(); ++b)
    if (r.balance[b].relative > r.balance[worst].relative) worst = b;
  const auto& bb = r.balance[worst];
  std::ostringstream os;
  os << std::setprecision(3) << spec.file << ": the forces on body '" << spec.bodies[worst].name
     << "' do not balance: reactions (" << bb.reactions.x() << ", " << bb.reactions.y()
     << ") + loads (" << bb.loads.x() << ", " << bb.loads.y() << ") + contact ("
     << bb.contact.x() << ", " << bb.contact.y() << ") leave " << bb.relative
     << " of the largest force (limit " << kEquilibriumLimit << "): the solve's residual is "
        "that large (solver.tolerance " << spec.solver.tolerance << " is relative to the "
        "residual's norm; make it smaller), or a force acts where the reactions do not see it";
  return os.str();
}

std::string reaction_header(const model::ProblemSpec& spec, const model::Reactions& r) {
  std::ostringstream os;
  for (const auto& s : r.supports) {
    const std::string name = "reaction_" + spec.bodies[s.body].name + "_" + std::to_string(s.constraint);
    os << ',' << name << "_x," << name << "_y," << name << "_moment";
  }
  os << ",equilibrium_residual";
  return os.str();
}

std::string reaction_row(const model::Reactions& r) {
  std::ostringstream os;
  os << std::setprecision(12);
  for (const auto& s : r.supports) {
    os << ',' << s.reaction.force.x() << ',' << s.reaction.force.y() << ',';
    if (!std::isnan(s.reaction.moment)) os << s.reaction.moment;
  }
  os << ',' << r.equilibrium_residual;
  return os.str();
}

}  // namespace hpcontact::driver
