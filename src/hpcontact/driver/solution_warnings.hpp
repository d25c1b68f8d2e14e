// What a user should know about a solution the run still reports: a section across its axis,
// a contact zone far smaller than the elements that carry it.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Dense>

#include "hpcontact/model/contact_results.hpp"
#include "hpcontact/model/discretization.hpp"
#include "hpcontact/model/problem_spec.hpp"

namespace hpcontact::driver {

/// A contact zone shorter than this share of the contact edges it lies on is resolved by their
/// degree alone: the pressure's shape, its peak and the zone's ends are then the polynomial's.
constexpr double kZoneToEdgeLimit = 0.1;

/// The warnings about a solved state (each names the file, the place and the cause):
/// - an axisymmetric body of linear elasticity whose deformed section crosses its axis;
/// - per contact pair, a contact zone that lies within at most two of its contact edges and is
///   shorter than kZoneToEdgeLimit times the shortest of them;
/// - per singular point of a pair (ContactResult::singular_points), where it is, that its peak
///   is no converged value, and the fitted strength.
std::vector<std::string> solution_warnings(const model::ProblemSpec& spec,
                                           const model::Discretization& d, const Eigen::VectorXd& u,
                                           const std::vector<model::ContactPair>& pairs,
                                           const std::vector<model::ContactResult>& contact);

}  // namespace hpcontact::driver
