#!/usr/bin/python3
"""Mutation testing: does the test suite catch plausible one-line bugs, and by a property?

usage: mutate.py [--build DIR] [--jobs N] [--only ID[,ID...]] [--quick | --full] [--list] [--out FILE]

Each entry of MUTATIONS below changes one line of the library (a wrong sign, factor, index or
bound someone could write). For each, the script replaces the line, rebuilds (incremental Ninja
with ccache: one object and the links), runs the fast suite (what `make test` runs: `ctest -LE
slow`), puts the file back and records which tests failed. The suite runs in two parts: the C++
tests (unit, verification, fuzz replays) with the docs, install and slurm tests (~2 min on 2
cores), then the command-line and Python tests (labels cli, python: one ctest test per pytest
file; 2-5 min) — the second part only when it can change the verdict (no property test has
failed in the first, or the mutation's property tests are command-line ones), unless --full. A
failed pytest file counts as the pytest tests that failed in it. Test processes run with a 4 GB
address-space limit and a 120 s timeout (the pytest files: their own, and the second part
stops after 15 min), since a mutant can loop or allocate without bound on a machine others
share. The file is restored in a `finally` (also on Ctrl-C or SIGTERM), and a copy of the
original is kept in DIR/mutate-backup/ while a mutation is applied, so that a run killed
outright is repaired by the next start. At the end the build is brought back to the sources as
they are.

Every mutation names the tests that check a property it breaks (`expect`: a closed form, a patch
test, a convergence rate, a symmetry, a tangent against differences); it counts as caught only
when one of them fails. A mutation caught by other tests alone (a snapshot, a run that stops
converging) is reported as "other only"; one caught by nothing as "SURVIVED". The table:

  id | module | file:line | mutation | verdict | property tests failed | other tests failed

--quick leaves out the command-line and Python tests altogether; --full runs them for every
mutation (then "other tests failed" lists every failing test). --only runs some mutations;
--list prints them. A run of all 232 takes over two hours on 2 cores (--full: about four). Exit status 0 when every mutation run
was caught by a property test, 1 otherwise, 2 on a usage error.

Left out on purpose: model/contact_solve.cpp (but for its adjoint and its load-step cuts) and contact/penalty.cpp,
two_body.cpp (being rewritten), and mutations that cannot change a result (e.g. the predictor's length in the
arc-length method, which the corrector's constraint overrides).
"""
import argparse
import dataclasses
import os
import re
import resource
import shutil
import signal
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


@dataclasses.dataclass
class Mutation:
    id: str
    module: str
    path: str      # relative to the repository root
    old: str       # the exact text of the line's change (must occur once in the file)
    new: str
    what: str      # the bug, in words
    expect: list   # property tests that must catch it (ctest names or pytest node ids)


def expected(test, m):
    """Whether a failed test is one of the mutation's property tests: its id, or a parametrized
    case of one (`test_x[case]` of `test_x`)."""
    return test in m.expect or test.split("[")[0] in m.expect


