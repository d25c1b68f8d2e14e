// The contact system's residual and tangent: the elastic operator, finite-strain bodies, the
// penalty forces and the multiplier constraints of every pair, on the unknowns of the solve.
#include "hpcontact/model/contact_system.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

#include "hpcontact/core/error.hpp"
#include "hpcontact/model/follower_forces.hpp"

namespace hpcontact::model {

ContactSystem::ContactSystem(const Discretization& d, const std::vector<ContactPair>& pairs,
                             bool condense, Tangent tangent,
                             std::shared_ptr<const ElasticOperator> elastic)
    : d_(d),
      pairs_(pairs),
      op_(elastic ? std::move(elastic)
                  : std::make_shared<const ElasticOperator>(
                        assemble_elastic(d, condense && !d.finite_strain()))),
      K_uu_(op_->unknown_block(d)),
      finite_(d),
      tangent_(tangent),
      n_u_(op_->n_unknowns) {
  HPC_ASSERT(op_->K.rows() == d.n_dofs, "the elastic operator given is of another discretisation");
  // per exact pair: its normal multipliers, then (with friction) its tangential ones
  for (const auto& pair : pairs_) {
    z_offset_.push_back(pair.constraints ? n_z_ : -1);
    if (pair.constraints) n_z_ += pair.constraints->size() * (pair.constraints->has_friction() ? 2 : 1);
  }
  gamma_ = Eigen::VectorXd::Zero(n_z_);
  initial_overlap_.resize(pairs_.size());
  for (size_t k = 0; k < pairs_.size(); ++k)
    if (const auto& c = pairs_[k].constraints; c && c->ramp_interference)
      initial_overlap_[k] = initial_overlaps(d_, pairs_[k]);
  // The augmentation keeps the displacement block definite where only the contact holds a body
  // or the finite-strain tangent is indefinite. Bodies held by their constraints at small strain
  // need none: the Newton step is the same, and the block is K at every iteration (one
  // factorisation per solve, SaddlePointSolver).
  const bool held = std::all_of(d_.bodies.begin(), d_.bodies.end(),
                                [](const Body& b) { return b.free_rigid_motions.empty(); });
  const bool augmented = !held || d_.finite_strain();
  for (size_t k = 0; augmented && k < pairs_.size(); ++k)
    if (const auto& c = pairs_[k].constraints) {
      // the rows κ_j ∇G_j augment the tangent by (κ_j² / γ_j) ∇G_j ∇G_jᵀ = ε_j W_j ∇ĝ_j ∇ĝ_jᵀ
      const Eigen::VectorXd k2w = c->scale.cwiseProduct(c->scale).cwiseProduct(c->weight);
      gamma_.segment(z_offset_[k], c->size()) = k2w.cwiseQuotient(c->augmentation);
      if (c->has_friction())
        gamma_.segment(z_offset_[k] + c->size(), c->size()) = k2w.cwiseQuotient(c->tangential_augmentation);
    }
  K_prescribed_ = op_->K * d_.prescribed;
  unknown_of_dof_.resize(d_.n_dofs);
  for (int dof = 0; dof < d_.n_dofs; ++dof) unknown_of_dof_[dof] = op_->unknown(d_, dof);
  u_committed_ = Eigen::VectorXd::Zero(d_.n_dofs);
  u_step_start_ = u_committed_;
  step_slips_.resize(pairs_.size());
  total_slips_.resize(pairs_.size());
}

void ContactSystem::set_factors(const Vec2& displacements, double loads) {
  factors_ = displacements;
  lambda_f_ = loads;
  for (const auto& pair : pairs_)
    if (pair.moving) pair.moving->set_load_factors(displacements);
}

void ContactSystem::set_force_target(std::optional<std::pair<int, double>> target, bool scales_loads) {
  HPC_ASSERT(!target || (!pairs_.empty() && pairs_.front().constraints), "force target needs an exact first pair");
  if (target.has_value() != target_.has_value()) {
    n_z_ += target ? 1 : -1;
    gamma_.conservativeResize(n_z_);
    if (target) gamma_(n_z_ - 1) = 0;
  }
  target_ = target;
  target_scales_loads_ = scales_loads;
}

Vec2 ContactSystem::displacement_factors(const Eigen::VectorXd& x) const {
  return target_ ? Vec2(x(size() - 1), x(size() - 1)) : factors_;
}

Eigen::VectorXd ContactSystem::prescribed(const Vec2& factors) const {
  if (factors.x() == factors.y()) return factors.x() * d_.prescribed;
  // a body's dofs are (x, y) per mode from an even offset
  Eigen::VectorXd v = d_.prescribed;
  for (int i = 0; i < v.size(); ++i) v(i) *= factors(i % 2);
  return v;
}

double ContactSystem::loads_factor(const Eigen::VectorXd& x) const {
  return target_ && target_scales_loads_ ? x(size() - 1) : lambda_f_;
}

void ContactSystem::commit(const Eigen::VectorXd& x) {
  if (!has_friction()) return;
  committed_friction_ = friction_resultants(x);
  const Eigen::VectorXd u = full(x);
  // exact friction measures slips from here
  u_step_start_ = u_committed_;
  factors_step_start_ = factors_committed_;
  u_committed_ = u;
  factors_committed_ = displacement_factors(x);
  for (const auto& pair : pairs_)
    if (pair.memory) commit_friction(pair, pair_forces(d_, pair, u, nullptr));
  // the slip the step just converged made at each node, added to the path's
  step_slips_ = measure_step_slips(x);
  for (size_t k = 0; k < pairs_.size(); ++k) {
    if (total_slips_[k].size() != step_slips_[k].size())
      total_slips_[k] = Eigen::VectorXd::Zero(step_slips_[k].size());
    total_slips_[k] += step_slips_[k];
  }
}

FrictionInputs ContactSystem::friction_inputs(const ContactPair& pair, const Eigen::VectorXd& lambda_t,
                                              const Eigen::VectorXd& u_from, const Vec2& factors_from,
                                              const Vec2& factors) const {
  FrictionInputs fi;
  fi.lambda_t = &lambda_t;
  fi.u_committed = &u_from;
  if (pair.moving) fi.obstacle_increment = (factors - factors_from).cwiseProduct(pair.moving->direction());
  return fi;
}

std::vector<Eigen::VectorXd> ContactSystem::measure_step_slips(const Eigen::VectorXd& x) const {
  std::vector<Eigen::VectorXd> slips(pairs_.size());
  const Eigen::VectorXd u = full(x);
  const Vec2 factors = displacement_factors(x);
  for (size_t k = 0; k < pairs_.size(); ++k) {
    const ContactPair& pair = pairs_[k];
    if (!pair.constraints || !pair.constraints->has_friction()) continue;
    const PairConstraints& c = *pair.constraints;
    const int o = n_u_ + z_offset_[k];
    const Eigen::VectorXd lambda = x.segment(o, c.size());
    const Eigen::VectorXd lambda_t = x.segment(o + c.size(), c.size());
    const ConstraintState s =
        evaluate_constraints(d_, pair, u, lambda, nullptr, nullptr, false,
                             friction_inputs(pair, lambda_t, u_step_start_, factors_step_start_, factors));
    slips[k] = Eigen::VectorXd::Zero(c.size());
    for (int j = 0; j < c.size(); ++j)
      if (c.weight(j) != 0.0 && s.GT.size() == c.size()) slips[k](j) = s.GT(j) / c.weight(j);
  }
  return slips;
}

Eigen::VectorXd ContactSystem::load_vector() const { return op_->restrict(d_, op_->load); }

Eigen::VectorXd ContactSystem::load_vector(const Eigen::VectorXd& x) const {
  if (d_.follower_loads.empty()) return load_vector();
  const Eigen::VectorXd u = full(x);
  Eigen::VectorXd f = op_->load;
  for (size_t i = 0; i < d_.follower_loads.size(); ++i) {
    const FollowerLoad& L = d_.follower_loads[i];
    const WetRange all{0, static_cast<double>(L.edges.size()), false};
    add_follower_force(d_, L, u, i < wet_ranges_.size() ? wet_ranges_[i] : all, 1.0, f, nullptr);
  }
  return op_->restrict(d_, f);
}

bool ContactSystem::has_friction() const {
  for (const auto& pair : pairs_)
    if (pair.memory || (pair.constraints && pair.constraints->has_friction())) return true;
  return false;
}

void ContactSystem::activate_touching(Eigen::VectorXd& x) const {
  const Eigen::VectorXd u = full(x);
  for (size_t k = 0; k < pairs_.size(); ++k) {
    const ContactPair& pair = pairs_[k];
    if (!pair.constraints) continue;
    const PairConstraints& c = *pair.constraints;
    const double touching = 1e-9 * d_.bodies[pair.body].mesh.size();
    const std::vector<char> at = touching_nodes(d_, pair, touching);
    const int o = n_u_ + z_offset_[k];
    const ConstraintState s = evaluate_constraints(d_, pair, u, x.segment(o, c.size()), nullptr, nullptr,
                                                   false, {}, relief(k, displacement_factors(x).y()));
    for (int j = 0; j < c.size(); ++j)
      if (s.found[j] && c.weight(j) > 0 && at[j])  // touching or overlapping
        x(o + j) = std::max(x(o + j), (1 + 1e-9) * c.scale(j) * std::max(0.0, s.G(j)) / c.weight(j));
  }
}

InterferenceRelief ContactSystem::relief(size_t k, double f) const {
  // g + (1 − f) o: at f = 0 the overlapping bodies just touch, at f = 1 the input's overlap holds
  if (initial_overlap_[k].size() == 0 || f >= 1) return {};
  return {&initial_overlap_[k], 1 - f};
}

bool ContactSystem::has_unsymmetric_tangent() const {
  if (has_friction()) return true;
  for (const auto& pair : pairs_)
    if (pair.constraints && pair.constraints->mean_normal) return true;
  return false;
}

Eigen::VectorXd ContactSystem::unknowns(const Eigen::VectorXd& u,
                                        const std::vector<Eigen::VectorXd>& multipliers) const {
  Eigen::VectorXd x = Eigen::VectorXd::Zero(size());
  x.head(n_u_) = op_->restrict(d_, u);
  for (size_t k = 0; k < pairs_.size() && k < multipliers.size(); ++k)
    if (z_offset_[k] >= 0 && multipliers[k].size() == n_multipliers(k))
      x.segment(n_u_ + z_offset_[k], multipliers[k].size()) = multipliers[k];
  if (target_) x(size() - 1) = factors_.y();
  return x;
}

std::vector<Eigen::VectorXd> ContactSystem::multipliers(const Eigen::VectorXd& x) const {
  std::vector<Eigen::VectorXd> m(pairs_.size());
  for (size_t k = 0; k < pairs_.size(); ++k)
    if (z_offset_[k] >= 0) {
      m[k] = x.segment(n_u_ + z_offset_[k], n_multipliers(k));
      fill_passive_multipliers(*pairs_[k].constraints, m[k]);
    }
  return m;
}

Eigen::VectorXd ContactSystem::full(const Eigen::VectorXd& x) const {
  const Vec2 f = displacement_factors(x);
  if (f.x() == f.y()) return op_->expand(d_, x.head(n_u_), f.x());
  return op_->expand(d_, x.head(n_u_), 0.0) + prescribed(f);
}

Eigen::VectorXd ContactSystem::solution(const Eigen::VectorXd& x) const {
  Eigen::VectorXd u = full(x);
  op_->recover_internal(d_, u, loads_factor(x));
  return u;
}

Eigen::VectorXd ContactSystem::homogeneous_field(const Eigen::VectorXd& x) const {
  Eigen::VectorXd u = op_->expand(d_, x.head(n_u_), 0.0);
  op_->recover_internal(d_, u, 0.0);
  return u;
}

double ContactSystem::force_scale(const Eigen::VectorXd& x) const {
  const Eigen::VectorXd f = op_->K * prescribed(displacement_factors(x));
  const Eigen::VectorXd u = full(x);
  Eigen::VectorXd g = op_->K * u;
  if (!finite_.empty()) finite_.add(u, g, nullptr, nullptr);
  // the follower loads over all of their edges
  Eigen::VectorXd follower = Eigen::VectorXd::Zero(d_.n_dofs);
  for (const FollowerLoad& L : d_.follower_loads)
    add_follower_force(d_, L, u, WetRange{0, static_cast<double>(L.edges.size()), false},
                       loads_factor(x), follower, nullptr);
  return op_->restrict(d_, f).norm() + std::abs(loads_factor(x)) * op_->restrict(d_, op_->load).norm() +
         op_->restrict(d_, g).norm() + op_->restrict(d_, follower).norm();
}

void ContactSystem::evaluate(const Eigen::VectorXd& x, Eigen::VectorXd& r, solve::SparseMatrix* K) {
  if (K && tangent_ != Tangent::analytic) {
    PairStates undisturbed;
    residual(x, r, nullptr, &undisturbed, nullptr);
    *K = finite_difference_tangent(x, tangent_ == Tangent::seed_difference ? &undisturbed : nullptr);
    return;
  }
  Triplets T;
  solve::SparseMatrix K_finite;
  residual(x, r, K ? &T : nullptr, nullptr, nullptr, K ? &K_finite : nullptr);
  if (!K) return;
  previous_tangent_states_ = std::move(tangent_states_);
  tangent_states_ = states_;
  solve::SparseMatrix Kc(size(), size());
  Kc.setFromTriplets(T.begin(), T.end());
  if (K_finite.nonZeros() > 0) {
    K_finite.conservativeResize(size(), size());
    Kc = K_finite + Kc;
  }
  if (K_uu_.nonZeros() == 0) {  // finite-strain bodies alone: their triplets are the tangent
    K->swap(Kc);
    return;
  }
  if (n_z_ == 0) {
    *K = K_uu_ + Kc;
    return;
  }
  // K_uu_ widened to the whole system: empty columns and rows added, its entries as they are
  // (made again only when the unknowns change in number: a force target set or cleared)
  if (K_uu_wide_.rows() != size()) {
    K_uu_wide_ = K_uu_;
    K_uu_wide_.conservativeResize(size(), size());
    K_uu_wide_.makeCompressed();
  }
  *K = K_uu_wide_ + Kc;
}

int ContactSystem::states_changed() const {
  if (std::none_of(pairs_.begin(), pairs_.end(), [](const ContactPair& p) { return p.constraints != nullptr; }))
    return -1;
  if (previous_tangent_states_.size() != tangent_states_.size()) return static_cast<int>(tangent_states_.size());
  int changed = 0;
  for (std::size_t k = 0; k < tangent_states_.size(); ++k) changed += tangent_states_[k] != previous_tangent_states_[k];
  return changed;
}

double ContactSystem::admissible_step(const Eigen::VectorXd& x, const Eigen::VectorXd& dx) const {
  if (!target_) return 1;
  const double a = x(size() - 1), da = dx(size() - 1);
  if (!(std::abs(a) > 0)) return 1;
  // α + τ Δα within [α/2, 2α]
  const double limit = da > 0 ? std::abs(a) : 0.5 * std::abs(a);
  return std::abs(da) > limit ? limit / std::abs(da) : 1.0;
}

std::string ContactSystem::describe() const {
  std::ostringstream os;
  os << std::setprecision(4);
  for (std::size_t k = 0; k < pairs_.size(); ++k) {
    if (z_offset_[k] < 0 || k >= deepest_.size()) continue;
    const int o = z_offset_[k], m = pairs_[k].constraints->size();
    int active = 0, changed = 0;
    for (int j = 0; j < m; ++j) {
      active += states_[o + j] != 0;
      if (tangent_states_.size() == states_.size() && previous_tangent_states_.size() == states_.size())
        changed += tangent_states_[o + j] != previous_tangent_states_[o + j];
    }
    if (os.tellp() > 0) os << "; ";
    os << "contact[" << k << "]: " << active << " of " << m << " multiplier nodes active, " << changed
       << " changed at the last tangent";
    if (deepest_[k].gap < 0)
      os << ", largest penetration " << -deepest_[k].gap << " at (" << deepest_[k].x.x() << ", "
         << deepest_[k].x.y() << ")";
    else
      os << ", no penetration";
  }
  return os.str();
}

std::vector<Vec2> ContactSystem::friction_resultants(const Eigen::VectorXd& x) const {
  const auto z = multipliers(x);
  std::vector<Vec2> out(pairs_.size(), Vec2::Zero());
  for (std::size_t k = 0; k < pairs_.size(); ++k) {
    const auto& c = pairs_[k].constraints;
    if (!c || !c->has_friction()) continue;
    const int m = c->size();
    for (int j = 0; j < m; ++j) out[k] += c->weight(j) * Vec2(z[k](j), z[k](m + j));
  }
  return out;
}

std::string ContactSystem::capacity_used() const {
  std::ostringstream os;
  os << std::setprecision(4);
  for (std::size_t k = 0; k < committed_friction_.size(); ++k) {
    const auto& c = pairs_[k].constraints;
    if (!c || c->friction.kind != contact::FrictionLaw::Kind::coulomb) continue;
    const double normal = committed_friction_[k].x(), capacity = c->friction.mu * normal;
    if (!(capacity > 0)) continue;
    const double share = std::abs(committed_friction_[k].y()) / capacity;
    if (share < 0.9) continue;
    os << "; there contact[" << k << "] carries " << 100 * share << " % of the tangential force its "
       << "friction can (mu = " << c->friction.mu << " times the normal force " << normal
       << "): a tangential load at the capacity or above it has no (unique) equilibrium";
  }
  return os.str();
}

void ContactSystem::factorize(solve::LinearSolver& sparse, const solve::SparseMatrix& K) {
  if (n_z_ == 0) return sparse.factorize(K);
  saddle_.factorize(sparse, K, n_u_, gamma_);
}

Eigen::VectorXd ContactSystem::solve(const solve::LinearSolver& sparse, const Eigen::VectorXd& b) const {
  if (n_z_ == 0) return sparse.solve(b);
  return saddle_.solve(sparse, b);
}

void ContactSystem::residual(const Eigen::VectorXd& x, Eigen::VectorXd& r, Triplets* T,
                             PairStates* states, const PairStates* frozen,
                             solve::SparseMatrix* K_finite) const {
  const Vec2 factors = displacement_factors(x);
  if (target_)
    for (const auto& pair : pairs_)
      if (pair.moving) pair.moving->set_load_factors(factors);
  const Eigen::VectorXd u = full(x);
  Eigen::VectorXd R = op_->K * u - loads_factor(x) * op_->load;
  // The tangent's triplets on all dofs (finite strain, penalty contact, curvature of the
  // multiplier constraints), mapped onto the unknowns below.
  Triplets t_all;
  Triplets* t = T ? &t_all : nullptr;
  r = Eigen::VectorXd::Zero(size());
  // (under force control the finite-strain triplets on prescribed dofs make the factor's column)
  const bool in_place = T && K_finite && !target_;
  if (!finite_.empty() && !(in_place ? finite_.add(u, R, unknown_of_dof_, n_u_, *K_finite, &failure_)
                                     : finite_.add(u, R, t, &failure_))) {
    // An inverted element has no internal force: a not-finite residual makes Newton stop and
    // the load step be cut.
    r.setConstant(std::numeric_limits<double>::quiet_NaN());
    return;
  }
  if (states) states->resize(pairs_.size());
  // per pair, where its points or nodes are in contact (for pressure penetration; not needed
  // while the fronts are held)
  std::vector<std::vector<ContactMark>> marks(has_penetration() && !frozen_wet_ranges_ ? pairs_.size() : 0);
  points_in_contact_ = 0;
  states_.assign(n_z_, 0);
  // Rows of z, filled per exact pair; their u-parts as (row, dof of all dofs, value).
  Triplets z_rows;
  for (size_t k = 0; k < pairs_.size(); ++k) {
    const ContactPair& pair = pairs_[k];
    if (!pair.constraints) {
      PairForces f = pair_forces(d_, pair, u, t, frozen ? &(*frozen)[k] : nullptr);
      for (const auto* side : {&f.states, &f.other_states})
        for (const auto& s : *side) points_in_contact_ += s.pressure > 0;
      if (!marks.empty()) add_point_marks(pair, f, marks[k]);
      R.segment(d_.bodies[pair.body].dof_offset, f.body.size()) -= f.body;
      if (pair.other >= 0) R.segment(d_.bodies[pair.other].dof_offset, f.other.size()) -= f.other;
      if (states) (*states)[k] = std::move(f.states);
      continue;
    }
    const PairConstraints& c = *pair.constraints;
    const int o = n_u_ + z_offset_[k];
    const Eigen::VectorXd lambda = x.segment(o, c.size());
    const bool tangential = c.has_friction();
    const Eigen::VectorXd lambda_t = tangential ? Eigen::VectorXd(x.segment(o + c.size(), c.size()))
                                                : Eigen::VectorXd();
    const FrictionInputs fi = tangential ? friction_inputs(pair, lambda_t, u_committed_, factors_committed_, factors)
                                         : FrictionInputs{};
    const ConstraintState s =
        evaluate_constraints(d_, pair, u, lambda, &R, t, T != nullptr, fi, relief(k, factors.y()));
    deepest_.resize(pairs_.size());
    deepest_[k] = {};
    for (const auto& q : s.points)
      if (q.gap < deepest_[k].gap) deepest_[k] = {q.gap, q.x};
    if (states) (*states)[k] = s.points;
    int active_nodes = 0;
    for (int j = 0; j < c.size(); ++j) {
      const bool active = node_active(c, s, lambda, j);
      // an inactive node's row W_j λ_j = 0; a passive one (W_j = 0) is pinned with a regular W
      const double Wj = !c.passive.empty() && c.passive[j] ? c.passive_row_weight : c.weight(j);
      active_nodes += active;
      states_[z_offset_[k] + j] = active;
      if (!marks.empty()) marks[k].push_back(node_mark(pair, j, active ? lambda(j) : 0.0));
      r(o + j) = active ? c.scale(j) * s.G(j) : Wj * lambda(j);
      if (!T) continue;
      for (const auto& [dof, v] : s.dG[j]) {
        // force column ∂r_u/∂λ_j = −∂G_j/∂u, and the row's u-part (zeros when inactive, so that
        // the pattern stays)
        const int i = op_->unknown(d_, dof);
        if (i >= 0) {
          T->emplace_back(i, o + j, -v);
          T->emplace_back(o + j, i, active ? c.scale(j) * v : 0.0);
        } else if (target_ && active) {
          z_rows.emplace_back(o + j, dof, c.scale(j) * v);  // for ∂r_j/∂α
        }
      }
      if (!active) T->emplace_back(o + j, o + j, Wj);
      else if (target_ && pair.moving)
        T->emplace_back(o + j, size() - 1, c.scale(j) * s.dG_dfactor(j));
    }
    points_in_contact_ += active_nodes;
    if (tangential) tangential_rows(c, s, lambda, lambda_t, o, r, T, target_ ? &z_rows : nullptr);
    if (target_ && k == 0) {
      // The target row: s·F_c − F, s the sign of the resultant's component; held (Δα = 0)
      // while no node carries force.
      const int comp = target_->first, row = size() - 1;
      const double F = s.resultant(comp), sign = F < 0 ? -1.0 : 1.0;
      if (active_nodes == 0) {
        // No node carries force: the factor grows (as if the force grew with it, F ∝ α: the
        // step doubles α). Never a solution: the residual is the whole target.
        r(row) = -target_->second;
        if (T) T->emplace_back(row, row, target_->second / std::max(std::abs(factors.y()), 1e-300));
      } else {
        r(row) = sign * F - target_->second;
        if (T) {
          for (int j = 0; j < c.size(); ++j)
            if (const double v = sign * s.d_resultant[j](comp); v != 0.0) T->emplace_back(row, o + j, v);
          if (tangential)
            for (int j = 0; j < c.size(); ++j)
              if (const double v = sign * s.d_resultant_t[j](comp); v != 0.0)
                T->emplace_back(row, o + c.size() + j, v);
        }
      }
    }
  }
  Eigen::VectorXd follower_force;
  add_follower_loads(u, loads_factor(x), marks, R, t, target_ && target_scales_loads_ ? &follower_force : nullptr);
  r.head(n_u_) = op_->restrict(d_, R);
  if (!T) return;
  T->reserve(T->size() + t_all.size());
  for (const auto& e : t_all) {
    const int i = op_->unknown(d_, e.row()), j = op_->unknown(d_, e.col());
    if (i >= 0 && j >= 0) T->emplace_back(i, j, e.value());
  }
  if (target_) {
    // ∂r/∂α: the prescribed displacements' column of the tangent (linear bodies: K u_p; the
    // finite-strain and contact parts from their triplets) less the loads when they follow α,
    // and of the active constraint rows.
    const int col = size() - 1;
    Eigen::VectorXd column = K_prescribed_;
    if (target_scales_loads_) column -= op_->load;
    if (follower_force.size()) column -= follower_force;
    for (const auto& e : t_all)
      if (const double up = d_.prescribed(e.col()); up != 0.0) column(e.row()) += e.value() * up;
    const Eigen::VectorXd cu = op_->restrict(d_, column);
    for (int i = 0; i < n_u_; ++i)
      if (cu(i) != 0.0) T->emplace_back(i, col, cu(i));
    for (const auto& e : z_rows)
      if (const double up = d_.prescribed(e.col()); up != 0.0) T->emplace_back(e.row(), col, e.value() * up);
  }
}

bool ContactSystem::has_penetration() const {
  return std::any_of(d_.follower_loads.begin(), d_.follower_loads.end(),
                     [](const FollowerLoad& L) { return L.penetration.has_value(); });
}

void ContactSystem::add_follower_loads(const Eigen::VectorXd& u, double loads_factor,
                                       const std::vector<std::vector<ContactMark>>& marks,
                                       Eigen::VectorXd& R, std::vector<Eigen::Triplet<double>>* t,
                                       Eigen::VectorXd* f) const {
  wet_ranges_.resize(d_.follower_loads.size());
  if (f) *f = Eigen::VectorXd::Zero(d_.n_dofs);
  Eigen::VectorXd force = Eigen::VectorXd::Zero(d_.n_dofs);
  std::vector<Eigen::Triplet<double>> stiffness;
  for (size_t i = 0; i < d_.follower_loads.size(); ++i) {
    const FollowerLoad& L = d_.follower_loads[i];
    static const std::vector<ContactMark> none;
    wet_ranges_[i] = frozen_wet_ranges_ ? (*frozen_wet_ranges_)[i]
                     : wetted_range(L, L.penetration ? marks[L.penetration->pair] : none, loads_factor);
    add_follower_force(d_, L, u, wet_ranges_[i], 1.0, force, t ? &stiffness : nullptr);
  }
  if (freeze_next_) {
    frozen_wet_ranges_ = wet_ranges_;
    freeze_next_ = false;
  }
  // R = ... − λ f(u): its tangent −λ ∂f/∂u
  R -= loads_factor * force;
  if (f) *f = force;
  if (t)
    for (const auto& e : stiffness) t->emplace_back(e.row(), e.col(), -loads_factor * e.value());
}

void ContactSystem::tangential_rows(const PairConstraints& c, const ConstraintState& s,
                                    const Eigen::VectorXd& lambda, const Eigen::VectorXd& lambda_t,
                                    int o, Eigen::VectorXd& r, Triplets* T, Triplets* z_rows) const {
  const int m = c.size();
  for (int j = 0; j < m; ++j) {
    const int row = o + m + j;
    const double W = c.weight(j), cT = c.scale(j);
    // held: a sticking node whose slip no unknown moves (on a symmetry line, its tangent along
    // the held direction: the axis node of a half model); its λ_T is the support's and is pinned
    // to 0 (else the row is zero and the system singular). Decided at each tangent, kept between.
    using State = TangentialState;
    State state = State::open;
    double sign = 1;
    if (node_active(c, s, lambda, j)) {
      state = State::stick;
      bool held = false;
      if (T) {
        double free = 0, all = 0;  // |∂G_T/∂u| over the unknowns and over all dofs
        for (const auto& [dof, v] : s.dGT[j]) {
          all += std::abs(v);
          if (op_->unknown(d_, dof) >= 0) free += std::abs(v);
        }
        held = free <= 1e-10 * all;  // round-off of a normal that is the held direction's
      } else {
        held = tangent_states_.size() == states_.size() &&
               tangent_states_[row - n_u_] == static_cast<char>(State::held);
      }
      if (held) state = State::held;
      if (!held && c.friction.kind == contact::FrictionLaw::Kind::coulomb) {
        // the trial traction against the augmented normal pressure
        const double trial = lambda_t(j) + cT * s.GT(j) / W;
        const double bound = c.friction.mu * (lambda(j) - c.scale(j) * s.G(j) / W);
        // On the cone to round-off (a step that holds a slipping point where it is: the trial
        // is the bound itself) both rows hold; the point keeps its state of the last tangent,
        // so that round-off does not switch it from one iteration to the next.
        const bool on_cone = std::abs(std::abs(trial) - bound) <= 1e-10 * bound;
        const bool was_slip = tangent_states_.size() == states_.size() &&
                              tangent_states_[row - n_u_] == static_cast<char>(State::slip);
        if (on_cone ? was_slip : std::abs(trial) > bound) {
          state = State::slip;
          sign = trial < 0 ? -1.0 : 1.0;
        }
      }
    }
    states_[row - n_u_] = static_cast<char>(state);
    switch (state) {
      case State::open:
      case State::held: r(row) = W * lambda_t(j); break;
      case State::stick: r(row) = cT * s.GT(j); break;
      case State::slip: r(row) = W * (lambda_t(j) - c.friction.mu * sign * lambda(j)); break;
    }
    if (!T) continue;
    // force column ∂r_u/∂λ_T = +dT_j (the body receives −λ_T τ), and the row's u-part cT ∂G_T/∂u
    for (const auto& [dof, v] : s.dT[j])
      if (const int i = op_->unknown(d_, dof); i >= 0) T->emplace_back(i, row, v);
    for (const auto& [dof, v] : s.dGT[j]) {
      const int i = op_->unknown(d_, dof);
      if (i >= 0) {
        T->emplace_back(row, i, state == State::stick ? cT * v : 0.0);
      } else if (z_rows && state == State::stick) {
        z_rows->emplace_back(row, dof, cT * v);
      }
    }
    if (state != State::stick) T->emplace_back(row, row, W);
    if (state == State::slip) T->emplace_back(row, o + j, -W * c.friction.mu * sign);
  }
}

namespace {

/// The seed's difference tangent solves the symmetric part of the displacement block ("symmetric
/// equation system"): central differences are symmetric there up to round-off and up to columns
/// straddling a contact switch. The rows and columns of the multipliers and of the bordered
/// force are left as differenced: the saddle-point system is not symmetric (an inactive
/// multiplier's row is the multiplier itself, its column the constraint's), and averaging it
/// with its transpose mixed the two (Newton cycled between two residuals with no multiplier
/// node active).
void symmetrize_displacement_block(std::vector<Eigen::Triplet<double>>& t, int n_u) {
  std::vector<Eigen::Triplet<double>> s;
  s.reserve(t.size() + t.size() / 2);
  for (const auto& e : t) {
    if (e.row() < n_u && e.col() < n_u) {
      s.emplace_back(e.row(), e.col(), 0.5 * e.value());
      s.emplace_back(e.col(), e.row(), 0.5 * e.value());
    } else {
      s.push_back(e);
    }
  }
  t = std::move(s);
}

}  // namespace

solve::SparseMatrix ContactSystem::finite_difference_tangent(const Eigen::VectorXd& x,
                                                             const PairStates* undisturbed) const {
  std::vector<Eigen::Triplet<double>> t;
  Eigen::VectorXd xd = x, r_plus, r_minus;
  for (int m = 0; m < size(); ++m) {
    const double h = 1e-6 * (std::abs(x(m)) + 1e-3);
    xd(m) = x(m) + h / 2;
    residual(xd, r_plus, nullptr, nullptr, undisturbed);
    xd(m) = x(m) - h / 2;
    residual(xd, r_minus, nullptr, nullptr, undisturbed);
    xd(m) = x(m);
    for (int i = 0; i < size(); ++i)
      if (const double v = (r_plus(i) - r_minus(i)) / h; v != 0) t.emplace_back(i, m, v);
  }
  solve::SparseMatrix K(size(), size());
  if (undisturbed) symmetrize_displacement_block(t, n_u_);
  K.setFromTriplets(t.begin(), t.end());
  return K;
}

}  // namespace hpcontact::model
