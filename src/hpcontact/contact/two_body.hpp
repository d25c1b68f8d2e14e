// Normal penalty contact between two deformable bodies: one body's Gauss points against the
// other's deformed boundary, with the consistent tangent on the dofs of both.
#pragma once

#include <vector>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include "hpcontact/contact/contact_boundary.hpp"
#include "hpcontact/contact/deformable_boundary.hpp"
#include "hpcontact/contact/penalty.hpp"

namespace hpcontact::contact {

/// The points of body s against the boundary of body m (its displacement set).
///
/// At each point x_s the gap is g = (x_s − x_m)·n_m at the closest point x_m(ξ) of the deformed
/// boundary of m, n_m its outward normal, and Π = ½ ε_N ∫ <−g>² ds (seed eq. 3.22) with the
/// point weights scaled by `weight_factor` (½ when the pair is evaluated from both sides, seed
/// §3.6). With t = ∂x_m/∂ξ, a = t·t, κ = n·∂²x_m/∂ξ², c = a − gκ and the vectors over the dofs
/// of both bodies G_n = ∂g/∂u, G_t = ∂[(x_s − x_m)·t]/∂u (ξ fixed) and D_n = ∂(n·t)/∂u,
/// the linearisation of δg is δuᵀ M Δu with
///   M = −[D_n (G_t + g D_n)ᵀ / c + G_t D_nᵀ / a + κ G_t (G_t + g D_n)ᵀ / (a c)]   (symmetric),
/// and the tangent of an active point is w (ε_N G_n G_nᵀ − p_N M), p_N = ε_N <−g>.
/// force_s and force_m receive the contact forces −∂Π/∂u on each body's dofs; `tangent` (may
/// be null) the triplets of ∂²Π/∂u², rows and columns offset by offset_s and offset_m.
///
/// With friction, an anchored active point has g_T = (x_s − x_m(anchor))·τ (τ frozen), G_T =
/// ∂g_T/∂u (N_s τ on s, −N_m(anchor) τ on m), the forces −w t_T G_T and the tangent
/// w G_T ∂t_T/∂uᵀ: ε_T G_T G_Tᵀ in stick, −μ s ε_N G_T G_nᵀ in slip (not symmetric).
void two_body_contact(const std::vector<ContactPoint>& points, const Eigen::VectorXd& u_s,
                      const DeformableBoundary& master, double eps_n, double weight_factor,
                      Eigen::VectorXd& force_s, Eigen::VectorXd& force_m,
                      std::vector<Eigen::Triplet<double>>* tangent, int offset_s, int offset_m,
                      std::vector<PointState>* states, FrictionInput friction = {});

}  // namespace hpcontact::contact
