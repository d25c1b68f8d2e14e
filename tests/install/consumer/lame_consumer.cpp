// Solves the Lamé thick cylinder of a problem file through the installed library (read,
// discretise, solve, evaluate) and checks the radial displacement against the closed form.
//   lame_consumer PROBLEM.yaml   (examples/lame/thick-cylinder.yaml: a = 10, b = 20, p = 100,
//                                 E = 200000, nu = 0.3, plane strain)
// Prints "u_r(r) = computed (exact ...)" per point; exit 0 if every point agrees to 1e-6
// relative, 1 if not, 2 on an error (its message on stderr).
#include <cmath>
#include <cstdio>
#include <exception>

#include "hpcontact/io/problem_reader.hpp"
#include "hpcontact/model/discretization.hpp"
#include "hpcontact/model/linear_solve.hpp"
#include "hpcontact/post/fields.hpp"
#include "hpcontact/post/point_location.hpp"

namespace {

// Lamé: u_r(r) = (1 + nu)/E ((1 - 2 nu) A r + B / r), A = p a² / (b² - a²), B = A b²
// (plane strain, internal pressure p on r = a, r = b free).
double lame_radial_displacement(double r) {
  const double a = 10, b = 20, p = 100, E = 200000, nu = 0.3;
  const double A = p * a * a / (b * b - a * a), B = A * b * b;
  return (1 + nu) / E * ((1 - 2 * nu) * A * r + B / r);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: lame_consumer PROBLEM.yaml\n");
    return 2;
  }
  try {
    using namespace hpcontact;
    const model::ProblemSpec spec = io::read_problem(argv[1]);
    const model::Discretization d = model::discretize(spec);
    const model::LinearSolution solution = model::solve_linear(d, {});
    const post::PointLocator locator(d);
    bool ok = true;
    for (double r : {10.0, 12.5, 15.0, 20.0}) {
      const double angle = 0.3;  // any direction of the quarter: the solution is radial
      const Vec2 X(r * std::cos(angle), r * std::sin(angle));
      const auto at = locator.locate(X);
      if (!at) {
        std::fprintf(stderr, "lame_consumer: %s: point (%g, %g) is in no element\n", argv[1], X.x(), X.y());
        return 2;
      }
      const post::PointResult v = post::evaluate(d.bodies[at->body], at->element, at->xi, at->eta, solution.u);
      const double computed = v.u.dot(X) / r, exact = lame_radial_displacement(r);
      const bool close = std::abs(computed - exact) <= 1e-6 * std::abs(exact);
      std::printf("u_r(%g) = %.12g (exact %.12g)%s\n", r, computed, exact, close ? "" : "  MISMATCH");
      ok = ok && close;
    }
    return ok ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lame_consumer: %s\n", e.what());
    return 2;
  }
}
