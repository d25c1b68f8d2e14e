// The problem description as plain data: what a problem file says, validated once when read.
#pragma once

#include <array>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace hpcontact::model {

/// The largest polynomial degree an input may ask for (discretization.degree, per element).
inline constexpr int kMaxDegree = 30;

/// Every real number of a problem file (values, coordinates, numbers and values of formulas) is
/// 0 or of a magnitude in [1/kMaxMagnitude, kMaxMagnitude] (formulas: at most kMaxMagnitude):
/// products of a few of them (a modulus times a length squared times a displacement) then stay
/// inside double precision's 1e±308.
constexpr double kMaxMagnitude = 1e100;

/// Where a value came from, for messages: "thick-cylinder.yaml:12:5: bodies[0].material.nu".
struct SourceRef {
  std::string file;
  int line = 0;  ///< 1-based; 0 when unknown (e.g. a --set override)
  int column = 0;
  std::string key;  ///< dotted key path with [i] indices
  std::string origin;  ///< "" when the value is in the file; else "from --set" or "default"
  /// "file:line:col: key (origin)", leaving out the parts that are unknown or empty.
  std::string str() const;
};

enum class PlaneMode { plane_strain, plane_stress, axisymmetric };

struct MaterialSpec {
  std::string model = "linear-elastic";
  double youngs_modulus = 0;  ///< E [force/length²] (not of a rubber law)
  double poisson_ratio = 0;   ///< ν (not of a rubber law)
  /// A rubber law's constants (material/rubber.hpp) [force/length²]; those the law does not
  /// take stay 0.
  double C10 = 0, C01 = 0, C20 = 0, C30 = 0, K = 0;
  /// A rubber law with 1/K = 0 (K not given): J = 1, held by the mixed element's pressure.
  bool incompressible = false;
  /// A rubber law's element: "displacement" (W of u alone) or "mixed" (u and an element-wise
  /// pressure, fem/mixed_finite_strain.hpp).
  std::string formulation = "displacement";
  PlaneMode plane = PlaneMode::plane_strain;
  double thickness = 1.0;  ///< out-of-plane thickness [length]
  SourceRef where;
};

enum class CurveKind { arc, parametric };

/// Exact geometry of one mesh edge between two nodes (user ids), oriented from node a to node b.
struct CurveSpec {
  int node_a = 0, node_b = 0;
  CurveKind kind = CurveKind::arc;
  std::array<double, 2> center{0, 0};  ///< arc
  double radius = 0;                   ///< arc
  int ccw = 0;                         ///< arc: +1 counter-clockwise, -1 clockwise, 0 shorter arc
  std::string x_expr, y_expr;          ///< parametric: x(s), y(s) for s in [0, 1] from node a to b
  SourceRef where;
};

/// A set of mesh edges, each given by its two end nodes (user ids).
struct EdgeSetSpec {
  std::string name;
  std::vector<std::array<int, 2>> edges;
  SourceRef where;
};

/// A prescribed displacement component on edges and/or nodes; value may be an expression in x, y.
struct ConstraintSpec {
  std::vector<std::string> edge_sets;  ///< names of EdgeSetSpec
  std::vector<int> nodes;              ///< user node ids
  std::optional<std::string> ux, uy;   ///< number or expression in x, y; unset = free
  SourceRef where;
};

enum class LoadKind { pressure, traction };

/// Load profile shapes along the loaded part, parameter t in [0, 1] from its start to its end:
/// constant 1; linear 1 - t; bspline1 (1 - t)² (one-sided quadratic B-spline, ½(1-t)² up to scale);
/// bspline2 1 - 3t² (t <= ⅓), 1.5(1 - t)² (t >= ⅓): the right half of the uniform quadratic
/// B-spline from its peak, C1 at the joint (eq. 4.9 scaled to 1 at t = 0); hermite 1 - 3t² + 2t³
/// (eq. 4.10 mapped from [-1, 1] and scaled to 1 at t = 0); expression: a user formula in x, y.
enum class LoadShape { constant, linear, bspline1, bspline2, hermite, expression };

