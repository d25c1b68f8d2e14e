// The isoparametric h-version converges at the algebraic rates of its degree on a smooth problem.
#include <gtest/gtest.h>

#include <cmath>

#include "hpcontact/driver/run.hpp"
#include "problems.hpp"

using namespace hpcontact;

namespace {
/// Slope beta of log(error) against log(dofs) between two meshes.
double rate(model::LagrangeElement el, int n1, int n2) {
  double e[2], n[2];
  int k = 0;
  for (int m : {n1, n2}) {
    auto spec = test_problems::lame_quarter(m, 2 * m);
    spec.discretization.method = model::Method::h;
    spec.discretization.element = el;
    const auto s = driver::run_problem(spec, {}).summary;
    e[k] = *s.error->energy_norm_rel_percent;
    n[k] = s.dofs;
    ++k;
  }
  return -std::log(e[1] / e[0]) / std::log(n[1] / n[0]);
}
}  // namespace

// Under uniform refinement of the Lamé cylinder the energy-norm error falls like N^-beta with
// beta = p/2: 0.5 for Q4 and 1.0 for Q8 and Q9 (asserted within 0.1).
TEST(HVersion, AlgebraicRatesOnLame) {
  const double q4 = rate(model::LagrangeElement::q4, 8, 16);
  const double q8 = rate(model::LagrangeElement::q8, 4, 8);
  const double q9 = rate(model::LagrangeElement::q9, 4, 8);
  RecordProperty("beta_q4", std::to_string(q4));
  RecordProperty("beta_q8", std::to_string(q8));
  RecordProperty("beta_q9", std::to_string(q9));
  EXPECT_NEAR(q4, 0.5, 0.1);
  EXPECT_NEAR(q8, 1.0, 0.1);
  EXPECT_NEAR(q9, 1.0, 0.1);
}

// The p-version on the same structured mesh (2 × 4 elements) converges exponentially: each
// degree step from 2 to 8 reduces the error at least threefold.
TEST(PVersion, ExponentialOnStructuredLameMesh) {
  double previous = 1e300;
  for (int p = 2; p <= 8; ++p) {
    auto spec = test_problems::lame_quarter(2, 4);
    spec.discretization.degree = {p, p};
    const double e = *driver::run_problem(spec, {}).summary.error->energy_norm_rel_percent;
    EXPECT_LT(e, previous / 3) << "p = " << p;
    previous = e;
  }
}
