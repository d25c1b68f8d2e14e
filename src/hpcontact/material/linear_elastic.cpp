// Elasticity matrices: the 3D law and the plane ones.
#include "hpcontact/material/linear_elastic.hpp"

#include <cmath>
#include <string>

#include "hpcontact/core/error.hpp"

namespace hpcontact::material {

void LinearElastic::validate(const std::string& where) const {
  HPC_REQUIRE(std::isfinite(youngs_modulus) && youngs_modulus > 0, InputError, where,
              ".E: Young's modulus must be > 0 (got ", youngs_modulus, ")");
  HPC_REQUIRE(std::isfinite(poisson_ratio) && poisson_ratio > -1 && poisson_ratio < 0.5, InputError,
              where, ".nu: Poisson's ratio must satisfy -1 < nu < 0.5 (got ", poisson_ratio, ")");
}

Elasticity LinearElastic::D() const {
  const double E = youngs_modulus, nu = poisson_ratio;
  Elasticity D = Elasticity::Zero();
  if (plane != Plane::stress) {
    const double c = E / ((1 + nu) * (1 - 2 * nu));
    D << c * (1 - nu), c * nu, 0, c * nu, c * (1 - nu), 0, 0, 0, c * (1 - 2 * nu) / 2;
  } else {
    const double c = E / (1 - nu * nu);
    D << c, c * nu, 0, c * nu, c, 0, 0, 0, c * (1 - nu) / 2;
  }
  return D;
}

Elasticity3 LinearElastic::D3() const {
  const double l = lambda(), m = mu();
  Elasticity3 D = Elasticity3::Zero();
  D.topLeftCorner<3, 3>().setConstant(l);
  D.diagonal() << l + 2 * m, l + 2 * m, l + 2 * m, m, m, m;
  return D;
}

double LinearElastic::sigma_zz(const Voigt& sigma) const {
  return plane == Plane::strain ? poisson_ratio * (sigma(0) + sigma(1)) : 0.0;
}

double LinearElastic::lambda() const {
  const double nu = poisson_ratio;
  return youngs_modulus * nu / ((1 + nu) * (1 - 2 * nu));
}

double LinearElastic::mu() const { return youngs_modulus / (2 * (1 + poisson_ratio)); }

double LinearElastic::plane_modulus() const {
  return plane == Plane::stress ? youngs_modulus
                                : youngs_modulus / (1 - poisson_ratio * poisson_ratio);
}

Voigt LinearElastic::axisymmetric_stress(const Voigt& eps, double eps_hoop, double* hoop) const {
  const double l = lambda(), l2m = D()(0, 0);  // λ + 2μ
  if (hoop) *hoop = l * (eps(0) + eps(1)) + l2m * eps_hoop;
  return D() * eps + l * eps_hoop * Voigt(1, 1, 0);
}

}  // namespace hpcontact::material
