// The displacement a force target causes, against what double precision and elasticity allow.
#include "hpcontact/model/load_scale.hpp"

#include <algorithm>
#include <cmath>

#include "hpcontact/core/error.hpp"

namespace hpcontact::model {

namespace {

/// The smallest Young's modulus of a body (its regions' included).
double softest(const Body& body) {
  double E = body.material.youngs_modulus;
  for (const auto& m : body.region_materials) E = std::min(E, m.youngs_modulus);
  return E;
}

}  // namespace

void require_force_scale(const ProblemSpec& spec, const Discretization& d, int body, int other) {
  const auto& tr = spec.solver.target_resultant;
  if (!tr || tr->value == 0) return;
  int b = body;
  if (other >= 0 && softest(d.bodies[other]) < softest(d.bodies[body])) b = other;
  const Body& B = d.bodies[b];
  const double E = softest(B), L = B.mesh.size();
  if (!(E > 0) || !(L > 0)) return;
  const double across = B.axisymmetric() ? L : B.thickness;  // what carries F: E × this × u
  const double u = std::abs(tr->value) / (E * across), share = u / L;
  HPC_REQUIRE(share >= kSmallestRelativeDisplacement && share <= kLargestRelativeDisplacement,
              InputError, spec.solver.where.str(), ".target_resultant.value: a force of ",
              tr->value, " moves body '", B.name, "' (E = ", E, " at ",
              spec.bodies[b].material.where.str(), ", size ", L, ") by about F / (E ",
              B.axisymmetric() ? "L" : "t", ") = ", u, ", ", share, " of its size: ",
              share < kSmallestRelativeDisplacement
                  ? "below what double precision resolves against its coordinates (1e-13 of them)"
                  : "no elastic solution means anything there (strains beyond a million)",
              "; do the units of E and of the force agree?");
}

}  // namespace hpcontact::model