S = "src/hpcontact/"
MUTATIONS = [
    # basis
    Mutation("legendre-bonnet", "basis", S + "basis/legendre.cpp",
             "L[n] = ((2 * n - 1) * x * L[n - 1] - (n - 1) * L[n - 2]) / n;",
             "L[n] = ((2 * n - 1) * x * L[n - 1] - (n - 1) * L[n - 2]) / (n + 1);",
             "Bonnet's recursion divided by n + 1",
             ["Legendre.RecursionMatchesClosedForms", "IntegratedLegendre.EqualsIntegralOfLegendre"]),
    Mutation("hierarchic-derivative", "basis", S + "basis/legendre.cpp",
             "if (dN) dN[k] = std::sqrt(0.5 * (2 * k - 1)) * L_km1;",
             "if (dN) dN[k] = std::sqrt(0.5 * (2 * k + 1)) * L_km1;",
             "derivative of the bubble modes with sqrt((2k+1)/2)",
             ["Hierarchic1D.DerivativeMatchesFiniteDifference", "HierarchicQuad.GradientsMatchFiniteDifferences",
              "PatchTest.DirichletConstantStressOnDistortedMesh"]),
    Mutation("edge-orientation-sign", "basis", S + "basis/quad_modes.cpp",
             "return (h.edge_reversed[e] && k % 2 == 1) ? -1.0 : 1.0;",
             "return 1.0;",
             "odd edge modes of a reversed edge keep their sign",
             ["DofNumbering.MinimumRuleKeepsConformity", "HpMesh.RefinementIsConformingAndContinuous",
              "HierarchicQuad.ReversedEdgeFlipsOddModes", "PolynomialReproduction.HarmonicGradientFieldOfDegreeP"]),
    Mutation("gauss-weight", "basis", S + "basis/quadrature.cpp",
             "const double w = 2.0 / D;",
             "const double w = 2.0 / D * (1 + 1e-6);",
             "Gauss–Legendre weights off by a relative 1e-6",
             ["GaussLegendre.ExactForMonomialsUpToDegree2nMinus1", "GaussLegendre.ClosedFormsForSmallN",
              "GaussLegendre.SymmetricAscendingWeightsSumToTwo"]),
    # geometry
    Mutation("blending-jacobian", "geometry", S + "geometry/blending.cpp",
             "    x_eta -= 0.5 * D;",
             "    x_eta += 0.5 * D;",
             "the E1 edge term's eta-derivative with the wrong sign",
             ["BlendingQuad.JacobianMatchesFiniteDifferences", "ElementMapProperties.JacobianMatchesFiniteDifferences"]),
    Mutation("arc-tangent", "geometry", S + "geometry/curve.cpp",
             "return r_ * (t1_ - t0_) * Vec2(-std::sin(t), std::cos(t));",
             "return r_ * Vec2(-std::sin(t), std::cos(t));",
             "the arc's tangent without the chain-rule factor t1 - t0",
             ["CircularArc.DerivativesMatchFiniteDifferences", "CircularArc.QuarterCircleLength",
              "BlendingQuad.AnnularSectorAreaIsExact"]),
    # fem
    Mutation("stiffness-coupling", "fem", S + "fem/elasticity.cpp",
             "K.topRightCorner(n, n) = d12 * XY + d33 * XY.transpose();",
             "K.topRightCorner(n, n) = d12 * XY + d33 * XY;",
             "the shear part of the xy block not transposed",
             ["ElementStiffness.HierarchicStraightSidedRigidBodyNullSpace", "ElementStiffness.EnergyOfConstantStrain",
              "PatchTest.NeumannUniformTensionOnDistortedMesh"]),
    Mutation("jacobian-weight", "fem", S + "fem/element_values.cpp",
             "ev.JxW(k) = rule.weights[i] * rule.weights[j] * det;",
             "ev.JxW(k) = rule.weights[i] * rule.weights[i] * det;",
             "quadrature weight w_i w_i instead of w_i w_j",
             ["PatchTest.DirichletConstantStressOnDistortedMesh", "ElementStiffness.EnergyOfConstantStrain"]),
    Mutation("edge-normal", "fem", S + "fem/edge_load.cpp",
             "if (normal) *normal = (le < 2 ? Vec2(T.y(), -T.x()) : Vec2(-T.y(), T.x())) / len;",
             "if (normal) *normal = (le < 1 ? Vec2(T.y(), -T.x()) : Vec2(-T.y(), T.x())) / len;",
             "the outward normal of local edge E2 turned inwards",
             ["EdgeLoadProperties.UniformPressureOnStraightEdge", "EdgeLoadProperties.UniformPressureOnCircularArc"]),
    Mutation("edge-degree-direction", "fem", S + "fem/dof_map.cpp",
             "pe = (edge.local_edge[s] % 2 == 0) ? deg[0] : deg[1];  // E1, E3 run along xi",
             "pe = (edge.local_edge[s] % 2 == 0) ? deg[1] : deg[0];  // E1, E3 run along xi",
             "an edge's degree taken from the element's other direction",
             ["DofNumbering.MinimumRuleKeepsConformity", "DofMapProperties.MinimumRuleOnSharedEdges"]),
    Mutation("geometric-stiffness", "fem", S + "fem/finite_strain.cpp",
             "G += XY + XY.transpose();",
             "G += XY;",
             "the geometric stiffness's S12 term not symmetrised",
             ["FiniteStrainTangent.AxleInRingAgreesWithCentralDifferences",
              "FiniteStrainElement.TangentAndForceAgreeWithFiniteDifferences"]),
    Mutation("condensation-recovery", "fem", S + "fem/condensation.cpp",
             "const Eigen::VectorXd ui = load_factor * Kii_inv_fi - Kii_inv_Kie * u_external;",
             "const Eigen::VectorXd ui = load_factor * Kii_inv_fi + Kii_inv_Kie * u_external;",
             "internal modes recovered with the coupling's sign flipped",
             ["StaticCondensation.SameDisplacementsAsFullSolve",
              "Condensation.CondensedSolvePlusRecoveryEqualsFullSolve", "Condensation.RecoveryUnderALoadFactor"]),
    # material
    Mutation("cauchy-1-over-J", "material", S + "material/hyperelastic.cpp",
             "const Eigen::Matrix2d sigma = F * S * F.transpose() / state.J;",
             "const Eigen::Matrix2d sigma = F * S * F.transpose();",
             "Cauchy stress without the 1/J of the push-forward",
             ["HyperelasticCauchy.UniaxialStretchClosedForms",
              "FiniteStrainPatch.HomogeneousDeformationIsExact"]),
    Mutation("neo-hooke-tangent", "material", S + "material/hyperelastic.cpp",
             "const double c = 2 * (mu - lambda * lnJ);",
             "const double c = 2 * (mu + lambda * lnJ);",
             "Neo-Hooke tangent with the wrong sign of λ ln J",
             ["Hyperelastic.TangentIsDerivativeOfStress",
              "FiniteStrainElement.TangentAndForceAgreeWithFiniteDifferences"]),
    Mutation("shear-modulus", "material", S + "material/linear_elastic.cpp",
             "D << c * (1 - nu), c * nu, 0, c * nu, c * (1 - nu), 0, 0, 0, c * (1 - 2 * nu) / 2;",
             "D << c * (1 - nu), c * nu, 0, c * nu, c * (1 - nu), 0, 0, 0, c * (1 - 2 * nu);",
             "plane-strain shear modulus 2G",
             ["Lame.PostProcessedStressesAreLames", "LinearElastic.PlaneStrainMatrix"]),
    Mutation("sigma-zz", "material", S + "material/linear_elastic.cpp",
             "return plane == Plane::strain ? poisson_ratio * (sigma(0) + sigma(1)) : 0.0;",
             "return plane == Plane::strain ? poisson_ratio * sigma(0) : 0.0;",
             "plane-strain σzz without σyy",
             ["Lame.PostProcessedStressesAreLames", "LinearElastic.OutOfPlaneStress"]),
    Mutation("rubber-tangent-without-c01", "material", S + "material/rubber.cpp",
             "d.W22 * voigt(A2) * voigt(A2).transpose() + d.W1 * dA1 + d.W2 * dA2);",
             "d.W22 * voigt(A2) * voigt(A2).transpose() + d.W1 * dA1);",
             "the rubber tangent without the C01 (Ī₂) term of ∂A₂/∂C",
             ["RubberLaw.StressAndTangentAreDerivatives", "RubberLaw.IsochoricAndPressurePartsAreDerivatives",
              "RubberTangent.ORingAgreesWithCentralDifferences"]),
    Mutation("rubber-pressure-sign", "material", S + "material/rubber.cpp",
             "return {0.5 * K * (J - 1) * (J - 1), K * (J - 1), K};",
             "return {0.5 * K * (J - 1) * (J - 1), K * (1 - J), K};",
             "the volumetric pressure U'(J) with the wrong sign",
             ["RubberLaw.StressAndTangentAreDerivatives", "RubberLaw.VolumetricPartIsThePressure",
              "RubberClosedForms.UniaxialStretchOfACylinder"]),
    Mutation("rubber-isochoric-power", "material", S + "material/rubber.cpp",
             "const double j23 = std::pow(J, -2.0 / 3.0), j43 = j23 * j23;",
             "const double j23 = std::pow(J, -1.0 / 3.0), j43 = j23 * j23;",
             "the isochoric invariants with J^(−1/3) for J^(−2/3)",
             ["RubberLaw.StressAndTangentAreDerivatives", "RubberLaw.IsochoricPartIgnoresVolumeChange",
              "RubberClosedForms.UniaxialStretchOfACylinder"]),
    Mutation("rubber-tangent-c-cinv", "material", S + "material/rubber.cpp",
             "2.0 / 3.0 * sym_outer(C, Ci) + 4.0 / 9.0 * I2 * CiCi",
             "1.0 / 3.0 * sym_outer(C, Ci) + 4.0 / 9.0 * I2 * CiCi",
             "∂A₂/∂C with the wrong factor on C⊗C⁻¹ + C⁻¹⊗C",
             ["RubberLaw.StressAndTangentAreDerivatives", "RubberTangent.ORingAgreesWithCentralDifferences"]),
    Mutation("rubber-small-strain-nu", "material", S + "material/rubber.cpp",
             "m.poisson_ratio = (3 * K - 2 * mu) / (2 * (3 * K + mu));",
             "m.poisson_ratio = (3 * K - mu) / (2 * (3 * K + mu));",
             "a rubber body's small-strain Poisson ratio not that of its μ and K",
             ["RubberLaw.SmallStrainLimitIsLinearElasticity"]),
    Mutation("rubber-plane-strain-shear", "material", S + "material/hyperelastic.cpp",
             "constexpr int kPlane[3] = {0, 1, 5};",
             "constexpr int kPlane[3] = {0, 1, 3};",
             "the plane-strain rubber tangent's shear row taken from the 23 component",
             ["RubberLaw.PlaneAndHoopStatesAreDerivatives", "FiniteStrainElement.TangentAndForceAgreeWithFiniteDifferences"]),
    Mutation("rubber-hoop-stress", "material", S + "material/hyperelastic_hoop.cpp",
             "s.S << r.S(0, 0), r.S(1, 1), r.S(0, 1), r.S(2, 2);",
             "s.S << r.S(0, 0), r.S(1, 1), r.S(0, 1), r.S(1, 1);",
             "the rubber hoop stress S_θθ taken as S_zz",
             ["RubberLaw.PlaneAndHoopStatesAreDerivatives", "RubberClosedForms.UniaxialStretchOfACylinder"]),
    Mutation("mixed-pressure-row-sign", "fem", S + "fem/mixed_finite_strain.cpp",
             "el.f_int.tail(m) += (w * (s.J - 1 - inverse_bulk * p)) * psi.col(k);",
             "el.f_int.tail(m) += (w * (s.J - 1 + inverse_bulk * p)) * psi.col(k);",
             "the mixed element's pressure rows with +p/K: J − 1 = −p/K, a bulk modulus of the wrong sign",
             ["MixedFiniteStrain.ResidualIsTheGradientOfPiAndTangentItsJacobian",
              "MixedRubber.NoLockingAtHighBulkModulus"]),
    Mutation("mixed-hoop-geometric", "fem", S + "fem/mixed_finite_strain.cpp",
             "wS33(k) = w * s.S(3) * inv_R(k) * inv_R(k);",
             "wS33(k) = w * s.S(3) * inv_R(k);",
             "the mixed element's hoop geometric stiffness S_θθ N_a N_b / R instead of / R²",
             ["MixedFiniteStrain.ResidualIsTheGradientOfPiAndTangentItsJacobian"]),
    Mutation("mixed-dJ-shear", "material", S + "material/mixed_rubber.cpp",
             "s.dJ << Ci(0, 0), Ci(1, 1), Ci(0, 1), Ci(2, 2);",
             "s.dJ << Ci(0, 0), Ci(1, 1), 2 * Ci(0, 1), Ci(2, 2);",
             "∂J/∂E's shear entry doubled (the Voigt factor 2 put on the stress-like vector)",
             ["MixedFiniteStrain.ResidualIsTheGradientOfPiAndTangentItsJacobian"]),
    Mutation("mixed-equal-order-pressure", "fem", S + "fem/mixed_finite_strain.cpp",
             "int pressure_degree(const ElementSpace& space) { return std::max(space.max_degree() - 1, 0); }",
             "int pressure_degree(const ElementSpace& space) { return std::max(space.max_degree(), 0); }",
             "the pressure of degree p, as the displacement (too many constraints: locking)",
             ["MixedRubber.ThickTubeInflationMatchesRivlin", "MixedRubber.ConvergesExponentiallyWithDegree"]),
    Mutation("mixed-stress-without-pressure", "model", S + "model/body_stress.cpp",
             "const auto m = material::mixed_rubber_state(body.rubber, ps.F, F33, pressure);",
             "const auto m = material::mixed_rubber_state(body.rubber, ps.F, F33, 0.0);",
             "a mixed body's reported Cauchy stress without its pressure",
             ["MixedRubber.IncompressiblePatchTestOnADistortedMesh",
              "MixedRubber.IncompressibleStretchesMatchClosedForms",
              "cli:tests/cli/test_o_ring_incompressible.py::test_force_pressure_and_stress_mean"]),
    # contact
    Mutation("slip-update-sign", "contact", S + "contact/friction.cpp",
             "r.slip = g_t - r.traction / law.eps_t;",
             "r.slip = g_t + r.traction / law.eps_t;",
             "the slip of the return mapping with the wrong sign",
             ["ReturnMap.SpringSliderClosedForm", "FrictionPath.LoadShearUnloadFollowsTheClosedForm"]),
    Mutation("friction-dt-dp", "contact", S + "contact/friction.cpp",
             "r.dt_dp = std::copysign(law.mu, trial);",
             "r.dt_dp = law.mu;",
             "slip tangent's dt/dp without the sign of the traction",
             ["ReturnMap.SpringSliderClosedForm", "FrictionTangent.TwoBarsAgreeWithCentralDifferences"]),
    Mutation("circle-curvature", "contact", S + "contact/obstacle.cpp",
             "if (dnormal_dx) *dnormal_dx = r > 0 ? Mat2(s * (Mat2::Identity() - e * e.transpose()) / r) : Mat2::Zero();",
             "if (dnormal_dx) *dnormal_dx = r > 0 ? Mat2(s * (Mat2::Identity() - e * e.transpose()) / (2 * r)) : Mat2::Zero();",
             "the rigid circle's dn/dx halved",
             ["ContactTangent.AnalyticEqualsFiniteDifference", "RigidObstacle.DiscAndHoleGaps"]),
    Mutation("displaced-obstacle", "contact", S + "contact/obstacle.cpp",
             "return base_->gap(x - offset(), normal, dnormal_dx);",
             "return base_->gap(x + offset(), normal, dnormal_dx);",
             "a displaced obstacle moved the opposite way",
             ["RigidObstacle.PlaneAndDisplacedPlaneGaps", "RigidObstacle.DiscAndHoleGaps"]),
    Mutation("contact-weight", "contact", S + "contact/contact_boundary.cpp",
             "cp.weight = ws[i] * ds_dt * thickness.at(cp.X);",
             "cp.weight = ws[i] * thickness.at(cp.X);",
             "contact quadrature weight without the edge's ds/dt",
             ["FrictionPath.LoadShearUnloadFollowsTheClosedForm"]),
    Mutation("deformable-normal", "contact", S + "contact/deformable_boundary.cpp",
             "bp.normal = (e.local_edge < 2 ? Vec2(T.y(), -T.x()) : Vec2(-T.y(), T.x())).normalized();",
             "bp.normal = (e.local_edge < 1 ? Vec2(T.y(), -T.x()) : Vec2(-T.y(), T.x())).normalized();",
             "the deformed boundary's normal on local edge E2 turned inwards",
             ["DeformableBoundary.GapToADeformedSquareIsTheSignedDistance"]),
    # solve
    Mutation("arc-length-constraint", "solve", S + "solve/arc_length.cpp",
             "c = u.head(n).squaredNorm() - dl * dl;",
             "c = u.head(n).squaredNorm() - 2 * dl * dl;",
             "arc-length constraint with the wrong factor on Δl²",
             ["ArcLength.EveryStepKeepsItsLengthOnTheEquilibriumPath"]),
    Mutation("arc-length-root", "solve", S + "solve/arc_length.cpp",
             "const bool first = d1.head(n).dot(Dx.head(n)) >= d2.head(n).dot(Dx.head(n));",
             "const bool first = d1.head(n).dot(Dx.head(n)) <= d2.head(n).dot(Dx.head(n));",
             "the constraint's root that turns back along the path",
             ["ArcLength.EveryStepKeepsItsLengthOnTheEquilibriumPath"]),
    Mutation("singular-pivot", "solve", S + "solve/linear_solver.cpp",
             "constexpr double default_singular_pivot_ratio = 1e-11;",
             "constexpr double default_singular_pivot_ratio = 1e-20;",
             "a pivot of round-off size accepted as regular",
             ["LinearSolver.RoundOffSingularMatrixIsANumericalError"]),
    Mutation("newton-tolerance", "solve", S + "solve/newton.cpp",
             "if (rn == 0.0 || (it > 0 && rn <= options.tolerance * scale && system.settled())) {",
             "if (rn == 0.0 || (it > 0 && rn <= 1e4 * options.tolerance * scale && system.settled())) {",
             "Newton stops at 1e4 × its tolerance",
             ["FiniteStrainPatch.HomogeneousDeformationIsExact", "FiniteStrainPatch.RigidRotationIsStressFree"]),
    # adapt
    Mutation("hp-split-position", "adapt", S + "adapt/geometric_refinement.cpp",
             "const double t = m.edge(e).v0 == c_index ? -1 + 2 * factor : 1 - 2 * factor;",
             "const double t = m.edge(e).v0 == c_index ? -1 + factor : 1 - factor;",
             "geometric refinement splits edges at factor/2 instead of factor",
             ["HpMesh.NewBoundaryNodesLieOnTheCircleAndEdgeSetsFollow"]),
    Mutation("hp-degree-by-layer", "adapt", S + "adapt/hp.cpp",
             "const int p = options.min_degree + std::clamp(layer, 0, steps + 1);",
             "const int p = options.min_degree + std::clamp(layer - 1, 0, steps + 1);",
             "hp degrees rise one layer late",
             ["HpMesh.AdaptiveDegreesRiseByOnePerLayer"]),
    Mutation("rp-track-parameter", "adapt", S + "adapt/boundary_track.cpp",
             "return std::atan2(cross(axis_, r), axis_.dot(r));",
             "return std::atan2(-cross(axis_, r), axis_.dot(r));",
             "rp's angle along a circle measured the wrong way round",
             ["BoundaryTrack.NodeOnTheArcMovesAlongTheCircle",
              "BoundaryTrack.MovedNodeStaysOnTheCircleAndTheMeshStaysValid"]),
    # post
    Mutation("von-mises-shear", "post", S + "post/fields.cpp",
             "                   3 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));",
             "                   2 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));",
             "von Mises with 2 τ² instead of 3 τ² (the plane and the 3D fields share it)",
             ["VonMises.HandValues", "Lame.PostProcessedStressesAreLames",
              "cli:tests/cli/test_vtu_output.py::test_stress_fields_of_lame_cylinder"]),
    Mutation("principal-order", "post", S + "post/fields.cpp",
             "const double c = 0.5 * (sxx + syy), R = std::hypot(0.5 * (sxx - syy), sxy);",
             "const double c = 0.5 * (sxx + syy), R = std::hypot(0.5 * (sxx + syy), sxy);",
             "Mohr's radius from the mean instead of the half difference",
             ["PrincipalStresses.HandValues", "Lame.PostProcessedStressesAreLames"]),
    Mutation("strain-energy-half", "post", S + "post/fields.cpp",
             "U += 0.5 * body.thickness * ev.JxW(k) * eps.col(k).dot(D * eps.col(k));",
             "U += body.thickness * ev.JxW(k) * eps.col(k).dot(D * eps.col(k));",
             "linear strain energy without the ½",
             ["Lame.ExponentialConvergenceInP", "Lame.EnergyDifferenceEqualsErrorNorm",
              "ContactSolve.StrainEnergyIsHalfTheWorkOfTheForces"]),
    Mutation("pressure-error-norm", "post", S + "post/pressure_error.cpp",
             "e.e_L2 = 100 * std::sqrt(diff2 / ref2);",
             "e.e_L2 = 100 * diff2 / ref2;",
             "relative L2 pressure error without the square root",
             ["PressureErrors.HertzAgainstShtayermanMatchesBruteForce", "PressureErrors.ExactAndScaled"]),
    Mutation("singular-corner-inside", "post", S + "post/fields.cpp",
             "if (!(body.maps[q].regularity(xi, eta) > 1e-6) || !ps.strain.allFinite() ||",
             "if (!(body.maps[q].regularity(xi, eta) > 0) || !ps.strain.allFinite() ||",
             "a 180° corner sampled at the corner itself",
             ["Fields.SingularCornerIsSampledInside"]),
    Mutation("cholmod-gives-way-to-lu", "solve", S + "solve/linear_solver.cpp",
             "if (!ok && lu_when_indefinite_) {  // not positive definite: LU from now on",
             "if (false) {  // not positive definite: LU from now on",
             "an indefinite contact tangent refused instead of solved by LU",
             ["LinearSolver.CholmodGivesWayToLuOnAnIndefiniteMatrix"]),
    # axisymmetry
    Mutation("axisymmetric-hoop-coupling", "fem", S + "fem/elasticity.cpp",
             "K.topLeftCorner(n, n) = l2m * XX + mu * YY + l * (HX + HX.transpose()) + l2m * HH;",
             "K.topLeftCorner(n, n) = l2m * XX + mu * YY + l2m * HH;",
             "the coupling of the hoop strain with the radial strain left out",
             ["Axisymmetric.PatchTestOnTheAxis", "Axisymmetric.ThickSphereAgainstLame"]),
    Mutation("axisymmetric-radius-weight", "fem", S + "fem/elasticity.cpp",
             "w(k) = ev.JxW(k) * OutOfPlane(0, true).at(ev.x[k]);",
             "w(k) = ev.JxW(k) * 2 * 3.14159265358979323846;",
             "the axisymmetric stiffness integrated without the radius",
             ["Axisymmetric.PatchTestOnTheAxis", "Axisymmetric.ThickSphereAgainstLame"]),
    Mutation("exact-hoop-strain-dropped", "post", S + "post/fields.cpp",
             "const double e_hoop = exact.hoop(ev.x[k]) - ur(k) / ev.x[k].x();",
             "const double e_hoop = 0;",
             "the energy error against an axisymmetric closed form without the hoop strain",
             ["Axisymmetric.ThickSphereAgainstLame",
              "cli:tests/cli/test_axisymmetric.py::test_thick_sphere_energy_is_lames"]),
    Mutation("lame-sphere-tangential-strain", "analytic", S + "analytic/lame_sphere.cpp",
             "const double jump = radial - tangential;",
             "const double jump = radial - 0.5 * tangential;",
             "Lamé's sphere with a wrong meridian tangential strain",
             ["LameSphere.StrainsAreTheDisplacements", "Axisymmetric.ThickSphereAgainstLame"]),
    Mutation("rp-end-out-of-reach", "adapt", S + "adapt/solved.cpp",
             "if (must_reach && !track.reaches(end.X)) continue;",
             "if (false) continue;",
             "rp gives an end the nearest node even when its track does not reach it",
             ["cli:tests/cli/test_stick_slip_rp.py::test_rp_moves_a_node_of_each_bar_onto_the_stick_slip_point"]),
    Mutation("expression-unguarded", "model", S + "model/expression.cpp",
             "const std::lock_guard<std::mutex> lock(impl_->turn);",
             "// unguarded",
             "a formula evaluated from several threads at once",
             ["ParallelFor.OneFormulaEvaluatedFromEveryThread"]),
    Mutation("mean-normal-dropped", "contact", S + "contact/point_gap.cpp",
             "    if (mean_length > 1e-8) n = mean / mean_length;",
             "    if (false) n = mean / mean_length;",
             "normal: mean measures the gap along the other body's normal alone",
             ["cli:tests/cli/test_hertz.py::test_bilateral_equals_unilateral"]),
    Mutation("friction-tangent-rigid-turn", "contact", S + "contact/point_gap.cpp",
             "const Mat2 Qdn = tangent_rotation() * dn;",
             "const Mat2 Qdn = 0 * tangent_rotation() * dn;",
             "friction's tangent against a curved rigid obstacle leaves out how tau turns",
             ["ExactContactTangent.EqualsCentralDifferences"]),
    Mutation("friction-tangent-two-body-turn", "contact", S + "contact/point_gap.cpp",
             "    pg.ddt = turning_field(pg.tangent, pg.dtau);",
             "    pg.ddt = Eigen::MatrixXd::Zero(L, L);",
             "friction's tangent between two bodies leaves out how tau turns and the foot slides",
             ["ExactContactTangent.EqualsCentralDifferences"]),
    Mutation("friction-held-row", "model", S + "model/contact_system.cpp",
             "held = free <= 1e-10 * all;",
             "held = false;",
             "a sticking node whose slip no unknown moves keeps its (zero) stick row",
             ["cli:tests/cli/test_friction_driving.py::test_friction_on_a_curved_obstacle_from_a_symmetry_line"]),
    Mutation("total-slip-last-step", "model", S + "model/contact_system.cpp",
             "total_slips_[k] += step_slips_[k];",
             "total_slips_[k] = step_slips_[k];",
             "contact.csv's slip of exact friction is the last step's, not the path's",
             ["cli:tests/cli/test_friction_driving.py::test_slip_is_the_path_total"]),
    Mutation("hp-unserved-stick-slip", "adapt", S + "adapt/zone_resolution.cpp",
             "      if (!served) unserved.push_back(end);",
             "      (void)served;",
             "hp's zone resolution leaves a stick-slip point no node can serve unresolved",
             ["cli:tests/cli/test_two_bars.py::test_coulomb_hp_traction_without_oscillation"]),
    Mutation("hp-lost-point-fails", "adapt", S + "adapt/hp.cpp",
             "  auto ends = without_ends_at_singular_points(zone_ends_of(s, options.stick_slip), singular_ends_of(s));",
             "  auto ends = without_ends_at_singular_points(adapt_targets(s, options.stick_slip), singular_ends_of(s));",
             "an hp step whose coarse elements lose the stick-slip point ends the loop",
             ["cli:tests/cli/test_two_bars.py::test_coulomb_hp_step_that_loses_the_point_goes_on"]),
    Mutation("other-rows-no-slip", "model", S + "model/contact_result_rows.cpp",
             "if (m.total_slips) ps.slip = c.nodes.interpolate(foot.edge, foot.t, *m.total_slips);",
             "(void)m.total_slips;",
             "the other body's rows of an exact pair report no path slip",
             ["cli:tests/cli/test_friction_driving.py::test_the_other_bodys_rows_slip_as_the_pair_does"]),
    Mutation("hp-degree-beyond-layers", "adapt", S + "adapt/hp.cpp",
             "std::clamp(layer, 0, steps + 1);",
             "std::max(layer, 0);",
             "hp's degree keeps rising over the input's elements beyond the refinement layers",
             ["cli:tests/cli/test_hp_tolerance.py::test_far_elements_get_the_outermost_layers_degree"]),
    Mutation("pressure-error-breaks-ignored", "post", S + "post/pressure_error.cpp",
             "it != cuts.end() && *it < b; ++it) {",
             "it != cuts.end() && *it < a; ++it) {",
             "the pressure error integrals' pieces straddle the kinks they are given",
             ["PressureErrors.ABreakAtTheOtherZoneEnd"]),
    Mutation("mean-normal-stress-side", "model", S + "model/boundary_stress.cpp",
             "    if (pair.constraints && pair.constraints->mean_normal) {",
             "    if (false) {",
             "the pressure from stresses of a mean-normal pair projected on the other body's normal",
             ["cli:tests/cli/test_hertz.py::test_bilateral_equals_unilateral"]),
    Mutation("axisymmetric-lumped-share", "contact", S + "contact/multiplier_nodes.cpp",
             "if (thickness.axisymmetric) {",
             "if (false) {",
             "the multiplier nodes' shares lumped by Lobatto in axisymmetry (the axis node's lost)",
             ["cli:tests/cli/test_axisymmetric_contact.py::test_contact_patch_of_a_solid_cylinder[1]"]),
    Mutation("axisymmetric-contact-weight", "contact", S + "contact/contact_boundary.cpp",
             "cp.weight = ws[i] * ds_dt * thickness.at(cp.X);",
             "cp.weight = ws[i] * ds_dt * thickness.thickness;",
             "contact points weighted by the thickness in axisymmetry instead of 2 pi r",
             ["cli:tests/cli/test_axisymmetric_contact.py::test_ball_on_a_flat_is_3d_hertz"]),
    # adapt (hp to a tolerance) and the reference it is judged by
    Mutation("estimate-scaled", "adapt", S + "adapt/error_estimate.cpp",
             "if (norm2 > 0) est.pressure = std::sqrt(diff2 / norm2);",
             "if (norm2 > 0) est.pressure = 0.2 * std::sqrt(diff2 / norm2);",
             "the error estimate five times too small (a wrong constant)",
             ["cli:tests/cli/test_hp_tolerance.py::test_the_estimate_brackets_the_true_error_at_every_step",
              "cli:tests/cli/test_hp_tolerance.py::test_a_tolerance_of_1e4_is_reached_and_said"]),
    Mutation("tolerance-compare", "adapt", S + "adapt/hp.cpp",
             "if (rec.estimate.traction() <= options.tolerance) {",
             "if (rec.estimate.traction() <= 10 * options.tolerance) {",
             "the loop stops an order of magnitude early",
             ["cli:tests/cli/test_hp_tolerance.py::test_a_tolerance_of_1e4_is_reached_and_said"]),
    Mutation("zone-resolution-skipped", "adapt", S + "adapt/zone_resolution.cpp",
             "return move <= 0.5 * room;",
             "return true;",
             "a zone narrow against its elements is not resolved before hp grades",
             ["cli:tests/cli/test_hp_tolerance.py::test_zones_far_smaller_than_the_start_mesh_reach_the_tolerance[100]",
              "cli:tests/cli/test_hp_tolerance.py::test_zones_far_smaller_than_the_start_mesh_reach_the_tolerance[10000]"]),
    # adapt (goal-oriented degrees and the estimate's start)
    Mutation("goal-unweighted", "adapt", S + "adapt/error_estimate.cpp",
             "for (size_t q = 0; q < eta[b].size(); ++q) eta[b][q] = std::sqrt(eta[b][q] * weight[b][q]);",
             "for (size_t q = 0; q < eta[b].size(); ++q) eta[b][q] = std::sqrt(eta[b][q]);",
             "goal-oriented indicators without the adjoint's weight (the energy surplus alone)",
             ["cli:tests/cli/test_hp_tolerance.py::test_a_tolerance_of_1e4_is_reached_and_said",
              "cli:tests/cli/test_hp_tolerance.py::test_a_tolerance_of_1e3",
              "cli:tests/cli/test_hp_tolerance.py::test_goal_oriented_degrees_need_half_the_dofs_of_the_rising_degree"]),
    Mutation("goal-not-per-dof", "adapt", S + "adapt/goal_degrees.cpp",
             "score[b][q] /= 2 * coarse.discretization.bodies[b].dofs.element(static_cast<int>(q)).max_degree() + 3;",
             "score[b][q] /= 1;",
             "degrees bought by the indicator alone, not by what a degree more costs",
             ["cli:tests/cli/test_hp_tolerance.py::test_a_tolerance_of_1e4_is_reached_and_said",
              "cli:tests/cli/test_hp_tolerance.py::test_a_tolerance_of_1e3",
              "cli:tests/cli/test_hp_tolerance.py::test_goal_oriented_degrees_need_half_the_dofs_of_the_rising_degree"]),
    Mutation("surplus-all-modes", "adapt", S + "adapt/error_estimate.cpp",
             "if (std::find(kept.begin(), kept.end(), all[a]) != kept.end()) ue(a) = ue(a + n) = 0;",
             "if (false) ue(a) = ue(a + n) = 0;",
             "the surplus energy counts the modes the coarser space has too",
             ["SurplusEnergies.AreTheEnergyOfTheModesTheCoarserSpaceLacks"]),
    Mutation("adjoint-unbordered", "model", S + "model/contact_solve.cpp",
             "    system.set_force_target(std::make_pair(tr->component, tr->value), spec.solver.stages.empty());",
             "    (void)0;",
             "the adjoint of a force-controlled solve without the force held",
             ["MultiplierAdjoint.PredictsTheFunctionalUnderForceControl"]),
    Mutation("carry-over-nested-skipped", "adapt", S + "adapt/transfer.cpp",
             "if (nested(from_d, to)) {",
             "if (false) {",
             "the estimate's solve starts from the vertex values only",
             ["CarryOver.OneDegreeMoreOnTheSameMeshIsTheSameSolution"]),
    Mutation("recentre-with-tolerance", "adapt", S + "adapt/hp.cpp",
             "if (rec.inside || rec.recentred >= options.max_recentre || options.tolerance > 0) break;",
             "if (rec.inside || rec.recentred >= options.max_recentre) break;",
             "a step to a tolerance is solved again around each Γ* outside its smallest elements",
             ["cli:tests/cli/test_hp_tolerance.py::test_a_tolerance_of_1e4_is_reached_and_said"]),
    # model (the seed's difference tangent with exact contact)
    Mutation("difference-tangent-whole-symmetrised", "model", S + "model/contact_system.cpp",
             "if (undisturbed) symmetrize_displacement_block(t, n_u_);",
             "if (undisturbed) symmetrize_displacement_block(t, size());",
             "the seed's difference tangent symmetrised over the multipliers' rows and columns too",
             ["ContactTangent.SeedFiniteDifferenceTangentEqualsAnalyticWithMultipliers",
              "ContactTangent.FiniteDifferenceTangentGivesTheSameSolution"]),
    Mutation("cuts-counted-in-a-row", "model", S + "model/contact_solve.cpp",
             "      accept_step(std::move(attempt), name);",
             "      accept_step(std::move(attempt), name), cuts = 0;",
             "a converged step resets the count of halvings: a load beyond what can be carried is "
             "approached by ever shorter steps",
             ["cli:tests/cli/test_friction_driving.py::test_a_shear_at_the_friction_capacity_stops_at_the_shortest_step"]),
    # model (an axisymmetric body's axis)
    Mutation("axis-contact-edge-accepted", "model", S + "model/contact_pairs.cpp",
             "HPC_REQUIRE(!edge_on_axis(body.mesh, e),",
             "HPC_REQUIRE(!edge_on_axis(body.mesh, e) || true,",
             "a contact edge along the axis of an axisymmetric body accepted",
             ["cli:tests/cli/test_axis.py::test_a_contact_edge_on_the_axis_is_refused"]),
    Mutation("axis-radial-motion-accepted", "model", S + "model/discretization.cpp",
             "HPC_REQUIRE(d.free_index[dof] != -1 || d.prescribed(dof) == 0, InputError, where,",
             "HPC_REQUIRE(true || d.prescribed(dof) == 0, InputError, where,",
             "u_r != 0 prescribed on the axis accepted",
             ["cli:tests/cli/test_axis.py::test_a_radial_motion_of_the_axis_is_refused"]),
    Mutation("axis-round-off-kept", "model", S + "model/discretization.cpp",
             "if (bs.material.plane == PlaneMode::axisymmetric) snap_to_axis(xy);",
             "(void)xy;",
             "nodes off the axis by round-off not put on it",
             ["cli:tests/cli/test_axis.py::test_nodes_off_the_axis_by_round_off_are_on_it"]),
    Mutation("axis-crossing-unseen", "model", S + "model/axis.cpp",
             "    if (r < r_min) {",
             "    if (r < r_min && r > 0) {",
             "a deformed section across the axis not warned about",
             ["cli:tests/cli/test_axis.py::test_a_section_pulled_across_the_axis_is_warned"]),
    Mutation("axis-free-unwarned", "model", S + "model/discretization.cpp",
             "if (free.empty() || !body.axisymmetric()) return std::nullopt;",
             "if (true) return std::nullopt;",
             "an axis free to move radially not warned about",
             ["cli:tests/cli/test_axis.py::test_an_axis_free_to_move_radially_is_warned"]),
    # inputs legal value by value, not together
    Mutation("force-scale-unchecked", "model", S + "model/load_scale.cpp",
             "if (!tr || tr->value == 0) return;",
             "return;",
             "a force target no double precision or elasticity can carry accepted",
             ["cli:tests/cli/test_input_causes.py::test_a_force_target_that_double_precision_cannot_resolve_is_refused",
              "cli:tests/cli/test_input_causes.py::test_a_force_target_beyond_elasticity_is_refused"]),
    Mutation("parallel-planes-unchecked", "model", S + "model/contact_pairs.cpp",
             "if (std::abs(na.dot(nb)) < 1 - 1e-12) continue;",
             "if (std::abs(na.dot(nb)) < 2) continue;",
             "two exact pairs against parallel planes on one edge set accepted",
             ["cli:tests/cli/test_input_causes.py::test_two_parallel_planes_on_one_edge_set_are_refused"]),
    Mutation("reference-nan-accepted", "driver", S + "driver/contact_compare.cpp",
             "HPC_REQUIRE(std::isfinite(v.back()), InputError, where,",
             "HPC_REQUIRE(!std::isinf(v.back()), InputError, where,",
             "a NaN in a reference curve read as a number",
             ["cli:tests/cli/test_input_causes.py::test_a_reference_curve_with_a_nan_row_is_refused"]),
    Mutation("stacked-elements-accepted", "mesh", S + "mesh/mesh.cpp",
             "  refuse_stacked_elements();",
             "  (void)0;",
             "two elements on one another under other node numbers accepted",
             ["cli:tests/cli/test_input_causes.py::test_elements_stacked_on_one_another_are_refused"]),
    # mesh quality and solution warnings
    Mutation("contact-stretch-unmeasured", "mesh", S + "mesh/element_shape.cpp",
             "        along.add(q, L * L / s.area);",
             "        along.add(q, L / std::sqrt(s.area));",
             "the contact edge's stretch measured as L / sqrt(A) instead of L^2 / A",
             ["ElementShape.NeedleAlongAContactEdgeIsWarned",
              "cli:tests/cli/test_mesh_quality.py::test_check_warns_about_needles_along_a_contact_edge"]),
    Mutation("element-area-weight", "mesh", S + "mesh/element_shape.cpp",
             "shape.area += rule.weights[i] * rule.weights[j] * det;",
             "shape.area += rule.weights[i] * rule.weights[i] * det;",
             "the element's area with the weights w_i w_i",
             ["ElementShape.TrapezoidJacobianRatioIsItsDeterminantsRatio",
              "ElementShape.ArcEdgeLengthIsTheArcs"]),
    Mutation("coarse-zone-unwarned", "driver", S + "driver/solution_warnings.cpp",
             "if (!(c.contact_length < kZoneToEdgeLimit * shortest)) return std::nullopt;",
             "if (!(c.contact_length < kZoneToEdgeLimit * shortest) || true) return std::nullopt;",
             "a contact zone within one coarse edge not warned about",
             ["cli:tests/cli/test_mesh_quality.py::test_a_contact_zone_within_one_coarse_edge_is_warned"]),
    # the gap only where the partner is; near-mechanisms
    Mutation("corner-foot-any-end", "contact", S + "contact/deformable_boundary.cpp",
             "return edges_[k].shared_end[e] && j >= 0 && beyond(j, other);",
             "return edges_[k].shared_end[e];",
             "a shared vertex taken as the foot of a point beyond the boundary's free end",
             ["PinInHole.ContactArcAndPressureArePerssonsFrom20To75Degrees",
              "cli:tests/cli/test_press_fit.py::test_no_row_beyond_the_hub_is_in_contact"]),
    Mutation("node-beyond-partner-kept", "model", S + "model/contact_multipliers.cpp",
             "      if (s.found[j] && covered[j] < 0.5 * support[j] &&",
             "      if (s.found[j] && covered[j] < -1.0 * support[j] &&",
             "a multiplier node beyond the other body's boundary kept in contact",
             ["cli:tests/cli/test_press_fit.py::test_no_row_beyond_the_hub_is_in_contact"]),
    Mutation("mirror-end-singular", "model", S + "model/singular_points.cpp",
             "  return d.free_index[held] < 0 && d.prescribed(held) == 0 && d.free_index[other] >= 0;",
             "  return d.free_index[held] < 0 && d.prescribed(held) != 0 && d.free_index[other] >= 0;",
             "a zone closed up to a mirror (Hertz's half model) reported as singular",
             ["cli:tests/cli/test_singular_points.py::test_smooth_zones_and_mirrors_have_none"]),
    Mutation("singular-peak-in-pressure-max", "model", S + "model/singular_points.cpp",
             "      return std::abs(result.s[i] - p.s) < p.pressure_max_beyond * (1 + 1e-6);",
             "      return std::abs(result.s[i] - p.s) < p.pressure_max_beyond * (1e-6);",
             "pressure_max takes in the pressures of the elements touching a singular point",
             ["cli:tests/cli/test_singular_points.py::test_pressure_max_is_the_largest_away_from_the_corner"]),
    Mutation("singular-fit-from-the-peak", "model", S + "model/singular_points.cpp",
             "    if (dist >= sp.excluded * (1 + 1e-6) + tol && dist <= 0.25 * reach) dp.push_back({dist, r.pressure[i]});",
             "    if (dist > tol && dist <= 0.25 * reach) dp.push_back({dist, r.pressure[i]});",
             "the singularity fitted from the pressures of the elements touching it too",
             ["cli:tests/cli/test_singular_points.py::test_the_punch_corner_is_singular_with_sadowskys_strength"]),
    Mutation("other-corner-undeformed", "model", S + "model/singular_points.cpp",
             "    if (!pair.boundary->project(x_end, foot)) return std::nullopt;",
             "    if (!pair.boundary->project(end.X, foot)) return std::nullopt;",
             "the other body's corner sought on this body at its undeformed place",
             ["cli:tests/cli/test_press_fit.py::test_the_hub_end_is_singular_whichever_body_carries"]),
    Mutation("hp-blind-to-singular-points", "adapt", S + "adapt/hp.cpp",
             "            add_singular_centres(*s, ends, centres);",
             "            (void)add_singular_centres;",
             "hp refines towards Γ* only: a zone closed up to a corner is not graded towards",
             ["cli:tests/cli/test_singular_points.py::test_hp_from_a_coarse_mesh_grades_towards_the_corner"]),
    Mutation("estimate-through-singular-point", "adapt", S + "adapt/error_estimate.cpp",
             "      if (std::abs(s - p.s) < p.excluded * (1 + 1e-6)) return true;",
             "      if (std::abs(s - p.s) < p.excluded * (1e-6)) return true;",
             "hp's estimate measures the unbounded pressure at a singular point too (it never converges)",
             ["cli:tests/cli/test_singular_points.py::test_hp_from_a_coarse_mesh_grades_towards_the_corner"]),
    Mutation("repeated-residuals-cut-again", "model", S + "model/contact_solve.cpp",
             "    const bool unchanged = same_residuals(failed_before, rep.residual_history);",
             "    const bool unchanged = false && same_residuals(failed_before, rep.residual_history);",
             "cuts that fail with the same residuals (an interference no load scales) go on cutting",
             ["cli:tests/cli/test_press_fit.py::test_cuts_that_repeat_the_residuals_stop_at_once"]),
    Mutation("unfollowed-zone-end-left", "adapt", S + "adapt/hp.cpp",
             "  if (!peak || peak->share < kErrorPeakShare) return false;",
             "  if (true || !peak || peak->share < kErrorPeakShare) return false;",
             "a zone end that no centre follows (two ends at one coarse node) is never refined towards",
             ["cli:tests/cli/test_singular_points.py::test_hp_reaches_1e_3_on_a_punch_with_rounded_corners"]),
    Mutation("edge-set-end-moved", "adapt", S + "adapt/boundary_track.cpp",
             "HPC_REQUIRE(holds(neighbours[0]) == holds(neighbours[1]), AdaptError, who, \" ends edge set '\",",
             "HPC_REQUIRE(true, AdaptError, who, \" ends edge set '\",",
             "hp and rp move the last node of an edge set (the contact edges shrink)",
             ["PinInHole.ContactArcAndPressureArePerssonsFrom20To75Degrees",
              "cli:tests/cli/test_rp.py::test_no_node_that_can_move_keeps_the_first_solve"]),
    Mutation("near-mechanism-not-cut", "model", S + "model/contact_solve.cpp",
             "const bool held_before = sol_.load_steps > 0;",
             "const bool held_before = false;",
             "a singular tangent after converged load steps ends the run without cutting the step",
             ["cli:tests/cli/test_friction_driving.py::test_a_shear_at_the_friction_capacity_stops_at_the_shortest_step"]),
    # solve (factors and Schur columns kept between equal tangents)
    Mutation("kept-factors-pattern-only", "solve", S + "solve/linear_solver.cpp",
             "std::equal(A.valuePtr(), A.valuePtr() + nnz, matrix.valuePtr());",
             "true;",
             "a matrix of the same pattern keeps the last factors whatever its values",
             ["LinearSolver.EqualMatrixKeepsItsFactors"]),
    Mutation("kept-factors-never", "solve", S + "solve/linear_solver.cpp",
             "kept_factors_ = impl_->is_factorised(A_in);",
             "kept_factors_ = false;",
             "every tangent factorised anew",
             ["LinearSolver.EqualMatrixKeepsItsFactors",
              "ExactContactHertz.HeldBodyFactorisesItsStiffnessOncePerLoadStep"]),
    Mutation("schur-columns-unchecked", "solve", S + "solve/saddle_point.cpp",
             "if (c >= 0 && Eigen::VectorXd(E_hat_.col(c)) == E_hat.col(f)) Y.col(f) = Y_.col(c);",
             "if (c >= 0) Y.col(f) = Y_.col(c);",
             "a multiplier's column of A⁻¹Ê kept from the last tangent though its Ê column changed",
             ["SaddlePoint.UnchangedColumnsAreKeptFromTheLastTangent"]),
    Mutation("augmented-when-held", "model", S + "model/contact_system.cpp",
             "const bool augmented = !held || d_.finite_strain();",
             "const bool augmented = true;",
             "the augmentation also for bodies their constraints hold (K changes with the active set)",
             ["ExactContactHertz.HeldBodyFactorisesItsStiffnessOncePerLoadStep"]),
    Mutation("augmentation-never", "model", S + "model/contact_system.cpp",
             "const bool augmented = !held || d_.finite_strain();",
             "const bool augmented = false;",
             "no augmentation even where only the contact holds a body",
             ["cli:tests/cli/test_contact_pairs.py::test_o_ring_reports_both_plates_in_balance",
              "cli:tests/cli/test_friction_input.py::test_exact_friction_needs_no_tangential_penalty"]),
    Mutation("touching-between-nodes-not-active", "model", S + "model/contact_multipliers.cpp",
             "if (std::min(f1, f2) <= touching) at[j0] = at[j1] = 1;",
             "if (false) at[j0] = at[j1] = 1;",
             "only a node touching at its own point starts active, not the two around a point where "
             "the bodies touch between nodes",
             ["cli:tests/cli/test_mirror_friction.py::test_touching_between_two_nodes_friction_holds_the_body_from_the_start"]),
    Mutation("zone-around-one-node-not-resolved", "adapt", S + "adapt/zone_resolution.cpp",
             "if (end.kind == ZoneEnd::Kind::contact && node_between_ends(*s, nodes, end))",
             "if (false && node_between_ends(*s, nodes, end))",
             "a zone whose two ends are nearest to one node in its middle is not refined towards "
             "it: the node serves one end, the other stays in the coarse element",
             ["cli:tests/cli/test_roller_block_friction.py::test_hp_gives_each_end_of_a_zone_around_one_node_its_own"]),
    Mutation("shear-not-in-tolerance", "adapt", S + "adapt/error_estimate.hpp",
             "double traction() const { return shear > pressure ? shear : pressure; }",
             "double traction() const { return pressure; }",
             "the hp tolerance holds the pressure only, not the shear",
             ["cli:tests/cli/test_partial_slip_hp.py::test_the_shear_is_held_to_the_tolerance"]),
    Mutation("shear-estimate-of-normal", "adapt", S + "model/boundary_pressure.cpp",
             "return pair_.constraints->nodes.interpolate(k, t, multipliers_->segment(n, n));",
             "return pair_.constraints->nodes.interpolate(k, t, multipliers_->segment(0, n));",
             "the shear estimated from the normal multipliers",
             ["ErrorEstimate.ShearOfTheTangentialMultipliers"]),
    Mutation("shear-estimate-against-capacity", "adapt", S + "adapt/error_estimate.cpp",
             "  return shear2 > kIncidentalShear * kIncidentalShear * capacity2 ? shear2 : pressure2;",
             "  return shear2 > kIncidentalShear * kIncidentalShear * capacity2 ? capacity2 : pressure2;",
             "the shear's estimated error relative to the friction's capacity mu |p|, not to its own size",
             ["cli:tests/cli/test_partial_slip_hp.py::test_the_estimate_is_the_error_against_a_finer_run_of_the_same_model"]),
    Mutation("facing-degrees-unmatched", "adapt", S + "adapt/hp.cpp",
             "  if (options.degree != model::HpDegree::constant) match_facing_degrees(spec);",
             "",
             "hp leaves the facing contact edges of two bodies with the degrees each body's corrections gave",
             ["cli:tests/cli/test_partial_slip_hp.py::test_facing_contact_edges_have_equal_degrees"]),
    Mutation("facing-degrees-smaller", "adapt", S + "adapt/facing_degrees.cpp",
             "        const int p = std::max(pa, pb);",
             "        const int p = std::min(pa, pb);",
             "facing contact edges matched to the smaller degree (the estimate's request dropped)",
             ["FacingDegrees.FacingElementsTakeTheLargerDegree"]),
    Mutation("goal-without-shear", "adapt", S + "adapt/error_estimate.cpp",
             "      g[k](n + j) = node.weight * (sb - pa.tangential_traction(node.edge, node.t));",
             "      g[k](n + j) = 0;",
             "the goal-oriented functional without the shear's error",
             ["ErrorEstimate.ShearOfTheTangentialMultipliers"]),
    Mutation("stop-ignored", "solve", S + "solve/newton.cpp",
             "    if (stop_requested()) {",
             "    if (false) {",
             "Newton's method does not stop when asked (a SIGTERM'd run goes on or is killed with nothing)",
             ["NewtonStop.EndsBeforeTheNextIterationWithTheIterateReached",
              "cli:tests/cli/test_stop_signal.py::test_a_stopped_hp_loop_keeps_its_best_step"]),
    Mutation("polar-one-ring", "scripts", "scripts/partial_slip_mesh.py",
             "    if len(radii) < 2:",
             "    if False:",
             "the polar partial-slip mesh with one ring: its contact edges end at a, where the zone ends",
             ["cli:tests/cli/test_partial_slip_hp.py::test_rings_too_large_for_the_contact_zone_are_refused"]),
    Mutation("stop-before-commit-ignored", "driver", S + "driver/run.cpp",
             "  HPC_REQUIRE(!stop_requested(), NumericalError, spec.file, \": \", stop_reason(),",
             "  HPC_REQUIRE(true, NumericalError, spec.file, \": \", stop_reason(),",
             "a run asked to stop during its last solve commits its results (Slurm says CANCELLED)",
             ["RunStop.ALinearRunAskedToStopWritesNoResults"]),
    Mutation("outlived-run-ignored", "driver", S + "driver/slurm_study.cpp",
             "  if (summary_written_since(row.run_dir, task->submitted))",
             "  if (false)",
             "a run that committed after Slurm lost its task is a failed row, and a resubmission finds nothing to run",
             ["slurm"]),
    Mutation("outlived-run-any-age", "driver", S + "driver/slurm_study.cpp",
             "  return since > 0 && ::stat((run_dir + \"/summary.json\").c_str(), &st) == 0 && st.st_mtime >= since;",
             "  return since > 0 && ::stat((run_dir + \"/summary.json\").c_str(), &st) == 0;",
             "a summary older than the task's submission counts as the task's run",
             ["slurm"]),
    Mutation("incidental-shear-own-size", "adapt", S + "adapt/error_estimate.cpp",
             "  return shear2 > kIncidentalShear * kIncidentalShear * capacity2 ? shear2 : pressure2;",
             "  return shear2 > 0 ? shear2 : pressure2;",
             "the numerical rest of a shear on a contact pressed only held to its own size: hp never ends",
             ["cli:tests/cli/test_partial_slip_hp.py::test_pressed_only_the_tolerance_holds_the_pressure"]),
    Mutation("adjoint-not-transposed", "model", S + "model/contact_solve.cpp",
             "  lu.compute(At);",
             "  lu.compute(A);",
             "the adjoint solved with the tangent itself, not its transpose",
             ["MultiplierAdjoint.PredictsTheShearOfTwoCylindersUnderForceControlThroughStages"]),
    Mutation("force-stage-loads-follow-factor", "model", S + "model/contact_system.cpp",
             "  return target_ && target_scales_loads_ ? x(size() - 1) : lambda_f_;",
             "  return target_ ? x(size() - 1) : lambda_f_;",
             "under force control through stages the loads follow the found factor (shear while pressing)",
             ["cli:tests/cli/test_friction_driving.py::test_force_control_through_stages"]),
    Mutation("force-stage-share-ignored", "model", S + "model/contact_solve.cpp",
             "  double share(double s) const { return share_from + s * (share_to - share_from); }",
             "  double share(double s) const { return s; }",
             "each force-controlled stage pressed from 0 to the whole target again",
             ["cli:tests/cli/test_friction_driving.py::test_force_control_through_stages"]),
    Mutation("adjoint-stages-unbordered", "model", S + "model/contact_solve.cpp",
             "  const bool bordered = tr && !sol.pairs.empty() && sol.pairs.front().constraints;",
             "  const bool bordered = spec.solver.stages.empty() && tr && !sol.pairs.empty() && sol.pairs.front().constraints;",
             "the goal-oriented adjoint under force control through stages forgets the force held",
             ["MultiplierAdjoint.PredictsTheFunctionalUnderForceControlThroughStages"]),
    Mutation("stop-after-loop-ignored", "driver", S + "driver/run.cpp",
             "    if (converged && stop_requested()) {",
             "    if (false) {",
             "an adaptive run asked to stop after its loop's last solve commits its result as a success",
             ["RunStop.AnAdaptiveRunAskedToStopAfterItsLastSolveKeepsItAsLastGood"]),
    Mutation("repeated-stop-signal-kills", "apps", "apps/main.cpp",
             "constexpr long long kRepeatNs = 1'000'000'000;",
             "constexpr long long kRepeatNs = 0;",
             "a stop signal delivered twice at once (Ctrl-C to a study and its runs) kills the runs",
             ["cli:tests/cli/test_stop_signal.py::test_the_same_signal_twice_at_once_is_one_stop",
              "cli:tests/cli/test_output_folder.py::test_ctrl_c_on_a_study_keeps_what_its_runs_had_converged"]),
    Mutation("stopped-study-logs-dropped", "driver", S + "driver/study.cpp",
             '    if (fs::exists(stage / "runs")) {',
             "    if (false) {",
             "a stopped study's run logs left in its staging folder, which the next study removes",
             ["cli:tests/cli/test_output_folder.py::test_study_passes_signals_to_its_runs",
              "cli:tests/cli/test_output_folder.py::test_ctrl_c_on_a_study_keeps_what_its_runs_had_converged"]),
    Mutation("uniform-metric-over-a", "scripts", "scripts/partial_slip_compare.py",
             "    x = np.linspace(-extent * a, extent * a, n)",
             "    x = np.linspace(-a, a, n)",
             "the uniform metric over [-a, a]: a traction beyond the Hertz width, a penalty's, goes uncounted",
             ["cli:tests/cli/test_partial_slip.py::test_uniform_metric_closed_form"]),
    Mutation("uniform-metric-signed-q", "scripts", "scripts/partial_slip_compare.py",
             '    P, Q = pair["normal_force"], abs(pair["tangential_force"])',
             '    P, Q = pair["normal_force"], pair["tangential_force"]',
             "the uniform metric's closed form for the signed tangential force (the force on the body, against the push): a stick zone wider than the contact",
             ["cli:tests/cli/test_partial_slip.py::test_uniform_metric_reads_both_methods_alike"]),
    Mutation("carried-shear-with-applied-q", "scripts", "scripts/partial_slip_compare.py",
             'closed_form(R_star, E_star, mu, P, abs(out["shear_integral"]))',
             "closed_form(R_star, E_star, mu, P, Q)",
             "the shear's closed form for the carried force taken for the applied Q",
             ["cli:tests/cli/test_partial_slip.py::test_shear_against_the_force_it_carries"]),
    Mutation("reference-linear", "driver", S + "driver/contact_compare.cpp",
             "if (a >= 0 && b >= 0 && (a > 0 || b > 0)) return std::sqrt((1 - w) * a * a + w * b * b);",
             "if (false) return 0;",
             "the reference pressure interpolated linearly up to the square-root end",
             ["ReferenceCurve.KeepsTheSquareRootEndOfTheZone"]),
    Mutation("stick-slip-midway", "model", S + "model/stick_slip_points.cpp",
             ": pegasus_root(psi, ta, tb, fa, fb, 1e-14);",
             ": 0.5 * (ta + tb);",
             "the stick–slip point put midway between its nodes instead of at the root of ψ",
             ["cli:tests/cli/test_partial_slip.py::test_stick_slip_points_located_between_their_nodes",
              "cli:tests/cli/test_stick_slip_rp.py::test_stick_slip_point_between_a_stick_and_a_slip_node"]),
    Mutation("stick-slip-one-body", "adapt", S + "adapt/solved.cpp",
             "ends.push_back({pair.other, X, ZoneEnd::Kind::stick_slip});",
             "(void)X;",
             "the other body's stick–slip points left out of what rp and hp adapt to",
             ["cli:tests/cli/test_stick_slip_rp.py::test_rp_moves_a_node_of_each_bar_onto_the_stick_slip_point"]),
    Mutation("stick-slip-cone-loose", "contact", S + "contact/friction.cpp",
             "const bool on_cone = std::abs(t_t) >= (1 - 1e-9) * law.mu * p_n;",
             "const bool on_cone = std::abs(t_t) >= (1 - 1e-3) * law.mu * p_n;",
             "a point within 1e-3 of Coulomb's cone counted as slipping (the test's tolerance a thousandth)",
             ["StickOrSlip.CoulombsConeToARelative1em9", "ReturnMap.ClassifiesItsTrialByTheCone"]),
    Mutation("stick-slip-cone-signed", "contact", S + "contact/friction.cpp",
             "const bool on_cone = std::abs(t_t) >= (1 - 1e-9) * law.mu * p_n;",
             "const bool on_cone = t_t >= (1 - 1e-9) * law.mu * p_n;",
             "a point on Coulomb's cone with a negative traction counted as sticking",
             ["StickOrSlip.CoulombsConeToARelative1em9", "ReturnMap.ClassifiesItsTrialByTheCone"]),
    Mutation("hoop-cauchy-one-stretch", "material", S + "material/hyperelastic_hoop.cpp",
             "if (hoop) *hoop = F_hoop * F_hoop * state.S(3) / state.J;",
             "if (hoop) *hoop = F_hoop * state.S(3) / state.J;",
             "the axisymmetric finite-strain hoop stress σ_θθ = F_θθ S_θθ / J, a factor F_θθ lost",
             ["HoopHyperelastic.DiagonalStretchClosedForms",
              "AxisymmetricFiniteStrain.UniformRadialExpansionIsHomogeneous"]),
    Mutation("hoop-row-without-stretch", "fem", S + "fem/axisymmetric_finite_strain.cpp",
             "B.block(4 * k + 3, 0, 1, n) = (F_hoop(k) * inv_R(k)) * ev.N.col(k).transpose();",
             "B.block(4 * k + 3, 0, 1, n) = inv_R(k) * ev.N.col(k).transpose();",
             "the axisymmetric finite-strain element's hoop row δE_θθ = N_a / R δu_r, the factor F_θθ lost",
             ["AxisymmetricFiniteStrain.UniformRadialExpansionIsHomogeneous",
              "AxisymmetricFiniteStrainElement.TangentAndForceAgreeWithFiniteDifferences"]),
    Mutation("estimate-quadrature-short", "adapt", S + "adapt/error_estimate.cpp",
             "const auto& rule = basis::gauss_legendre(p + 3);",
             "const auto& rule = basis::gauss_legendre(p);",
             "the estimate's traction integrals one Gauss point short of exact (p points for (t − t⁺)² of degree 2p)",
             ["ErrorEstimate.TractionIntegralsAreExact"]),
    Mutation("reference-force-never-refused", "driver", S + "driver/contact_compare.cpp",
             "HPC_REQUIRE(std::abs(2 * carried - force) <= 1e-2 * force, InputError",
             "HPC_REQUIRE(std::abs(2 * carried - force) <= 1e2 * force, InputError",
             "compare.reference of another load accepted (its force checked to 100 times, not 1 %)",
             ["cli:tests/cli/test_compare_reference.py::test_a_reference_of_another_load_is_refused[above-plane]",
              "cli:tests/cli/test_compare_reference.py::test_a_reference_of_another_load_is_refused[below-plane]",
              "cli:tests/cli/test_compare_reference.py::test_a_reference_of_another_load_is_refused[above-axisymmetric]",
              "cli:tests/cli/test_compare_reference.py::test_a_reference_of_another_load_is_refused[below-axisymmetric]"]),
    Mutation("reference-ring-weight-doubled", "driver", S + "driver/contact_compare.cpp",
             "const double wb = in_.axisymmetric ? std::numbers::pi * x[i + 1] : 1.0;",
             "const double wb = in_.axisymmetric ? 2 * std::numbers::pi * x[i + 1] : 1.0;",
             "the force an axisymmetric compare.reference carries with a ring weight 2 pi r at one end of each piece",
             ["cli:tests/cli/test_compare_reference.py::test_a_reference_of_the_runs_load_is_compared[axisymmetric]",
              "cli:tests/cli/test_compare_reference.py::test_a_reference_of_another_load_is_refused[above-axisymmetric]",
              "cli:tests/cli/test_compare_reference.py::test_a_reference_of_another_load_is_refused[below-axisymmetric]"]),
    Mutation("facing-degrees-one-sweep", "adapt", S + "adapt/facing_degrees.cpp",
             "        changed = true;",
             "        changed = false;",
             "facing contact edges matched in one sweep: an element facing two of different degrees leaves the first at the smaller",
             ["FacingDegrees.AnElementFacingTwoTakesTheLargestAndSoDoBoth",
              "HpMesh.EveryStepKeepsTheMinimumDegreeAndEqualFacingDegrees"]),
    Mutation("hp-min-degree-ignored", "adapt", S + "adapt/hp.cpp",
             "  o.min_degree = adapt.min_degree;",
             "  o.min_degree = 1;",
             "hp's degrees start from 1 at the refinement centres whatever adapt.min_degree says",
             ["HpMesh.EveryStepKeepsTheMinimumDegreeAndEqualFacingDegrees",
              "cli:tests/cli/test_two_bars.py::test_coulomb_hp_traction_without_oscillation"]),
    # analytic: Persson's pin in a hole
    Mutation("pin-kernel-constant", "analytic", S + "analytic/pin_in_hole.cpp",
             "- 0.5 * (1 - beta) * (1 + 0.5 * std::cos(x))",
             "- 0.5 * (1 + beta) * (1 + 0.5 * std::cos(x))",
             "the closed-form kernel's constant and cos x terms with 1 + β for 1 − β",
             ["PinInHole.GapClosesOnTheArcAndOpensOutside"]),
    Mutation("yaml-values-at-the-limit", "io", S + "io/yaml_limits.cpp",
             "if (values_ > most_) throw Stop{mark};",
             "if (values_ >= most_) throw Stop{mark};",
             "a YAML text of exactly the values an input may have refused",
             ["YamlLimits.RefusedOneValuePastTheLimitAtThatValue", "YamlLimits.AnAliasCountsAsWhatItRepeats",
              "YamlLimits.EveryYamlFileOfTheRepositoryIsReadAtItsValues"]),
    Mutation("yaml-alias-counts-one", "io", S + "io/yaml_limits.cpp",
             "    add(mark, size);",
             "    add(mark, 1);",
             "an alias counted as one value, not as the subtree it repeats (a few bytes for a tree of millions)",
             ["YamlLimits.AnAliasCountsAsWhatItRepeats",
              "cli:tests/cli/test_limits.py::test_yaml_values_are_counted_before_the_tree_is_built[aliases]",
              "cli:tests/cli/test_limits.py::test_set_values_are_bounded_as_files_are"]),
    Mutation("yaml-cycle-as-values", "io", S + "io/yaml_limits.cpp",
             "    if (size == kOpen) throw Stop{mark, true};",
             "    if (size == kOpen) throw Stop{mark, false};",
             "an alias inside what it names reported as too many values, not as a cycle",
             ["YamlLimits.ACycleIsRefused", "cli:tests/cli/test_limits.py::test_an_alias_cycle_is_refused"]),
    Mutation("yaml-flow-collections-unbounded", "io", S + "io/yaml_limits.cpp",
             "  if (const auto start = FlowScanner(text, 2 * most + 1).run())",
             "  if (const auto start = FlowScanner(text, 2 * most + 1).run(); false)",
             "flow lists left to yaml-cpp's scanner, which holds one whole before the values are counted",
             ["YamlLimits.AFlowCollectionIsBoundedAtItsBracket",
              "cli:tests/cli/test_limits.py::test_yaml_values_are_counted_before_the_tree_is_built[flow-list-as-item]"]),
    Mutation("yaml-flow-quote-escape", "io", S + "io/yaml_limits.cpp",
             "        if (quote == '\"' || i_ >= text_.size() || text_[i_] != '\\'') return;",
             "        return;",
             "a single-quoted scalar taken to end at its escaped quote ('it''s'): its brackets read as a flow list",
             ["YamlLimits.OnlyFlowCollectionsAreBoundedFromTheText"]),
    Mutation("yaml-bytes-unbounded", "io", S + "io/yaml_limits.cpp",
             "  if (bytes <= kMaxYamlBytes) return std::nullopt;",
             "  if (true) return std::nullopt;",
             "YAML text given as a string (Problem.from_yaml, set=) read whatever its size",
             ["YamlLimits.SyntaxErrorsAndBytes",
              "python:tests/python/test_limits.py::test_from_yaml_is_bounded_as_a_file_is",
              "python:tests/python/test_limits.py::test_set_values_are_bounded_as_files_are"]),
    Mutation("set-value-budget-whole", "io", S + "io/overrides.cpp",
             "kMaxYamlValues - std::min(rest, kMaxYamlValues)))",
             "kMaxYamlValues))",
             "each --set value bounded alone, not by what the rest of the problem leaves it",
             ["python:tests/python/test_limits.py::test_set_values_are_bounded_as_files_are",
              "cli:tests/cli/test_limits.py::test_set_values_are_bounded_as_files_are"]),
    Mutation("overrides-total-unchecked", "io", S + "io/problem_reader.cpp",
             "      if (values > kMaxYamlValues)",
             "      if (false)",
             "the keys --set values create left out of the problem's values",
             ["YamlLimits.OverridesAreBoundedWithTheFile"]),
    Mutation("gmsh-mesh-values-unbounded", "io", S + "io/gmsh_import.cpp",
             "    if (*values + added > kMaxYamlValues)",
             "    if (false)",
             "a Gmsh mesh written into the problem's YAML tree whatever its values",
             ["cli:tests/cli/test_limits.py::test_gmsh_meshes_are_bounded_before_they_are_read"]),
    Mutation("gmsh-node-count-unbounded", "io", S + "io/gmsh_reader.cpp",
             '    require_at_most(n_nodes, kMaxMeshNodes, "nodes");',
             "    (void)n_nodes;",
             "a .msh file's nodes read whatever its $Nodes header says",
             ["GmshReader.RejectsBrokenFiles",
              "cli:tests/cli/test_limits.py::test_gmsh_meshes_are_bounded_before_they_are_read"]),
    Mutation("gmsh-volume-z-dropped", "io", S + "io/gmsh_reader.cpp",
             "? volume_mesh_.nodes.emplace(node, std::array{x, y, z}).second",
             "? volume_mesh_.nodes.emplace(node, std::array{x, y, 0.0}).second",
             "a 3D mesh's nodes read in the plane z = 0",
             ["GmshVolumeReader.ReadsHexahedraAndBoundaryQuads", "GmshHexImport.MakesTheBodyOfABox"]),
    Mutation("gmsh-hex-corners-as-quad", "io", S + "io/gmsh_reader.cpp",
             "    const std::size_t n_corners = hex ? 8 : quad ? 4 : 2;",
             "    const std::size_t n_corners = hex ? 4 : quad ? 4 : 2;",
             "a hexahedron with a vertex twice read when the repeat is among its top vertices",
             ["GmshHexImport.RefusesInvertedAndDegenerateHexahedra"]),
    Mutation("hex-face-set-keeps-interior-face", "io", S + "io/gmsh_hex_import.cpp",
             "      if (!f.on_boundary())",
             "      if (false)",
             "a physical surface's quad between two of the body's hexahedra kept in its face set",
             ["GmshHexImport.ChoosesVolumes", "GmshHexImport.RefusesFacesOffTheBoundary"]),
    Mutation("hex-other-volume-counts-dropped", "io", S + "io/gmsh_hex_import.cpp",
             "        counts.push_back(counted(type, c.second, c.first));",
             "        counts.push_back(counted(type, c.second, 1));",
             "the refusal of tetrahedra, prisms and pyramids names one of each instead of their counts",
             ["GmshHexImport.RefusesOtherVolumeElements"]),
    Mutation("hex20-completion-vertex-weight", "io", S + "io/gmsh_hex_import.cpp",
             "        N *= (r[0] * c[0] + r[1] * c[1] + r[2] * c[2] - 2) / 8.0;",
             "        N *= (r[0] * c[0] + r[1] * c[1] + r[2] * c[2] - 1) / 8.0;",
             "a 20-node hexahedron's face and centre nodes completed with wrong serendipity vertex weights",
             ["GmshHexImport.CompletesTwentyNodeHexahedraBySerendipity",
              "GmshHexImport.MakesTheBodyOfABox"]),
    Mutation("hex-surface-body-accepted", "io", S + "io/gmsh_hex_import.cpp",
             "      if (!e.on_volume)\n        fail_at(e.first_line,",
             "      if (false)\n        fail_at(e.first_line,",
             "a 2D mesh beside the volumes read as part of a 3D body's file",
             ["GmshHexImport.RefusesTwoDimensionalMeshes"]),
    Mutation("hex-jacobian-unchecked", "io", S + "io/gmsh_hex_import.cpp",
             "      mesh::check_hex_jacobian(map, mesh_.file",
             "      if (false) mesh::check_hex_jacobian(map, mesh_.file",
             "an inverted or flat hexahedron of a Gmsh file imported",
             ["GmshHexImport.RefusesInvertedAndDegenerateHexahedra"]),
    Mutation("hex-face-of-other-volume-refused", "io", S + "io/gmsh_hex_import.cpp",
             "        if (volume_faces_.count(face_key(q.corners[0], q.corners[1], q.corners[2], q.corners[3])) ||",
             "        if (false ||",
             "a physical surface's quad on a volume not chosen refused instead of left out of the body's face set",
             ["GmshHexImport.ChoosesVolumes"]),
    Mutation("input-file-buffer-doubles", "io", S + "io/text_file.cpp",
             "  std::string text(static_cast<std::size_t>(st.st_size) + 1, '\\0');",
             "  std::string text(static_cast<std::size_t>(st.st_size), '\\0');",
             "an input file's buffer grown to find its end, twice the file in memory",
             ["cli:tests/cli/test_limits.py::test_gmsh_meshes_are_bounded_before_they_are_read"]),
    Mutation("effective-input-values-unchecked", "io", S + "io/problem_reader.cpp",
             "    if (const std::size_t effective_values = count_yaml_values(root); effective_values > kMaxYamlValues)",
             "    if (const std::size_t effective_values = count_yaml_values(root); false)",
             "a problem whose defaults take it past the values limit read, its input.yaml then refused",
             ["YamlLimits.TheEffectiveInputCanBeReadBack"]),
    Mutation("effective-input-bytes-unchecked", "io", S + "io/problem_reader.cpp",
             "    if (read.effective_yaml.size() > kMaxYamlBytes)",
             "    if (false)",
             "a problem whose defaults take it past 16 MB read, its input.yaml then refused",
             ["cli:tests/cli/test_limits.py::test_the_effective_input_is_bounded_as_a_file_is"]),
    Mutation("script-newline-unchecked", "driver", S + "driver/slurm_script.cpp",
             "  const bool control = std::any_of(value.begin(), value.end(), is_control);",
             "  const bool control = false;",
             "a newline in a study's name, path, override or --time ends its line of the Slurm script: the rest runs as a command",
             ["SlurmScript.ValuesThatWouldEndTheirLineAreRefused"]),
    Mutation("study-sighup-kills", "driver", S + "driver/study.cpp",
             "    for (const int signal : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&signals_, signal);",
             "    for (const int signal : {SIGINT, SIGTERM}) sigaddset(&signals_, signal);",
             "SIGHUP (a closed terminal) kills a study at once, orphaning its runs and leaving its staging folder",
             ["cli:tests/cli/test_output_folder.py::test_study_passes_signals_to_its_runs[1]"]),
    Mutation("runs-outlive-killed-study", "apps", "apps/main.cpp",
             "  ::prctl(PR_SET_PDEATHSIG, SIGTERM);",
             "  (void)PR_SET_PDEATHSIG;",
             "the runs of a study killed by SIGKILL go on computing and writing on their own",
             ["cli:tests/cli/test_output_folder.py::test_runs_of_a_killed_study_stop_and_keep_what_had_converged"]),
    Mutation("newton-iteration-unstoppable", "solve", S + "solve/newton.cpp",
             "  const StoppableWork stoppable;",
             "  const bool stoppable = false;",
             "a stop waits for the whole Newton iteration (seconds at high degree, minutes in 3D)",
             ["NewtonStop.AStopInsideAnIterationGivesItUp",
              "cli:tests/cli/test_stop_signal.py::test_a_stop_inside_a_long_newton_iteration_takes_effect_at_once"]),
    Mutation("assembly-unstoppable", "model", S + "model/linear_solve.cpp",
             "  const StoppableWork stoppable;\n  struct Ref {",
             "  struct Ref {",
             "a stop waits for a contact system's whole assembly (13 s of a degree-30 Hertz run)",
             ["RunStop.AContactRunAskedToStopWhileItAssemblesEndsThere"]),
    Mutation("point-blocks-skip", "fem", S + "fem/point_blocks.hpp",
             "  for (int first = 0; first < n_points; first += size) {",
             "  for (int first = 0; first < n_points; first += size + 1) {",
             "an element's products by blocks of points leave a point out between blocks",
             ["PointBlocks.CoverEveryPointOnceInOrder", "PointBlocks.HighDegreeStiffnessIsTheSumOverEveryPoint"]),
    Mutation("stop-point-unarmed", "core", S + "core/stop.cpp",
             "  if (requested.load(std::memory_order_relaxed) != 0 && armed.load() > 0) throw Stopped(doing);",
             "  if (requested.load(std::memory_order_relaxed) != 0) throw Stopped(doing);",
             "a stop point throws outside stoppable work: a stopped run cannot write its last-good/",
             ["NewtonStop.StopPointsActOnlyInsideStoppableWork", "PointBlocks.AStopEndsThemBetweenBlocks",
              "cli:tests/cli/test_stop_signal.py::test_a_stopped_load_path_keeps_its_converged_steps[15]"]),
    Mutation("direction-controls-raw", "apps", "apps/main.cpp",
             "    if (point) {",
             "    if (false) {",
             "U+202E in a case or body name reaches the terminal and turns the rest of its line around",
             ["cli:tests/cli/test_messages.py::test_a_newline_or_direction_control_in_a_name_does_not_reach_the_terminal"]),
    Mutation("log-json-strict-utf8", "apps", "apps/main.cpp",
             "    std::cout << fields.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << std::endl;",
             "    std::cout << fields.dump() << std::endl;",
             "--log-json of a path that is not UTF-8 ends in an internal error",
             ["cli:tests/cli/test_run.py::test_log_json_stays_json_with_a_path_that_is_not_utf8"]),
    Mutation("manifest-other-kind-as-edited", "driver", S + "driver/output_folder.cpp",
             '    HPC_REQUIRE(plain_relative(line), IoError, shown(kManifest), ":", number, ": ", shown_line,',
             '    HPC_REQUIRE(plain_relative(line) && layout_.is_output(line, false), IoError, shown(kManifest), ":", number, ": ", shown_line,',
             "a study into a run's folder (or the other way round) is said to have an edited manifest",
             ["OutputFolder.ManifestWithForeignNamesIsRefused",
              "cli:tests/cli/test_output_folder.py::test_a_run_and_a_study_do_not_share_a_folder"]),
    Mutation("record-rows-unchecked", "driver", S + "driver/slurm_record.cpp",
             '      rows(s, at, "rows", runs.size(), true);',
             "      (void)0;",
             "a forged submission record's rows reach the collection: an internal error, or a row beyond the study",
             ["SlurmRecord.ForgedRecordsAreRefusedByTheirKey",
              "cli:tests/cli/test_study_command.py::test_collect_of_a_forged_submission_record_names_the_key"]),
    Mutation("killed-run-as-exit-code", "driver", S + "driver/study.cpp",
             "  if (WIFSIGNALED(status)) return -WTERMSIG(status);",
             "  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);",
             "a study row whose run was killed by a signal says 'exit code 137', not which signal",
             ["cli:tests/cli/test_output_folder.py::test_a_run_killed_by_a_signal_is_a_failed_row_that_says_so"]),
    Mutation("gone-summary-unsaid", "driver", S + "driver/slurm_study.cpp",
             "    row.exit_code = complete && row.summary.is_object() ? 0 : -1;",
             "    row.exit_code = complete ? 0 : -1;",
             "a Slurm row found complete whose summary.json has since gone is a failed row without a reason",
             ["SlurmCollect.ARowWhoseSummaryHasGoneIsNotASuccess"]),
    Mutation("marker-kept-while-placing", "driver", S + "driver/output_folder.cpp",
             "  if (replaced.count(marker)) unlink_listed(marker);",
             "  (void)replaced;",
             "the earlier summary.json stays while the new files move in: a commit failing half way leaves it beside new results",
             ["OutputFolderAtomicity.AFailedRenameLeavesNoSummaryOfAnUnfinishedRun"]),
    Mutation("mooney-rivlin-without-c01", "io", S + "io/problem_reader.cpp",
             ": model == \"mooney-rivlin\" ? std::vector<std::string>{\"C10\", \"C01\"}",
             ": model == \"mooney-rivlin\" ? std::vector<std::string>{\"C10\"}",
             "mooney-rivlin read without its C01 (refused as a constant it does not take)",
             ["ProblemReader.ReadsRubberLawsAndRefusesConstantsTheyDoNotTake"]),
    Mutation("one-sided-normal-by-default", "io", S + "io/problem_reader.cpp",
             "          c.mean_normal = true;",
             "          c.mean_normal = false;",
             "friction between two bodies presses along the other body's normal: mirror images shear each other",
             ["cli:tests/cli/test_mirror_friction.py::test_no_shear_between_mirror_images"]),
    Mutation("mean-normal-foot-fixed", "contact", S + "contact/point_gap.cpp",
             "    pg.dg_row = pg.dg - (n.dot(t) / cc) * H + dn_du.transpose() * r;",
             "    pg.dg_row = pg.dg + dn_du.transpose() * r;",
             "the mean normal's constraint gradient forgets that the foot slides along the other boundary",
             ["TwoBodyContact.MeanNormalGapDerivativesAgreeWithDifferences"]),
    Mutation("mean-normal-force-along-gradient", "contact", S + "contact/point_gap.cpp",
             "    pg.d2g = turning_field(n, dn_du);  // ∂(force direction)/∂u: not symmetric",
             "    pg.d2g = turning_field(n, dn_du).transpose();",
             "the derivative of the mean normal's force direction transposed (the tangent of another force)",
             ["TwoBodyContact.MeanNormalGapDerivativesAgreeWithDifferences"]),
    Mutation("interference-unramped", "model", S + "model/contact_multipliers.cpp",
             "      pg.g += relief.remaining * overlap_q;",
             "      pg.g += overlap_q;",
             "a ramped interference relieved from the start, whatever the factor: its first step carries the whole fit",
             ["cli:tests/cli/test_press_fit.py::test_a_ramped_interference_presses_step_by_step_to_the_same_fit"]),
    Mutation("stretch-per-parameter", "contact", S + "contact/deformable_boundary.cpp",
             "  return tangent_at(k, t).norm() / dS_dt;",
             "  return tangent_at(k, t).norm();",
             "a boundary's stretch per unit edge parameter, not per unit undeformed length",
             ["DeformableBoundary.GapToADeformedSquareIsTheSignedDistance"]),
    Mutation("other-rows-unstretched", "model", S + "model/contact_result_rows.cpp",
             "      pair.other_boundary->stretch(cp.edge, cp.t) /",
             "      1.0 /",
             "the other body's rows of an exact pair keep the carrier's length: its pressure off by the two surfaces' tangential strains (a press fit: 3e-4)",
             ["cli:tests/cli/test_press_fit.py::test_the_carriers_agree"]),
    Mutation("other-rows-carriers-radius", "model", S + "model/contact_result_rows.cpp",
             "      (other.out_of_plane().at(cp.X) * pair.boundary->stretch(foot.edge, foot.t));",
             "      (body.out_of_plane().at(pair.boundary->undeformed(foot.edge, foot.t)) * pair.boundary->stretch(foot.edge, foot.t));",
             "the other body's rows of an axisymmetric pair per unit of the carrier's circumference, not their own (a shaft in a hub: 1e-3)",
             ["cli:tests/cli/test_press_fit.py::test_the_carriers_agree",
              "cli:tests/cli/test_axisymmetric_contact.py::test_shrink_fit_pressure_is_lames"]),
    Mutation("carrier-outside-the-other", "model", S + "model/contact_carrier.cpp",
             "    obstacle_carries = other.facing > own.facing;",
             "    obstacle_carries = other.facing < own.facing;",
             "carrier: auto lets the body whose contact boundary reaches beyond the other's carry (a shaft past its hub's end)",
             ["cli:tests/cli/test_carrier_choice.py::test_auto_chooses_the_same_body_whichever_the_input_names_first",
              "cli:tests/cli/test_press_fit.py::test_auto_lets_the_hub_carry_and_says_why"]),
    Mutation("carrier-tie-as-written-order", "model", S + "model/contact_carrier.cpp",
             "    obstacle_carries = other.index < own.index;",
             "    obstacle_carries = false;",
             "carrier: auto between two alike bodies keeps the pair's order: the answer depends on how the input names the pair",
             ["cli:tests/cli/test_carrier_choice.py::test_auto_chooses_the_same_body_whichever_the_input_names_first"]),
    Mutation("carrier-normal-direction-kept", "model", S + "model/contact_carrier.cpp",
             "      for (double& v : *pair.normal_direction) v = -v;",
             "      (void)0;",
             "carrier: auto swapping the bodies keeps normal_direction: the normal force measured on the other body, its sign turned",
             ["cli:tests/cli/test_press_fit.py::test_auto_lets_the_hub_carry_and_says_why"]),
    Mutation("touching-node-starts-inactive", "model", S + "model/contact_solve.cpp",
             "    system_.activate_touching(x_);",
             "    (void)0;",
             "a body touching its partner at one point starts with no active node: held by friction alone, its tangent is singular",
             ["cli:tests/cli/test_roller_block_friction.py::test_pressed_and_sheared_from_a_one_point_touch",
              "cli:tests/cli/test_mirror_friction.py::test_touching_at_one_point_friction_holds_the_body_from_the_start"]),
    Mutation("memory-later-slip-ignored", "model", S + "model/memory_points.cpp",
             "      if (k >= history[later].stuck.size() || !stuck_at(history[later].stuck[k], history[later].slipped[k], s))",
             "      if (false && (k >= history[later].stuck.size() || !stuck_at(history[later].stuck[k], history[later].slipped[k], s)))",
             "an earlier stick zone end is a memory point though a later step slipped there (its kink rewritten)",
             ["cli:tests/cli/test_memory_points.py::test_unloaded_after_a_shear_the_loading_stick_zone_end_is_a_memory_point",
              "cli:tests/cli/test_memory_points.py::test_a_shear_that_only_grows_leaves_no_memory"]),
    Mutation("friction-step-cut-not-continued", "model", S + "model/contact_solve.cpp",
             "    if (cuts == 0 && system_.has_friction())",
             "    if (false && cuts == 0 && system_.has_friction())",
             "a frictional step Newton finds hard is cut into committed shorter steps: another load path",
             ["cli:tests/cli/test_memory_points.py::test_a_step_newton_finds_hard_keeps_the_load_path"]),
    Mutation("load-history-wrong-component", "python", "python/hpcontact_module.cpp",
             "    resultant_y.push_back(p.resultant.y());",
             "    resultant_y.push_back(p.resultant.x());",
             "Python's load history gives the resultant's x as its y",
             ["python:tests/python/test_load_history.py::test_load_and_contact_history_are_the_files"]),
    Mutation("last-good-files-unnamed", "driver", S + "driver/run.cpp",
             '  return folder.filename() == "last-good" ? "last-good/" + file + " (the last converged state)" : file;',
             "  return file;",
             "a failed run's progress says it wrote summary.json, which went to last-good/",
             ["cli:tests/cli/test_axle_ring.py::test_a_failed_run_says_its_files_went_to_last_good"]),
    Mutation("cut-part-unnamed", "model", S + "model/contact_solve.cpp",
             '    if (!whole) name += " (a part of it, cut)";',
             "    if (false) name += \" (a part of it, cut)\";",
             "a converged part of a cut load step is reported as if it were the whole step",
             ["cli:tests/cli/test_axle_ring.py::test_a_cut_step_keeps_its_number"]),
    Mutation("hex-face-flip-ignored", "basis", S + "basis/hex_modes.cpp",
             "        const bool negative = (o.flip1 && i % 2 == 1) != (o.flip2 && j % 2 == 1);",
             "        const bool negative = (o.flip1 && i % 2 == 1);",
             "a face whose second global axis runs against the element's keeps its odd modes: the trace jumps across the face",
             ["HexConformity.TwoElementsAgreeOnTheirFaceInEveryOrientation"]),
    Mutation("hex-shear-transpose-dropped", "fem", S + "fem/hex_elasticity.cpp",
             "      K.block(i * n, j * n, n, n) = lambda * M[i][j] + mu * M[i][j].transpose();",
             "      K.block(i * n, j * n, n, n) = lambda * M[i][j];",
             "the hexahedron's stiffness loses the μ ∇vᵀ:∇u coupling of different components (the patch test cannot see a wrong law: any constant stress balances)",
             ["HexStiffness.BlockKernelIsBtDB"]),
    Mutation("solid-face-set-unchecked", "io", S + "io/solid_reader.cpp",
             "      if (std::find(known.begin(), known.end(), out[i]) == known.end()) {",
             "      if (false) {",
             "a 3D constraint naming a face set the mesh does not have is not refused by its key",
             ["cli:tests/cli/test_solid.py::test_a_wrong_3d_input_is_refused_naming_the_cause"]),
    Mutation("solid-traction-per-reference-area", "fem", S + "fem/hex_face_load.cpp",
             "    return n_dA.norm() * traction;",
             "    return traction;",
             "a face traction integrated over the reference face (area 4) instead of the physical one",
             ["cli:tests/cli/test_solid.py::test_a_uniform_stress_is_reproduced_to_round_off",
              "HexFaceLoad.BoxFaceTractionResultantAndMoment", "HexFaceLoad.SphericalOctantTractionResultant",
              "HexCantilever.EqualElementsConvergeInPWithoutLocking"]),
    Mutation("solid-constraint-on-every-face-mode", "model", S + "model/solid_model.cpp",
             "          const double value = vertex ? *c.u[k] : 0.0;",
             "          const double value = *c.u[k];",
             "a prescribed displacement given to a face's edge and face modes as well as its vertex modes: not a constant on the face",
             ["cli:tests/cli/test_solid.py::test_a_uniform_stress_is_reproduced_to_round_off"]),
    Mutation("hex-singular-stiffness-solved", "solve", S + "solve/fixed_dofs.cpp",
             "  solver.set_singular_pivot_ratio(kSlenderSingularPivotRatio);",
             "  solver.set_singular_pivot_ratio(0.0);",
             "a 3D body free to move rigidly is solved (round-off pivots) instead of refused",
             ["cli:tests/cli/test_solid.py::test_a_wrong_3d_input_is_refused_naming_the_cause"]),
    Mutation("solid-surfaces-ignored", "model", S + "model/solid_model.cpp",
             "  put_faces_on_surfaces(m, spec.body.surfaces);\n",
             "",
             "the faces named on an exact surface keep the mesh's quadratic geometry: the plate's volume is 1.6e-7 off",
             ["cli:tests/cli/test_plate_hole_3d.py::test_the_stress_concentration_is_howlands"]),
    Mutation("solid-face-on-two-surfaces", "model", S + "model/solid_model.cpp",
             "      HPC_REQUIRE(!on[h][lf] || on[h][lf] == surface, InputError, s.where.str(), \": face \", lf,",
             "      HPC_REQUIRE(true, InputError, s.where.str(), \": face \", lf,",
             "a face named on two surfaces silently takes the last one",
             ["cli:tests/cli/test_solid.py::test_a_face_on_two_surfaces_is_refused"]),
    Mutation("face-modes-incomplete", "fem", S + "fem/hex_dof_map.cpp",
             "  for (int k = 0; k < n_face_modes(face); ++k) modes.push_back(face_first_mode(face) + k);",
             "  for (int k = 0; k + 1 < n_face_modes(face); ++k) modes.push_back(face_first_mode(face) + k);",
             "a condition on a hexahedron's face leaves its last face mode free",
             ["HexDofMap.ModesOnAFaceAreThoseNonZeroOnIt"]),
    Mutation("hex-factored-column-sign-dropped", "fem", S + "fem/hex_factored_stiffness.cpp",
             "        for (int a = 0; a < n; ++a) out[a] = sign[a] * sign[b] * column[left[a]];",
             "        for (int a = 0; a < n; ++a) out[a] = sign[a] * column[left[a]];",
             "the sum-factorised stiffness forgets the sign of its column's mode (an odd mode of a reversed edge or turned face)",
             ["HexFactoredStiffness.EqualsTheReferenceKernel"]),
    Mutation("hex-factored-shear-transpose-dropped", "fem", S + "fem/hex_factored_stiffness.cpp",
             "A(row, 3 * r + s) = w * (lambda * Ji(r, i) * Ji(s, j) + mu * Ji(r, j) * Ji(s, i) +",
             "A(row, 3 * r + s) = w * (lambda * Ji(r, i) * Ji(s, j) + mu * Ji(r, i) * Ji(s, j) +",
             "the sum-factorised stiffness takes μ ∇v:∇uᵀ as μ M_ij instead of μ M_ji (the patch test cannot see a wrong law)",
             ["HexFactoredStiffness.EqualsTheReferenceKernel"]),
    Mutation("hex-kernel-choice-reversed", "fem", S + "fem/hex_element.cpp",
             "  return f.factored < kFactoredFlopRatio * f.blocks ? HexStiffnessKernel::factored",
             "  return f.factored > kFactoredFlopRatio * f.blocks ? HexStiffnessKernel::factored",
             "the slower hexahedron kernel chosen: the O(p⁹) products for the tensor space at high p, sum factorisation at low p",
             ["HexFactoredStiffness.ChosenWhereItIsFaster"]),
    Mutation("fixed-values-sign", "solve", S + "solve/fixed_dofs.cpp",
             "        rhs.row(position[row]) -= it.value() * values.row(-1 - position[col]);",
             "        rhs.row(position[row]) += it.value() * values.row(-1 - position[col]);",
             "prescribed values moved to the right-hand side with the wrong sign",
             ["HexPatch.UniformStrainOnDistortedStraightHexes", "HexPatch.UniformStrainOnCurvedHexes"]),
    Mutation("factor-estimate-without-factor", "solve", S + "solve/linear_solver.cpp",
             "    m.estimate_bytes = sizeof(int) * integers + std::max(2 * copy, sizeof(double) * reals + copy) +",
             "    m.estimate_bytes = sizeof(int) * integers + 2 * copy +",
             "the factor's memory estimate counts the copies of the matrix but not the factor: a factor that will not fit is tried",
             ["LinearSolverMemory.EstimateIsWhatTheFactorisationTakes",
              "LinearSolverMemoryDeathTest.FactorBeyondTheLimitIsRefusedWithItsEstimate"]),
    Mutation("factor-not-checked", "solve", S + "solve/linear_solver.cpp",
             "      require_memory_for_factor(impl_->memory, A.rows(), A.nonZeros());",
             "      (void)0;",
             "a factor is allocated without comparing its estimate with the memory available (past a limit the kernel ends the process)",
             ["LinearSolverMemoryDeathTest.FactorBeyondTheLimitIsRefusedWithItsEstimate",
              "cli:tests/cli/test_failures.py::test_a_3d_factor_that_will_not_fit_is_refused_with_its_size"]),
    Mutation("address-space-in-use-ignored", "solve", S + "solve/available_memory.cpp",
             '    take(cap - in_use, "the address-space limit (ulimit -v) of " + gigabytes(cap) + ", " +',
             '    take(cap, "the address-space limit (ulimit -v) of " + gigabytes(cap) + ", " +',
             "the memory available under ulimit -v taken as the whole limit, not what the process has left of it",
             ["LinearSolverMemoryDeathTest.FactorBeyondTheLimitIsRefusedWithItsEstimate"]),
    Mutation("box-face-set-dropped", "mesh", S + "mesh/hex_mesh.cpp",
             "          if (index[d] == 0) m.face_sets[side_names[2 * d]].push_back({element, 2 * d});",
             "          if (index[d] == 0 && element > 0) m.face_sets[side_names[2 * d]].push_back({element, 2 * d});",
             "a structured grid's first element (the box's, the sector's) is left out of its first side sets (x0, y0, z0): a clamp or load there misses a face",
             ["HexBox.CountsFaceSetsAndVolume", "HexBox.GivenPlanes"]),
    Mutation("sector-inner-face-flat", "mesh", S + "mesh/cylinder_sector.cpp",
             "                             cylinder[i], cylinder[i + 1], meridian[j],",
             "                             i == 0 ? nullptr : cylinder[i], cylinder[i + 1], meridian[j],",
             "the cylinder sector's inner face is the flat interpolant of chords instead of the cylinder",
             ["CylinderSector.CountsFaceSetsPolarMapAndVolume"]),
    Mutation("sector-angles-unequal", "mesh", S + "mesh/cylinder_sector.cpp",
             "angle[j] = std::lerp(angle0, angle1, step(j, n[1]));",
             "angle[j] = std::lerp(angle0, angle1, step(j, n[1]) * step(j, n[1]));",
             "the cylinder sector's elements span unequal angles (nodes still on the cylinders, the volume still exact)",
             ["CylinderSector.CountsFaceSetsPolarMapAndVolume"]),
    Mutation("shell-octant-planes-swapped", "mesh", S + "mesh/shell_octant.cpp",
             "std::array<std::vector<ElementFace>*, 3> symmetry{&m.face_sets[\"x0\"], &m.face_sets[\"y0\"],",
             "std::array<std::vector<ElementFace>*, 3> symmetry{&m.face_sets[\"y0\"], &m.face_sets[\"x0\"],",
             "the shell octant's face sets x0 and y0 exchanged: a symmetry condition holds the wrong component",
             ["BlendingHex.ShellOctantFacesLieOnTheirSurfaces", "HexSphere.AnisotropicDegreesReachOneInTenToTheFive",
              "HexSphere.EnergyConvergesExponentiallyFromBelow"]),
    Mutation("face-set-interior-accepted", "mesh", S + "mesh/hex_mesh.cpp",
             "HPC_REQUIRE(t.face(t.hex_face(h, lf)).on_boundary(), MeshError",
             "HPC_REQUIRE(true || t.face(t.hex_face(h, lf)).on_boundary(), MeshError",
             "a face set may hold a face between two elements (a load or condition inside the body)",
             ["HexMeshCheck.RefusesBadFaceSetsAndMissingMaps"]),
    Mutation("singular-pivot-ratio-as-2d", "solve", S + "solve/fixed_dofs.hpp",
             "inline constexpr double kSlenderSingularPivotRatio = 1e-13;",
             "inline constexpr double kSlenderSingularPivotRatio = 1e-11;",
             "the 3D solve refuses as singular a slender solid whose bending pivots are small but not round-off (the 1:1000 cantilever)",
             ["HexCantilever.EqualElementsConvergeInPWithoutLocking"]),
    Mutation("traction-sign", "fem", S + "fem/hex_face_load.cpp",
             "    return n_dA.norm() * traction;",
             "    return -n_dA.norm() * traction;",
             "a face traction acts against its direction (the cantilever bends the other way)",
             ["HexFaceLoad.BoxFaceTractionResultantAndMoment", "HexCantilever.EqualElementsConvergeInPWithoutLocking",
              "HexCantilever.GradedElementsAreWithinHalfAPercentFromP4"]),
    # the plot scripts: several pairs, several runs, the squeeze, the field's magnification
    Mutation("field-scale-parts-closed-contact", "scripts", "scripts/plot_field.py",
             "        return depth(s) <= allowed and closed.separation(s) <= tolerance",
             "        return depth(s) <= allowed",
             "plot_field's automatic scale bounds only overlap: a press fit's closed interface drawn millimetres apart",
             ["cli:tests/cli/test_plots.py::test_plot_field_keeps_a_press_fit_closed"]),
    Mutation("history-pairs-one-polyline", "scripts", "scripts/plot_contact_history.py",
             '        return [i for i, p in enumerate(self.cols["pair"]) if int(p) == pair]',
             '        return list(range(len(self.cols["pair"])))',
             "the history of every pair drawn as one curve in each panel (the zig-zag of rows of all pairs)",
             ["cli:tests/cli/test_plots.py::test_contact_history_one_panel_per_pair_one_label_per_run",
              "cli:tests/cli/test_plots.py::test_contact_history_axes_a_user_chooses"]),
    Mutation("squeeze-is-the-factor", "scripts", "scripts/plot_runs.py",
             "        return (factor_x * self.d[0] ** 2 + factor_y * self.d[1] ** 2) / norm",
             "        return factor_y",
             "the squeeze axis plots the displacement factor, not the distance the plate has moved",
             ["cli:tests/cli/test_plots.py::test_contact_history_one_panel_per_pair_one_label_per_run",
              "cli:tests/cli/test_plots.py::test_labels_and_units_of_several_runs"]),
    Mutation("contact-plot-pairs-one-polyline", "scripts", "scripts/plot_contact.py",
             '        rows = [i for i, p in enumerate(self.cols["pair"]) if int(p) == pair]',
             '        rows = list(range(len(self.cols["pair"])))',
             "plot_contact draws the rows of every pair in each panel (top, bottom and wall rows as one line)",
             ["cli:tests/cli/test_plots.py::test_contact_plot_one_panel_per_pair_one_label_per_run"]),
    Mutation("run-label-ignored", "scripts", "scripts/plot_runs.py",
             "        return list(labels)",
             "        return [os.path.basename(os.path.normpath(f)) for f in folders]",
             "--label ignored: runs labelled by folder name whatever the user names them",
             ["cli:tests/cli/test_plots.py::test_contact_history_one_panel_per_pair_one_label_per_run",
              "cli:tests/cli/test_plots.py::test_labels_and_units_of_several_runs"]),
    Mutation("units-swapped", "scripts", "scripts/plot_runs.py",
             '    return {"length": parts[0], "force": parts[1]}',
             '    return {"length": parts[1], "force": parts[0]}',
             "--units mm,N read as length N, force mm (labels say [N], [mm/N])",
             ["cli:tests/cli/test_plots.py::test_contact_history_one_panel_per_pair_one_label_per_run",
              "cli:tests/cli/test_plots.py::test_labels_and_units_of_several_runs"]),
    # model: reactions
    Mutation("reaction-all-modes", "model", S + "model/reactions.cpp",
             "  Eigen::VectorXd w = Eigen::VectorXd::Zero(body.dofs.n_modes());",
             "  Eigen::VectorXd w = Eigen::VectorXd::Ones(body.dofs.n_modes());",
             "a resultant sums every mode of a force vector, not the vertex modes alone",
             ["Reactions.ResultantAndMomentOfALoadOnACurvedEdge",
              "cli:tests/cli/test_reactions.py::test_bar_reaction_is_E_A_u_over_L"]),
    Mutation("reaction-lagrange-vertices", "model", S + "model/reactions.cpp",
             "  if (body.dofs.lagrange()) return Eigen::VectorXd::Ones(body.dofs.n_modes());",
             "  if (false) return Eigen::VectorXd::Ones(body.dofs.n_modes());",
             "an h-version resultant sums the corner nodes alone (a Q8 edge's mid node carries 2/3)",
             ["Reactions.ResultantAndMomentOfALoadOnACurvedEdge"]),
    Mutation("reaction-without-load", "model", S + "model/reactions.cpp",
             "  Eigen::VectorXd R = -loads_factor * d.load - f_c;",
             "  Eigen::VectorXd R = -f_c;",
             "a reaction leaves out the external load at the prescribed dofs (a body force's share)",
             ["cli:tests/cli/test_reactions.py::test_bar_under_its_weight"]),
    Mutation("reaction-moment-wrong-point", "model", S + "model/reactions.cpp",
             "    fm.moment += x.x() * f(2 * m + 1) - x.y() * f(2 * m);",
             "    fm.moment += (x.x() - 1.0) * f(2 * m + 1) - x.y() * f(2 * m);",
             "the moment is taken about (1, 0), not the origin",
             ["cli:tests/cli/test_reactions.py::test_moment_of_a_bent_block"]),
    Mutation("reaction-moment-undeformed", "model", S + "model/reactions.cpp",
             "    if (body.finite_strain()) x += Vec2(u_body(2 * m), u_body(2 * m + 1));",
             "    if (false) x += Vec2(u_body(2 * m), u_body(2 * m + 1));",
             "a finite-strain moment taken about the undeformed position, not where the force acts",
             ["cli:tests/cli/test_reactions.py::test_finite_strain_moments_about_the_deformed_position"]),
    Mutation("reaction-curved-edge-straight", "model", S + "model/reactions.cpp",
             "      X[body.dofs.edge_mode(e, static_cast<int>(i) + 2)] = Vec2(x[i], y[i]);",
             "      X[body.dofs.edge_mode(e, static_cast<int>(i) + 2)] = Vec2::Zero();",
             "a curved edge's position taken as the chord between its vertices (its edge modes left out)",
             ["Reactions.ResultantAndMomentOfALoadOnACurvedEdge"]),
    Mutation("equilibrium-never-warned", "driver", S + "driver/reaction_report.cpp",
             "  if (!(r.equilibrium_residual > kEquilibriumLimit)) return std::nullopt;",
             "  if (true) return std::nullopt;",
             "a body whose forces do not balance is not warned about",
             ["cli:tests/cli/test_reactions.py::test_a_loose_solve_is_warned"]),
    Mutation("shared-dof-last-entry", "model", S + "model/discretization.cpp",
             "    if (taken[dof - body.dof_offset]) return;",
             "    if (false && taken[dof - body.dof_offset]) return;",
             "a dof two constraint entries prescribe counts in both reactions",
             ["cli:tests/cli/test_reactions.py::test_a_dof_two_entries_hold_belongs_to_the_first"]),
]



