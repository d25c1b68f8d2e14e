"""scripts/energy_extrapolation.py: the seed's extrapolation of the exact energy from three
discretisations (eq. 4.14), the relative energy-norm error (eq. 4.3) and the fitted rate β."""
import math

import pytest
from conftest import load_script

ee = load_script("energy_extrapolation")
DOF_TRIPLES = [(220, 312, 420), (544, 1204, 2112), (40, 41, 100)]


def synthetic(u_ex, dofs, beta, first_error, sign=1.0):
    """Energies U_i = U_ex - sign·k·N_i^(-2β) (eq. 4.13), k chosen so that the relative energy
    difference at N_0 is first_error."""
    k = first_error * u_ex * dofs[0] ** (2 * beta)
    return [u_ex - sign * k * n ** (-2 * beta) for n in dofs]


@pytest.mark.parametrize("dofs", DOF_TRIPLES)
@pytest.mark.parametrize("beta", [0.3, 1.0, 1.75, 3.0, 6.0])
@pytest.mark.parametrize("first_error", [1e-1, 1e-3])
def test_extrapolation_recovers_the_exact_energy(dofs, beta, first_error):
    """For energies that follow U_ex - U_i = k N_i^(-2β) exactly, eq. 4.14 gives back U_ex to
    1e-10 relative, whatever β, k and the spacing of the three DOF counts."""
    u_ex = 7595.967
    energies = synthetic(u_ex, dofs, beta, first_error)
    u = ee.extrapolate_energy(dofs, energies)
    assert abs(u - u_ex) <= 1e-10 * u_ex, (u, u_ex)
    assert ee.implied_beta(dofs, energies, u) == pytest.approx(beta, rel=1e-4)


@pytest.mark.parametrize("beta", [0.5, 2.0])
def test_extrapolation_of_falling_energies(beta):
    """Energies that fall towards U_ex (a displacement-driven problem) extrapolate as well, to
    the far side of the last value."""
    dofs = (220, 312, 420)
    energies = synthetic(3.5, dofs, beta, 1e-2, sign=-1.0)
    u = ee.extrapolate_energy(dofs, energies)
    assert abs(u - 3.5) <= 1e-10 * 3.5 and u < energies[-1]


@pytest.mark.parametrize("energies", [[1.0, 1.2, 1.1], [1.0, 0.9, 1.1], [1.0, 1.0, 1.1],
                                      [1.0, 1.1, 1.1]])
def test_non_monotone_energies_are_refused(energies):
    """Energies that are not strictly monotone raise ExtrapolationError naming them."""
    with pytest.raises(ee.ExtrapolationError, match="monotone"):
        ee.extrapolate_energy([100, 200, 300], energies)


def test_no_solution_is_refused():
    """Increments that do not shrink fast enough for any positive β (here they grow) leave
    eq. 4.14 without a root: ExtrapolationError says so."""
    with pytest.raises(ee.ExtrapolationError, match="no solution"):
        ee.extrapolate_energy([100, 200, 300], [1.0, 2.0, 3.5])
    # just past the limit: the increment ratio 1.0001 Q, Q = ln(N2/N1)/ln(N1/N0) (β = 0 at Q)
    q = math.log(300 / 200) / math.log(200 / 100)
    with pytest.raises(ee.ExtrapolationError, match="no solution"):
        ee.extrapolate_energy([100, 200, 300], [1.0, 2.0, 2.0 + 1.0001 * q])
    # just before it the root exists, far out (β small)
    assert ee.extrapolate_energy([100, 200, 300], [1.0, 2.0, 2.0 + 0.999 * q]) > 100


def test_bad_dofs_are_refused():
    """DOF counts must be three, positive and strictly increasing."""
    with pytest.raises(ee.ExtrapolationError, match="increasing"):
        ee.extrapolate_energy([200, 100, 300], [1.0, 1.5, 1.6])
    with pytest.raises(ee.ExtrapolationError, match="three"):
        ee.extrapolate_energy([100, 200], [1.0, 1.5])


def test_relative_energy_error_is_eq_4_3():
    """100·sqrt(|U_ref - U| / U_ref): 5 % for U = 0.9975 U_ref, from either side."""
    assert ee.relative_energy_error(3.99, 4.0) == pytest.approx(5.0, rel=1e-12)
    assert ee.relative_energy_error(4.01, 4.0) == pytest.approx(5.0, rel=1e-12)
    assert ee.relative_energy_error(4.0, 4.0) == 0.0
    with pytest.raises(ValueError):
        ee.relative_energy_error(1.0, 0.0)


@pytest.mark.parametrize("beta", [0.5, 1.0, 1.75, 4.2])
def test_fit_beta_recovers_the_rate(beta):
    """Errors exactly k·N^-β give back β (to round-off) and k."""
    dofs = [40, 84, 144, 220, 312, 420, 544]
    errors = [3.7 * n ** -beta for n in dofs]
    assert ee.fit_beta(dofs, errors) == pytest.approx(beta, abs=1e-12)
    b, k = ee.fit_power_law(dofs, errors)
    assert k == pytest.approx(3.7, rel=1e-10)


def test_fit_beta_refuses_zero_errors():
    """A zero error (the reference run itself) cannot be fitted on a log scale."""
    with pytest.raises(ValueError, match="positive"):
        ee.fit_beta([10, 20, 30], [1.0, 0.5, 0.0])