/// Distributed load on edges: pressure (normal, positive pushes into the body) or traction (vector).
struct EdgeLoadSpec {
  std::vector<std::string> edge_sets;
  LoadKind kind = LoadKind::pressure;
  std::array<double, 2> value{0, 0};  ///< pressure: value[0]; traction: (tx, ty) at t = 0
  std::optional<double> resultant;    ///< if set, scales the load so its |∫ load ds| equals it
  LoadShape shape = LoadShape::constant;
  std::string expression;  ///< shape == expression: formula in x, y multiplying value
  char along = 'x';        ///< coordinate along which t runs: 'x' or 'y'
  std::optional<std::array<double, 2>> interval;  ///< [start, end] in that coordinate; default: whole edges
  /// A pressure on the deformed boundary (finite strain; the dead pressure in the linear theory).
  bool follower = false;
  /// Pressure penetration: the follower pressure stops at the first point in contact of a pair.
  struct Penetration {
    int contact = 0;        ///< the pair's index in ProblemSpec::contact
    bool from_end = false;  ///< pressurised from the end of the edges' chain (else its start)
    SourceRef where;
  };
  std::optional<Penetration> penetration;
  SourceRef where;
};

/// Concentrated force at a node (user id).
struct NodalForceSpec {
  int node = 0;
  std::array<double, 2> force{0, 0};
  SourceRef where;
};

/// Elements of a body with their own elastic constants (same law and plane as the body's).
struct MaterialRegionSpec {
  std::vector<int> elements;  ///< element ids
  MaterialSpec material;
  SourceRef where;
};

struct BodySpec {
  std::string name;
  MaterialSpec material;
  std::vector<MaterialRegionSpec> regions;
  std::vector<int> node_ids;
  std::vector<std::array<double, 2>> nodes;
  std::vector<int> element_ids;
  std::vector<std::array<int, 4>> elements;  ///< user node ids, counter-clockwise
  std::vector<CurveSpec> curves;
  std::optional<std::array<int, 2>> degree;  ///< (p_xi, p_eta) for all elements; default: discretization.degree
  std::map<int, std::array<int, 2>> element_degrees;  ///< per element user id
  std::vector<EdgeSetSpec> edge_sets;
  std::vector<ConstraintSpec> constraints;
  std::vector<EdgeLoadSpec> edge_loads;
  std::vector<NodalForceSpec> nodal_forces;
  std::array<double, 2> body_force{0, 0};  ///< force per volume
  SourceRef where;
};

enum class Method { p, h };
enum class ShapeSpace { tensor_product, trunk };
enum class LagrangeElement { q4, q8, q9 };

struct DiscretizationSpec {
  Method method = Method::p;
  std::array<int, 2> degree{4, 4};  ///< p-version default (p_xi, p_eta)
  ShapeSpace space = ShapeSpace::tensor_product;
  LagrangeElement element = LagrangeElement::q8;  ///< h-version element
  int quadrature_extra = 2;  ///< Gauss points per direction = max(p_xi, p_eta) + quadrature_extra
  bool condense = false;     ///< static condensation of internal modes
  SourceRef where;
};

/// Load control by a target force: the prescribed displacements are scaled by the factor for
/// which the contact resultant's component equals `value` (the Hertz case: v such that F/2).
struct TargetResultantSpec {
  double value = 0;
  int component = 1;  ///< 0: x, 1: y
  double tolerance = 1e-9;  ///< relative
};

/// One stage of the load path: the factors on the prescribed displacements and on the loads
/// go linearly from the previous stage's (0, 0 at the start) to these, in `steps` load steps.
struct LoadStageSpec {
  double displacements = 1, loads = 1;
  int steps = 0;  ///< 0: solver.load_steps
  /// The factors on the prescribed displacements' x and y components where they differ from
  /// `displacements` (a stage that pushes sideways with the press held).
  std::optional<double> x_displacements, y_displacements;
  double displacements_x() const { return x_displacements.value_or(displacements); }
  double displacements_y() const { return y_displacements.value_or(displacements); }
  bool per_direction() const { return displacements_x() != displacements_y(); }
};

