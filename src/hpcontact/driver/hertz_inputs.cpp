// The closed forms' inputs of a pair: E* and R* from both bodies, the force from the load.
#include "hpcontact/driver/hertz_inputs.hpp"

#include <cmath>
#include <limits>
#include <sstream>

#include "hpcontact/analytic/hertz.hpp"
#include "hpcontact/core/error.hpp"
#include "hpcontact/geometry/curve.hpp"

namespace hpcontact::driver {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// The radius of a body's contact edges where they are arcs of one circle (positive where the
/// body lies inside the circle, convex; negative where outside, a hole), ∞ where they are
/// straight and on one line; nullopt where they are neither.
std::optional<double> edges_radius(const model::Body& body, const std::vector<int>& edges) {
  std::optional<Vec2> centre;
  double radius = 0;
  int straight = 0;
  for (const int e : edges) {
    const auto& edge = body.mesh.edge(e);
    const auto* arc = dynamic_cast<const geometry::CircularArc*>(edge.curve.get());
    if (!arc) {
      if (edge.curve) return std::nullopt;  // a parametric curve
      ++straight;
      continue;
    }
    const double tol = 1e-9 * arc->radius();
    if (centre && ((arc->center() - *centre).norm() > tol || std::abs(arc->radius() - radius) > tol))
      return std::nullopt;
    centre = arc->center();
    radius = arc->radius();
  }
  if (straight == static_cast<int>(edges.size())) {
    // one line: every end point on the line through the first edge
    const Vec2 a = body.mesh.node(body.mesh.edge(edges.front()).v0);
    const Vec2 t = (body.mesh.node(body.mesh.edge(edges.front()).v1) - a).normalized();
    for (const int e : edges)
      for (const int v : {body.mesh.edge(e).v0, body.mesh.edge(e).v1}) {
        const Vec2 r = body.mesh.node(v) - a;
        if (std::abs(r.x() * t.y() - r.y() * t.x()) > 1e-9 * (1 + r.norm())) return std::nullopt;
      }
    return kInfinity;
  }
  if (straight > 0) return std::nullopt;
  // Convex where the element on the first edge lies inside the circle.
  const auto& edge = body.mesh.edge(edges.front());
  Vec2 c = Vec2::Zero();
  for (const int v : body.mesh.quad(edge.quads[0])) c += body.mesh.node(v) / 4.0;
  return (c - *centre).norm() < radius ? radius : -radius;
}

/// E' of the element at the pair's first contact edge of `body`; InputError naming `where`.
double body_modulus(const model::Body& body, const std::vector<int>& edges, const std::string& where) {
  HPC_REQUIRE(!body.finite_strain(), InputError, where,
              ": Hertz and Shtayerman are the linear theory: body '", body.name,
              "' has a finite-strain material (bodies[].material.model)");
  const auto& m = body.material_of(body.mesh.edge(edges.front()).quads[0]);
  return analytic::contact_modulus(m.youngs_modulus, m.poisson_ratio, m.plane != material::Plane::stress);
}

std::string number(double v) {
  std::ostringstream os;
  os.precision(10);
  os << v;
  return os.str();
}

}  // namespace