class Interrupted(Exception):
    pass


def on_signal(signum, frame):
    raise Interrupted(f"signal {signum}")


def line_of(text, needle):
    return text[: text.index(needle)].count("\n") + 1


# A mutant can make a test allocate without bound (measured: 14 GB before this limit) on a
# machine others share; the suite's largest process needs 30 MB resident. Address space per
# process of a test run (virtual: thread stacks and allocator arenas count too).
MEMORY_LIMIT = 4 << 30


def limit_memory():
    resource.setrlimit(resource.RLIMIT_AS, (MEMORY_LIMIT, MEMORY_LIMIT))


# Each pytest file is a ctest test of its own with its own time limit (tests/CMakeLists.txt:
# 900 s, for a busy machine), so a mutant that makes every run hang would hold the end-to-end
# part for hours; unmutated it takes 2-5 minutes on 2 cores. ctest stops all its tests at this.
END_TO_END_SECONDS = 900


def stop_time(seconds):
    """ctest --stop-time's argument for `seconds` from now: local time of day (ctest adds its
    zone itself and ignores a time that has one; a time already past means the next day)."""
    return time.strftime("%H:%M:%S", time.localtime(time.time() + seconds))


def run(cmd, cwd, log, limited=False):
    """Runs cmd in its own process group, appends its output to log; returns (exit status,
    output). If this script is interrupted meanwhile, the group it started (ctest and the tests
    it runs, or the build) is ended by its id."""
    proc = subprocess.Popen(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                            start_new_session=True, preexec_fn=limit_memory if limited else None)
    try:
        out, _ = proc.communicate()
    except BaseException:
        os.killpg(proc.pid, signal.SIGTERM)
        try:
            proc.wait(timeout=20)
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGKILL)
        raise
    with open(log, "a") as f:
        f.write(f"$ {' '.join(cmd)}\n{out}\n")
    return proc.returncode, out


