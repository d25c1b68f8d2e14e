// A root of a scalar function in a bracket by the Pegasus method (seed §4.7).
#pragma once

#include <cmath>

namespace hpcontact {

/// A root of f in [a, b], given fa = f(a) and fb = f(b) of opposite signs (or one of them zero),
/// by the Pegasus method: regula falsi whose retained end has its value scaled by
/// f_b / (f_b + f_c), which keeps the convergence superlinear where plain regula falsi stalls.
/// Stops when |f| <= f_tol or the bracket is narrower than x_tol.
template <class F>
double pegasus_root(F&& f, double a, double b, double fa, double fb, double f_tol,
                    double x_tol = 1e-15, int max_iterations = 100) {
  if (fa == 0) return a;
  if (fb == 0) return b;
  double c = b;
  for (int it = 0; it < max_iterations && std::abs(b - a) > x_tol; ++it) {
    c = b - fb * (b - a) / (fb - fa);
    const double fc = f(c);
    if (std::abs(fc) <= f_tol) break;
    if (fc * fb < 0) {
      a = b;
      fa = fb;
    } else {
      fa *= fb / (fb + fc);
    }
    b = c;
    fb = fc;
  }
  return c;
}

}  // namespace hpcontact
