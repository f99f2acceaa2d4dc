"""Time domain against frequency domain: steady regular-wave response equals the RAO (San Nicolás Méndez
2024, DTU MSc thesis, eq. 3.31; ``boatland validate`` case td-vs-fd-rao runs the same code).

.. math:: \\hat x(\\omega) = \\left[-\\omega^2 (M + A(\\omega)) + i\\omega B(\\omega) + C\\right]^{-1} X(\\omega, \\beta)\\, a

The frequency domain is :func:`boatland.freqdomain.free_rao`. Both from the same database: the
hemisphere of HydroChrono's sphere.h5 (WAMIT), mass ρV, free floating, no additional damping. The
time-domain amplitude and phase come from a least-squares fit of c₀ + c₁t + Re{x̂ e^{iωt}} over the
last 10 periods (:func:`boatland.freqdomain.first_harmonic`; the trend absorbs the slow surge drift
of the start-up: surge has no restoring).
"""

import pytest

from boatland.validation.timedomain import RAO_FREQUENCIES, hemisphere_with_mass, regular_wave_response


@pytest.fixture(scope="module")
def hemisphere(refdata):
    return hemisphere_with_mass(refdata)


@pytest.mark.parametrize("w", RAO_FREQUENCIES)
def test_heave_surge_pitch_raos(hemisphere, w):
    db, mem = hemisphere
    td, expected, status = regular_wave_response(db, mem, w)      # a = 0.1 m (linear: the amplitude only scales)
    assert status == 0
    for d in (0, 2, 4):
        assert abs(td[d] - expected[d]) < 0.02 * abs(expected[d]), (d, td[d], expected[d])
