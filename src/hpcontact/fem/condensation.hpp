// Static condensation of the internal (bubble) modes of one element.
#pragma once

#include <vector>

#include <Eigen/Dense>

namespace hpcontact::fem {

/// Splits the local dofs of an element (component-blocked, n_modes per component, n_components
/// components: 2 in the plane, 3 for a hexahedron; the last n_internal modes internal) into external and internal ones and eliminates the internal ones:
///   K_c = K_ee - K_ei K_ii^{-1} K_ie,   f_c = f_e - K_ei K_ii^{-1} f_i.
/// The internal solution is recovered from the external one by u_i = K_ii^{-1} (λ f_i - K_ie u_e),
/// λ the factor on the load f.
struct CondensedElement {
  std::vector<int> external, internal;  ///< local dof indices
  Eigen::MatrixXd K;                    ///< condensed stiffness over `external`
  Eigen::VectorXd f;                    ///< condensed load over `external`
  Eigen::MatrixXd Kii_inv_Kie;          ///< K_ii^{-1} K_ie
  Eigen::VectorXd Kii_inv_fi;           ///< K_ii^{-1} f_i

  /// Full local vector (component-blocked) from the external values, under the load
  /// load_factor × f: u_e at `external`, K_ii⁻¹ (load_factor f_i − K_ie u_e) at `internal`.
  Eigen::VectorXd recover(const Eigen::VectorXd& u_external, double load_factor = 1) const;
};

CondensedElement condense(const Eigen::MatrixXd& K, const Eigen::VectorXd& f, int n_modes,
                          int n_internal, int n_components = 2);

}  // namespace hpcontact::fem