def failed_tests(output):
    """ctest's failed tests; a failed pytest test (the per-file cli/test_x, docs/test_x, the
    python suite) stands for the pytest node ids that failed or errored inside it, named
    "cli:tests/cli/test_x.py::test_y" (the ctest name when none is found: a timeout, a crash)."""
    names = []
    section = output.split("The following tests FAILED:", 1)
    if len(section) == 2:
        for line in section[1].splitlines():
            m = re.match(r"\s*\d+ - (\S+) \(", line)
            if m:
                names.append(m.group(1))
    # pytest -q's summary lines, e.g. "FAILED ../../tests/cli/test_x.py::test_y - AssertionError"
    # (ERROR: a fixture failed, e.g. the run a module's tests share)
    pytest = sorted({m.group(1) for m in re.finditer(
        r"^(?:FAILED|ERROR) (?:\.\./)*(tests/(?:cli|python|docs)/\S+?)(?: - .*)?$", output, re.M)})
    out = []
    for name in names:
        group, _, file = name.partition("/")
        if name == "python":
            prefix = "tests/python/"
        elif group in ("cli", "docs") and file:  # cli/test_x and cli/test_x:slow: test_x.py
            prefix = f"tests/{group}/{file.split(':')[0]}.py::"
        else:
            out.append(name)
            continue
        inner = [f"{group}:{n}" for n in pytest if n.startswith(prefix)]
        out.extend(inner or [name])
    if "The stop time has been passed" in output:
        out.append("(stopped at the stage's time limit: see mutate.log)")
    return list(dict.fromkeys(out))  # cli/test_x and cli/test_x:slow both name test_x.py's