struct SolverSpec {
  std::string linear = "cholmod";  ///< "cholmod" or "ldlt"
  std::string tangent = "analytic";  ///< "analytic" or "finite-difference" (seed eq. 3.36)
  int load_steps = 1;
  int max_iterations = 30;   ///< Newton iterations per load step
  double tolerance = 1e-10;  ///< relative residual norm
  int max_cuts = 5;          ///< halvings of a load step that does not converge
  std::string line_search = "auto";  ///< "auto" (on with friction), "on", "off"
  std::string control = "load";  ///< "load" (load steps) or "arc-length" (cylindrical, on the loads)
  /// A node whose displacement the load path records (path.csv): body name and node id.
  std::string monitor_body;
  int monitor_node = 0;
  std::optional<TargetResultantSpec> target_resultant;
  /// The load path; empty: one stage to (1, 1).
  std::vector<LoadStageSpec> stages;
  SourceRef where;
};

enum class ObstacleKind { plane, circle, curve, profile, body };

/// A rigid obstacle: a plane through `point` with outward `normal` (towards the body), a
/// circle (the body outside it, or inside it with `inside`), a curve through `points` (the body
/// on its left), a profile (segments through `points`, corners sharp or filleted, the body on
/// its left), or another body.
struct ObstacleSpec {
  ObstacleKind kind = ObstacleKind::plane;
  std::array<double, 2> point{0, 0}, normal{0, 1};
  std::array<double, 2> center{0, 0};
  double radius = 0;
  bool inside = false;
  std::vector<std::array<double, 2>> points;  ///< curve, profile: the points it passes through
  std::vector<double> fillets;  ///< profile: a fillet radius per corner (empty: all sharp)
  bool closed = false;          ///< profile: the last point joined to the first
  std::array<double, 2> displacement{0, 0};  ///< rigid ones: moved by λ × this
  std::string body;                    ///< body: the other deformable body
  std::vector<std::string> edge_sets;  ///< body: its contact edge sets
};

/// Closed forms (Hertz, Shtayerman for the exact circle) and an optional reference curve to
/// measure the contact pressure against (docs/cases.md §1). x runs along the obstacle from its point.
struct PressureCompareSpec {
  /// Radius of the body's surface at the contact [length]; 0: derived from its contact edges.
  double radius = 0;
  /// Radius of the obstacle's surface (negative: concave) [length]; nullopt: derived.
  std::optional<double> other_radius;
  /// Force on the whole cylinder per unit thickness [force/length]; 0: derived from the load.
  double force = 0;
  std::string reference;  ///< CSV (x, pressure) of a reference run; empty: none
  SourceRef where;
};

/// Friction of a contact pair (seed §3.3): none, full stick, or Coulomb, with a tangential penalty.
struct FrictionSpec {
  std::string law = "none";  ///< "none", "stick" or "coulomb"
  double mu = 0;             ///< Coulomb coefficient
  double penalty = 0;        ///< eps_T > 0
  SourceRef where;
};

/// How a pair's contact condition is enforced: exactly, with the pressure as an unknown at the
/// multiplier nodes (augmented Lagrangian: g_N ≥ 0, λ ≥ 0, λ g_N = 0), or by the seed's
/// penalty at the Gauss points (eq. 3.19: the pressure ε_N <−g_N>, some penetration).
enum class Enforcement { augmented_lagrangian, penalty };

/// Where an exact constraint is imposed: at the multiplier nodes (the Gauss–Lobatto points of
/// each contact edge: g_N(x_j) ≥ 0), or weighted by each node's polynomial over its edges
/// (mortar: ∫ L_j g_N ds ≥ 0, integrated on segments between the other body's element
/// boundaries); auto: collocation against a rigid obstacle, mortar against another body.
enum class ConstraintRule { automatic, mortar, collocation };

