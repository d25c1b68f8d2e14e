// Problems built in code for the verification tests: patches, polynomial fields, the quarter circle.
#pragma once

#include <string>

#include <Eigen/Dense>

#include "hpcontact/geometry/vec2.hpp"
#include "hpcontact/model/problem_spec.hpp"

namespace hpcontact::test_problems {

/// A body with the material set and nothing else.
model::BodySpec body(const std::string& name, double E, double nu);

/// Adds node (id, x, y) and element (id, n1..n4) entries.
void add_node(model::BodySpec& b, int id, double x, double y);
void add_element(model::BodySpec& b, int id, int n1, int n2, int n3, int n4);
void add_edge_set(model::BodySpec& b, const std::string& name, std::vector<std::array<int, 2>> edges);

/// Gives element `element_id` its nodes from `node_id` on (the same quad, counter-clockwise
/// still): its edges to neighbours that keep their order then run against theirs, so that odd
/// edge modes carry the orientation sign there.
void start_element_at(model::BodySpec& b, int element_id, int node_id);

/// The square [0,2]² as 2×2 quadrilaterals with the centre node moved to (1.2, 0.75) and the
/// mid-side nodes moved off their straight positions: a distorted patch. Edge set "boundary"
/// holds its 8 boundary edges; "left", "right", "bottom", "top" the sides.
model::ProblemSpec distorted_patch(int p);

/// The distorted patch's body held as a bar in tension: ux = 0 on "left", uy = 0 at node 1 (the
/// minimal supports), and a constant traction (tx, ty) on "right"; replaces its constraints and
/// loads.
void hold_as_bar(model::BodySpec& b, double tx, double ty);

/// Quarter of the Hertz cylinder (R = 10, centre (0, 10)): 2×2 elements, 9 nodes, exact arc,
/// node A on the arc at x = 2.48. Edge sets "symmetry" (x = 0), "centre" (y = 10), "arc".
/// ux = 0 on "symmetry", uy = -0.01 on "centre"; no contact (a linear problem).
model::ProblemSpec quarter_circle_2x2(int p);

/// quarter_circle_2x2 stressed and with shared edges of opposite directions: a pressure of 500
/// on the arc edge 1–2 (the Hertz contact zone), a body force (300, −200) per volume, and
/// element 4 given as (9, 8, 5, 6), so that its edges to elements 2 (5–6) and 3 (5–8) run
/// against theirs and their odd edge modes carry the orientation sign.
model::ProblemSpec quarter_circle_2x2_loaded(int p);

}  // namespace hpcontact::test_problems

namespace hpcontact::test_problems {

/// The Lamé quarter cylinder (radii 10, 20, internal pressure 100, E = 200000, nu = 0.3) as a
/// structured n_r × n_theta mesh with exact arcs; "exact" names the Lamé solution.
model::ProblemSpec lame_quarter(int n_r, int n_theta);

}  // namespace hpcontact::test_problems

namespace hpcontact::model {
struct Body;
struct Discretization;
struct NonlinearSolution;
}  // namespace hpcontact::model

namespace hpcontact::test_problems {

/// The displacement of a body's solution u (all dofs) at local edge le, parameter t of element
/// q, from the element's shape functions (to compare the traces of two neighbours).
Vec2 edge_displacement(const model::Body& body, int q, int le, double t, const Eigen::VectorXd& u);

/// max |K_analytic − K_differences| / max |K_analytic| of the nonlinear system at a converged
/// solution, K_differences the plain central differences of the residual
/// (model::residual_jacobian_by_differences); `asymmetry` (if not null) gets
/// max |K − Kᵀ| / max |K| of the analytic tangent.
double tangent_mismatch(const model::ProblemSpec& spec, const model::Discretization& d,
                        const model::NonlinearSolution& sol, double* asymmetry = nullptr);

}  // namespace hpcontact::test_problems
