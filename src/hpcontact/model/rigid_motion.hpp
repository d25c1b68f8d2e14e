// Which rigid-body motions of a body its prescribed displacements leave free.
#pragma once

#include <string>
#include <vector>

#include "hpcontact/geometry/vec2.hpp"

namespace hpcontact::model {

struct Discretization;
struct ProblemSpec;

/// One prescribed displacement component (0: x, 1: y) at a point of a body.
struct PointConstraint {
  Vec2 at;
  int component = 0;
};

/// The rigid motions u = (a - θ y, b + θ x) that no constraint stops (u_c(at) = 0 for every
/// constraint), described in words: "every rigid-body motion (nothing is prescribed)",
/// "translation in x", "translation along (0.6, 0.8)", "rotation about (1, 2)",
/// "translation in y and rotation". Empty when the constraints hold the body. `size` is the
/// body's extent, which makes the rotation comparable with the translations.
std::vector<std::string> free_rigid_motions(const std::vector<PointConstraint>& constraints,
                                            double size);

/// The constraints of body b of a discretisation: its vertices with a prescribed component.
std::vector<PointConstraint> prescribed_vertices(const Discretization& d, int b);

/// A body in no contact pair must be held by its constraints against every rigid-body motion,
/// else its stiffness is singular: InputError naming the body, its place in the file and the
/// free motions. (A body in contact may rely on the contact; that shows when the tangent is
/// factorised, see explain_singular.)
void require_held(const ProblemSpec& spec, const Discretization& d);

/// Where a global dof is: "body 'name', node 12, ux" (or an edge or internal mode).
std::string describe_dof(const Discretization& d, int dof);

/// What may make a tangent singular at unknown `row` (a free dof's index, -1: unknown): where
/// that unknown is, and the bodies that only contact holds, with the motions it must stop.
/// `frictional[b]`: a pair with friction touches body b (how the contact can hold it differs).
std::string explain_singular(const Discretization& d, int row, const std::vector<char>& frictional = {});

}  // namespace hpcontact::model