HertzInputs hertz_inputs(const model::ProblemSpec& spec, const model::Discretization& d,
                         const std::vector<model::ContactPair>& pairs, size_t k) {
  const auto& cs = spec.contact[k];
  const auto& cmp = *cs.compare;
  const auto& pair = pairs[k];
  const model::Body& body = d.bodies[pair.body];
  HertzInputs in;
  in.where = cmp.where.str();
  const std::string& w = in.where;

  // The materials: E*.
  in.modulus = body_modulus(body, pair.edges, w);
  in.other_modulus = pair.other >= 0 ? body_modulus(d.bodies[pair.other], pair.other_edges, w) : kInfinity;
  in.effective_modulus = analytic::pair_modulus(in.modulus, in.other_modulus);

  // The radii: R*.
  const auto own = edges_radius(body, pair.edges);
  if (cmp.radius > 0) {
    HPC_REQUIRE(!own || std::isinf(*own) || std::abs(std::abs(*own) - cmp.radius) <= 1e-6 * cmp.radius,
                InputError, w, ".radius: ", cmp.radius, " contradicts the body's contact edges, arcs of radius ",
                std::abs(*own), " (leave radius out to use theirs)");
    in.radius = cmp.radius;
  } else {
    HPC_REQUIRE(own && std::isfinite(*own) && *own > 0, InputError, w,
                ".radius: required: the contact edges of body '", body.name,
                "' are not convex arcs of one circle, so their radius cannot be derived");
    in.radius = *own;
  }
  std::optional<double> derived;  // the obstacle's radius where the obstacle fixes it
  bool fixed = false;             // a plane or a rigid circle: a given value must agree
  switch (cs.obstacle.kind) {
    case model::ObstacleKind::plane: derived = kInfinity; fixed = true; break;
    case model::ObstacleKind::circle:
      derived = cs.obstacle.inside ? -cs.obstacle.radius : cs.obstacle.radius;
      fixed = true;
      break;
    case model::ObstacleKind::curve:
    case model::ObstacleKind::profile: derived = kInfinity; break;
    case model::ObstacleKind::body: derived = edges_radius(d.bodies[pair.other], pair.other_edges); break;
  }
  if (cmp.other_radius) {
    const double r2 = *cmp.other_radius;
    HPC_REQUIRE(r2 != 0, InputError, w, ".other_radius: must not be 0 (a plane is infinite: leave it out)");
    HPC_REQUIRE(!fixed || (std::isfinite(*derived) && std::abs(r2 - *derived) <= 1e-6 * std::abs(*derived)),
                InputError, w, ".other_radius: ", r2, " contradicts the obstacle, ",
                std::isinf(*derived) ? std::string("a plane (infinite radius)")
                                     : "a circle of radius " + number(*derived) +
                                           (cs.obstacle.inside ? " (inside: negative)" : ""),
                " (leave other_radius out)");
    in.other_radius = r2;
  } else {
    HPC_REQUIRE(derived, InputError, w, ".other_radius: required: the contact edges of body '",
                d.bodies[pair.other].name, "' are neither arcs of one circle nor one straight line");
    in.other_radius = *derived;
  }
  const double curvature = 1 / in.radius + 1 / in.other_radius;
  HPC_REQUIRE(curvature > 0, InputError, w, ": 1/radius + 1/other_radius = 1/", in.radius, " + 1/",
              in.other_radius, " is not positive: a concave obstacle must be wider than the body (|R_2| > R_1)");
  in.effective_radius = 1 / curvature;

  // A symmetric half (the contact boundary on one side of obstacle.point) or a whole model.
  double lo = kInfinity, hi = -kInfinity;
  for (const auto& cp : pair.points) {
    lo = std::min(lo, pair.coordinate(cp.X));
    hi = std::max(hi, pair.coordinate(cp.X));
  }
  const double tol = 1e-6 * body.mesh.size();
  in.axisymmetric = body.axisymmetric();
  // An axisymmetric section with the axis is the whole solid of revolution (its resultant the total).
  in.models_of_whole = in.axisymmetric ? 1 : lo >= -tol || hi <= tol ? 2 : 1;
  in.side = lo >= -tol || hi > tol ? 1 : -1;

  // The force: given, or from the target of force control (pair 0, its normal along the
  // controlled component).
  const auto& tr = spec.solver.target_resultant;
  std::optional<double> from_target;
  if (k == 0 && tr && std::abs(std::abs(pair.normal()(tr->component)) - 1) < 1e-9)
    from_target = in.models_of_whole * std::abs(tr->value);
  if (cmp.force > 0) {
    in.force = cmp.force;
    in.force_given = true;
    HPC_REQUIRE(!from_target || std::abs(cmp.force - *from_target) <= 1e-6 * *from_target, InputError, w,
                ".force: ", cmp.force, " contradicts solver.target_resultant.value = ", tr->value,
                ", which makes F = ", *from_target,
                in.models_of_whole == 2 ? " on the whole cylinder (this model is its symmetric half: F/2)"
                                        : " (a whole model)",
                "; leave compare.force out to derive it");
  } else {
    in.force = from_target;
  }
  return in;
}

double carried_force(const HertzInputs& in, const model::ContactPair& pair,
                     const model::ContactResult& result) {
  return in.models_of_whole * std::abs(result.resultant.dot(pair.normal()));
}

double comparison_force(const HertzInputs& in, const model::ContactPair& pair,
                        const model::ContactResult& result) {
  return in.force ? *in.force : carried_force(in, pair, result);
}

}  // namespace hpcontact::driver
