"""Floating hemisphere in heave against Hulme's analytic coefficients.

Reference: A. Hulme (1982), "The wave forces acting on a floating hemisphere undergoing forced
periodic oscillations", J. Fluid Mech. 121, 443–463 — table transcribed in
tests/data/refdata/hulme (from LHEEA/Hulme_Heaving_Sphere). BEM data: HydroChrono's
demos/sphere/hydroData/sphere.h5 (WAMIT, radius 5 m, 200 m depth ≈ deep for these kA).
"""

import numpy as np
import pytest

from boatland.validation.hemisphere import RADIUS, bemio_sphere, hulme_nondim, hulme_rel_error, hulme_table


@pytest.fixture(scope="module")
def hulme(refdata):
    return hulme_table(refdata)


@pytest.fixture(scope="module")
def sphere(refdata):
    return bemio_sphere(refdata)


# Hulme's table is printed to 4 decimals; the error is measured to the interval each printed value stands
# for (boatland.validation.hemisphere.hulme_rel_error), the code `boatland validate` runs too.
rel_error = hulme_rel_error
nondim = hulme_nondim


def test_added_mass_within_half_percent_of_hulme(sphere, hulme):
    kA, mu, _ = nondim(sphere)
    rows = hulme[hulme[:, 0] >= kA[0]]  # kA = 0 is ω = 0 (not in the band); 0.05 is at ω = 0.31
    assert rows.shape[0] >= 24
    mu_bem = np.interp(rows[:, 0], kA, mu)
    rel = rel_error(mu_bem, rows[:, 1])
    assert rel.max() < 0.005, dict(zip(rows[:, 0], rel.round(4)))


def test_damping_within_half_percent_of_hulme_up_to_ka_4(sphere, hulme):
    kA, _, lam = nondim(sphere)
    rows = hulme[(hulme[:, 0] > 0) & (hulme[:, 0] <= 4.0)]
    lam_bem = np.interp(rows[:, 0], kA, lam)
    rel = rel_error(lam_bem, rows[:, 2])
    # measured: worst at kA = 4, λ_BEM = 0.02201 vs 0.0219 printed (0.53 % from the digits, 0.28 %
    # from the rounding interval); everywhere else < 0.3 % from the printed digits
    assert rel.max() < 0.005, dict(zip(rows[:, 0], rel.round(4)))
    # Not checked: beyond kA = 4 this file's damping exceeds Hulme's table by 0.4–1.4e-4 absolute
    # (1.2 % at kA = 5, 2.1 % at kA = 6): short waves (λ/a ≈ 1.3) on a 5 m sphere test the BEM mesh,
    # not the readers. See tests/validation/test_hemisphere_codes.py for the cross-code comparison.


def test_a_inf_tends_to_half(sphere):
    V = 2 / 3 * np.pi * RADIUS ** 3
    assert abs(sphere.A_inf[2, 2] / (sphere.rho * V) - 0.5) < 0.005