/// A contact boundary of a body against a rigid obstacle or another body.
struct ContactPairSpec {
  std::string body;                    ///< body name
  std::vector<std::string> edge_sets;  ///< its contact edges
  ObstacleSpec obstacle;
  Enforcement enforcement = Enforcement::augmented_lagrangian;
  ConstraintRule constraint = ConstraintRule::automatic;
  /// Between two bodies, exact enforcement: the gap along the mean of both boundaries' normals
  /// (two-sided) instead of the other body's normal (one-sided).
  bool mean_normal = false;
  /// Exact enforcement: an overlap of the bodies in the input (an interference fit) is relieved
  /// in proportion to the factor on the prescribed displacements, closed at factor 1, instead of
  /// being there from the start (contact[].interference: ramp).
  bool ramp_interference = false;
  /// Between two bodies, exact enforcement: the program chooses which body carries the
  /// multipliers (contact[].carrier: auto; model/contact_carrier.hpp), instead of `body`.
  bool auto_carrier = false;
  /// How the carrier was chosen, for summary.json: empty as written, else "auto: " and the rule
  /// that chose it (with_chosen_carriers, which then swaps body and obstacle where it says so).
  std::string carrier_choice;
  /// eps_N [force/length³]: the penalty; with augmented_lagrangian the augmentation (0: the
  /// default E p² / h at each node), a parameter of convergence speed, not of the answer.
  double penalty = 0;
  int quadrature = 50;  ///< Gauss points per contact edge, independent of p (seed: 50)
  std::optional<PressureCompareSpec> compare;
  FrictionSpec friction;
  /// The direction the pair's normal force is measured along (unit; the force on the body,
  /// positive along it); none: a plane's normal, else the resultant's direction.
  std::optional<std::array<double, 2>> normal_direction;
  SourceRef where;
};

/// A closed-form solution to measure the error against.
struct ExactSpec {
  std::string type;  ///< "" (none), "lame" (thick cylinder) or "lame_sphere"
  double inner_radius = 0, outer_radius = 0;
  double inner_pressure = 0, outer_pressure = 0;
  std::array<double, 2> center{0, 0};
  SourceRef where;
};

struct OutputSpec {
  bool vtu = true;
  bool steps = false;        ///< a .vtu per converged load step and a .pvd of them
  int vtu_subdivisions = 0;  ///< 0: automatic from the degree
  bool effective_input = true;
  SourceRef where;
};

enum class AdaptMethod { none, rp, hp };

/// hp's degrees: rising, min_degree at Γ* and one more per layer away from it; constant, the
/// input's; goal, rising and corrected step by step where goal-oriented indicators of the contact
/// traction's error show too few or too many (with a tolerance, whose estimate supplies them).
enum class HpDegree { rising, constant, goal };

/// Adaptive mesh changes around the ends of the contact zone (seed §4.7–4.8).
struct AdaptSpec {
  AdaptMethod method = AdaptMethod::none;
  /// rp: stop when |node − Γ*| <= tolerance · body size (default 1e-10); hp, when given: the
  /// requested relative L2 accuracy of the contact pressure, estimated.
  double tolerance = 1e-10;
  bool tolerance_given = false;
  int max_dofs = 200000;     ///< hp with a tolerance: no mesh of more free dofs
  int max_iterations = 20;   ///< rp: relocations after the first solve
  bool secant = true;        ///< rp: secant steps (false: the seed's plain move onto Γ*)
  double factor = 0.5;       ///< hp: size of the corner square per refinement step
  int steps = 8;             ///< hp: refinement steps
  HpDegree degree = HpDegree::rising;  ///< hp (goal by default with a tolerance)
  int min_degree = 1;        ///< hp: degree of the elements at Γ*
  /// rp and hp: adapt to the stick–slip points of exact Coulomb pairs as to the zone ends.
  bool stick_slip = true;
  SourceRef where;
};

struct SolidSpec;

struct ProblemSpec {
  std::string file;  ///< the problem file, for messages
  std::string case_name;
  std::string description;
  /// A 3D problem (`dimension: 3`, model/solid_spec.hpp): its body and discretisation; the 2D
  /// members below are then empty, except output.
  std::shared_ptr<const SolidSpec> solid;
  std::vector<BodySpec> bodies;
  DiscretizationSpec discretization;
  SolverSpec solver;
  std::vector<ContactPairSpec> contact;
  ExactSpec exact;
  AdaptSpec adapt;
  OutputSpec output;
};

}  // namespace hpcontact::model