def restore_leftovers(backup_dir):
    """Puts back files a killed earlier run left mutated."""
    if not os.path.isdir(backup_dir):
        return
    for dirpath, _, files in os.walk(backup_dir):
        for name in files:
            saved = os.path.join(dirpath, name)
            rel = os.path.relpath(saved, backup_dir)
            print(f"restoring {rel} from an interrupted run", file=sys.stderr)
            shutil.copyfile(saved, os.path.join(ROOT, rel))
            os.remove(saved)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog=__doc__.split("\n\n", 1)[1])
    ap.add_argument("--build", default=os.path.join(ROOT, "build"), help="configured build folder")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 2,
                    help="parallel build and test jobs (default: the cores, %(default)s)")
    ap.add_argument("--only", help="comma-separated mutation ids")
    ap.add_argument("--quick", action="store_true", help="leave out the cli and python tests")
    ap.add_argument("--full", action="store_true",
                    help="run the cli and python tests for every mutation, not only where needed")
    ap.add_argument("--list", action="store_true", help="list the mutations and exit")
    ap.add_argument("--out", help="also write the table (Markdown) to this file")
    args = ap.parse_args()

    chosen = MUTATIONS
    if args.only:
        ids = args.only.split(",")
        unknown = [i for i in ids if i not in {m.id for m in MUTATIONS}]
        if unknown:
            print(f"unknown mutation ids: {', '.join(unknown)}", file=sys.stderr)
            return 2
        chosen = [m for m in MUTATIONS if m.id in ids]
    # Every mutation must apply to the sources as they are: exactly one occurrence.
    for m in chosen:
        text = open(os.path.join(ROOT, m.path)).read()
        if text.count(m.old) != 1:
            print(f"{m.id}: the text to change occurs {text.count(m.old)} times in {m.path}",
                  file=sys.stderr)
            return 2
    if args.list:
        for m in chosen:
            text = open(os.path.join(ROOT, m.path)).read()
            print(f"{m.id:24} {m.path}:{line_of(text, m.old)}  {m.what}")
        return 0
    if not os.path.exists(os.path.join(args.build, "build.ninja")):
        print(f"{args.build} is not a configured Ninja build (run `make build` first)", file=sys.stderr)
        return 2

    backup_dir = os.path.join(args.build, "mutate-backup")
    restore_leftovers(backup_dir)
    signal.signal(signal.SIGTERM, on_signal)
    signal.signal(signal.SIGINT, on_signal)  # the children run in their own groups: Ctrl-C is ours
    log = os.path.join(args.build, "mutate.log")
    open(log, "w").close()
    # --timeout: for the tests without their own (the C++ ones: 12 s at most unmutated).
    ctest = ["ctest", "-j", str(args.jobs), "--timeout", "120", "--output-on-failure"]
    # unit, verification, fuzz replays, and the docs, install and slurm tests: ~2 min
    cpp_tests = ctest + ["-LE", "slow|cli|python"]
    end_to_end = ctest + ["-L", "cli|python", "-LE", "slow"]  # the command line, Python: 2-5 min
    suite = ("ctest -LE 'slow|cli|python'" if args.quick else
             "ctest -LE slow" + ("" if args.full else " (cli, python only where needed: see --help)"))
    build = ["cmake", "--build", args.build, "-j", str(args.jobs)]

    status, out = run(build, ROOT, log)
    if status != 0:
        print("the unmutated sources do not build; see " + log, file=sys.stderr)
        return 2
    rows = []
    start = time.time()
    try:
        for k, m in enumerate(chosen, 1):
            path = os.path.join(ROOT, m.path)
            original = open(path, "rb").read()
            text = original.decode()
            where = f"{m.path.removeprefix(S)}:{line_of(text, m.old)}"
            t0 = time.time()
            saved = os.path.join(backup_dir, m.path)
            os.makedirs(os.path.dirname(saved), exist_ok=True)
            shutil.copyfile(path, saved)
            try:
                with open(path, "w") as f:
                    f.write(text.replace(m.old, m.new))
                status, _ = run(build, ROOT, log)
                if status != 0:
                    verdict, props, others = "no build", [], []
                else:
                    failed = []
                    stages = [cpp_tests]
                    if not args.quick:
                        stages.append(end_to_end)
                    for stage, cmd in enumerate(stages):
                        # The end-to-end tests only when they can decide the verdict: no property
                        # test has failed yet, or the mutation's property tests are among them.
                        if stage == 1 and not args.full and any(expected(t, m) for t in failed) and \
                                not any(t.startswith(("cli:", "cli/", "python")) for t in m.expect):
                            break
                        if stage == 1:
                            cmd = cmd + ["--stop-time", stop_time(END_TO_END_SECONDS)]
                        status, out = run(cmd, args.build, log, limited=True)
                        found = failed_tests(out)
                        if status != 0 and not found:
                            found = ["(ctest failed: see mutate.log)"]
                        failed += found
                    props = [t for t in failed if expected(t, m)]
                    others = [t for t in failed if not expected(t, m)]
                    verdict = "caught" if props else ("other only" if others else "SURVIVED")
            finally:
                with open(path, "wb") as f:
                    f.write(original)
                os.remove(saved)
            rows.append((m, where, verdict, props, others))
            print(f"[{k}/{len(chosen)}] {m.id}: {verdict} ({time.time() - t0:.0f} s)"
                  f"{': ' + ', '.join(props) if props else ''}", flush=True)
    except (KeyboardInterrupt, Interrupted) as e:
        print(f"interrupted ({e or 'Ctrl-C'}); the mutated file is restored", file=sys.stderr)
    finally:
        run(build, ROOT, log)  # the build matches the sources again

    def cell(names, limit=4):
        shown = ", ".join(names[:limit])
        return shown + (f" (+{len(names) - limit} more)" if len(names) > limit else "")

    lines = [f"{len(rows)} mutations, {time.time() - start:.0f} s, suite: {suite}", "",
             "| id | module | where | mutation | verdict | property tests failed | other tests failed |",
             "|---|---|---|---|---|---|---|"]
    for m, where, verdict, props, others in rows:
        lines.append(f"| {m.id} | {m.module} | {where} | {m.what} | {verdict} | {cell(props)} | "
                     f"{len(others)}{': ' + cell(others, 3) if others else ''} |")
    table = "\n".join(lines)
    print("\n" + table)
    if args.out:
        with open(args.out, "w") as f:
            f.write(table + "\n")
    return 0 if rows and all(r[2] == "caught" for r in rows) and len(rows) == len(chosen) else 1


if __name__ == "__main__":
    sys.exit(main())
